// Validates .glb files with the Khronos glTF validator (npm gltf-validator) and prints one JSON
// line per file: {"file", "errors", "warnings", "infos", "messages": [first few issues]}.
// Usage: node validate_gltf.mjs FILE.glb...  (used by tests/viz/gltf_validator_test.cc)
import { validateBytes } from 'gltf-validator';
import { readFileSync } from 'fs';

for (const file of process.argv.slice(2)) {
  const report = await validateBytes(new Uint8Array(readFileSync(file)), { maxIssues: 20 });
  console.log(JSON.stringify({
    file,
    errors: report.issues.numErrors,
    warnings: report.issues.numWarnings,
    infos: report.issues.numInfos,
    messages: report.issues.messages.slice(0, 5).map((m) => `${m.code} ${m.pointer || ''}: ${m.message}`),
  }));
}
