// The page's side of the grading worker: requests with ids and time limits.
//
// A request waits until the worker is ready, then gets a limit. When a limit
// fires on a cross-origin isolated page (the service worker adds COOP/COEP), the
// page writes SIGINT into a buffer it shares with the worker, and Python raises
// KeyboardInterrupt; if the request is still running INTERRUPT_GRACE_MS later, or
// the page is not isolated, the worker is terminated and a fresh one started.
// "Still running" is read from the buffer, never from the order of a timer and a
// message: the worker clears the request's id there when the run has returned
// (its reply is then on its way), and Python clears the signal when it sees it, so a
// worker that has not yet been given the CPU to see it gets up to INTERRUPT_WAIT_MS.
// Either way the request that ran too long is answered with a "timeout" error,
// and every other request waits for the worker instead of failing.
//
// Every request resolves (never rejects) with an envelope: {ok: true, value} or
// {ok: false, error: {kind, message}} (CONTRACT.md).
//
// The same class drives the sandbox that runs Build code (sandbox-client.js),
// with two options: it does not set <html data-workbook-runtime> (that is the
// grader's), and it sends one request at a time and expects it to be
// acknowledged at once: a sandbox that does not is gone (killed, or closed),
// and a fresh one gets the request.

import { BOOT_PHASE, ERROR, RUNTIME, setRootState } from "./contract.js";

const DEFAULT_LIMIT_MS = 10_000;
const LOAD_LIMIT_MS = 120_000; // fetching a package (NumPy) before a run starts
const INTERRUPT_GRACE_MS = 2_000; // after an interrupt seen by Python, how long it may take to stop
const INTERRUPT_WAIT_MS = 10_000; // at most, after an interrupt, before the worker is terminated
const SIGINT = 2;

function setRuntimeState(state) {
  setRootState("runtime", state);
  document.dispatchEvent(new CustomEvent("workbook:runtime", { detail: state }));
}

const failure = (kind, message) => ({ ok: false, error: { kind, message } });

function timeoutReply(entry, how) {
  const seconds = (entry.limitMs / 1000).toLocaleString();
  const after = how === "interrupt" ? "It was interrupted" : "The Python runtime was restarted";
  return failure(ERROR.timeout,
    `Stopped after ${seconds} s: the code did not finish in time (an endless loop?). ${after}; your code is kept.`);
}

const crashReply = () =>
  failure(ERROR.crash, "The Python runtime crashed while running this; it was restarted. Your code is kept.");

const QUIET_POLL_MS = 100; // quietFor looks again at least this long after a busy moment

export class Runtime {
  /**
   * `workerURL`: the worker's script, or a function that starts the worker; `early`: a worker
   * the page's head started. Options: `role` ("grader" sets the runtime state of the page,
   * "sandbox" does not), `ackMs` (when set, requests are sent one at a time, and a worker
   * that does not acknowledge one within `ackMs` is replaced and the request sent again, once).
   */
  constructor(workerURL, early, { role = "grader", ackMs = 0 } = {}) {
    this.workerURL = workerURL;
    this.workerName = early?.name ?? ""; // what the page's head told its worker (worker.js), told again to a successor
    this.role = role;
    this.setState = role === "grader" ? setRuntimeState : () => {};
    this.ackMs = ackMs;
    this.nextId = 1;
    this.pending = new Map(); // id -> {msg, resolve, limitMs, timer, onProgress}
    this.readyAt = null;
    this.failure = null;
    this.restarts = 0; // runs stopped by terminating the worker
    this.interrupts = 0; // runs stopped by KeyboardInterrupt
    this.lastStop = null; // "interrupt" | "terminate"
    this.wasmModule = null; // once ready: the compiled WebAssembly its worker started from, when it says
    this.lastActivityAt = performance.now(); // the last request sent or answered (quietFor)
    this.pageHasStarted = false; // whether the page said so (pageStarted)
    this.spawn(early);
  }

  spawn(early) {
    this.ready = false;
    this.startedAt = early ? early.started : performance.now();
    this.setState(RUNTIME.loading);
    const worker = early
      ? early.worker
      : typeof this.workerURL === "function" ? this.workerURL() : new Worker(this.workerURL, { name: this.workerName });
    this.worker = worker;
    this.spawns = (this.spawns || 0) + 1; // workers started, the first included
    this.reportBoot({ phase: BOOT_PHASE.download, loaded: 0, total: 0, step: null }); // a new start: nothing yet
    // A worker that was replaced is not heard any more: a late message or error of a
    // terminated one (its Python stopped mid-run) must not fail or answer for its successor.
    worker.onmessage = (event) => {
      if (worker === this.worker) this.receive(event.data);
    };
    worker.onerror = (event) => {
      event.preventDefault?.();
      if (worker !== this.worker) return;
      if (!this.ready) {
        this.fail("The Python runtime could not start" + (event.message ? `: ${event.message}` : "."));
        return;
      }
      // A crash after start-up: answer the request that was running, start afresh.
      const [running] = this.pending.values();
      if (running) this.restart(running, crashReply());
    };
    // Shared with the worker: [0] Pyodide's signal slot, [1] the id of the request now running.
    this.interrupt = null;
    if (self.crossOriginIsolated && typeof SharedArrayBuffer === "function") {
      this.interrupt = new Int32Array(new SharedArrayBuffer(8));
      this.worker.postMessage({ type: "interrupt-buffer", buffer: this.interrupt });
    }
    if (this.pageHasStarted) worker.postMessage({ type: "page-started" }); // a successor: the page started long ago
    if (early) for (const data of early.messages.splice(0)) this.receive(data);
  }

  /** Name the page's exercises, so that the worker warms up for them (worker.js). */
  announce(ids) {
    this.worker.postMessage({ type: "page", ids });
  }

  /** The page has started (after DOMContentLoaded): the worker's Python may start now (worker.js); so
   *  may every later worker's, at once. */
  pageStarted() {
    this.pageHasStarted = true;
    this.worker.postMessage({ type: "page-started" });
  }

  /** The worker's start, as it goes: {phase, loaded, total, step} (boot.js, boot-steps.js); an event each
   *  time: "workbook:boot" for the grader's, "workbook:sandbox-boot" for the sandbox's (loading.js shows both). */
  reportBoot(boot) {
    this.boot = boot;
    const name = this.role === "grader" ? "workbook:boot" : `workbook:${this.role}-boot`;
    document.dispatchEvent(new CustomEvent(name, { detail: boot }));
  }

  receive(data) {
    if (data.type === "boot") {
      this.reportBoot({ phase: data.phase, loaded: data.loaded, total: data.total, step: data.step });
      return;
    }
    if (data.type === "ready") {
      this.ready = true;
      this.readyAt = performance.now();
      this.startedFrom = data.from; // "snapshot", or "boot" when the snapshot could not be used
      this.startStages = data.stages;
      // Pyodide's compiled WebAssembly (the grader's: the sandbox starts from it).
      this.wasmModule = data.module ?? null;
      if (data.why) console.warn("Python runtime: booted without the snapshot:", data.why);
      const total = this.boot?.total || 0;
      this.reportBoot({ phase: BOOT_PHASE.ready, loaded: total, total, step: null });
      this.setState(RUNTIME.ready);
      for (const entry of this.pending.values()) this.send(entry);
      return;
    }
    if (data.type === "failed") {
      this.fail(`The Python runtime could not start: ${data.message}`);
      return;
    }
    const entry = this.pending.get(data.id);
    if (!entry) return;
    if (data.type === "received") {
      clearTimeout(entry.ackTimer);
    } else if (data.type === "progress") {
      entry.onProgress?.(data.message);
    } else if (data.type === "started") {
      this.arm(entry, entry.limitMs); // the learner's code starts now
    } else if (data.type === "reply") {
      clearTimeout(entry.timer);
      clearTimeout(entry.ackTimer);
      this.pending.delete(data.id);
      this.lastActivityAt = performance.now();
      const kind = data.reply.ok ? null : data.reply.error.kind;
      if (entry.interrupted) {
        this.interrupts++;
        this.lastStop = "interrupt";
        entry.resolve(timeoutReply(entry, "interrupt"));
      } else if (kind === ERROR.memory || kind === ERROR.runtime || kind === ERROR.crash) {
        this.pending.set(data.id, entry);
        this.restart(entry, data.reply); // Python may be left broken: replace it
        return;
      } else entry.resolve(data.reply);
      this.sendNext(entry);
    }
  }

  fail(message) {
    this.failure = message;
    this.setState(RUNTIME.failed);
    for (const [id, entry] of this.pending) {
      clearTimeout(entry.timer);
      clearTimeout(entry.ackTimer);
      entry.resolve(failure(ERROR.runtime, message));
      this.pending.delete(id);
    }
  }

  arm(entry, ms) {
    clearTimeout(entry.timer);
    entry.timer = setTimeout(() => this.expire(entry), ms);
  }

  send(entry) {
    if (this.ackMs) {
      if (this.inFlight && this.inFlight !== entry) return; // sent when the one in flight is answered
      this.inFlight = entry;
      clearTimeout(entry.ackTimer);
      entry.ackTimer = setTimeout(() => this.unacknowledged(entry), this.ackMs);
    }
    this.arm(entry, entry.msg.op === "run" ? LOAD_LIMIT_MS : entry.limitMs);
    this.worker.postMessage(entry.msg);
  }

  /** `done` was answered: send the next request, when they go one at a time. */
  sendNext(done) {
    if (this.inFlight !== done) return;
    this.inFlight = null;
    const [next] = this.pending.values();
    if (next && this.ready) this.send(next);
  }

  /** The worker did not even acknowledge `entry`: it is gone. A fresh one gets it (once). */
  unacknowledged(entry) {
    if (entry.resent) {
      this.restart(entry, crashReply());
      return;
    }
    entry.resent = true;
    this.lost = (this.lost || 0) + 1;
    this.replace();
  }

  expire(entry) {
    const buffer = this.interrupt;
    if (buffer && !entry.interrupted && Atomics.load(buffer, 1) === entry.msg.id) {
      entry.interrupted = true; // answered as a timeout when the worker replies
      this.interruptsSent = (this.interruptsSent || 0) + 1;
      Atomics.store(buffer, 0, SIGINT);
      let waited = 0;
      const check = () => {
        waited += INTERRUPT_GRACE_MS;
        const running = Atomics.load(buffer, 1) === entry.msg.id;
        const unseen = Atomics.load(buffer, 0) === SIGINT;
        // The run has returned (its reply is coming), or Python has not yet seen the signal: wait on.
        if ((!running || unseen) && waited < INTERRUPT_WAIT_MS) entry.timer = setTimeout(check, INTERRUPT_GRACE_MS);
        else this.terminate(entry);
      };
      entry.timer = setTimeout(check, INTERRUPT_GRACE_MS);
      return;
    }
    this.terminate(entry);
  }

  terminate(entry) {
    this.restart(entry, timeoutReply(entry, "terminate"));
  }

  /** Answer `entry` with `reply`, replace the worker; other requests wait for the new one. */
  restart(entry, reply) {
    this.pending.delete(entry.msg.id);
    clearTimeout(entry.timer);
    clearTimeout(entry.ackTimer);
    entry.resolve(reply);
    this.restarts++;
    this.lastStop = "terminate";
    this.replace();
  }

  /** A fresh worker in place of this one; pending requests are sent to it once it is ready. */
  replace() {
    this.worker.onmessage = this.worker.onerror = null;
    this.worker.terminate();
    this.inFlight = null;
    for (const other of this.pending.values()) {
      clearTimeout(other.timer); // re-armed when re-sent
      clearTimeout(other.ackTimer);
    }
    this.spawn(null);
  }

  /**
   * Send `request` ({op, ...}); resolves with an envelope, never rejects.
   * @param {{ op: string, [key: string]: any }} request
   * @param {{ limitMs?: number, onProgress?: (text: string) => void, onWait?: () => void }} [options]
   */
  request(request, { limitMs = DEFAULT_LIMIT_MS, onProgress } = {}) {
    if (this.failure) return Promise.resolve(failure(ERROR.runtime, this.failure));
    return new Promise((resolve) => {
      const msg = { ...request, id: this.nextId++ };
      const entry = { msg, resolve, limitMs, onProgress, timer: null };
      this.pending.set(msg.id, entry);
      this.lastActivityAt = performance.now();
      if (this.ready) this.send(entry);
    });
  }

  /**
   * Resolves once this runtime has had nothing to do for `ms`: no request waiting or running, and
   * none sent or answered in the last `ms`. Work that would compete with the learner's Checks (the
   * sandbox's start: kinds/build.js) waits for it.
   * @returns {Promise<void>}
   */
  quietFor(ms) {
    return new Promise((resolve) => {
      const check = () => {
        const since = performance.now() - this.lastActivityAt;
        if (this.pending.size === 0 && since >= ms) resolve();
        else setTimeout(check, Math.max(QUIET_POLL_MS, ms - since));
      };
      check();
    });
  }
}
