// Offline use: registers the service worker (sw.js at the site root, written at
// build time by docs/hooks/offline.py), asks it what is stored, and asks it to
// store the site once the learner has been told (offline-ui.js draws).
//
// <html data-workbook-offline> (the contract's OFFLINE states), always as the
// service worker reports it, never inferred from the page being controlled:
// - "caching": the copy is announced or running (the footer shows its progress);
// - "ready": every file of the manifest is stored and verified (sw.js);
// - "asking": a metered connection (Save-Data, or a 2G/3G effective type): the
//   copy waits for the learner's consent;
// - "declined": the learner said no (kept; the footer offers it again);
// - "unavailable": no service worker can run here, or the copy failed.
// The attribute is absent until the service worker has answered.
//
// The copy starts a while after the runtime is ready and the browser is idle
// (earlier, it competed with the start for the link and with the first Check
// for the machine). Once asked, the service worker carries it on by itself
// across navigations and reloads.

import { OFFLINE, setRootState } from "./contract.js";
import { delay, idle, runtimeSettled } from "./wait.js";
import { drawFooter, hideNotice, remindToExport, setFooter, showNotice, showUpdate } from "./offline-ui.js";

const UPDATE_CHECK_MS = 30 * 60_000;
const READ_MS = 8_000; // the notice stays this long before the copy starts by itself
const NARROW = "(max-width: 600px)"; // a phone's screen: the copy waits for the learner's word there
const setOffline = (state) => setRootState("offline", state);

// ---- Small local notes (declined, whether persist() was asked) ----------------------
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

/** Whether the connection is metered or slow (Save-Data, cellular, 2G/3G): the copy then waits for consent. */
export function metered(connection = navigator.connection) {
  return Boolean(connection && (connection.saveData || connection.type === "cellular"
    || /(^|-)2g$|^3g$/.test(connection.effectiveType || "")));
}

/** Whether the copy waits for the learner's word: a metered connection, or a phone's narrow screen. */
function waitsForWord() {
  return metered() || Boolean(window.matchMedia?.(NARROW).matches);
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

// ---- Registration -----------------------------------------------------------------
export function registerOffline(siteRoot, progress = null) {
  const note = notes(siteRoot);
  window.document$?.subscribe?.(() => drawFooter());
  remindToExport(progress, siteRoot, note).catch(() => {});

  const sw = navigator.serviceWorker;
  if (!sw || !window.isSecureContext || location.protocol === "file:") {
    setOffline(OFFLINE.unavailable);
    return;
  }
  let controlled = Boolean(sw.controller);
  sw.addEventListener("controllerchange", () => {
    // A new version took over: reload rather than mix this page with its files.
    if (controlled && sw.controller) location.reload();
    controlled = true;
  });
  const watch = (registration, worker) => {
    worker?.addEventListener("statechange", () => {
      if (worker.state === "installed" && controlled) showUpdate(registration);
      if (worker.state === "redundant" && !registration.active) setOffline(OFFLINE.unavailable);
    });
  };

  let last = null; // the service worker's last status
  let persisted = false;
  const actions = { onStore: () => store(), onDecline: () => decline() };
  function show(status) {
    last = status;
    if (status.state === "complete") {
      hideNotice();
      setOffline(OFFLINE.ready);
      setFooter({ ...status, persisted }, actions);
    } else if (status.state === "copying") {
      setOffline(OFFLINE.caching);
      setFooter(status, actions);
    }
  }
  sw.addEventListener("message", (event) => {
    const data = event.data || {};
    if (data.type === "status" || data.type === "progress") show(data);
    if (data.type === "status" && data.state === "complete") {
      askToPersist(note).then((yes) => {
        persisted = yes;
        setFooter({ ...last, persisted }, actions);
      });
    }
    if (data.type === "store-failed" && data.message !== "declined") {
      setOffline(OFFLINE.unavailable);
      setFooter({ ...(last || {}), state: "failed", message: data.message }, actions);
    }
  });

  let worker = null;
  let started = false; // the copy was started (by the learner, or after the notice)
  function store() {
    started = true;
    note.set("declined", false);
    hideNotice();
    setOffline(OFFLINE.caching);
    setFooter({ ...(last || {}), state: "copying", bytes: last?.bytes || 0 }, actions);
    worker?.postMessage({ type: "store" });
  }
  function decline() {
    note.set("declined", true);
    hideNotice();
    setOffline(OFFLINE.declined);
    setFooter({ ...(last || {}), state: "declined" }, actions);
    worker?.postMessage({ type: "decline" });
  }

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
      worker = registration.active;
      const status = await ask(worker, { type: "status" });
      show(status);
      if (status.state !== "partial") return; // stored, or being stored: the service worker goes on
      if (status.wanted) return store(); // asked for before (another page): carry on
      if (note.get("declined")) {
        setOffline(OFFLINE.declined);
        setFooter({ ...status, state: "declined" }, actions);
        return;
      }
      if (waitsForWord()) {
        setOffline(OFFLINE.asking);
        setFooter({ ...status, state: "partial" }, actions);
        await runtimeSettled();
        if (note.get("declined") || last.state !== "partial") return;
        showNotice({ mode: "ask", totalBytes: status.totalBytes, wireBytes: status.wireBytes, metered: metered() },
          actions);
        return;
      }
      // Announced at ready, started once the notice has been there long enough to read (or at
      // its OK), unless declined meanwhile; "Stop storing" in the footer declines it later.
      setOffline(OFFLINE.caching);
      setFooter({ ...status, state: "copying" }, actions);
      await runtimeSettled();
      const agreed = new Promise((resolve) => showNotice({ mode: "announce", totalBytes: status.totalBytes,
        wireBytes: status.wireBytes },
        { ...actions, onOK: () => resolve(undefined) }));
      await Promise.race([delay(READ_MS), agreed]);
      await idle(2000);
      if (note.get("declined") || last.state === "complete" || started) return;
      store();
    })
    .catch(() => {
      setOffline(OFFLINE.unavailable); // the site still works online
    });
}

/** Send `message` to the service worker; resolves with its reply of the same type. */
function ask(worker, message) {
  const sw = navigator.serviceWorker;
  return new Promise((resolve) => {
    const onMessage = (event) => {
      if (event.data?.type !== message.type) return;
      sw.removeEventListener("message", onMessage);
      resolve(event.data);
    };
    sw.addEventListener("message", onMessage);
    worker.postMessage(message);
  });
}
