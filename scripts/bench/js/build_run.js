// Runs the Build exercise's tests once: click Run -> data-state change.
async ({ id, code, timeoutMs, C }) => {
  const B = window.__bench;
  const el = B.exercise(id);
  if (code !== null) (await B.openEditor(el, timeoutMs)).setCode(code);
  const { ms, state } = await B.clickAndWait(el, el.querySelector(C.sel.run), timeoutMs);
  const passed = [...el.querySelectorAll(C.sel["test-result"])].map((r) => r.getAttribute(C.attr.passed) === "true");
  return { ms, state, passed };
}
