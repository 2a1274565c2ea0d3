// Progress at a glance: labelled bars on every chapter page and on the home page
// (solved, mastered, due for review), a count beside each chapter of the home
// page's list, and a ✓ in the navigation for a finished chapter. The "Your
// progress" page's table and controls are progress-page.js.
//
// Which exercises each chapter holds comes from assets/exercises.json, written
// at build time by docs/hooks/exercises.py. initProgressPage() runs on every page
// (the first and each instant navigation) and is idempotent.

import { progressPanel } from "./progress-page.js";
import { el } from "./dom.js";
import { loadManifest } from "./exercise-list.js";
import { MASTERY_RULE, countBars, dueLine, plural, reviewText, tally } from "./progress-view.js";

let listening = false;
let current = { progress: null, siteRoot: null };

const pathOf = (href) => {
  const url = new URL(href, location.href);
  return url.hash && url.pathname === location.pathname ? null : url.pathname;
};

// ---- At a glance ------------------------------------------------------------
function markNavigation(manifest, progress, siteRoot) {
  const done = new Map(manifest.chapters.map((c) => [new URL(c.url, siteRoot).pathname,
    tally(manifest, progress, c.ids).done]));
  const links = /** @type {NodeListOf<HTMLAnchorElement>} */ (document.querySelectorAll(
    ".md-nav--primary a.md-nav__link"));
  for (const link of links) {
    const url = new URL(link.href);
    const finished = !url.hash && done.get(url.pathname);
    const mark = link.querySelector(".wb-nav-done");
    if (finished && !mark) {
      link.append(el("span", { className: "wb-nav-done", title: "All exercises solved" },
        el("span", { ariaHidden: "true", textContent: "✓" }), el("span", { className: "wb-sr-only",
        textContent: " (finished)" })));
    } else if (!finished && mark) mark.remove();
  }
}

function chapterSummary(manifest, progress, siteRoot) {
  const chapter = manifest.chapters.find((c) => new URL(c.url, siteRoot).pathname === location.pathname);
  const article = document.querySelector(".md-content__inner");
  if (!chapter || !article) return;
  const count = tally(manifest, progress, chapter.ids);
  let box = /** @type {HTMLElement | null} */ (article.querySelector("[data-wb-chapter-progress]"));
  if (!box) {
    box = el("div", { className: "wb-chapter-progress" });
    box.dataset.wbChapterProgress = "";
    box.setAttribute("aria-label", "Your progress in this chapter");
    box.setAttribute("role", "group");
    const h1 = article.querySelector("h1");
    if (h1) h1.after(box);
    else article.prepend(box);
  }
  box.classList.toggle("is-done", count.done);
  const review = count.reviewable ? [el("span", { className: "wb-bar-note",
    textContent: `Review: ${reviewText(count)}.` })] : [];
  const finished = count.done ? [el("span", { className: "wb-bar-note wb-finished",
    textContent: "✓ Chapter finished." })] : [];
  box.replaceChildren(...countBars(count), ...review, ...finished);
}

function overallSummary(manifest, progress, siteRoot) {
  const slots = document.querySelectorAll("[data-wb-overall-progress]");
  if (!slots.length) return;
  const all = tally(manifest, progress, manifest.chapters.flatMap((c) => c.ids));
  const finished = manifest.chapters.filter((c) => tally(manifest, progress, c.ids).done).length;
  for (const slot of slots) {
    slot.classList.add("wb-overall-progress");
    slot.setAttribute("role", "group");
    slot.setAttribute("aria-label", "Your progress in the whole workbook");
    slot.replaceChildren(...countBars(all),
      el("span", { className: "wb-bar-note",
      textContent: `${finished} of ${plural(manifest.chapters.length, "chapter")} finished.` }),
      el("span", { className: "wb-bar-note wb-bar-rule", textContent: MASTERY_RULE }));
  }
  // The count beside each chapter of the page's own list (the home page).
  const byPath = new Map(manifest.chapters.map((c) => [new URL(c.url, siteRoot).pathname, c]));
  const listed = /** @type {NodeListOf<HTMLAnchorElement>} */ (document.querySelectorAll(
    ".md-content__inner li > a[href]"));
  for (const link of listed) {
    const chapter = byPath.get(pathOf(link.href));
    if (!chapter) continue;
    const count = tally(manifest, progress, chapter.ids);
    let badge = /** @type {HTMLElement | null} */ (link.parentElement.querySelector("[data-wb-badge]"));
    if (!badge) {
      badge = el("span", { className: "wb-badge" });
      badge.dataset.wbBadge = "";
      link.after(badge);
    }
    badge.classList.toggle("is-done", count.done);
    badge.textContent = `${count.done ? "✓ " : ""}${count.solved + count.afterReveal} of ${count.total} solved`;
  }
}

// ---- Review: how many exercises are due (the home page, the Practise link) ------
function dueSummary(manifest, progress, siteRoot) {
  for (const slot of document.querySelectorAll("[data-wb-due]")) {
    const { due, text } = dueLine(manifest, progress);
    slot.classList.add("wb-due");
    slot.classList.toggle("is-due", due > 0);
    slot.replaceChildren(el("span", { textContent: `${text} ` }),
      el("a", { href: new URL("practise/", siteRoot).href,
      textContent: due ? "Practise now" : "Open the Practise page" }));
  }
}

async function refresh() {
  const { progress, siteRoot } = current;
  const manifest = await loadManifest(siteRoot);
  if (!manifest) return;
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
