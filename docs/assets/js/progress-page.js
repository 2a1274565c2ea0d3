// The "Your progress" page: per chapter, how many exercises are solved and
// mastered and how many are due for review (a table: numbers in words, bars for
// the eye), and the controls that keep progress: export, import (merged, never
// replacing: progress-schema.js), reset.

import { MAX_IMPORT_BYTES, parseImport } from "./progress.js";
import { exportProgress } from "./notice.js";
import { el } from "./dom.js";
import { plural, reviewText, tally } from "./progress-view.js";
import { groupDigits } from "./number-text.js";

/** A table cell: "3 of 7" (and more words) above a bar filled to value/max. */
function countCell(value, max, text) {
  if (!max) return el("td", { className: "wb-count-none", textContent: "none here" });
  const fill = el("span", { className: "wb-mini-fill" });
  fill.style.setProperty("--wb-fill", `${Math.round((100 * value) / max)}%`);
  const mini = el("span", { className: "wb-mini" }, fill);
  mini.setAttribute("aria-hidden", "true");
  return el("td", {}, el("span", { className: "wb-count-text", textContent: text }), mini);
}

function row(header, count, tag = "td") {
  const solvedText = `${count.solved} of ${count.total}`
    + `${count.afterReveal ? ` (+${count.afterReveal} with help)` : ""}`;
  const review = el("td", { className: "wb-review-cell", textContent: count.reviewable ? reviewText(count) : "—" });
  if (count.due) review.classList.add("is-due");
  const tr = el("tr", {},
    el(tag, tag === "th" ? { scope: "row" } : {}, header),
    countCell(count.solved + count.afterReveal, count.total, solvedText),
    countCell(count.mastered, count.masterable, `${count.mastered} of ${count.masterable}`),
    review);
  if (count.done) tr.classList.add("is-done");
  return tr;
}

function table(manifest, progress, siteRoot) {
  const rows = manifest.chapters.map((c) => {
    const count = tally(manifest, progress, c.ids);
    const link = el("a", { href: new URL(c.url, siteRoot).href, textContent: c.title });
    const name = count.done ? [link, el("span", { className: "wb-finished", textContent: " ✓ finished" })] : [link];
    return row(el("span", {}, ...name), count, "th");
  });
  const total = tally(manifest, progress, manifest.chapters.flatMap((c) => c.ids));
  const t = el("table", { className: "wb-progress-table" },
    el("caption", { textContent: "Your progress, chapter by chapter" }),
    el("thead", {}, el("tr", {},
      ...["Chapter", "Solved", "Mastered", "Review"].map((text) => el("th", { scope: "col", textContent: text })))),
    el("tbody", {}, ...rows),
    el("tfoot", {}, row(el("span", { textContent: "All chapters" }), total, "th")));
  t.dataset.wbProgressTable = "";
  return t;
}

const list = (ids) => (ids.length <= 12 ? ` (${ids.join(", ")})` : "");

function describeMerge({ added, merged, unchanged }) {
  const total = added.length + merged.length + unchanged.length;
  if (!total) return "The file holds no exercises; nothing changed.";
  const parts = [];
  if (added.length) parts.push(`${added.length} added${list(added)}`);
  if (merged.length) parts.push(`${merged.length} combined with what this browser had${list(merged)}`);
  if (unchanged.length) parts.push(`${unchanged.length} already up to date${list(unchanged)}`);
  return `Imported a file with ${plural(total, "exercise")}: ${parts.join("; ")}. Nothing was lost: answers, solved `
    + `marks and review boxes from both are kept.`;
}

// ---- The controls: export, import, reset -------------------------------------------
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
    const { name, count } = exportProgress(progress);
    say(`Exported ${plural(count, "exercise record")} to ${name}.`, "ok");
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
      ? { ok: false,
        reason: `The file is too large (${groupDigits(chosen.size)} bytes); a progress file is much smaller.` }
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
    el("p", { textContent: "Every answer, solved mark and piece of Build code saved in this browser for this workbook "
    + "will be erased. Export first if you may want it back." }),
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
  const wrap = el("div", { className: "wb-progress-table-wrap" });
  wrap.dataset.wbProgressTableWrap = "";
  panel.replaceChildren(wrap,
    el("div", { className: "wb-progress-actions" }, exportButton, importButton, resetButton, file),
    message, dialog);
  panel.dataset.wbBuilt = "true";
}

/** Build (once) and refresh the panel of every [data-wb-progress-panel] on the page. */
export function progressPanel(manifest, progress, siteRoot) {
  for (const panel of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll("[data-wb-progress-panel]"))) {
    if (!panel.dataset.wbBuilt) buildPanel(panel, manifest, progress);
    panel.querySelector("[data-wb-progress-table-wrap]").replaceChildren(table(manifest, progress, siteRoot));
  }
}
