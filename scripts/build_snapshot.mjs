// Make the Pyodide memory snapshot the page's worker starts from.
//
// A fresh Pyodide spends most of its start-up booting the interpreter and
// importing modules. Here, at build time, Node boots the same vendored Pyodide
// with the same core standard library (which holds the grading package: see
// scripts/split_stdlib.py), imports the whole grading package and grades one answer of
// every kind, then saves the interpreter's memory. The worker restores that
// memory instead of booting (docs/performance.md has the numbers).
//
// The snapshot is tied to the exact pyodide.asm.wasm build (Pyodide checks its
// build id on load), so it is made from the vendored files and nothing else.
// Output: <vendor>/workbook.snapshot.gz (zero pages left out, see sparse(), then
// gzip: the service worker or the worker inflates it with DecompressionStream) and build/snapshot.json (sizes, hashes, the core it was made with).
//
// Usage: node scripts/build_snapshot.mjs [vendor-dir]
import { createHash } from "node:crypto";
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { gzipSync } from "node:zlib";
import path from "node:path";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");
const vendor = path.resolve(process.argv[2] || path.join(root, "docs/assets/vendor/pyodide")) + "/";
const require = createRequire(import.meta.url);
const { loadPyodide } = require(vendor + "pyodide.js");

const core = readFileSync(vendor + "python_stdlib.core.zip"); // run scripts/split_stdlib.py first

// Everything imported here is in the snapshot; nothing may hold a JavaScript
// object (Pyodide refuses to snapshot those), so the warm-up goes through JSON.
const WARM_UP = `
import importlib, json, pkgutil
import workbook
for info in pkgutil.walk_packages(workbook.__path__, "workbook."):
    importlib.import_module(info.name)
from workbook import api, bank
kinds = {}
for ex in bank.all_exercises():
    kinds.setdefault(ex.kind, ex)
for kind, ex in sorted(kinds.items()):
    if ex.op == "run":  # the grader's part of a Build run: its cases and its judgement (the code runs in the sandbox)
        from workbook_sandbox.runner import run_json
        job = json.loads(api.handle(json.dumps({"op": "cases", "exercise": ex.id, "code": ex.starter})))["value"]["job"]
        request = {"op": "judge", "exercise": ex.id, "outputs": run_json(job, ex.starter)}
    else:
        request = {"op": ex.op, "exercise": ex.id, "answer": "1"}
    reply = json.loads(api.handle(json.dumps(request)))
    assert reply["ok"], reply
# Leave no trace of this machine or this script: loadPyodide puts "" back on
# sys.path after a restore, and Node's "_" names the build script.
import gc, os, sys
os.environ.pop("_", None)
while "" in sys.path:
    sys.path.remove("")
gc.collect()
`;

// About 40 % of the memory is zero pages. The file leaves them out, so a start
// reads 12 MB instead of 21 MB from the cache. Layout (little-endian u32s):
// "WBSPARSE", the full length, the number of runs, (offset, length) per run,
// then the bytes of each run; the worker (worker.js) puts them back in place.
const PAGE = 4096;
function sparse(bytes) {
  const runs = [];
  for (let at = 0; at < bytes.length; at += PAGE) {
    const page = bytes.subarray(at, Math.min(at + PAGE, bytes.length));
    if (page.every((b) => b === 0)) continue;
    const last = runs[runs.length - 1];
    if (last && last[0] + last[1] === at) last[1] += page.length;
    else runs.push([at, page.length]);
  }
  const head = 16 + 8 * runs.length;
  const out = new Uint8Array(head + runs.reduce((n, [, len]) => n + len, 0));
  const view = new DataView(out.buffer);
  out.set(new TextEncoder().encode("WBSPARSE"), 0);
  view.setUint32(8, bytes.length, true);
  view.setUint32(12, runs.length, true);
  let data = head;
  runs.forEach(([offset, length], i) => {
    view.setUint32(16 + 8 * i, offset, true);
    view.setUint32(20 + 8 * i, length, true);
    out.set(bytes.subarray(offset, offset + length), data);
    data += length;
  });
  return out;
}

const t0 = performance.now();
// The worker's own start: the core standard library, which holds the package too (scripts/split_stdlib.py).
const stdLibURL = vendor + "python_stdlib.core.zip";
const py = await loadPyodide({ indexURL: vendor, stdLibURL, _makeSnapshot: true, stdout: () => {}, stderr: () => {} });
py.runPython(WARM_UP);
const snapshot = py.makeMemorySnapshot();
const packed = sparse(snapshot);
const gz = gzipSync(packed, { level: 9 });
writeFileSync(vendor + "workbook.snapshot.gz", gz);
const sha256 = (b) => createHash("sha256").update(b).digest("hex");
const info = {
  pyodide: py.version,
  stdlib_core_sha256: sha256(core),
  bytes: snapshot.length,
  sparse_bytes: packed.length,
  gzip_bytes: gz.length,
  sha256: sha256(snapshot),
};
mkdirSync(path.join(root, "build"), { recursive: true });
writeFileSync(path.join(root, "build/snapshot.json"), JSON.stringify(info, null, 2) + "\n");
const mb = (n) => (n / 1e6).toFixed(1) + " MB";
console.log(`snapshot: ${mb(info.bytes)} (${mb(info.gzip_bytes)} gzip) in ${((performance.now() - t0) / 1000).toFixed(1)} s`);
