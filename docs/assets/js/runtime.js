// The page's side of the grading worker: requests with ids and time limits.
//
// A request waits until the worker is ready, then gets a limit. When a limit
// fires, the worker is terminated and a fresh one started; the request that ran
// too long is answered with a "timeout" result and every other request waits for
// the new worker instead of failing.

const root = document.documentElement;
const DEFAULT_LIMIT_MS = 10_000;
const LOAD_LIMIT_MS = 120_000; // fetching a package (NumPy) before a run starts

function setRuntimeState(state) {
  root.dataset.workbookRuntime = state;
  document.dispatchEvent(new CustomEvent("workbook:runtime", { detail: state }));
}

export class Runtime {
  constructor(workerURL, early) {
    this.workerURL = workerURL;
    this.nextId = 1;
    this.pending = new Map(); // id -> {msg, resolve, limitMs, timer, onProgress}
    this.readyAt = null;
    this.failure = null;
    this.listeners = new Set();
    this.spawn(early);
  }

  spawn(early) {
    this.ready = false;
    this.startedAt = early ? early.started : performance.now();
    setRuntimeState("loading");
    this.worker = early ? early.worker : new Worker(this.workerURL);
    this.worker.onmessage = (event) => this.receive(event.data);
    this.worker.onerror = (event) => {
      event.preventDefault?.();
      this.fail("The Python runtime could not start" + (event.message ? `: ${event.message}` : "."));
    };
    if (early) for (const data of early.messages.splice(0)) this.receive(data);
  }

  receive(data) {
    if (data.type === "ready") {
      this.ready = true;
      this.readyAt = performance.now();
      this.lastStartMs = this.readyAt - this.startedAt;
      setRuntimeState("ready");
      for (const entry of this.pending.values()) this.send(entry);
      return;
    }
    if (data.type === "failed") {
      this.fail(`The Python runtime could not start: ${data.message}`);
      return;
    }
    const entry = this.pending.get(data.id);
    if (!entry) return;
    if (data.type === "progress") {
      entry.onProgress?.(data.message);
    } else if (data.type === "started") {
      this.arm(entry, entry.limitMs); // the learner's code starts now
    } else if (data.type === "result") {
      clearTimeout(entry.timer);
      this.pending.delete(data.id);
      entry.resolve(data.result);
    }
  }

  fail(message) {
    this.failure = message;
    setRuntimeState("failed");
    for (const [id, entry] of this.pending) {
      clearTimeout(entry.timer);
      entry.resolve({ status: "error", tag: "runtime", message, data: {} });
      this.pending.delete(id);
    }
  }

  arm(entry, ms) {
    clearTimeout(entry.timer);
    entry.timer = setTimeout(() => this.expire(entry), ms);
  }

  send(entry) {
    this.arm(entry, entry.msg.op === "run" ? LOAD_LIMIT_MS : entry.limitMs);
    this.worker.postMessage(entry.msg);
  }

  expire(entry) {
    this.pending.delete(entry.msg.id);
    this.worker.terminate();
    const seconds = (entry.limitMs / 1000).toLocaleString();
    entry.resolve({
      status: "error",
      tag: "timeout",
      message: `Stopped after ${seconds} s: the code did not finish in time (an endless loop?). The Python runtime was restarted; your code is kept.`,
      data: {},
    });
    this.restarts = (this.restarts || 0) + 1;
    this.spawn(null); // other pending requests are re-sent once the new worker is ready
  }

  /** Send `request` ({op, id, ...}); resolves with a result, never rejects. */
  request(request, { limitMs = DEFAULT_LIMIT_MS, onProgress } = {}) {
    if (this.failure) {
      return Promise.resolve({ status: "error", tag: "runtime", message: this.failure, data: {} });
    }
    return new Promise((resolve) => {
      const msg = { ...request, id: this.nextId++ };
      const entry = { msg, resolve, limitMs, onProgress, timer: null };
      this.pending.set(msg.id, entry);
      if (this.ready) this.send(entry);
    });
  }
}
