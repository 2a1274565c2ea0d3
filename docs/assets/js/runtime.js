// The page's side of the grading worker: requests with ids and time limits.
//
// A request waits until the worker is ready, then gets a limit. When a limit
// fires on a cross-origin isolated page (the service worker adds COOP/COEP), the
// page writes SIGINT into a buffer it shares with the worker, and Python raises
// KeyboardInterrupt; if the worker has not answered within a second, or the page
// is not isolated, the worker is terminated and a fresh one started. Either way
// the request that ran too long is answered with a "timeout" result, and every
// other request waits for the worker instead of failing.

const root = document.documentElement;
const DEFAULT_LIMIT_MS = 10_000;
const LOAD_LIMIT_MS = 120_000; // fetching a package (NumPy) before a run starts
const INTERRUPT_GRACE_MS = 2_000; // after an interrupt, how long to wait before terminating
const SIGINT = 2;

function setRuntimeState(state) {
  root.dataset.workbookRuntime = state;
  document.dispatchEvent(new CustomEvent("workbook:runtime", { detail: state }));
}

function timeoutResult(entry, how) {
  const seconds = (entry.limitMs / 1000).toLocaleString();
  const after = how === "interrupt" ? "It was interrupted" : "The Python runtime was restarted";
  return {
    status: "error",
    tag: "timeout",
    message: `Stopped after ${seconds} s: the code did not finish in time (an endless loop?). ${after}; your code is kept.`,
    data: { stoppedBy: how },
  };
}

function crashResult() {
  return {
    status: "error",
    tag: "crash",
    message: "The Python runtime crashed while running this; it was restarted. Your code is kept.",
    data: {},
  };
}

export class Runtime {
  constructor(workerURL, early) {
    this.workerURL = workerURL;
    this.nextId = 1;
    this.pending = new Map(); // id -> {msg, resolve, limitMs, timer, onProgress}
    this.readyAt = null;
    this.failure = null;
    this.listeners = new Set();
    this.restarts = 0; // runs stopped by terminating the worker
    this.interrupts = 0; // runs stopped by KeyboardInterrupt
    this.lastStop = null; // "interrupt" | "terminate"
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
      if (!this.ready) {
        this.fail("The Python runtime could not start" + (event.message ? `: ${event.message}` : "."));
        return;
      }
      // A crash after start-up: answer the request that was running, start afresh.
      const [running] = this.pending.values();
      if (running) this.restart(running, crashResult());
    };
    // Shared with the worker: [0] Pyodide's signal slot, [1] the id of the request now running.
    this.interrupt = null;
    if (self.crossOriginIsolated && typeof SharedArrayBuffer === "function") {
      this.interrupt = new Int32Array(new SharedArrayBuffer(8));
      this.worker.postMessage({ type: "interrupt-buffer", buffer: this.interrupt });
    }
    if (early) for (const data of early.messages.splice(0)) this.receive(data);
  }

  receive(data) {
    if (data.type === "ready") {
      this.ready = true;
      this.readyAt = performance.now();
      this.lastStartMs = this.readyAt - this.startedAt;
      this.startedFrom = data.from; // "snapshot", or "boot" when the snapshot could not be used
      this.startStages = data.stages;
      if (data.why) console.warn("Python runtime: booted without the snapshot:", data.why);
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
      if (entry.interrupted) {
        this.interrupts++;
        this.lastStop = "interrupt";
        entry.resolve(timeoutResult(entry, "interrupt"));
      } else if (data.result.tag === "memory" || data.result.tag === "runtime") {
        this.pending.set(data.id, entry);
        this.restart(entry, data.result); // Python may be left broken: replace it
      } else entry.resolve(data.result);
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
    const buffer = this.interrupt;
    if (buffer && !entry.interrupted && Atomics.load(buffer, 1) === entry.msg.id) {
      entry.interrupted = true; // answered as a timeout when the worker replies
      this.interruptsSent = (this.interruptsSent || 0) + 1;
      Atomics.store(buffer, 0, SIGINT);
      entry.timer = setTimeout(() => this.terminate(entry), INTERRUPT_GRACE_MS);
      return;
    }
    this.terminate(entry);
  }

  terminate(entry) {
    this.restart(entry, timeoutResult(entry, "terminate"));
  }

  /** Answer `entry` with `result`, replace the worker; other requests wait for the new one. */
  restart(entry, result) {
    this.pending.delete(entry.msg.id);
    clearTimeout(entry.timer);
    this.worker.terminate();
    for (const other of this.pending.values()) clearTimeout(other.timer); // re-armed when re-sent
    entry.resolve(result);
    this.restarts++;
    this.lastStop = "terminate";
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
