// The exercise list (assets/exercises.json, the manifest of chapters) and the pages built from it:
// Practise, the teacher's, assignment and class pages.

import { el } from "./dom.js";

let manifestPromise = null;

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

/**
 * A page built from the exercise list (Practise, the teacher's, assignment and class pages):
 * its root element (`[attr]`, once per page) and the list; null when the page has no such
 * element, or when the list cannot be loaded (then the page says so).
 */
export async function listPage(attr, siteRoot) {
  const root = /** @type {HTMLElement | null} */ (document.querySelector(`[${attr}]`));
  if (!root || root.dataset.wbBuilt) return null;
  root.dataset.wbBuilt = "true";
  const manifest = await loadManifest(siteRoot);
  if (manifest) return { root, manifest };
  const text = "The list of exercises could not be loaded. Reload the page to try again.";
  root.replaceChildren(el("p", { textContent: text }));
  return null;
}

/** The exercises that join the review queue (Derive, Build and Debug; an older manifest: the Derive ones). */
export const reviewedIds = (manifest) => manifest.reviewed || manifest.variants || [];
