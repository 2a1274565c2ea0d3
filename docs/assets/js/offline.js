// Offline use: registers the service worker (sw.js at the site root, written at
// build time by docs/hooks/offline.py), says whether the site is stored, and
// tells the learner when a new version of the workbook is ready.
//
// <html data-workbook-offline="caching|ready|unavailable"> (the contract's
// OFFLINE states): "caching" while the service worker stores the site, "ready"
// once a complete copy is stored in this browser, "unavailable" where it cannot
// be (no service worker, a page opened from a file, an install that failed).
//
// Once stored: a quiet line in the footer ("Stored for offline use · 27 MB"),
// and one request (ever) for persistent storage. Where the browser may delete
// what scripts stored (WebKit, Safari's 7 days without a visit, unless storage is
// persistent), a learner with solved exercises is reminded, at most once a week,
// to export their progress.

import { ATTR, OFFLINE, RUNTIME, setRootState } from "./contract.js";

const UPDATE_CHECK_MS = 30 * 60_000;
const REMIND_EVERY_MS = 7 * 86_400_000;
const MB = 1_000_000;
const setOffline = (state) => setRootState("offline", state);

// ---- Small local notes (which version was measured, whether persist() was asked) ----
function notes(siteRoot) {
  const key = `robotics-workbook:${new URL(siteRoot).pathname}:offline`;
  let store = null;
  try {
    store = window.localStorage;
  } catch {
    /* storage disabled: every note is forgotten with the page */
  }
  let data = {};
  try {
    data = JSON.parse(store?.getItem(key) || "{}") || {};
  } catch {
    data = {};
  }
  return {
    get: (name) => data[name],
    set(name, value) {
      data[name] = value;
      try {
        store?.setItem(key, JSON.stringify(data));
      } catch {
        /* full or disabled: not worth a message */
      }
    },
  };
}

// ---- The update banner ----------------------------------------------------------
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

// ---- What is stored, and how much -------------------------------------------------
/** Send `message` to the service worker `worker`; resolves with its first reply of one of `types`. */
function ask(worker, message, types) {
  const sw = navigator.serviceWorker;
  return new Promise((resolve) => {
    const onMessage = (event) => {
      if (!types.includes(event.data?.type)) return;
      sw.removeEventListener("message", onMessage);
      resolve(event.data);
    };
    sw.addEventListener("message", onMessage);
    worker.postMessage(message);
  });
}

/** The version the active service worker serves, or null. */
async function activeVersion(registration) {
  const worker = registration.active;
  return worker ? (await ask(worker, { type: "version" }, ["version"])).version : null;
}

// The offline copy waits until the runtime has started (ready, or failed), a
// little longer, and until the browser is idle: storing it earlier competed with
// the start for the link, and right after ready with the learner's first Check
// for the machine (the service worker writes some 16 MB).
const AFTER_READY_MS = 2_000;
function runtimeSettled() {
  const root = document.documentElement;
  const settled = () => [RUNTIME.ready, RUNTIME.failed].includes(root.getAttribute(ATTR.runtime));
  return new Promise((resolve) => {
    if (settled()) return resolve();
    const observer = new MutationObserver(() => {
      if (!settled()) return;
      observer.disconnect();
      resolve();
    });
    observer.observe(root, { attributes: true, attributeFilter: [ATTR.runtime] });
  });
}
const idle = () => new Promise((resolve) => (window.requestIdleCallback ? requestIdleCallback(() => resolve(), { timeout: 2000 }) : setTimeout(resolve, 0)));

/** Resolves once the active service worker has stored every file; rejects if it could not. */
async function stored(registration) {
  const first = await ask(registration.active, { type: "stored?" }, ["stored"]);
  if (first.complete) return;
  await runtimeSettled();
  await new Promise((resolve) => setTimeout(resolve, AFTER_READY_MS));
  await idle();
  const worker = registration.active; // still the same unless an update took over meanwhile
  const done = await ask(worker, { type: "store" }, ["stored", "store-failed"]);
  if (done.type !== "stored") throw new Error(done.message);
}

/** Bytes of the stored copy: the sum of the cached responses' bodies. */
async function cachedBytes(cacheName) {
  const cache = await caches.open(cacheName);
  let total = 0;
  for (const request of await cache.keys()) {
    const response = await cache.match(request);
    if (!response) continue;
    const length = Number(response.headers.get("Content-Length"));
    // A compressed transfer's length is not what is stored; no length, measure the body.
    total += length && !response.headers.get("Content-Encoding") ? length : (await response.blob()).size;
  }
  return total;
}

/** The stored copy's size in bytes, measured once per version (kept in the notes). */
async function storedBytes(registration, siteRoot, note) {
  const version = await activeVersion(registration);
  if (!version) return null;
  const known = note.get("size");
  if (known?.version === version) return known.bytes;
  const name = `robotics-workbook:${new URL(siteRoot).pathname}:${version}`;
  if (!(await caches.has(name))) return null;
  const bytes = await cachedBytes(name);
  note.set("size", { version, bytes });
  return bytes;
}

export function formatSize(bytes) {
  const mb = bytes / MB;
  return mb >= 10 ? `${Math.round(mb)} MB` : `${mb.toFixed(1)} MB`;
}

// The footer is part of what instant navigation replaces: draw the line on every page.
function drawIndicator(status) {
  if (!status) return;
  const footer = document.querySelector(".md-footer-meta__inner");
  if (!footer || footer.querySelector("[data-wb-offline-indicator]")) return;
  const line = document.createElement("p");
  line.className = "wb-offline-indicator";
  line.dataset.wbOfflineIndicator = "";
  line.textContent = status.bytes ? `Stored for offline use · ${formatSize(status.bytes)}` : "Stored for offline use";
  line.title = status.persisted
    ? "Every page and the Python grader are stored in this browser, which has agreed to keep them."
    : "Every page and the Python grader are stored in this browser: the workbook works without a network.";
  footer.append(line);
}

/** Ask once (ever, per site) for storage the browser will not evict on its own. */
async function askToPersist(note) {
  const storage = navigator.storage;
  if (!storage?.persist) return false;
  try {
    if (await storage.persisted?.()) return true;
    if (note.get("persistAsked")) return false;
    note.set("persistAsked", Date.now());
    return await storage.persist();
  } catch {
    return false;
  }
}

// ---- The export reminder (browsers that delete script-written storage) ------------
/** WebKit (Safari, and every browser on iOS) deletes script-written storage after 7 days without a visit. */
export function evictsStorage(userAgent = navigator.userAgent) {
  return /AppleWebKit\//.test(userAgent) && !/(Chrome|Chromium|Edg|OPR|SamsungBrowser)\//.test(userAgent);
}

async function remindToExport(progress, siteRoot, note) {
  if (!progress || !evictsStorage()) return;
  if (!Object.values(progress.all()).some((record) => record.solved)) return;
  const last = note.get("remindedAt") || 0;
  if (Date.now() - last < REMIND_EVERY_MS) return;
  try {
    if (await navigator.storage?.persisted?.()) return;
  } catch {
    /* unknown: remind */
  }
  const main = document.querySelector(".md-content__inner");
  if (!main || main.querySelector("[data-wb-reminder]")) return;
  note.set("remindedAt", Date.now());
  const box = document.createElement("div");
  box.className = "admonition note wb-reminder";
  box.dataset.wbReminder = "";
  box.setAttribute("role", "note");
  box.setAttribute("aria-label", "Keep a copy of your progress");
  const title = document.createElement("p");
  title.className = "admonition-title";
  title.textContent = "Keep a copy of your progress";
  const text = document.createElement("p");
  text.append("This browser may delete what the workbook stored, your progress included, after 7 days without a visit. ");
  const link = document.createElement("a");
  link.href = new URL("progress/", siteRoot).href;
  link.textContent = "Export your progress";
  text.append(link, " to keep it in a file.");
  const dismiss = document.createElement("button");
  dismiss.type = "button";
  dismiss.className = "md-button";
  dismiss.textContent = "Dismiss";
  dismiss.dataset.wbAction = "dismiss-reminder";
  dismiss.addEventListener("click", () => box.remove());
  box.append(title, text, dismiss);
  main.prepend(box);
}

// ---- Registration -----------------------------------------------------------------
export function registerOffline(siteRoot, progress = null) {
  const note = notes(siteRoot);
  let status = null; // {bytes, persisted} once the site is stored
  window.document$?.subscribe?.(() => drawIndicator(status));
  remindToExport(progress, siteRoot, note).catch(() => {});

  const sw = navigator.serviceWorker;
  if (!sw || !window.isSecureContext || location.protocol === "file:") {
    setOffline(OFFLINE.unavailable);
    return;
  }
  let controlled = Boolean(sw.controller);
  // A worker controls pages only once every file of its version is stored.
  setOffline(controlled ? OFFLINE.ready : OFFLINE.caching);
  sw.addEventListener("controllerchange", () => {
    // A new version took over: reload rather than mix this page with its files.
    if (controlled) location.reload();
    controlled = true;
  });
  const watch = (registration, worker) => {
    worker?.addEventListener("statechange", () => {
      if (worker.state === "installed" && controlled) showUpdate(registration);
      if (worker.state === "redundant" && !registration.active) setOffline(OFFLINE.unavailable);
    });
  };
  sw.register(new URL("sw.js", siteRoot), { scope: new URL(siteRoot).pathname, updateViaCache: "none" })
    .then((registration) => {
      if (registration.waiting && controlled) showUpdate(registration);
      watch(registration, registration.installing);
      registration.addEventListener("updatefound", () => watch(registration, registration.installing));
      // Instant navigation never reloads the page, so look for a new version now and then.
      let checked = Date.now();
      window.document$?.subscribe?.(() => {
        if (Date.now() - checked < UPDATE_CHECK_MS) return;
        checked = Date.now();
        registration.update().catch(() => {});
      });
      return sw.ready;
    })
    .then(async (registration) => {
      await stored(registration);
      setOffline(OFFLINE.ready);
      whenStored(registration).catch(() => {});
    })
    .catch(() => {
      setOffline(OFFLINE.unavailable); // the site still works online
    });

  async function whenStored(registration) {
    const persisted = await askToPersist(note);
    const bytes = await storedBytes(registration, siteRoot, note).catch(() => null);
    status = { bytes, persisted };
    drawIndicator(status);
  }
}
