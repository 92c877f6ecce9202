// Runs the Khronos glTF-Validator (npm package gltf-validator) over the files given on the command
// line. Prints each report's counts and messages; exits 1 when any file has errors, and 77 (ctest's
// SKIP_RETURN_CODE) when the package is not installed (run `npm ci` at the repository root).
import { readFile } from 'node:fs/promises';
import path from 'node:path';

let validator;
try {
  validator = await import('gltf-validator');
} catch (e) {
  console.log(`SKIP: the npm package gltf-validator is not installed (${e.code ?? e.message}); run npm ci`);
  process.exit(77);
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node validate_gltf.mjs FILE.glb...');
  process.exit(2);
}

let failed = 0;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(await readFile(file));
  } catch (e) {
    console.error(`${file}: cannot read: ${e.message}`);
    failed++;
    continue;
  }
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    writeTimestamp: false,
    // External URIs (images next to the file) are loaded relative to it.
    externalResourceFunction: (uri) =>
      readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints (validator ${report.validatorVersion})`);
  for (const m of issues.messages) {
    const severity = ['error', 'warning', 'info', 'hint'][m.severity] ?? m.severity;
    console.log(`  ${severity} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
  }
  if (issues.numErrors > 0) failed++;
}
process.exit(failed > 0 ? 1 : 0);
