// The grading worker: loads Pyodide and the grading package once, then answers
// requests from the page. One request at a time; the page enforces time limits
// by an interrupt when it is cross-origin isolated (it shares a buffer, see
// runtime.js), else by terminating this worker.
/* global loadPyodide, importScripts */

const indexURL = new URL("../vendor/pyodide/", self.location.href).href;
let handle = null;
let pyodide = null;
let interruptBuffer = null; // [0]: signal written by the page, [1]: id of the request running

const ready = (async () => {
  const t0 = performance.now();
  importScripts(indexURL + "pyodide.js");
  pyodide = await loadPyodide({ indexURL, packages: ["robotics-workbook"] });
  handle = pyodide.pyimport("workbook.api").handle;
  self.postMessage({ type: "ready", ms: performance.now() - t0 });
})().catch((err) => {
  self.postMessage({ type: "failed", message: String((err && err.message) || err) });
  throw err;
});

async function serve(msg) {
  await ready;
  if (msg.op === "run" && /\bimport\b/.test(msg.code || "")) {
    const needs = /^\s*(?:import|from)\s+numpy\b/m.test(msg.code);
    if (needs) self.postMessage({ id: msg.id, type: "progress", message: "Loading NumPy…" });
    try {
      await pyodide.loadPackagesFromImports(msg.code);
    } catch (err) {
      return { status: "error", tag: "package", message: "A package your code imports could not be loaded: " + err.message, data: {} };
    }
  }
  if (msg.op === "run") self.postMessage({ id: msg.id, type: "started" });
  const { id, ...request } = msg;
  if (interruptBuffer) {
    Atomics.store(interruptBuffer, 0, 0); // a late signal meant for an earlier request
    Atomics.store(interruptBuffer, 1, id);
  }
  try {
    return JSON.parse(handle(JSON.stringify(request)));
  } finally {
    if (interruptBuffer) Atomics.store(interruptBuffer, 1, 0);
  }
}

// Requests are served strictly one after another.
let queue = Promise.resolve();
self.onmessage = (event) => {
  const msg = event.data;
  if (msg?.type === "interrupt-buffer") {
    interruptBuffer = msg.buffer;
    ready.then(() => pyodide.setInterruptBuffer(interruptBuffer)).catch(() => {});
    return;
  }
  if (!msg || typeof msg.id !== "number") return;
  queue = queue.then(async () => {
    let result;
    try {
      result = await serve(msg);
    } catch (err) {
      const text = String((err && err.message) || err);
      result = /MemoryError|out of memory/i.test(text)
        ? { status: "error", tag: "memory", message: "Your code ran out of memory. The Python runtime was restarted; your code is kept.", data: {} }
        : { status: "error", tag: "runtime", message: "The Python runtime failed: " + text.split("\n").slice(-2).join(" "), data: {} };
    }
    self.postMessage({ id: msg.id, type: "result", result });
  });
};
