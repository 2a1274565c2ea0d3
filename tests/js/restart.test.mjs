// A replaced worker is told what the first one was told (docs/assets/js/runtime.js): the page's head
// names, in the grader's worker name, its chapter's part of the compiled package and whether the
// service worker controls the page (docs/overrides/main.html, worker.js). Run by
// tests/unit/test_runtime_restart.py.

import { test } from "node:test";
import assert from "node:assert/strict";

globalThis.self = globalThis;
globalThis.document = new EventTarget();
const made = [];
globalThis.Worker = class {
  constructor(url, options) {
    made.push({ url: String(url), options });
  }
  postMessage() {}
  terminate() {}
};

const { Runtime } = await import("../../docs/assets/js/runtime.js");
const URL_ = new URL("https://example.org/workbook/assets/dist/worker.js");

test("a successor of the head's worker gets the same name", () => {
  const name = "package=workbook.compiled.ch1.zip&sw=1";
  const early = { worker: new globalThis.Worker(URL_, { name }), name, messages: [], started: 0 };
  const runtime = new Runtime(URL_, early, { role: "sandbox" });
  assert.equal(made.length, 1); // the head's own
  runtime.replace();
  runtime.replace();
  assert.deepEqual(made.slice(1).map((m) => m.options?.name), [name, name]);
  assert.ok(made.every((m) => m.url === URL_.href));
});

test("a worker started without the head's has no name to pass on", () => {
  made.length = 0;
  const runtime = new Runtime(URL_, null, { role: "sandbox" });
  runtime.replace();
  assert.deepEqual(made.map((m) => m.options?.name), ["", ""]);
});

test("once the page has started, a successor is told so at once, and a first worker only when it is", () => {
  const sent = [];
  globalThis.Worker = class {
    postMessage(message) {
      sent.push(message);
    }
    terminate() {}
  };
  const runtime = new Runtime(URL_, null, { role: "sandbox" });
  const told = () => sent.filter((m) => m?.type === "page-started").length;
  assert.equal(told(), 0); // the page has not started yet: Python's start waits (worker.js)
  runtime.replace();
  assert.equal(told(), 0);
  runtime.pageStarted();
  assert.equal(told(), 1);
  runtime.replace(); // a successor must not wait for a start that happened long ago
  assert.equal(told(), 2);
});
