// Progress at a glance (chapter pages, the home page, a ✓ in the navigation) and
// the "Your progress" page's controls: export, import, reset.
//
// Which exercises each chapter holds comes from assets/exercises.json, written
// at build time by docs/hooks/exercises.py. initProgressPage() runs on every page
// (the first and each instant navigation) and is idempotent.

import { MAX_IMPORT_BYTES, parseImport } from "./progress.js";
import { MASTERED, dueIds, isMastered, isSolved, isSolvedAfterReveal, nextDue } from "./review.js";

let manifestPromise = null;
let listening = false;
let current = { progress: null, siteRoot: null };

export function loadManifest(siteRoot) {
  manifestPromise ??= fetch(new URL("assets/exercises.json", siteRoot))
    .then((r) => (r.ok ? r.json() : null))
    .catch(() => null)
    .then((m) => {
      if (!m || !Array.isArray(m.chapters)) manifestPromise = null; // try again on the next page
      return m && Array.isArray(m.chapters) ? m : null;
    });
  return manifestPromise;
}

// Solved: one variant answered before its derivation was opened. Mastered (the
// exercises that draw variants): MASTERED different variants solved so.
let variantIds = new Set();

function tally(progress, ids) {
  let solved = 0;
  let afterReveal = 0;
  let mastered = 0;
  let masterable = 0;
  for (const id of ids) {
    const r = progress.get(id);
    if (isSolved(r)) solved++;
    else if (isSolvedAfterReveal(r)) afterReveal++;
    if (variantIds.has(id)) {
      masterable++;
      if (isMastered(r)) mastered++;
    }
  }
  return { solved, afterReveal, mastered, masterable, total: ids.length, done: ids.length > 0 && solved + afterReveal === ids.length };
}

function phrase({ solved, afterReveal, total, mastered, masterable }, noun = "exercises") {
  const extra = afterReveal ? ` (and ${afterReveal} more after revealing the solution)` : "";
  const master = masterable ? `; ${mastered} of ${masterable} mastered` : "";
  return `${solved} of ${total} ${noun} solved${extra}${master}`;
}

/** A new element with `props` and `children`. */
export function el(tag, props = {}, ...children) {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}

const pathOf = (href) => {
  const url = new URL(href, location.href);
  return url.hash && url.pathname === location.pathname ? null : url.pathname;
};

// ---- At a glance ------------------------------------------------------------
function markNavigation(manifest, progress, siteRoot) {
  const done = new Map(manifest.chapters.map((c) => [new URL(c.url, siteRoot).pathname, tally(progress, c.ids).done]));
  for (const link of document.querySelectorAll(".md-nav--primary a.md-nav__link")) {
    const url = new URL(link.href);
    const finished = !url.hash && done.get(url.pathname);
    const mark = link.querySelector(".wb-nav-done");
    if (finished && !mark) {
      link.append(el("span", { className: "wb-nav-done", title: "All exercises solved" },
        el("span", { ariaHidden: "true", textContent: "✓" }), el("span", { className: "wb-sr-only", textContent: " (finished)" })));
    } else if (!finished && mark) mark.remove();
  }
}

function meter(count, label) {
  const solved = el("progress", { max: count.total, value: count.solved + count.afterReveal, ariaLabel: `${label}: solved` });
  if (!count.masterable) return solved;
  const mastered = el("progress", { className: "wb-mastered", max: count.masterable, value: count.mastered,
    ariaLabel: `${label}: mastered (${MASTERED} different variants solved)` });
  return el("span", { className: "wb-meters" }, solved, mastered);
}

function chapterSummary(manifest, progress, siteRoot) {
  const chapter = manifest.chapters.find((c) => new URL(c.url, siteRoot).pathname === location.pathname);
  const article = document.querySelector(".md-content__inner");
  if (!chapter || !article) return;
  const count = tally(progress, chapter.ids);
  let box = article.querySelector(".wb-chapter-progress");
  if (!box) {
    box = el("p", { className: "wb-chapter-progress" });
    const h1 = article.querySelector("h1");
    if (h1) h1.after(box);
    else article.prepend(box);
  }
  box.classList.toggle("is-done", count.done);
  box.replaceChildren(meter(count, "Progress in this chapter"),
    el("span", { textContent: `${count.done ? "✓ Chapter finished: " : "This chapter: "}${phrase(count)}.` }));
}

function overallSummary(manifest, progress, siteRoot) {
  const slots = document.querySelectorAll("[data-wb-overall-progress]");
  if (!slots.length) return;
  const all = tally(progress, manifest.chapters.flatMap((c) => c.ids));
  const finished = manifest.chapters.filter((c) => tally(progress, c.ids).done).length;
  for (const slot of slots) {
    slot.classList.add("wb-overall-progress");
    slot.replaceChildren(meter(all, "Progress in the whole workbook"),
      el("span", { textContent: `So far: ${phrase(all)}; ${finished} of ${manifest.chapters.length} chapters finished.` }));
  }
  // Badges next to the chapter links of the page's own list (the home page).
  const byPath = new Map(manifest.chapters.map((c) => [new URL(c.url, siteRoot).pathname, c]));
  for (const link of document.querySelectorAll(".md-content__inner li > a[href]")) {
    const chapter = byPath.get(pathOf(link.href));
    if (!chapter) continue;
    const count = tally(progress, chapter.ids);
    let badge = link.nextElementSibling?.classList.contains("wb-badge") ? link.nextElementSibling : null;
    if (!badge) {
      badge = el("span", { className: "wb-badge" });
      link.after(badge);
    }
    badge.classList.toggle("is-done", count.done);
    badge.textContent = `${count.done ? "✓ " : ""}${count.solved + count.afterReveal}/${count.total}`;
    badge.title = phrase(count);
  }
}

// ---- The "Your progress" page -------------------------------------------------
function table(manifest, progress, siteRoot) {
  const rows = manifest.chapters.map((c) => {
    const count = tally(progress, c.ids);
    return el("tr", {},
      el("td", {}, el("a", { href: new URL(c.url, siteRoot).href, textContent: c.title })),
      el("td", { textContent: `${count.solved} / ${count.total}` }),
      el("td", { textContent: String(count.afterReveal) }),
      el("td", { textContent: `${count.mastered} / ${count.masterable}` }),
      el("td", { textContent: count.done ? "✓ finished" : "" }));
  });
  return el("table", { className: "wb-progress-table" },
    el("caption", { className: "wb-sr-only", textContent: "Exercises solved per chapter" }),
    el("thead", {}, el("tr", {}, ...["Chapter", "Solved", "After reveal", "Mastered", "Status"].map((t) => el("th", { scope: "col", textContent: t })))),
    el("tbody", {}, ...rows));
}

function download(name, text) {
  const url = URL.createObjectURL(new Blob([text], { type: "application/json" }));
  const a = el("a", { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

const list = (ids) => (ids.length <= 12 ? ` (${ids.join(", ")})` : "");

function describeMerge({ added, replaced, kept }) {
  const total = added.length + replaced.length + kept.length;
  if (!total) return "The file holds no exercises; nothing changed.";
  const parts = [];
  if (added.length) parts.push(`${added.length} added${list(added)}`);
  if (replaced.length) parts.push(`${replaced.length} replaced by the file's newer record${list(replaced)}`);
  if (kept.length) parts.push(`${kept.length} kept as they were, yours being as new or newer${list(kept)}`);
  return `Imported a file with ${total} exercise${total === 1 ? "" : "s"}: ${parts.join("; ")}.`;
}

// ---- The progress page's panel: export, import, reset ----------------------------
function statusLine() {
  const message = el("div", { className: "wb-progress-message", role: "status" });
  message.setAttribute("aria-live", "polite");
  message.dataset.wbProgressMessage = "";
  const say = (text, kind = "info") => {
    message.dataset.kind = kind;
    message.replaceChildren(el("p", { textContent: text }));
  };
  return { message, say };
}

function actionButton(text, action) {
  const b = el("button", { type: "button", className: "md-button", textContent: text });
  b.dataset.wbAction = action;
  return b;
}

function exportAction(progress, say) {
  const button = actionButton("Export progress", "export");
  button.addEventListener("click", () => {
    const data = progress.exportData();
    const name = `robotics-math-workbook-progress-${data.exported.slice(0, 10)}.json`;
    download(name, JSON.stringify(data, null, 1));
    const n = Object.keys(data.exercises).length;
    say(`Exported ${n} exercise record${n === 1 ? "" : "s"} to ${name}.`, "ok");
  });
  return [button];
}

function importAction(progress, say, knownIds) {
  const button = actionButton("Import progress…", "import");
  const file = el("input", { type: "file", accept: "application/json,.json", hidden: true });
  file.dataset.wbAction = "import-file";
  file.setAttribute("aria-label", "Progress file to import");
  button.addEventListener("click", () => file.click());
  file.addEventListener("change", async () => {
    const chosen = file.files?.[0];
    file.value = "";
    if (!chosen) return;
    const result = chosen.size > MAX_IMPORT_BYTES
      ? { ok: false, reason: `The file is too large (${chosen.size.toLocaleString("en")} bytes); a progress file is much smaller.` }
      : parseImport(await chosen.text().catch(() => null), knownIds);
    if (!result.ok) say(`Import refused: ${result.reason} Nothing was changed.`, "error");
    else say(describeMerge(progress.merge(result.exercises)), "ok");
  });
  return [button, file];
}

function resetAction(progress, say) {
  const button = actionButton("Reset all progress…", "reset");
  const dialog = el("dialog", { className: "wb-confirm" });
  dialog.setAttribute("aria-labelledby", "wb-confirm-title");
  const form = el("form", { method: "dialog" },
    el("p", { id: "wb-confirm-title", className: "wb-confirm-title", textContent: "Erase all progress?" }),
    el("p", { textContent: "Every answer, solved mark and piece of Build code saved in this browser for this workbook will be erased. Export first if you may want it back." }),
    el("div", { className: "wb-confirm-buttons" },
      el("button", { value: "cancel", className: "md-button", textContent: "Cancel", autofocus: true }),
      el("button", { value: "reset", className: "md-button md-button--primary", textContent: "Erase everything" })));
  form.querySelector('[value="reset"]').dataset.wbAction = "confirm-reset";
  dialog.append(form);
  button.addEventListener("click", () => dialog.showModal());
  dialog.addEventListener("close", () => {
    if (dialog.returnValue === "reset") {
      progress.reset();
      say("All progress was erased.", "ok");
    }
    dialog.returnValue = "";
    button.focus();
  });
  return [button, dialog];
}

function buildPanel(panel, manifest, progress) {
  const knownIds = new Set(manifest.chapters.flatMap((c) => c.ids));
  const { message, say } = statusLine();
  const [exportButton] = exportAction(progress, say);
  const [importButton, file] = importAction(progress, say, knownIds);
  const [resetButton, dialog] = resetAction(progress, say);
  panel.replaceChildren(
    el("div", { className: "wb-progress-table-wrap" }),
    el("div", { className: "wb-progress-actions" }, exportButton, importButton, resetButton, file),
    message, dialog);
  panel.dataset.wbBuilt = "true";
}

function progressPanel(manifest, progress, siteRoot) {
  for (const panel of document.querySelectorAll("[data-wb-progress-panel]")) {
    if (!panel.dataset.wbBuilt) buildPanel(panel, manifest, progress);
    panel.querySelector(".wb-progress-table-wrap").replaceChildren(table(manifest, progress, siteRoot));
  }
}

// ---- Review: how many exercises are due (the home page, the Practise link) ------
function when(ms) {
  const minutes = Math.round((ms - Date.now()) / 60_000);
  if (minutes < 60) return `in ${Math.max(1, minutes)} minute${minutes === 1 ? "" : "s"}`;
  const hours = Math.round(minutes / 60);
  if (hours < 36) return `in ${hours} hour${hours === 1 ? "" : "s"}`;
  const days = Math.round(hours / 24);
  return `in ${days} days`;
}

export function dueLine(manifest, progress) {
  const ids = manifest.variants || [];
  const due = dueIds(progress, ids).length;
  const next = nextDue(progress, ids);
  if (due) return { due, text: `${due} exercise${due === 1 ? " is" : "s are"} due for review.` };
  if (next !== null) return { due, text: `Nothing is due for review; the next exercise comes back ${when(next)}.` };
  return { due, text: "Your review queue is empty: exercises join it when you answer them in the chapters." };
}

function dueSummary(manifest, progress, siteRoot) {
  for (const slot of document.querySelectorAll("[data-wb-due]")) {
    const { due, text } = dueLine(manifest, progress);
    slot.classList.add("wb-due");
    slot.classList.toggle("is-due", due > 0);
    slot.replaceChildren(el("span", { textContent: `${text} ` }),
      el("a", { href: new URL("practise/", siteRoot).href, textContent: due ? "Practise now" : "Open the Practise page" }));
  }
}

async function refresh() {
  const { progress, siteRoot } = current;
  const manifest = await loadManifest(siteRoot);
  if (!manifest) return;
  variantIds = new Set(manifest.variants || []);
  dueSummary(manifest, progress, siteRoot);
  markNavigation(manifest, progress, siteRoot);
  chapterSummary(manifest, progress, siteRoot);
  overallSummary(manifest, progress, siteRoot);
  progressPanel(manifest, progress, siteRoot);
}

let scheduled = false;
function scheduleRefresh() {
  if (scheduled) return;
  scheduled = true;
  queueMicrotask(() => {
    scheduled = false;
    refresh();
  });
}

/** Call on every page (first load and each instant navigation). */
export function initProgressPage(progress, siteRoot) {
  current = { progress, siteRoot };
  if (!listening) {
    listening = true;
    progress.onChange(scheduleRefresh);
  }
  return refresh();
}
