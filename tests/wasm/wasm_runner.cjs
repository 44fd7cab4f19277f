// Runs the WebAssembly module (wasm/) under Node on a list of cases and writes each answer to
// a file, for check_wasm_same_bytes.py to compare with the native program's. The module reads
// the cases' files through Node's file system, mounted at the same absolute paths, so that the
// paths in its answers are the native program's.
//
// Usage: node wasm_runner.cjs MODULE.js CASES.json
//   CASES.json: {"mounts": [dir...], "cases": [{"kind": "pair"|"golden", "request"|"path",
//                "out": file}]}
// Exit status 0 when every case ran (an error answer is written as {"error": message}).
'use strict';
const fs = require('fs');
const path = require('path');

async function main() {
  const [modulePath, casesPath] = process.argv.slice(2);
  if (!modulePath || !casesPath) {
    console.error('usage: node wasm_runner.cjs MODULE.js CASES.json');
    process.exit(2);
  }
  const createRecodeModule = require(path.resolve(modulePath));
  const m = await createRecodeModule();
  const spec = JSON.parse(fs.readFileSync(casesPath, 'utf8'));
  for (const dir of spec.mounts) {
    m.FS.mkdirTree(dir);
    m.FS.mount(m.NODEFS, {root: dir}, dir);
  }
  const pair = m.cwrap('recode_pair', 'number', ['string']);
  const golden = m.cwrap('recode_check_golden', 'number', ['string']);
  const error = m.cwrap('recode_error', 'string', []);
  const started = Date.now();
  for (const c of spec.cases) {
    const answer = c.kind === 'pair' ? pair(JSON.stringify(c.request)) : golden(c.path);
    // An error answer is written as the checker writes the native program's refusal.
    const text = answer ? m.UTF8ToString(answer) : JSON.stringify({error: error()}) + '\n';
    fs.writeFileSync(c.out, text);
  }
  console.log('wasm_runner: ' + spec.cases.length + ' cases in ' + (Date.now() - started) + ' ms');
}

main().catch((e) => {
  console.error('wasm_runner: ' + (e && e.stack ? e.stack : e));
  process.exit(1);
});
