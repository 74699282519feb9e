// Validates a glTF/GLB file with the Khronos glTF-Validator and prints its report.
// Usage: node tools/validate-gltf.mjs FILE.glb   — exit status 1 when the report has errors.
import { readFile } from 'node:fs/promises';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const validator = require('gltf-validator');

const path = process.argv[2];
if (!path) {
  console.error('usage: node validate-gltf.mjs FILE.glb');
  process.exit(2);
}
try {
  const bytes = new Uint8Array(await readFile(path));
  const report = await validator.validateBytes(bytes, { uri: path, maxIssues: 100 });
  const { numErrors, numWarnings, numInfos, numHints } = report.issues;
  console.log(`${path}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
  for (const m of report.issues.messages) console.log(`  [${['error', 'warning', 'info', 'hint'][m.severity]}] ${m.code} ${m.pointer ?? ''}: ${m.message}`);
  process.exit(numErrors > 0 ? 1 : 0);
} catch (e) {
  console.error(`${path}: ${e.message ?? e}`);
  process.exit(1);
}
