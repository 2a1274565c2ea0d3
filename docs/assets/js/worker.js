// The grading worker: loads Pyodide and the grading package once, then answers
// requests from the page. One request at a time; the page enforces time limits
// by an interrupt when it is cross-origin isolated (it shares a buffer, see
// runtime.js), else by terminating this worker.
// Replies are envelopes (CONTRACT.md): the grader's own, or {ok: false, error}
// when the runtime itself fails.
import { ERROR } from "./contract.js";
import { mark, stages, startPyodide } from "./boot.js";
import { BOOT_STEP } from "./boot-steps.js";

const indexURL = new URL("../vendor/pyodide/", self.location.href).href;
let handle = null;
let pyodide = null;
let interruptBuffer = null; // [0]: signal written by the page, [1]: id of the request running
let lazyStdlib = null; // workbook_sandbox.lazy_stdlib

// ---- Start-up -----------------------------------------------------------------
// boot.js starts Pyodide: it restores the memory snapshot made at build time
// (the interpreter with the grading package imported), or boots when that is
// not worth it or fails. Either way Python's standard library is the small
// core, which holds the grading package too; on a plain start over a link fast
// enough to bring their extra bytes (boot.js) the same compiled, in two files: the core
// without the package (the sandbox starts from it too) and the package. The rest is mounted
// on first use (scripts/split_stdlib.py, workbook_sandbox/lazy_stdlib.py). Its progress (bytes of
// the runtime files, then Python's start) goes to the page as it happens.

const STDLIB_CORE = indexURL + "python_stdlib.core.zip";
const STDLIB_CORE_COMPILED = indexURL + "python_stdlib.core.compiled.zip"; // without the grading package
const PACKAGE_COMPILED = "workbook.compiled.zip"; // the package, compiled
// The page tells this worker two things in its name (docs/overrides/main.html), which it reads before
// anything: `package`, a chapter page's own part of the compiled package (only that chapter's modules;
// the package's other modules then come from the sources' core on first use: lazy_stdlib.py), and `sw`,
// whether the page is under the service worker.
const CHAPTER_PACKAGE = /^workbook\.compiled\.ch\d+\.zip$/;
const told = new URLSearchParams(self.name);
const chapterPackage = CHAPTER_PACKAGE.test(told.get("package") ?? "") ? told.get("package") : null;
const STDLIB_REST = indexURL + "python_stdlib.rest.zip";
const SNAPSHOT = indexURL + "workbook.snapshot.gz";

const reportBoot = (progress) => self.postMessage({ type: "boot", ...progress });

// On a first visit the page and this worker start together, and on two cores Python's start (compiling
// pyodide.asm.js and the WebAssembly, unpacking the snapshot) made the page's own start-up tasks long:
// the theme's took 76-147 ms instead of about 50. So, unless the service worker controls the page (a
// revisit, where the worker's start is short and ready is what counts), Python's start waits until the
// page says it has started ({type: "page-started"}, after DOMContentLoaded: main.js), PAGE_WAIT_MS at
// most. The WebAssembly's download does not wait (boot.js keeps its bytes meanwhile).
const PAGE_WAIT_MS = 3000;
const controlled = told.get("sw") === "1";
let pageStarted;
const pageHasStarted = controlled ? null : new Promise((resolve) => {
  pageStarted = resolve;
  setTimeout(resolve, PAGE_WAIT_MS);
});

// The first grade after a start used to take 30-130 ms instead of 2: the
// browser compiles WebAssembly functions lazily, on their first call, and the
// first grade called many for the first time; the worker's own JavaScript path
// (JSON in, the call into Python, JSON out) is compiled on first use too. So
// before "ready" the worker answers, through that same path, the requests
// workbook.api.warm_up() lists for the page's own exercises (the page names
// them as soon as its script runs: {type: "page", ids}); only their chapters
// are imported, so a plain start (a slow first visit) compiles no others.
let pageIds = null;

/** One request through Python: the worker's only way in (JSON both ways). */
const answer = (request) => JSON.parse(handle(JSON.stringify(request)));

// ---- Requests ------------------------------------------------------------------
const ready = (async () => {
  const t0 = performance.now();
  const started = await startPyodide({ indexURL, stdLibURL: STDLIB_CORE, compiledStdLibURL: STDLIB_CORE_COMPILED,
    compiledPackageURL: indexURL + (chapterPackage ?? PACKAGE_COMPILED), snapshotURL: SNAPSHOT,
    onProgress: reportBoot, controlled, startAfter: pageHasStarted });
  pyodide = started.py;
  started.step(BOOT_STEP.import); // the grading package and this page's exercises
  lazyStdlib = pyodide.pyimport("workbook_sandbox.lazy_stdlib");
  lazyStdlib.install(STDLIB_REST).destroy();
  // Only a chapter's part of the compiled package leaves modules of the package out (and lists them).
  if (chapterPackage && stages.stdlib === "compiled") lazyStdlib.install_package_rest(STDLIB_CORE);
  handle = pyodide.pyimport("workbook.api").handle;
  mark("handle");
  const api = pyodide.pyimport("workbook.api");
  for (const request of JSON.parse(api.warm_up(pageIds))) answer(request);
  api.destroy();
  mark("ready");
  stages.timeOrigin = performance.timeOrigin; // to line the stages up with the page's clock
  // `module`: the compiled WebAssembly, which the page hands to the sandbox (sandbox-client.js).
  self.postMessage({ type: "ready", ms: performance.now() - t0, from: started.from, why: started.why, stages,
    module: started.module });
})().catch((err) => {
  self.postMessage({ type: "failed", message: String((err && err.message) || err) });
  throw err;
});

const failure = (kind, message) => ({ ok: false, error: { kind, message } });

// Learner code never runs here: Build code runs in the sandbox (sandbox.js),
// and the grader refuses "run" in the page (workbook/api.py).
async function serve(msg) {
  await ready;
  const { id, ...request } = msg;
  if (interruptBuffer) {
    Atomics.store(interruptBuffer, 0, 0); // a late signal meant for an earlier request
    Atomics.store(interruptBuffer, 1, id);
  }
  try {
    return answer(request);
  } finally {
    if (interruptBuffer) Atomics.store(interruptBuffer, 1, 0);
  }
}

// Requests are served strictly one after another.
let queue = Promise.resolve();
self.onmessage = (event) => {
  const msg = event.data;
  if (msg?.type === "page-started") {
    pageStarted?.();
    return;
  }
  if (msg?.type === "page") {
    pageIds ??= Array.isArray(msg.ids) ? msg.ids.map(String) : null;
    return;
  }
  if (msg?.type === "interrupt-buffer") {
    interruptBuffer = msg.buffer;
    ready.then(() => pyodide.setInterruptBuffer(interruptBuffer)).catch(() => {});
    return;
  }
  if (!msg || typeof msg.id !== "number") return;
  queue = queue.then(async () => {
    let reply;
    try {
      reply = await serve(msg);
    } catch (err) {
      const text = String((err && err.message) || err);
      reply = /MemoryError|out of memory/i.test(text)
        ? failure(ERROR.memory, "The grader ran out of memory. The Python runtime was restarted.")
        : failure(ERROR.runtime, "The Python runtime failed: " + text.split("\n").slice(-2).join(" "));
    }
    self.postMessage({ id: msg.id, type: "reply", reply });
  });
};
