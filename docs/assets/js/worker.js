// The grading worker: loads Pyodide and the grading package once, then answers
// requests from the page. One request at a time; the page enforces time limits
// by an interrupt when it is cross-origin isolated (it shares a buffer, see
// runtime.js), else by terminating this worker.
// Replies are envelopes (CONTRACT.md): the grader's own, or {ok: false, error}
// when the runtime itself fails.
/* global loadPyodide, importScripts */
import { ERROR } from "./contract.js";

const indexURL = new URL("../vendor/pyodide/", self.location.href).href;
let handle = null;
let pyodide = null;
let interruptBuffer = null; // [0]: signal written by the page, [1]: id of the request running
let lazyStdlib = null; // workbook.lazy_stdlib

// ---- Start-up -----------------------------------------------------------------
// The worker restores a memory snapshot made at build time
// (scripts/build_snapshot.mjs): the interpreter with the grading package already
// imported. If that fails for any reason (missing, damaged, a browser without
// DecompressionStream), it boots Pyodide instead. Either way Python's standard
// library is the small core, which holds the grading package too; the rest is
// mounted on first use (scripts/split_stdlib.py, workbook/lazy_stdlib.py).
// docs/performance.md has the measurements behind each step.

const networkFetch = self.fetch.bind(self); // kept before precompileWasm() stands in for it

// Once the service worker holds the site, its cache is read directly: the
// service worker's thread, busy serving the page, is then not in the way.
async function cached(url) {
  try {
    return (await self.caches?.match(url)) || null;
  } catch {
    return null; // no Cache Storage here (an insecure origin)
  }
}

const SNAPSHOT = indexURL + "workbook.snapshot.gz";
const STDLIB_CORE = indexURL + "python_stdlib.core.zip";
const STDLIB_REST = indexURL + "python_stdlib.rest.zip";

// On a first visit the snapshot is a 4.8 MB download that a plain start does
// not need: on a slow link (3.9 s at 10 Mbps, 24 s at 1.6 Mbps) it costs far
// more than booting Python and installing the wheel (under a second). From the
// cache (a revisit) it is always used. Otherwise its download waits until
// Pyodide asks for it (after loading pyodide.asm.js, which comes with the
// WebAssembly on the same link): if the link carried pyodide.asm.js fast
// enough to bring the snapshot in under BOOT_COST_MS (about 26 Mbps), it is fetched and used;
// if not, Pyodide boots plainly and the service worker stores the snapshot
// after the start, for the next visit.
const BOOT_COST_MS = 1500; // a plain start costs under a second; the margin keeps a loaded machine on localhost on the snapshot
const SNAPSHOT_BYTES = 4.9e6; // about; the file is 4.6-4.9 MB

/** Bytes per ms the link brought pyodide.asm.js's body at (Resource Timing), or null. */
function linkSpeed() {
  const entry = performance.getEntriesByName?.(indexURL + "pyodide.asm.js")?.[0];
  const size = entry?.encodedBodySize;
  const ms = entry ? entry.responseEnd - entry.responseStart : 0;
  if (!(size > 100_000)) return null;
  stages.link = ms > 0 ? Math.round(size / ms) : "instant"; // bytes per ms, for the benchmark
  return ms > 0 ? size / ms : null;
}

function snapshotDownload() {
  const stored = cached(SNAPSHOT);
  let fromCache = null;
  stored.then((hit) => (fromCache = Boolean(hit)));
  let decide;
  const decided = new Promise((resolve) => (decide = resolve)); // the network's response, or null: skipped
  const bytes = (async () => {
    const response = (await stored) || (await decided);
    if (!response) throw new Error("the snapshot was skipped");
    if (!response.ok) throw new Error(`snapshot: HTTP ${response.status}`);
    return new Uint8Array(await response.arrayBuffer());
  })();
  let use = null;
  return {
    bytes,
    /** Whether to use the snapshot (asked when Pyodide wants it; decided once). */
    worthIt() {
      if (use !== null) return use;
      const speed = fromCache ? null : linkSpeed();
      use = speed === null || SNAPSHOT_BYTES / speed < BOOT_COST_MS;
      decide(use && !fromCache ? networkFetch(SNAPSHOT) : null);
      return use;
    },
  };
}

async function readSnapshot(download) {
  let bytes = await download.bytes;
  if (bytes[0] === 0x1f && bytes[1] === 0x8b) {
    // Still gzipped (a first visit); the service worker stores it inflated, and some servers inflate it.
    const inflated = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    bytes = new Uint8Array(await new Response(inflated).arrayBuffer());
  }
  return checkSnapshot(unpack(bytes));
}

// The file leaves out the memory's zero pages (scripts/build_snapshot.mjs,
// sparse()): put each run of bytes back at its offset in a zeroed buffer.
function unpack(bytes) {
  const magic = new TextDecoder().decode(bytes.subarray(0, 8));
  if (magic !== "WBSPARSE") throw new Error("the snapshot file is damaged");
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const out = new Uint8Array(view.getUint32(8, true));
  const runs = view.getUint32(12, true);
  let data = 16 + 8 * runs;
  for (let i = 0; i < runs; i++) {
    const offset = view.getUint32(16 + 8 * i, true);
    const length = view.getUint32(20 + 8 * i, true);
    out.set(bytes.subarray(data, data + length), offset);
    data += length;
  }
  if (data !== bytes.byteLength) throw new Error("the snapshot file is damaged");
  return out;
}

// Pyodide waits forever on a snapshot too short for its memory, so a damaged
// one is turned away here: Pyodide's magic number, then a header and whole
// 64 KiB pages of memory.
const SNAPSHOT_MAGIC = 0x706e7300;
function checkSnapshot(bytes) {
  const head = bytes.byteLength >= 16 ? new DataView(bytes.buffer, bytes.byteOffset, 16) : null;
  const headerSize = head?.getUint32(4, true);
  const memory = bytes.byteLength - headerSize;
  if (!head || head.getUint32(0, true) !== SNAPSHOT_MAGIC || !(memory > 0) || memory % 65536 !== 0) {
    throw new Error("the snapshot file is damaged");
  }
  return bytes;
}

// Pyodide 0.27 reads the whole snapshot before it starts compiling its
// WebAssembly. When the service worker's cache already holds the WebAssembly,
// compiling it meanwhile takes that wait off the critical path: the compile
// starts here, Pyodide's own fetch of the file gets a stand-in response, and its
// instantiateStreaming call with that stand-in is answered with the module
// compiled here. On a first visit Pyodide fetches and compiles it as usual
// (compiling early then competed with the downloads and was slower). If the
// compile here fails, Pyodide compiles after all. (Pyodide's other start-up
// files go through the service worker: taking them from the cache as well was
// not faster.)
function precompileWasm(url) {
  const realFetch = self.fetch;
  const { instantiateStreaming: realInstantiate } = WebAssembly;
  const stored = cached(url);
  const compiled = stored.then((hit) => (hit ? WebAssembly.compileStreaming(hit) : null));
  compiled.catch(() => {}); // handled below
  const standIn = new Response(null);
  const restore = () => {
    self.fetch = realFetch;
    WebAssembly.instantiateStreaming = realInstantiate;
  };
  self.fetch = (resource, init) =>
    String(resource) === url ? stored.then((hit) => (hit ? standIn : realFetch(resource, init))) : realFetch(resource, init);
  WebAssembly.instantiateStreaming = async (source, imports) => {
    const response = await source;
    restore();
    if (response !== standIn) {
      stages.wasm = "compiled by Pyodide";
      return realInstantiate(response, imports);
    }
    let module;
    try {
      module = await compiled;
    } catch {
      stages.wasm = "compiled by Pyodide";
      return realInstantiate(realFetch(url), imports);
    }
    stages.wasm = "precompiled";
    return { module, instance: await WebAssembly.instantiate(module, imports) };
  };
  return restore; // undo, for a start without Pyodide's usual calls (the fallback boot)
}

// `stages` keeps when each step ended (ms since the worker started), for the benchmark.
const stages = {};
const mark = (name) => {
  stages[name] = Math.round(performance.now());
};

async function start() {
  const download = snapshotDownload();
  const snapshot = readSnapshot(download); // rejects without DecompressionStream where the file is still gzipped
  snapshot.then(() => mark("snapshot"), () => {}); // handled below
  const unpatch = precompileWasm(indexURL + "pyodide.asm.wasm");
  importScripts(indexURL + "pyodide.js");
  mark("pyodide.js");
  // Pyodide reads this option after loading pyodide.asm.js: the moment to decide
  // (not enumerable, so that loadPyodide's copy of its options does not read it earlier).
  const options = { indexURL, stdLibURL: STDLIB_CORE };
  let skipped = false;
  Object.defineProperty(options, "_loadSnapshot", {
    enumerable: false,
    get() {
      if (download.worthIt()) return snapshot;
      skipped = true;
      stages.snapshot = "skipped: a slow link";
      return undefined;
    },
  });
  try {
    const py = await loadPyodide(options);
    if (skipped) {
      mark("booted");
      return { py, from: "boot" };
    }
    mark("restored");
    py.runPython("import random; random.seed()"); // the snapshot's generator state is everyone's
    return { py, from: "snapshot" };
  } catch (err) {
    if (skipped) throw err;
    unpatch();
    const py = await loadPyodide({ indexURL, stdLibURL: STDLIB_CORE });
    return { py, from: "boot", why: String((err && err.message) || err) };
  }
}

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
  const started = await start();
  pyodide = started.py;
  lazyStdlib = pyodide.pyimport("workbook.lazy_stdlib");
  lazyStdlib.install(STDLIB_REST).destroy();
  handle = pyodide.pyimport("workbook.api").handle;
  mark("handle");
  const api = pyodide.pyimport("workbook.api");
  for (const request of JSON.parse(api.warm_up(pageIds))) answer(request);
  api.destroy();
  mark("ready");
  stages.timeOrigin = performance.timeOrigin; // to line the stages up with the page's clock
  self.postMessage({ type: "ready", ms: performance.now() - t0, from: started.from, why: started.why, stages });
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
        ? failure(ERROR.memory, "Your code ran out of memory. The Python runtime was restarted; your code is kept.")
        : failure(ERROR.runtime, "The Python runtime failed: " + text.split("\n").slice(-2).join(" "));
    }
    self.postMessage({ id: msg.id, type: "reply", reply });
  });
};
