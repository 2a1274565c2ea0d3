// What the learner sees of the offline copy (offline.js decides; this draws):
// - the notice (role offline-notice) that announces the copy with its size
//   before it starts, with a button to decline it (offline-decline) or, on a
//   metered connection, to agree to it first (offline-store);
// - the footer line (role offline-status): what is really stored, with the
//   copy's progress (offline-progress) while it runs, and a way back in after
//   a "no";
// - the update banner, and the export reminder for browsers that delete
//   script-written storage.

import { ATTR, ROLE } from "./contract.js";
import { el } from "./dom.js";

const MB = 1_000_000;

export function formatSize(bytes) {
  const mb = bytes / MB;
  return mb >= 10 ? `${Math.round(mb)} MB` : `${mb.toFixed(1)} MB`;
}

/**
 * `el` (progress-ui.js) with a contract role.
 * @param {string} tag
 * @param {{ role?: string, className?: string, text?: string }} [options]
 */
function element(tag, { role, className = "", text = "" } = {}) {
  const node = el(tag, { className, textContent: text });
  if (role) node.setAttribute(ATTR.role, role);
  return node;
}

function button(text, role, primary, onClick) {
  const b = element("button", { role, className: primary ? "md-button md-button--primary" : "md-button", text });
  b.type = "button";
  b.addEventListener("click", onClick);
  return b;
}

function progressBar(role, done, total, label) {
  const bar = element("progress", { role });
  bar.max = total || 1;
  bar.value = Math.min(done, total || 1);
  bar.setAttribute("aria-label", label);
  return bar;
}

// ---- The notice: announced before the copy starts, and declinable ---------------------
/** How big the copy is: its download (gzip, as the host sends it) and, when larger, what it
 * takes once stored (the memory snapshot is stored inflated). */
export function sizeText({ wireBytes, totalBytes }) {
  if (!wireBytes) return formatSize(totalBytes);
  const wire = formatSize(wireBytes);
  const stored = formatSize(totalBytes);
  return stored === wire ? `a ${wire} download` : `a ${wire} download (${stored} once stored)`;
}

/**
 * `view`: {mode: "announce" | "ask", totalBytes, wireBytes}. "announce": the copy starts by
 * itself in a moment; "ask": it waits for the learner (a metered connection).
 */
export function showNotice(view, { onStore, onDecline, onOK = () => {} }) {
  hideNotice();
  const size = sizeText(view);
  const short = formatSize(view.wireBytes || view.totalBytes);
  const box = element("div", { role: ROLE.offlineNotice, className: "wb-update wb-offline-notice" });
  box.setAttribute("role", "region");
  box.setAttribute("aria-label", "Offline copy");
  const text = element("p");
  if (view.mode === "ask") {
    const why = view.metered === false ? "on a phone that may be on mobile data" : "and your connection looks metered";
    text.textContent = `Store the workbook in this browser for offline use? It is ${size}, ${why}, so it waits for `
      + `your word.`;
    box.append(text, button(`Store (${short})`, ROLE.offlineStore, true, onStore), button("Not now",
      ROLE.offlineDecline, false, onDecline));
  } else {
    text.textContent = `The workbook will store itself in this browser for offline use: ${size}, starting in a few `
      + `seconds (or at OK).`;
    const ok = () => {
      hideNotice();
      onOK();
    };
    box.append(text, button("Don't store", ROLE.offlineDecline, false, onDecline), button("OK", null, false, ok));
  }
  document.body.append(box);
}

export function hideNotice() {
  for (const el of document.querySelectorAll(`[${ATTR.role}="${ROLE.offlineNotice}"]`)) el.remove();
}

// ---- The footer line: what is really stored --------------------------------------------
// The footer is part of what instant navigation replaces: it is drawn again on every page.
let footerView = null;
let footerActions = {};

/** `view`: {state: "copying"|"complete"|"declined"|"failed"|"partial", bytes, totalBytes, wireBytes, persisted,
 * message}. */
export function setFooter(view, actions = footerActions) {
  footerView = view;
  footerActions = actions;
  drawFooter();
}

export function drawFooter() {
  const view = footerView;
  const footer = document.querySelector(".md-footer-meta__inner");
  if (!footer) return;
  footer.querySelector(`[${ATTR.role}="${ROLE.offlineStatus}"]`)?.remove();
  if (!view) return;
  const line = element("p", { role: ROLE.offlineStatus, className: "wb-offline-indicator" });
  line.dataset.wbOfflineIndicator = "";
  const total = formatSize(view.totalBytes || 0);
  if (view.state === "complete") {
    line.textContent = view.totalBytes ? `Stored for offline use · ${total}` : "Stored for offline use";
    line.title = view.persisted
      ? "Every page and the Python grader are stored in this browser, which has agreed to keep them."
      : "Every page and the Python grader are stored in this browser: the workbook works without a network.";
  } else if (view.state === "copying") {
    line.append(`Storing for offline use · ${formatSize(view.bytes || 0)} of ${total} `);
    line.append(progressBar(ROLE.offlineProgress, view.bytes || 0, view.totalBytes, "Offline copy"));
    // Declined after it started (or once the notice is gone): the copy stops after its current file.
    if (footerActions.onDecline) line.append(" ", button("Stop storing", null, false, footerActions.onDecline));
  } else {
    const why = view.state === "failed" ? `Not stored for offline use (${view.message}). ` :
      "Not stored for offline use. ";
    line.append(why);
    const download = formatSize(view.wireBytes || view.totalBytes || 0);
    if (footerActions.onStore) line.append(button(`Store it (${download})`, ROLE.offlineStore, false,
      footerActions.onStore));
  }
  footer.append(line);
}

// ---- The update banner ------------------------------------------------------------------
export function showUpdate(registration) {
  if (document.querySelector("[data-wb-update]")) return;
  const bar = element("div", { className: "wb-update" });
  bar.dataset.wbUpdate = "";
  bar.setAttribute("role", "status");
  const text = element("p",
    { text: "A new version of the workbook is ready. Reload to use it (your progress is kept)." });
  const reload = button("Reload", null, true, () => {
    reload.disabled = true;
    // The waiting worker takes over; "controllerchange" then reloads every open page.
    if (registration.waiting) registration.waiting.postMessage({ type: "activate-update" });
    else location.reload();
  });
  reload.dataset.wbAction = "update";
  bar.append(text, reload, button("Later", null, false, () => bar.remove()));
  document.body.append(bar);
}

// ---- The export reminder (browsers that delete script-written storage) ----------------
const REMIND_EVERY_MS = 7 * 86_400_000;

/** WebKit (Safari, and every browser on iOS) deletes script-written storage after 7 days without a visit. */
export function evictsStorage(userAgent = navigator.userAgent) {
  return /AppleWebKit\//.test(userAgent) && !/(Chrome|Chromium|Edg|OPR|SamsungBrowser)\//.test(userAgent);
}

export async function remindToExport(progress, siteRoot, note) {
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
  const box = element("div", { className: "admonition note wb-reminder" });
  box.dataset.wbReminder = "";
  box.setAttribute("role", "note");
  box.setAttribute("aria-label", "Keep a copy of your progress");
  const title = element("p", { className: "admonition-title", text: "Keep a copy of your progress" });
  const text = element("p", { text: "This browser may delete what the workbook stored, your progress included, after 7 "
    + "days without a visit. " });
  const link = element("a", { text: "Export your progress" });
  link.href = new URL("progress/", siteRoot).href;
  text.append(link, " to keep it in a file.");
  const dismiss = button("Dismiss", null, false, () => box.remove());
  dismiss.dataset.wbAction = "dismiss-reminder";
  box.append(title, text, dismiss);
  main.prepend(box);
}
