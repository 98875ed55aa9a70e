// Runs the Khronos glTF validator on each .glb given on the command line and fails unless
// every file has 0 errors and 0 warnings. Infos and hints are printed, not counted.
//
// Usage: node validate.mjs FILE.glb...
import { readFile } from "node:fs/promises";
import validator from "gltf-validator";

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error("usage: node validate.mjs FILE.glb...");
  process.exit(2);
}
let failed = false;
for (const file of files) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, { uri: file, maxIssues: 100 });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  const info = report.info ?? {};
  console.log(
    `${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints ` +
      `(${info.animationCount ?? 0} animations, ${info.totalVertexCount ?? 0} vertices, ` +
      `${bytes.length} bytes)`,
  );
  for (const m of messages) {
    const severity = ["error", "warning", "info", "hint"][m.severity] ?? m.severity;
    console.log(`  ${severity} ${m.code} at ${m.pointer ?? ""}: ${m.message}`);
  }
  if (numErrors > 0 || numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);
