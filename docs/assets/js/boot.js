// Starting Pyodide in a worker: the one place that knows how.
//
//   const { py, from, why, stages, step, module } =
//     await startPyodide({ indexURL, stdLibURL, snapshotURL, onProgress });
//
// Both workers start here: the grader (worker.js: the core standard library and a snapshot) and the
// sandbox for learners' code (sandbox.js: its own standard library, lock file and snapshot, Python's
// output silenced: `lockFileURL`, `quiet`).
// - `stdLibURL`: the standard library zip to start with (the grader: the small
//   core of scripts/split_stdlib.py, which holds the grading package too);
//   `compiledStdLibURL`: the same compiled, for a plain start where the link
//   brings its extra bytes in less time than compiling the sources takes; it holds no
//   grading package, which the grader gives as `compiledPackageURL` (mounted beside it).
// - `snapshotURL`: a memory snapshot made at build time (scripts/build_snapshot.mjs)
//   to restore instead of booting; null boots plainly.
// - `linkSpeed`: the link's speed in bytes per ms when the caller knows it (the
//   sandbox: the grader measured it on the same link), else measured here.
// - `module`: Pyodide's WebAssembly already compiled, to start from instead of
//   compiling it again (the sandbox: the grader's, which the page passes on). The
//   result's `module` is the one this start used, for the caller to share.
// - `controlled`: the page is under the service worker, so its stored copy is
//   likely (the WebAssembly is then looked up there before it is downloaded).
// - `startAfter`: a promise Python's start waits for (the grader's on a first visit: the page's own
//   start, worker.js); the WebAssembly's download goes on meanwhile. `stages.held`: when it ended.
// - `onProgress({phase, loaded, total, step})`: phase "download" (bytes of the runtime
//   files, counted as they arrive), "start" (Python starting), then the caller
//   says "ready"; `step` (boot-steps.js) what is happening now: the start's steps
//   are told as they begin, and `step(name)` in the result tells the caller's own
//   (its imports). Sizes come from the build (boot-meter.js).
//
// It relies on Pyodide 0.27 internals beyond the public API, each named in
// pyodide-internals.json (beside this file; PYODIDE_INTERNALS below), which a
// test checks against the vendored Pyodide: the private `_loadSnapshot` option,
// read after pyodide.asm.js is loaded; the snapshot's header; Pyodide's
// `instantiateStreaming(fetch(wasm))`; the `stdLibURL` option and where the
// standard library is mounted; pyodide.asm.js loaded by importScripts.
// docs/performance.md has the measurements behind each step.
/* global loadPyodide */
import internals from "./pyodide-internals.json";
import { BOOT_STEP } from "./boot-steps.js";
import { fileIn, progressMeter } from "./boot-meter.js";
import { storedBytes, storedResponse } from "./stored-copy.js";

export const PYODIDE_INTERNALS = Object.freeze(internals.internals.map((entry) => entry.name));

const networkFetch = self.fetch.bind(self); // kept before patchWasm() stands in for it

// `stages` keeps when each step ended (ms since the worker started), for the benchmark.
export const stages = {};
export const mark = (name) => {
  stages[name] = Math.round(performance.now());
};

/** The bytes of the stored copy of `url` (stored-copy.js) when it is the build's; else the file through the
 *  service worker, which checks its copy (and repairs it) or fetches it. */
async function fromStored(url, hit, name) {
  return (await storedBytes(hit, name)) ?? networkFetch(url);
}

// ---- The memory snapshot ------------------------------------------------------------
// On a first visit the snapshot is a 5.7 MB download that a plain start does
// not need: on a slow link (4.6 s at 10 Mbps, 29 s at 1.6 Mbps) it costs more
// than booting Python and importing the grading package (1.2 s in Node with the
// compiled core, 2.7 s from the sources). From the
// stored copy (a revisit) it is always used. Otherwise its download waits until
// Pyodide asks for it (after loading pyodide.asm.js, which comes with the
// WebAssembly on the same link): if the link carried pyodide.asm.js fast
// enough to bring the snapshot in under BOOT_COST_MS (about 26 Mbps), it is fetched and used;
// if not, Pyodide boots plainly and the service worker stores the snapshot
// with the offline copy, for the next visit.
// A plain start's extra time over a restore, with a margin that keeps a loaded machine on localhost on the snapshot.
const BOOT_COST_MS = 1500;
// What the rule was tuned with (the file has since grown to 5.7 MB; the rule leans to the snapshot).
const SNAPSHOT_BYTES = 4.9e6;

/** Bytes per ms the link brought pyodide.asm.js's body at (Resource Timing), or null. */
function linkSpeed(indexURL) {
  const entry = /** @type {PerformanceResourceTiming | undefined} */ (
    performance.getEntriesByName?.(indexURL + "pyodide.asm.js")?.[0]);
  const size = entry?.encodedBodySize;
  const ms = entry ? entry.responseEnd - entry.responseStart : 0;
  if (!(size > 100_000)) return null;
  stages.link = ms > 0 ? Math.round(size / ms) : "instant"; // bytes per ms, for the benchmark
  return ms > 0 ? size / ms : null;
}

function snapshotDownload(url, indexURL, meter, knownSpeed) {
  let fromCache = null;
  let decide;
  const decided = new Promise((resolve) => (decide = resolve)); // the response, or null: skipped
  // Stored: read it at once, from the stored copy when it is the build's.
  const hitResponse = storedResponse(url);
  const stored = hitResponse.then(Boolean);
  hitResponse.then((hit) => {
    fromCache = Boolean(hit);
    if (hit) decide(fromStored(url, hit, meter.fileName(url)));
  });
  const bytes = (async () => {
    const response = await decided;
    if (!response) throw new Error("the snapshot was skipped");
    if (response instanceof Uint8Array) {
      meter.done(meter.fileName(url));
      return response;
    }
    if (!response.ok) throw new Error(`snapshot: HTTP ${response.status}`);
    const data = new Uint8Array(await response.arrayBuffer());
    meter.done(meter.fileName(url));
    return data;
  })();
  let use = null;
  return {
    bytes,
    stored, // whether the service worker's copy holds it (then it is always used)
    speed: null, // the link's speed worthIt() decided by (bytes per ms), null when stored or unknown
    /** Whether to use the snapshot (asked when Pyodide wants it, synchronously; decided once). */
    worthIt() {
      if (use !== null) return use;
      const speed = fromCache ? null : knownSpeed > 0 ? knownSpeed : linkSpeed(indexURL);
      this.speed = speed;
      use = speed === null || SNAPSHOT_BYTES / speed < BOOT_COST_MS;
      if (!use) meter.drop(meter.fileName(url));
      // Not stored (or not known yet: the stored copy, when there is one, decides itself above).
      else if (!fromCache) {
        const fetched = () => networkFetch(url).then((r) => meter.watch(meter.fileName(url), r));
        hitResponse.then((hit) => hit || decide(fetched()));
      }
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

// ---- The standard library's core: sources or compiled ---------------------------------
// A plain start (the snapshot skipped on a slow first visit) imports the core,
// and compiling its sources was most of that start: in Node, booting and
// importing took 2.7 s from the sources and 1.2 s compiled; at 10 Mbps ready
// came 0.5 s sooner compiled although the compiled core was 1.1 MB larger (0.7 MB
// since it keeps no column positions: scripts/split_stdlib.py). On
// a slower link (a phone's) those bytes cost more than they save: there, and
// for a snapshot start (which imports nothing, and whose zip importer knows the
// sources' file), the sources. Pyodide asks for the zip as it starts but waits
// for it only once Python starts, after the snapshot is decided: its request is
// held until then (`choose`), or until the snapshot is found stored.
// Bytes per ms of pyodide.asm.js's share of the link (335 at 10 Mbps). The 0.7 MB more cost the 1.5 s
// they save on a link near 3.6 Mbps (a share near 120; it was 6 Mbps for 1.1 MB).
const COMPILED_MIN_SPEED = 120;

// The compiled core holds no grading package (the sandbox starts from it too): the grader names the
// package's compiled part (`packageURL`), fetched with the core when it is chosen and mounted beside it.
function coreChoice(sourceURL, compiledURL, meter, packageURL) {
  let choose;
  let decided = !compiledURL; // nothing to choose: the sources
  const chosen = decided ? Promise.resolve(sourceURL) : new Promise((resolve) => (choose = resolve));
  let packageBytes = null;
  return {
    /** The URL Pyodide's request for `resource` stands for, once chosen; null for any other request. */
    held: (resource) => (String(resource) === sourceURL ? chosen : null),
    /** The bytes of the package's compiled part when the compiled core was chosen (a promise), else null. */
    package: () => packageBytes,
    /** Decide (the first call only): the compiled core for a plain start on a link at least COMPILED_MIN_SPEED
     *  fast, never for a stored site (`stored`: a promise; the offline copy holds the sources only, and a
     *  loaded machine can make even the stored copy's link look slow before the cache has answered). */
    choose(plain, speed, stored = Promise.resolve(false)) {
      if (decided) return;
      decided = true;
      stored.then((hit) => {
        const compiled = plain && speed >= COMPILED_MIN_SPEED && !hit;
        stages.stdlib = compiled ? "compiled" : "sources";
        if (compiled && packageURL) {
          packageBytes = downloadBytes(packageURL, meter);
          packageBytes.catch(() => {}); // a failure is the start's, once Python has started and waits for it
        }
        const taken = [compiledURL, packageURL].filter(Boolean).map(meter.fileName);
        if (compiled) meter.swap(meter.fileName(sourceURL), ...taken);
        choose(compiled ? compiledURL : sourceURL);
      });
    },
  };
}

async function downloadBytes(url, meter) {
  const name = meter.fileName(url);
  const response = meter.watch(name, await networkFetch(url, { credentials: "same-origin" }));
  if (!response.ok) throw new Error(`${name}: HTTP ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

/** Put the zip `bytes` on Python's path (`name`: its file in /lib), after the working folder and ahead of the
 *  standard library's core; the two hold no module in common. */
function mountZip(py, bytes, name) {
  const path = "/lib/" + name;
  py.FS.writeFile(path, bytes);
  const sys = py.pyimport("sys");
  sys.path.insert(1, path);
  sys.destroy();
}

// ---- The WebAssembly -------------------------------------------------------------------
// Pyodide 0.27 reads the whole snapshot before it starts compiling its WebAssembly. When the service
// worker has stored the WebAssembly, compiling it meanwhile takes that wait off the critical path: the
// compile starts here, Pyodide's own fetch of the file gets a stand-in response, and its
// instantiateStreaming call with that stand-in is answered with the module compiled here. On a first
// visit Pyodide compiles it as usual (compiling early then competed with the downloads and was slower).
// Either way its download starts here, with the worker: Pyodide asks for the file only once
// pyodide.asm.js has arrived and run, and asking the cache first takes a while on a first visit, which
// on a slow link left the largest file of the start to begin 1.6 s after the others (on a first visit
// its bytes are counted for the progress bar). If the compile here fails, Pyodide compiles after all. A
// module the caller already has (`given`) is used at once: nothing is fetched or compiled, and the
// compiled code (with what the browser has optimised of it since) is shared, not made again.
// `used.module` is the module the start instantiated, however it came.
function patchWasm(url, meter, compiledStep, given, used, core, controlled, waiting) {
  const realFetch = self.fetch;
  const { instantiateStreaming: realInstantiate } = WebAssembly;
  const counted = (resource, init) => {
    const name = meter.fileName(resource);
    return realFetch(resource, init).then((response) => (name ? meter.watch(name, response) : response));
  };
  // The file's one download starts now, with the worker, whichever way it is then compiled (the
  // service worker answers it from its copy when it has one). Its bytes are counted for the
  // progress bar on a first visit only: counting reads a copy of the stream and reports every
  // piece to the page, which a revisit (the whole file from the cache at once) felt.
  // Under a service worker (`controlled`, which the page knows) the stored copy is likely: it is asked for
  // first, and read from Cache Storage when it is the build's, so the download does not start.
  const abort = new AbortController();
  const fresh = () => realFetch(url, { credentials: "same-origin", signal: abort.signal });
  let download = given || controlled ? null : fresh();
  // While Python's start is `waiting`, nothing reads the download: counting it from the start keeps its bytes coming.
  const countedEarly = Boolean(download && waiting);
  const watched = (response) => meter.watch(meter.fileName(url), response);
  if (countedEarly) download = download.then(watched);
  download?.catch(() => {}); // reported where it is used
  const takeDownload = () => {
    const mine = download ?? fresh();
    download = null;
    return mine;
  };
  const hitResponse = given ? Promise.resolve(null) : storedResponse(url);
  const stored = given ? Promise.resolve(true) : hitResponse.then(Boolean);
  const compiled = given
    ? Promise.resolve(given)
    : hitResponse.then(async (hit) => {
      if (!hit) return null;
      const bytes = await storedBytes(hit, meter.fileName(url));
      if (!bytes) return WebAssembly.compileStreaming(takeDownload());
      if (download) abort.abort(); // started before the copy was found: not needed
      download = null;
      return WebAssembly.compile(bytes);
    });
  compiled.catch(() => {}); // handled below
  const standIn = new Response(null);
  const restore = () => {
    self.fetch = realFetch;
    WebAssembly.instantiateStreaming = realInstantiate;
  };
  const countedDownload = () => (countedEarly ? takeDownload() : takeDownload().then(watched));
  self.fetch = (resource, init) => {
    if (String(resource) === url) return stored.then((hit) => (hit ? standIn : countedDownload()));
    const held = core.held(resource);
    return held ? held.then((chosen) => counted(chosen, init)) : counted(resource, init);
  };
  WebAssembly.instantiateStreaming = async (source, imports) => {
    const response = await source;
    restore();
    const instantiated = (result) => {
      meter.step(compiledStep()); // compiled: Python starts now
      used.module = result.module;
      return result;
    };
    if (response !== standIn) {
      stages.wasm = "compiled by Pyodide";
      return realInstantiate(response, imports).then(instantiated);
    }
    let module;
    try {
      module = await compiled;
    } catch {
      stages.wasm = "compiled by Pyodide";
      return realInstantiate(realFetch(url), imports).then(instantiated);
    }
    stages.wasm = given ? "shared" : "precompiled";
    meter.done(meter.fileName(url));
    return instantiated({ module, instance: await WebAssembly.instantiate(module, imports) });
  };
  return restore; // undo, for a start without Pyodide's usual calls (the fallback boot)
}

// ---- The start ----------------------------------------------------------------------------
export async function startPyodide({ indexURL, stdLibURL, compiledStdLibURL = null, compiledPackageURL = null,
  snapshotURL = null,
  onProgress = null, lockFileURL = null, quiet = false, linkSpeed: knownSpeed = null, module: given = null,
  controlled = false, startAfter = null }) {
  const wasmURL = indexURL + "pyodide.asm.wasm";
  const lock = lockFileURL ? fileIn(indexURL, lockFileURL) : "pyodide-lock.json"; // the lock this start reads
  const files = ["pyodide.js", "pyodide.asm.js", "pyodide.asm.wasm", lock, fileIn(indexURL, stdLibURL)];
  if (snapshotURL) files.push(fileIn(indexURL, snapshotURL));
  const meter = progressMeter(indexURL, files, onProgress);
  meter.phase("download");
  const download = snapshotURL ? snapshotDownload(snapshotURL, indexURL, meter, knownSpeed) : null;
  // Rejects without DecompressionStream where the file is still gzipped.
  const snapshot = download ? readSnapshot(download) : null;
  snapshot?.then(() => mark("snapshot"), () => {}); // handled below
  let skipped = !download;
  const used = { module: null };
  const core = coreChoice(stdLibURL, compiledStdLibURL, meter, compiledPackageURL);
  download?.stored.then((hit) => hit && core.choose(false, null)); // a stored snapshot is used: the sources, at once
  const unpatch = patchWasm(wasmURL, meter, () => (skipped ? BOOT_STEP.boot : BOOT_STEP.restore), given, used, core,
    controlled, Boolean(startAfter));
  importScripts(indexURL + "pyodide.js");
  meter.done("pyodide.js");
  mark("pyodide.js");
  // Pyodide reads this option after loading pyodide.asm.js: the moment to decide
  // (not enumerable, so that loadPyodide's copy of its options does not read it earlier).
  const plain = {
    indexURL, stdLibURL, ...(lockFileURL && { lockFileURL }), ...(quiet && { stdout: () => {}, stderr: () => {} }) };
  const options = { ...plain };
  Object.defineProperty(options, "_loadSnapshot", {
    enumerable: false,
    get() {
      meter.done("pyodide.asm.js");
      if (download?.worthIt()) {
        core.choose(false, null);
        return snapshot;
      }
      skipped = true;
      if (download) stages.snapshot = "skipped: a slow link";
      // Compiled only where the link was measured: a start without a snapshot to skip (the sandbox's
      // replacement, say) has no measure here, and takes the sources.
      core.choose(Boolean(download), download?.speed ?? null, download?.stored);
      return undefined;
    },
  });
  const step = (name) => meter.step(name);
  if (startAfter) {
    await startAfter;
    mark("held"); // when the wait ended
  }
  try {
    const py = await loadPyodide(options);
    if (skipped) {
      const compiledPackage = core.package();
      if (compiledPackage) mountZip(py, await compiledPackage, meter.fileName(compiledPackageURL));
      mark("booted");
      return { py, from: "boot", stages, step, module: used.module };
    }
    mark("restored");
    py.runPython("import random; random.seed()"); // the snapshot's generator state is everyone's
    return { py, from: "snapshot", stages, step, module: used.module };
  } catch (err) {
    if (skipped) throw err;
    unpatch();
    skipped = true;
    meter.step(BOOT_STEP.boot);
    const py = await loadPyodide(plain);
    return { py, from: "boot", why: String((err && err.message) || err), stages, step, module: null };
  }
}
