// In-page instrumentation, installed before any of the page's scripts run.
// Called as init(C): C holds the page contract's names (scripts/bench/pagejs.py).
(C) => {
  if (window.__bench) return;
  const B = window.__bench = { runtime: [], states: [], clicks: [], longtasks: [], loaf: [], lcp: [] };
  const A = C.attr;
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) B.longtasks.push({
        start: e.startTime, duration: e.duration, name: e.name,
        attribution: (e.attribution || []).map((a) => ({ name: a.name, containerType: a.containerType,
          containerSrc: a.containerSrc, containerId: a.containerId, containerName: a.containerName })),
      });
    }).observe({ type: "longtask", buffered: true });
  } catch (err) { B.longtaskError = String(err); }
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) B.loaf.push({
        start: e.startTime, duration: e.duration, blockingDuration: e.blockingDuration,
        scripts: (e.scripts || []).map((s) => ({ sourceURL: s.sourceURL, sourceFunctionName: s.sourceFunctionName,
          invoker: s.invoker, invokerType: s.invokerType, start: s.startTime, duration: s.duration,
          forcedStyleAndLayoutDuration: s.forcedStyleAndLayoutDuration })),
      });
    }).observe({ type: "long-animation-frame", buffered: true });
  } catch (err) { B.loafError = String(err); }
  try {
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) B.lcp.push({ start: e.startTime, size: e.size,
        element: e.element ? e.element.tagName.toLowerCase() + (e.element.id ? "#" + e.element.id : "") : null });
    }).observe({ type: "largest-contentful-paint", buffered: true });
  } catch (err) { B.lcpError = String(err); }
  new MutationObserver((records) => {
    const t = performance.now();
    for (const r of records) {
      const el = r.target;
      if (r.attributeName === A.runtime) B.runtime.push([el.getAttribute(A.runtime), t]);
      else if (r.attributeName === A.state) B.states.push([el.getAttribute(A.exercise), el.getAttribute(A.state), t]);
      else if (r.attributeName === "data-baseline") B.runtime.push(["baseline-" + el.dataset.baseline, t]);
    }
  }).observe(document, { subtree: true, attributes: true, attributeFilter: [A.runtime, A.state, "data-baseline"] });
  // A Check that submits the form before our script has started reloads the page:
  // the tab's first navigation start and every click survive in sessionStorage.
  B.timeOrigin = performance.timeOrigin;
  try {
    const ss = sessionStorage;
    if (!ss.getItem("__benchOrigin")) ss.setItem("__benchOrigin", String(performance.timeOrigin));
    ss.setItem("__benchDocs", String(Number(ss.getItem("__benchDocs") || 0) + 1));
    B.tabOrigin = Number(ss.getItem("__benchOrigin"));
    B.docs = Number(ss.getItem("__benchDocs"));
  } catch (err) { B.tabOrigin = performance.timeOrigin; B.docs = 1; }
  addEventListener("click", () => {
    const t = performance.now();
    B.clicks.push(t);
    try {
      const all = JSON.parse(sessionStorage.getItem("__benchClicks") || "[]");
      all.push(performance.timeOrigin + t - B.tabOrigin);
      sessionStorage.setItem("__benchClicks", JSON.stringify(all));
    } catch (err) {}
  }, true);

  // Helpers for the bench's page scripts.
  B.exercise = (id) => document.querySelector(`[${A.exercise}="${CSS.escape(id)}"]`);
  // A Build exercise's editor, opened. Its host gets wbOpenEditor when the Build widget's script has
  // run (kinds/build.js), a moment after the exercise is marked started: waits for that first.
  B.openEditor = async (el, timeoutMs) => {
    const host = el.querySelector(C.sel.editor);
    for (const until = performance.now() + timeoutMs; typeof host.wbOpenEditor !== "function";) {
      if (performance.now() > until) throw new Error(`exercise ${el.getAttribute(A.exercise)}: its editor did not start within ${timeoutMs} ms`);
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    return host.wbOpenEditor();
  };
  // Clicks a button; resolves when the exercise leaves "pending" (timed in the page).
  B.clickAndWait = (el, button, timeoutMs) => {
    let mo, timer;
    const done = new Promise((resolve, reject) => {
      mo = new MutationObserver(() => {
        const state = el.getAttribute(A.state);
        if (state !== C.state.pending) resolve([performance.now(), state]);
      });
      mo.observe(el, { attributes: true, attributeFilter: [A.state] });
      timer = setTimeout(() => reject(new Error(
        `exercise ${el.getAttribute(A.exercise)}: no result within ${timeoutMs} ms`)), timeoutMs);
    });
    const t0 = performance.now();
    button.click();
    return done.then(([t1, state]) => ({ ms: t1 - t0, state })).finally(() => { mo.disconnect(); clearTimeout(timer); });
  };
}
