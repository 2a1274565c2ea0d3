// The sandbox's start (docs/assets/js/sandbox-client.js): started for a run the learner asked for, it
// is told so first, and skips its warm-up (sandbox.js); started ahead of any run, or as a
// replacement after one, it is not told, and warms up. Run by tests/unit/test_runtime_restart.py.

import { test } from "node:test";
import assert from "node:assert/strict";

globalThis.self = globalThis;
globalThis.document = new EventTarget();
globalThis.window = globalThis;
const workers = [];
globalThis.Worker = class {
  constructor(url, options) {
    this.url = String(url);
    this.options = options;
    this.sent = [];
    workers.push(this);
  }
  postMessage(message) {
    this.sent.push(message);
  }
  terminate() {
    this.terminated = true;
  }
};

const { startSandbox } = await import("../../docs/assets/js/sandbox-client.js");
const GRADER = "https://example.org/workbook/assets/dist/worker.js";
const told = (worker) => worker.sent.filter((m) => m?.type === "run-waiting").length;

test("a start for a run tells the sandbox so, and its replacement is not told", () => {
  const box = startSandbox(GRADER, null, null, true);
  assert.equal(workers.length, 1);
  assert.equal(told(workers[0]), 1);
  box.replace();
  assert.equal(workers.length, 2);
  assert.equal(told(workers[1]), 0);
  assert.equal(startSandbox(GRADER, null, null, true), box); // running: the same sandbox, nothing sent again
  assert.equal(told(workers[1]), 0);
});

test("a start ahead of any run is not told", async () => {
  const { startSandbox: fresh } = await import("../../docs/assets/js/sandbox-client.js?ahead");
  const before = workers.length;
  fresh(GRADER, null, null);
  assert.equal(workers.length, before + 1);
  assert.equal(told(workers.at(-1)), 0);
});
