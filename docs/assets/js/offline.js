// Offline use: registers the service worker (sw.js at the site root, written at
// build time by docs/hooks/offline.py) and tells the learner when a new version
// of the workbook is ready.
//
// <html data-workbook-offline="unsupported|installing|ready|failed">: "ready"
// once a complete copy of the site is cached in this browser.

const root = document.documentElement;
const UPDATE_CHECK_MS = 30 * 60_000;

function showUpdate(registration) {
  if (document.querySelector("[data-wb-update]")) return;
  const bar = document.createElement("div");
  bar.className = "wb-update";
  bar.dataset.wbUpdate = "";
  bar.setAttribute("role", "status");
  const text = document.createElement("p");
  text.textContent = "A new version of the workbook is ready. Reload to use it (your progress is kept).";
  const reload = document.createElement("button");
  reload.type = "button";
  reload.className = "md-button md-button--primary";
  reload.textContent = "Reload";
  reload.dataset.wbAction = "update";
  const later = document.createElement("button");
  later.type = "button";
  later.className = "md-button";
  later.textContent = "Later";
  reload.addEventListener("click", () => {
    reload.disabled = true;
    // The waiting worker takes over; "controllerchange" then reloads every open page.
    if (registration.waiting) registration.waiting.postMessage({ type: "activate-update" });
    else location.reload();
  });
  later.addEventListener("click", () => bar.remove());
  bar.append(text, reload, later);
  document.body.append(bar);
}

export function registerOffline(siteRoot) {
  const sw = navigator.serviceWorker;
  if (!sw || !window.isSecureContext || location.protocol === "file:") {
    root.dataset.workbookOffline = "unsupported";
    return;
  }
  let controlled = Boolean(sw.controller);
  root.dataset.workbookOffline = "installing";
  sw.addEventListener("controllerchange", () => {
    // A new version took over: reload rather than mix this page with its files.
    if (controlled) location.reload();
    controlled = true;
  });
  sw.register(new URL("sw.js", siteRoot), { scope: new URL(siteRoot).pathname, updateViaCache: "none" })
    .then((registration) => {
      if (registration.waiting && controlled) showUpdate(registration);
      registration.addEventListener("updatefound", () => {
        const next = registration.installing;
        next?.addEventListener("statechange", () => {
          if (next.state === "installed" && controlled) showUpdate(registration);
          if (next.state === "redundant" && !registration.active) root.dataset.workbookOffline = "failed";
        });
      });
      // Instant navigation never reloads the page, so look for a new version now and then.
      let checked = Date.now();
      window.document$?.subscribe?.(() => {
        if (Date.now() - checked < UPDATE_CHECK_MS) return;
        checked = Date.now();
        registration.update().catch(() => {});
      });
      return sw.ready;
    })
    .then(() => {
      root.dataset.workbookOffline = "ready";
    })
    .catch(() => {
      root.dataset.workbookOffline = "failed"; // the site still works online
    });
}
