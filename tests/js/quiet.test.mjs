// Runtime.quietFor (docs/assets/js/runtime.js): it resolves only once the runtime has had nothing to do
// for the time asked: nothing waiting or running, nothing sent or answered meanwhile. The sandbox's start
// waits for the grader to be quiet (kinds/build.js). Run by tests/unit/test_runtime_restart.py.

import { test } from "node:test";
import assert from "node:assert/strict";

globalThis.self = globalThis;
globalThis.document = new EventTarget();
globalThis.Worker = class {
  constructor() {
    this.sent = [];
  }
  postMessage(message) {
    this.sent.push(message);
  }
  terminate() {}
};

const { Runtime } = await import("../../docs/assets/js/runtime.js");
const URL_ = new URL("https://example.org/workbook/assets/dist/worker.js");
const QUIET_MS = 150;
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

/** A runtime whose worker said it is ready. */
function readyRuntime() {
  const runtime = new Runtime(URL_, null, { role: "sandbox" });
  runtime.receive({ type: "ready" });
  return runtime;
}
/** `done`: whether `promise` (a quietFor) has resolved yet. */
function watch(promise) {
  const state = { done: false };
  promise.then(() => { state.done = true; });
  return state;
}
const reply = (runtime, id) => runtime.receive({ type: "reply", id, reply: { ok: true, value: null } });

test("a runtime with nothing to do is quiet once the time has passed, not before", async () => {
  const runtime = readyRuntime();
  const quiet = watch(runtime.quietFor(QUIET_MS));
  await sleep(QUIET_MS / 3);
  assert.equal(quiet.done, false);
  await sleep(QUIET_MS * 2);
  assert.equal(quiet.done, true);
});

test("a request that is still running keeps it busy however long it takes", async () => {
  const runtime = readyRuntime();
  const answered = runtime.request({ op: "grade" });
  const quiet = watch(runtime.quietFor(QUIET_MS));
  await sleep(QUIET_MS * 3);
  assert.equal(quiet.done, false); // nothing answered yet
  reply(runtime, runtime.worker.sent.at(-1).id);
  await answered;
  await sleep(QUIET_MS / 3);
  assert.equal(quiet.done, false); // answered just now: the wait starts again from the answer
  await sleep(QUIET_MS * 2);
  assert.equal(quiet.done, true);
});

test("each request sent starts the wait again", async () => {
  const runtime = readyRuntime();
  const quiet = watch(runtime.quietFor(QUIET_MS));
  for (let i = 0; i < 4; i++) { // a learner checking every half of the quiet time
    await sleep(QUIET_MS / 2);
    const answered = runtime.request({ op: "grade" });
    reply(runtime, runtime.worker.sent.at(-1).id);
    await answered;
    assert.equal(quiet.done, false, `check ${i + 1}`);
  }
  await sleep(QUIET_MS * 2);
  assert.equal(quiet.done, true);
});
