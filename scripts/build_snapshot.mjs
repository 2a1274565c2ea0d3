// Make the Pyodide memory snapshots the page's workers start from: the grader's
// (by default) and, with --sandbox, the sandbox's (docs/assets/js/sandbox.js).
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
// The sandbox's: the same Pyodide with the sandbox's own standard library and lock
// (scripts/sandbox_files.py: no grading package), workbook_sandbox imported and one
// small run made through it (nothing of a learner's: a function of its own, here);
// output <vendor>/sandbox.snapshot.gz and build/sandbox-snapshot.json.
//
// Usage: node scripts/build_snapshot.mjs [--sandbox] [vendor-dir]
import { createHash } from "node:crypto";
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";
import { gzipSync } from "node:zlib";
import path from "node:path";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");
const args = process.argv.slice(2);
const forSandbox = args.includes("--sandbox");
const vendor = path.resolve(args.find((a) => a !== "--sandbox") || path.join(root, "docs/assets/vendor/pyodide")) + "/";
const require = createRequire(import.meta.url);
const { loadPyodide } = require(vendor + "pyodide.js");

const stdlibName = forSandbox ? "python_stdlib.sandbox.zip" : "python_stdlib.core.zip"; // scripts/split_stdlib.py, sandbox_files.py
const core = readFileSync(vendor + stdlibName);

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
assert json.loads(api.handle(json.dumps({"op": "version"})))["ok"]  # the sources' hash, worked out once (workbook/version.py)
# The finder of the rest of the standard library, installed here so that a restore reads no zip for it:
# the worker gives it its address (worker.js).
from workbook_sandbox import lazy_stdlib
lazy_stdlib.install(None)
# Leave no trace of this machine or this script: loadPyodide puts "" back on
# sys.path after a restore, and Node's "_" names the build script.
import gc, os, sys
os.environ.pop("_", None)
while "" in sys.path:
    sys.path.remove("")
gc.collect()
`;
// The sandbox's: its runner imported and used once (what a first run would import and compile).
const SANDBOX_WARM_UP = `
import json
from workbook_sandbox import runner
job = {"function": "f", "harness": "call", "cases": [[1.5], [0]]}
report = json.loads(runner.run_in_sandbox(json.dumps(job), "def f(x):\\n    return (1 / x, [x])\\n")[0])
assert "value" in report["cases"][0] and report["cases"][1]["error"]["type"] == "ZeroDivisionError", report
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
// The worker's own start: the core standard library, which holds the package too (scripts/split_stdlib.py);
// the sandbox's: its own standard library and lock.
const stdLibURL = vendor + stdlibName;
const lock = forSandbox ? { lockFileURL: vendor + "pyodide-lock.sandbox.json" } : {};
const py = await loadPyodide({ indexURL: vendor, stdLibURL, ...lock, _makeSnapshot: true, stdout: () => {}, stderr: () => {} });
py.runPython(forSandbox ? SANDBOX_WARM_UP : WARM_UP);
const snapshot = py.makeMemorySnapshot();
const packed = sparse(snapshot);
const gz = gzipSync(packed, { level: 9 });
writeFileSync(vendor + (forSandbox ? "sandbox.snapshot.gz" : "workbook.snapshot.gz"), gz);
const sha256 = (b) => createHash("sha256").update(b).digest("hex");
const info = {
  pyodide: py.version,
  stdlib: stdlibName,
  stdlib_core_sha256: sha256(core),
  bytes: snapshot.length,
  sparse_bytes: packed.length,
  gzip_bytes: gz.length,
  sha256: sha256(snapshot),
};
mkdirSync(path.join(root, "build"), { recursive: true });
writeFileSync(path.join(root, forSandbox ? "build/sandbox-snapshot.json" : "build/snapshot.json"), JSON.stringify(info, null, 2) + "\n");
const mb = (n) => (n / 1e6).toFixed(1) + " MB";
console.log(`${forSandbox ? "sandbox " : ""}snapshot: ${mb(info.bytes)} (${mb(info.gzip_bytes)} gzip) in ${((performance.now() - t0) / 1000).toFixed(1)} s`);
