// An exercise shown off its chapter page: the Practise card (practise.js) and the
// assignment page (assignment-page.js). The exercise is taken from its chapter page (the
// service worker has it offline), so it is the very element the chapter shows, graded and
// recorded the same way; its formulas arrive as TeX and are typeset as the chapter's are.

import { ATTR } from "./contract.js";
import { renderMath } from "./math.js";
import { el } from "./dom.js";

const pages = new Map(); // chapter address -> Promise<Document>

function chapterPage(href) {
  if (!pages.has(href)) {
    const loading = fetch(href)
      .then((r) => (r.ok ? r.text() : Promise.reject(new Error(`the page answered ${r.status}`))))
      .then((text) => new DOMParser().parseFromString(text, "text/html"));
    loading.catch(() => pages.delete(href));
    pages.set(href, loading);
  }
  return pages.get(href);
}

/**
 * Exercise `id` from its chapter page, shown in `slot` under a heading and a line that links
 * back to the chapter ("From <chapter>" then `from`), with `after` below it. Resolves to the
 * exercise element, not yet started (the caller starts it with initExercise); rejects with an
 * Error whose message says why it could not be loaded.
 * @param {HTMLElement} slot
 * @param {any} manifest
 * @param {string} id
 * @param {string} siteRoot
 * @param {{ from?: string | ((node: HTMLElement) => string), after?: Node[] }} [options]
 */
export async function showExerciseCard(slot, manifest, id, siteRoot, { from = ".", after = [] } = {}) {
  const chapter = manifest.chapters.find((c) => c.ids.includes(id));
  if (!chapter) throw new Error(`exercise ${id} is in no chapter`);
  const href = new URL(chapter.url, siteRoot).href;
  const doc = await chapterPage(href);
  const found = doc.querySelector(`[${ATTR.exercise}="${CSS.escape(id)}"]`);
  if (!found) throw new Error(`exercise ${id} is not on its chapter page`);
  const node = document.importNode(found, true);
  const heading = el("h2", { id: `${node.id}-title` },
    el("span", { id: `${node.id}-name`, textContent: `${id} · ${manifest.titles?.[id] ?? ""}` }));
  const line = el("p", { className: "wb-practise-from" },
    "From ", el("a", { href: `${href}#${node.id}-title`, textContent: chapter.title }),
    typeof from === "function" ? from(node) : from);
  slot.replaceChildren(heading, line, node, ...after);
  renderMath(node);
  return node;
}
