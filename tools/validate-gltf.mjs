// Validates a glTF/GLB file with the Khronos glTF-Validator (npm package gltf-validator).
// Usage: node tools/validate-gltf.mjs FILE.glb|FILE.gltf
// Prints a one-line summary, then the issues as JSON; exit status 1 when the report has errors
// (warnings and infos are printed, not fatal), 2 for a usage error.
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const validator = require('gltf-validator');

const path = process.argv[2];
if (!path) {
  console.error('usage: node validate-gltf.mjs FILE.glb|FILE.gltf');
  process.exit(2);
}
try {
  const bytes = new Uint8Array(await readFile(path));
  const report = await validator.validateBytes(bytes, { uri: path, maxIssues: 100 });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  console.log(`${path}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
  console.log(JSON.stringify({ file: path, numErrors, numWarnings, numInfos, messages }, null, 1));
  process.exit(numErrors > 0 ? 1 : 0);
} catch (e) {
  console.error(`${path}: ${e.message ?? e}`);
  process.exit(1);
}
