// Validates glTF/GLB files with the Khronos glTF validator (npm gltf-validator).
// Usage: node validate_gltf.mjs NODE_MODULES_DIR FILE...
// Prints one line per file (errors, warnings, and each issue at error or warning level);
// exits 0 when no file has errors, 1 when one has, 77 when the validator is not installed.
import { createRequire } from 'node:module';
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const [modules, ...files] = process.argv.slice(2);
let validator;
try {
  validator = createRequire(path.resolve(modules) + '/')('gltf-validator');
} catch (e) {
  console.log(`SKIPPED: gltf-validator is not installed in ${modules} (npm install in tests/tools/gltf_validator)`);
  process.exit(77);
}

let failed = 0;
for (const file of files) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) => readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))
      .then((b) => new Uint8Array(b)),
  });
  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos`);
  const seen = new Map();
  for (const m of issues.messages) {
    if (m.severity > 1) continue;
    const key = `${m.severity === 0 ? 'error' : 'warning'} ${m.code}`;
    if (!seen.has(key)) seen.set(key, { count: 0, example: `${m.pointer ?? ''} ${m.message}` });
    seen.get(key).count++;
  }
  for (const [key, v] of seen) console.log(`  ${key} x${v.count}: ${v.example}`);
  if (issues.numErrors > 0) failed++;
}
process.exit(failed ? 1 : 0);
