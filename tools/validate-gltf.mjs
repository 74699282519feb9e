// Usage: node tools/validate-gltf.mjs FILE.glb|FILE.gltf
// Runs the Khronos glTF-Validator on one file, prints its issue summary as JSON and exits 1 when
// it reports any error (warnings and infos are printed, not fatal).
import { readFile } from 'node:fs/promises';
import validator from 'gltf-validator';

const path = process.argv[2];
if (!path) {
  console.error('usage: node validate-gltf.mjs FILE');
  process.exit(2);
}
const bytes = new Uint8Array(await readFile(path));
const report = await validator.validateBytes(bytes, { maxIssues: 100 });
const { numErrors, numWarnings, numInfos, messages } = report.issues;
console.log(JSON.stringify({ file: path, numErrors, numWarnings, numInfos, messages }, null, 1));
process.exit(numErrors > 0 ? 1 : 0);
