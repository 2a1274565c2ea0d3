// Runs the Build exercise's tests once: click Run -> data-state change.
async ({ id, code, timeoutMs, C }) => {
  const B = window.__bench;
  const el = B.exercise(id);
  const host = el.querySelector(C.sel.editor);
  // wbOpenEditor comes with the Build widget's script (kinds/build.js), a moment after the exercise
  // is marked started: wait for it (the first Build run right after ready may come first).
  for (const until = performance.now() + timeoutMs; typeof host.wbOpenEditor !== "function";) {
    if (performance.now() > until) throw new Error(`exercise ${id}: its editor did not start within ${timeoutMs} ms`);
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
  if (code !== null) (await host.wbOpenEditor()).setCode(code);
  const { ms, state } = await B.clickAndWait(el, el.querySelector(C.sel.run), timeoutMs);
  const passed = [...el.querySelectorAll(C.sel["test-result"])].map((r) => r.getAttribute(C.attr.passed) === "true");
  return { ms, state, passed };
}
