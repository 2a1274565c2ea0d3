// What the page measured so far: the instrumentation's records, navigation timing,
// the runtime's own start-up record and the service worker's state.
async () => {
  const nav = performance.getEntriesByType("navigation")[0] || {};
  const rt = window.workbook && window.workbook.runtime;
  let sw = { supported: "serviceWorker" in navigator, registrations: 0, controlled: false };
  if (sw.supported) {
    try { sw.registrations = (await navigator.serviceWorker.getRegistrations()).length; } catch (e) {}
    sw.controlled = Boolean(navigator.serviceWorker.controller);
  }
  const B = window.__bench || {};
  return {
    runtime: B.runtime || [], states: B.states || [], clicks: B.clicks || [],
    longtasks: B.longtasks || [], loaf: B.loaf || [], longtaskError: B.longtaskError, loafError: B.loafError,
    lcp: B.lcp || [], lcpError: B.lcpError, timeOrigin: performance.timeOrigin,
    nav: { responseStart: nav.responseStart, responseEnd: nav.responseEnd,
           domInteractive: nav.domInteractive, domContentLoaded: nav.domContentLoadedEventEnd,
           load: nav.loadEventEnd, transferSize: nav.transferSize },
    workerStartedAt: rt ? rt.startedAt : null, workerReadyAt: rt ? rt.readyAt : null,
    startedFrom: rt ? rt.startedFrom || null : null, workerStages: rt ? rt.startStages || null : null,
    baseline: window.__baseline || null, sw, now: performance.now(),
    sinceTabStart: (B.timeOrigin || 0) - (B.tabOrigin || 0), docs: B.docs || 1,
    tabClicks: JSON.parse(sessionStorage.getItem("__benchClicks") || "[]"),
  };
}
