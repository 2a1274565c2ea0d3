// The sandbox: the Web Worker that runs a learner's Build code, and nothing else.
//
// The page starts it from a blob: URL (sandbox-client.js), so the browser
// applies the page's Content-Security-Policy here too: no eval or Function from
// strings, and nothing fetched, imported or connected outside the site's origin.
// Its Python holds no grading package: the standard library's core and
// workbook_sandbox only (python_stdlib.sandbox.zip, scripts/sandbox_files.py),
// and the rest of the standard library (the grader's python_stdlib.rest.zip)
// mounted on first use (workbook_sandbox/lazy_stdlib.py); its lock file names
// NumPy and nothing else. It starts from a memory snapshot
// of its own (sandbox.snapshot.gz, scripts/build_snapshot.mjs --sandbox: that
// Python with workbook_sandbox imported and one run made) when it is stored or
// the link is fast enough (boot.js decides, with the link speed the grader
// measured), and reports its start as the grader does. Once Pyodide has started, and
// before any learner code runs, tame() strips the worker's global scope down to
// what computing needs (ALLOWED): no network, storage, workers, channels,
// postMessage or close, no code from strings. Two capabilities stay, held in
// this file's closures: `post`, the only way to the page, and `vendorFetch`, the
// fetch Pyodide loads NumPy with, which gets the files of the sandbox's lock
// and nothing else. The finder of the rest holds `restSync`, which fetches that one
// file and takes no address. Learner code reaches neither, so a message from here is only
// ever this file's: the report of a run, which the grader reads as data.
//
// Messages in: {type: "wasm-module", module} first, when the page has the grader's compiled
// WebAssembly to start from (settings.module says it comes); {type: "run-waiting"} when the page
// started it for a run the learner asked for; {type: "interrupt-buffer", buffer};
// {id, op: "run", job, code}.
// Out: {type: "boot", phase, loaded, total, step} as it starts (boot.js), {type: "ready"|"failed"}; per request
// {id, type: "received"} at once,
// {type: "progress"}, {type: "started"} when the code starts (the page's time
// limit starts then) and {type: "reply", reply}: {ok: true, value: REPORT,
// recycle} or {ok: false, error}.
import { startPyodide, stages as bootStages } from "./boot.js";
import { ERROR } from "./contract.js";
import { BOOT_STEP } from "./boot-steps.js";

const post = self.postMessage.bind(self);
const networkFetch = self.fetch.bind(self);
const NetworkRequest = self.XMLHttpRequest;
/** @type {SandboxSettings} */
const settings = self.WB_SANDBOX || { indexURL: new URL("../vendor/pyodide/", self.location.href).href };
delete self.WB_SANDBOX;
const { indexURL } = settings;
const STDLIB = indexURL + "python_stdlib.sandbox.zip";
// A plain start on a fast enough link: the grader's compiled core, which holds no grading package (the
// grader mounts that beside it: scripts/split_stdlib.py), so a first visit finds it in the HTTP cache.
const STDLIB_COMPILED = indexURL + "python_stdlib.core.compiled.zip";
const LOCK = indexURL + "pyodide-lock.sandbox.json";
const SNAPSHOT = indexURL + "sandbox.snapshot.gz";
const STDLIB_REST = indexURL + "python_stdlib.rest.zip"; // the grader's too (scripts/split_stdlib.py)
const REST_PATH = "/lib/python_stdlib.rest.zip"; // where lazy_stdlib mounts it (REST)

// Failures are told by this file's own messages ("failed", or a reply): the browser's
// report of an uncaught error here (Pyodide's, when a download fails) would reach the
// page as an error of its own.
for (const type of ["error", "unhandledrejection"]) self.addEventListener(type, (event) => event.preventDefault());

let requests = null; // messages that came before start-up ended
let runWaiting = false; // the page started this sandbox for a run the learner asked for: no warm-up
let interruptBuffer = null; // [0]: signal written by the page, [1]: id of the request running
let lazy = null; // workbook_sandbox.lazy_stdlib
let packageImports = []; // what the lock's packages provide (numpy): loading one mounts the rest first
let takeModule = null; // resolves the compiled WebAssembly the page sends first (settings.module)
const given = settings.module ? new Promise((resolve) => (takeModule = resolve)) : Promise.resolve(null);

// Registered first, before anything else can listen: later listeners (an
// `onmessage` set by learner code) never see a message.
// Only the page's own messages count: not an event the sandbox's code dispatched.
self.addEventListener("message", (/** @type {MessageEvent} */ event) => {
  event.stopImmediatePropagation();
  if (!event.isTrusted) return;
  const msg = event.data;
  if (msg?.type === "wasm-module") {
    takeModule?.(msg.module instanceof WebAssembly.Module ? msg.module : null);
    takeModule = null; // once: before start-up
  } else if (msg?.type === "interrupt-buffer") {
    interruptBuffer = msg.buffer;
    ready.then(({ py }) => py.setInterruptBuffer(interruptBuffer)).catch(() => {});
  } else if (msg?.type === "run-waiting") {
    runWaiting = true;
  } else if (msg && typeof msg.id === "number") {
    post({ id: msg.id, type: "received" });
    requests = requests.then(() => serve(msg));
  }
});

// ---- Start-up ------------------------------------------------------------------
const failure = (kind, message) => ({ ok: false, error: { kind, message } });

/** A fetch for the files of the sandbox's lock: GET, nothing else. */
function guardedFetch(allowed) {
  return function fetch(resource, init = {}) {
    let url;
    try {
      const address = typeof resource === "string" || resource instanceof URL ? String(resource) : resource.url;
      url = new URL(address, indexURL).href;
    } catch {
      url = "";
    }
    const method = String(init.method || (resource instanceof Request ? resource.method : "GET")).toUpperCase();
    if (method !== "GET" || !allowed.has(url)) {
      return Promise.reject(new TypeError("The sandbox fetches the site's own Python packages, nothing else."));
    }
    return networkFetch(url, { integrity: init.integrity || "", credentials: "same-origin" });
  };
}

const stages = {};
const started = performance.now();
const mark = (name) => (stages[name] = Math.round(performance.now() - started));

const ready = (async () => {
  const lock = networkFetch(LOCK).then((r) => r.json());
  const reportBoot = (progress) => post({ type: "boot", ...progress });
  const { py, from, step } = await startPyodide({ indexURL, stdLibURL: STDLIB, compiledStdLibURL: STDLIB_COMPILED,
    lockFileURL: LOCK, snapshotURL: SNAPSHOT, quiet: true, onProgress: reportBoot, linkSpeed: settings.linkSpeed,
    module: await given });
  mark("booted");
  stages.from = from;
  stages.wasm = bootStages.wasm; // "shared": started from the grader's compiled WebAssembly
  stages.stdlib = bootStages.stdlib; // "compiled" on a plain start over a fast enough link
  step(BOOT_STEP.import);
  lazy = py.pyimport("workbook_sandbox.lazy_stdlib");
  lazy.install(STDLIB_REST, null, restSync).destroy();
  const runner = py.pyimport("workbook_sandbox.runner");
  // A run already waiting warms the same path itself: the warm-up would only delay it (four runs, 0.3 s of
  // a phone's first Build run, clicked the moment the page was ready).
  if (!runWaiting) warmUp(runner.run_in_sandbox);
  mark("warm");
  stages.warmedUp = !runWaiting;
  const packages = Object.values((await lock).packages);
  const allowed = new Set(packages.map((p) => new URL(p.file_name, indexURL).href));
  packageImports = packages.flatMap((p) => p.imports || []);
  tame(self, guardedFetch(allowed));
  mark("ready");
  stages.wasmBytes = py._module.HEAPU8.byteLength; // the interpreter's memory, for the benchmark
  post({ type: "ready", ms: performance.now() - started, stages });
  return { py, run: runner.run_in_sandbox };
})();
requests = ready.then(
  () => {},
  (err) => post({ type: "failed", message: String(err?.message || err) }),
);

// A few runs of a small job before the first real one: the functions every run calls are
// compiled now, and the browser starts optimising the hottest, while the learner is still reading.
const WARM_JOB = JSON.stringify(
  { function: "f", harness: "call", cases: Array.from({ length: 24 }, (_, i) => [i, i / 3]) });
const WARM_CODE = "import math\n\n\ndef f(a, b):\n    return (math.hypot(a, b), [a * b, a - b])\n";
function warmUp(run) {
  for (let i = 0; i < 4; i++) run(WARM_JOB, WARM_CODE).destroy();
}

// ---- The global scope, tamed ----------------------------------------------------
// What stays on the global object and its prototypes: the language, and what
// Pyodide and plain computing use. Everything else (fetch, XMLHttpRequest,
// WebSocket, EventSource, importScripts, caches, indexedDB, Worker,
// BroadcastChannel, postMessage, close, the file system APIs, fonts, ...) goes.
const LANGUAGE = `Object Function Array Number parseFloat parseInt Infinity NaN undefined Boolean String Symbol Date
  Promise RegExp Error AggregateError EvalError RangeError ReferenceError SyntaxError TypeError URIError SuppressedError
  globalThis JSON Math Intl ArrayBuffer SharedArrayBuffer Atomics Uint8Array Int8Array Uint16Array Int16Array
  Uint32Array Int32Array Float16Array Float32Array Float64Array Uint8ClampedArray BigUint64Array BigInt64Array
  DataView Map BigInt Set WeakMap WeakSet Proxy Reflect FinalizationRegistry WeakRef decodeURI decodeURIComponent
  encodeURI encodeURIComponent escape unescape isFinite isNaN Iterator DisposableStack AsyncDisposableStack Temporal
  WebAssembly`;
const PLATFORM = `console self location navigator performance crypto Crypto SubtleCrypto CryptoKey setTimeout
  clearTimeout setInterval clearInterval queueMicrotask structuredClone atob btoa TextEncoder TextDecoder URL
  URLSearchParams Blob Response Request Headers ReadableStream ReadableStreamDefaultReader
  ReadableStreamDefaultController
  ReadableByteStreamController ReadableStreamBYOBReader ReadableStreamBYOBRequest WritableStream
  WritableStreamDefaultWriter WritableStreamDefaultController TransformStream TransformStreamDefaultController
  ByteLengthQueuingStrategy CountQueuingStrategy MessageChannel MessagePort MessageEvent Event EventTarget ErrorEvent
  PromiseRejectionEvent CustomEvent DOMException AbortController AbortSignal crossOriginIsolated isSecureContext origin
  name onmessage onmessageerror onerror onunhandledrejection onrejectionhandled reportError constructor
  DedicatedWorkerGlobalScope WorkerGlobalScope WorkerLocation WorkerNavigator Performance PerformanceEntry
  PerformanceMark PerformanceMeasure`;
const NAVIGATOR = "hardwareConcurrency appCodeName appName appVersion platform product userAgent language languages "
  + "onLine constructor";
const ALLOWED = new Set(`${LANGUAGE} ${PLATFORM}`.split(/\s+/));

function strip(object, keep) {
  for (const name of Object.getOwnPropertyNames(object)) {
    if (!keep.has(name)) {
      try {
        delete object[name];
      } catch {
        /* a property the platform does not let go: it is not one of ours to worry about */
      }
    }
  }
}

function refuseCode() {
  throw new EvalError("The sandbox runs no code from strings.");
}

function tame(scope, fetch) {
  // The global object, and its prototypes up to (not including) EventTarget.prototype.
  for (let object = scope; object && object !== EventTarget.prototype; object = Object.getPrototypeOf(object)) {
    strip(object, ALLOWED);
  }
  strip(Object.getPrototypeOf(scope.navigator), new Set(NAVIGATOR.split(" ")));
  // Code from strings: every constructor of functions, however it is reached.
  const prototypes = [function () {}, async function () {}, function* () {}, async function* () {}]
    .map(Object.getPrototypeOf);
  for (const prototype of prototypes) {
    const denied = function () {
      refuseCode();
    };
    denied.prototype = prototype;
    Object.defineProperty(prototype, "constructor", { value: denied, writable: false, configurable: false });
  }
  Object.defineProperty(scope, "Function", { value: prototypes[0].constructor, writable: false, configurable: false });
  // Timers take functions only (a string would be evaluated).
  const timers = Object.getPrototypeOf(Object.getPrototypeOf(scope));
  for (const name of ["setTimeout", "setInterval"]) {
    const original = timers[name];
    if (typeof original !== "function") continue;
    Object.defineProperty(timers, name, {
      value: (handler, ...rest) =>
        (typeof handler === "function" ? original.call(scope, handler, ...rest) : refuseCode()),
      writable: false,
      configurable: false,
    });
  }
  // Pyodide fetches NumPy through the global fetch: the guarded one.
  Object.defineProperty(scope, "fetch", { value: fetch, writable: false, configurable: false });
}

// ---- The rest of the standard library ---------------------------------------------
/** The rest, synchronously (allowed in a worker), for an import no one saw coming: that one file only. */
function restSync() {
  const request = new NetworkRequest();
  request.open("GET", STDLIB_REST, false);
  request.responseType = "arraybuffer";
  request.send(null);
  if (request.status !== 200) throw new Error(`HTTP ${request.status}`);
  return new Uint8Array(request.response);
}

/** Mount the rest ahead of a run whose imports need it, so the run's time limit never pays for it. */
async function mountRestFor(py, id, code) {
  const names = py.pyodide_py.code.find_imports(code);
  try {
    if (!lazy.needs(names, packageImports)) return;
  } finally {
    names.destroy();
  }
  if (!/^\s*(?:import|from)\s+numpy\b/m.test(code)) {
    post({ id, type: "progress", message: "Loading Python's standard library…" });
  }
  const response = await networkFetch(STDLIB_REST);
  if (!response.ok) throw new Error(`HTTP ${response.status}`);
  py.FS.writeFile(REST_PATH, new Uint8Array(await response.arrayBuffer()));
  lazy.mount();
}

// ---- Runs ------------------------------------------------------------------------
async function serve(msg) {
  let reply;
  try {
    reply = await runOnce(msg);
  } catch (err) {
    const text = String(err?.message || err);
    reply = /MemoryError|out of memory/i.test(text)
      ? failure(ERROR.memory, "Your code ran out of memory. The sandbox was restarted; your code is kept.")
      : failure(ERROR.crash, "The sandbox crashed while running your code; it was restarted. Your code is kept.");
  }
  post({ id: msg.id, type: "reply", reply });
}

async function runOnce({ id, op, job, code }) {
  const { py, run } = await ready;
  if (op !== "run" || typeof job !== "string" || typeof code !== "string") {
    return failure(ERROR.badRequest, "The sandbox runs Build code only.");
  }
  if (/\bimport\b/.test(code)) {
    if (/^\s*(?:import|from)\s+numpy\b/m.test(code)) post({ id, type: "progress", message: "Loading NumPy…" });
    try {
      await mountRestFor(py, id, code);
      await py.loadPackagesFromImports(code);
    } catch (err) {
      return failure(ERROR.package,
        "A package your code imports could not be loaded: " + String(err?.message || err).slice(0, 200));
    }
  }
  post({ id, type: "started" });
  if (interruptBuffer) {
    Atomics.store(interruptBuffer, 0, 0); // a late signal meant for an earlier run
    Atomics.store(interruptBuffer, 1, id);
  }
  try {
    const result = run(job, code);
    const [report, recycle] = result.toJs();
    result.destroy();
    return { ok: true, value: report, recycle };
  } finally {
    if (interruptBuffer) Atomics.store(interruptBuffer, 1, 0);
  }
}
