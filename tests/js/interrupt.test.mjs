// The time limit of a run on a cross-origin isolated page (docs/assets/js/runtime.js): the page
// writes SIGINT into the buffer it shares with the worker, and terminates the worker only when
// the run is still going once Python has seen the signal. Run by tests/unit/test_runtime_interrupt.py.
//
// A fake worker stands for the sandbox; the buffer is a real SharedArrayBuffer, the timers are
// Node's mocked ones, so every case runs the page's own code on a clock the test moves.

import { mock, test } from "node:test";
import assert from "node:assert/strict";

globalThis.self = globalThis;
Object.defineProperty(globalThis, "crossOriginIsolated", { value: true, configurable: true });
globalThis.document = new EventTarget();

const { Runtime } = await import("../../docs/assets/js/runtime.js");

const SIGINT = 2;
const LIMIT = 5_000;

/** A sandbox whose worker the test plays: it acknowledges, starts, and answers when told. */
function sandbox() {
  const sent = [];
  let spawned = 0;
  const workers = [];
  const runtime = new Runtime(() => {
    spawned++;
    const worker = { postMessage: (msg) => sent.push(msg), terminate() { this.terminated = true; } };
    workers.push(worker);
    return worker;
  }, null, { role: "sandbox", ackMs: 5_000 });
  const worker = () => workers.at(-1);
  const say = (data) => worker().onmessage({ data });
  say({ type: "ready", stages: {} });
  const buffer = runtime.interrupt;
  assert.ok(buffer instanceof Int32Array, "the page shares an interrupt buffer on an isolated page");
  /** A run request, acknowledged and started as the worker does (the id written into the buffer). */
  const start = () => {
    let reply = null;
    runtime.request({ op: "run", job: "{}", code: "" }, { limitMs: LIMIT }).then((r) => (reply = r));
    const { id } = sent.filter((m) => m.op === "run").at(-1);
    say({ id, type: "received" });
    say({ id, type: "started" });
    Atomics.store(buffer, 0, 0);
    Atomics.store(buffer, 1, id);
    return { id, reply: () => reply };
  };
  /** Python sees the signal (Pyodide clears it), and the run returns: the worker clears the id. */
  const pythonSees = () => Atomics.store(buffer, 0, 0);
  const runReturns = () => Atomics.store(buffer, 1, 0);
  return { runtime, buffer, start, say, pythonSees, runReturns, spawned: () => spawned };
}

const flush = () => new Promise((resolve) => setImmediate(resolve));

/** Move the mocked clock on by `ms`, a millisecond at a time (Node 20's tick does not run a timer
 *  that a timer it ran has set, within the same tick). */
function advance(t, ms) {
  for (let i = 0; i < ms; i++) t.mock.timers.tick(1);
}

/** A sandbox on the mocked clock, with a run started and its time limit just reached. */
function atTheLimit(t) {
  t.mock.timers.enable({ apis: ["setTimeout"] });
  const s = sandbox();
  const run = s.start();
  advance(t, LIMIT);
  return { s, run };
}

/** Python stops the run on the signal: it clears the signal, the run returns, the worker replies. */
function stops(s, run) {
  s.pythonSees();
  s.runReturns();
  s.say({ id: run.id, type: "reply", reply: { ok: true, value: "{}" } });
}

test("the time limit interrupts the run, and its reply is a timeout told as interrupted", async (t) => {
  const { s, run } = atTheLimit(t);
  assert.equal(Atomics.load(s.buffer, 0), SIGINT, "the signal is written at the limit");
  stops(s, run);
  await flush();
  assert.equal(run.reply().error.kind, "timeout");
  assert.match(run.reply().error.message, /interrupted/);
  assert.deepEqual([s.runtime.lastStop, s.runtime.interrupts, s.runtime.restarts, s.spawned()], ["interrupt", 1, 0, 1]);
});

test("a run that has returned is not terminated when its reply comes after the grace period", async (t) => {
  // The page's thread was busy: the grace timer fires before the reply's message is handled.
  const { s, run } = atTheLimit(t);
  s.pythonSees();
  s.runReturns();
  advance(t, 3_000);
  assert.equal(s.spawned(), 1, "no new worker while the reply is on its way");
  s.say({ id: run.id, type: "reply", reply: { ok: true, value: "{}" } });
  await flush();
  assert.deepEqual([s.runtime.lastStop, s.runtime.interrupts, s.runtime.restarts], ["interrupt", 1, 0]);
});

test("a worker that has not yet seen the signal gets longer, then stops by the interrupt", async (t) => {
  const { s, run } = atTheLimit(t);
  advance(t, 6_000); // starved: the signal is still unseen
  assert.equal(s.spawned(), 1);
  stops(s, run);
  await flush();
  assert.deepEqual([s.runtime.lastStop, s.runtime.interrupts, s.runtime.restarts], ["interrupt", 1, 0]);
});

test("code that swallows the interrupt is terminated two seconds after Python saw it", async (t) => {
  const { s, run } = atTheLimit(t);
  s.pythonSees(); // ... and the loop goes on: the id stays
  advance(t, 1_999);
  assert.equal(s.spawned(), 1);
  advance(t, 1);
  await flush();
  assert.equal(run.reply().error.kind, "timeout");
  assert.match(run.reply().error.message, /restarted/);
  assert.deepEqual([s.runtime.lastStop, s.runtime.interrupts, s.runtime.restarts, s.spawned()], ["terminate", 0, 1, 2]);
});

test("a worker that never sees the signal is terminated ten seconds after it", async (t) => {
  const { s, run } = atTheLimit(t);
  advance(t, 9_999);
  assert.equal(s.spawned(), 1);
  advance(t, 1);
  await flush();
  assert.equal(run.reply().error.kind, "timeout");
  assert.deepEqual([s.runtime.lastStop, s.runtime.restarts, s.spawned()], ["terminate", 1, 2]);
});

mock.reset();
