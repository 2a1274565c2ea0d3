// Endless loop in the Build editor; the moment its timeout result appears, check a
// Derive exercise and time until that result.
async ({ buildId, deriveId, code, answer, timeoutMs, C }) => {
  const B = window.__bench, A = C.attr;
  const build = B.exercise(buildId);
  const derive = B.exercise(deriveId);
  derive.querySelector(C.sel.answer).value = answer;
  (await B.openEditor(build, timeoutMs)).setCode(code);
  const out = {};
  let timer;
  const observers = [];
  const finished = new Promise((resolve, reject) => {
    timer = setTimeout(() => reject(new Error(`no recovery within ${timeoutMs} ms: ${JSON.stringify(out)}`)), timeoutMs);
    const watchDerive = new MutationObserver(() => {
      if (out.fired === undefined || derive.getAttribute(A.state) === C.state.pending) return;
      out.done = performance.now(); out.deriveState = derive.getAttribute(A.state); resolve();
    });
    const watchBuild = new MutationObserver(() => {
      if (build.getAttribute(A.state) === C.state.pending || out.fired !== undefined) return;
      out.fired = performance.now(); out.buildState = build.getAttribute(A.state);
      out.message = (build.querySelector(C.sel.feedback) || {}).textContent || "";
      derive.querySelector(C.sel.check).click();
    });
    watchDerive.observe(derive, { attributes: true, attributeFilter: [A.state] });
    watchBuild.observe(build, { attributes: true, attributeFilter: [A.state] });
    observers.push(watchDerive, watchBuild);
  });
  out.clicked = performance.now();
  build.querySelector(C.sel.run).click();
  try { await finished; } finally { clearTimeout(timer); observers.forEach((o) => o.disconnect()); }
  return { ...out, recoveryMs: out.done - out.fired, runToLimitMs: out.fired - out.clicked };
}
