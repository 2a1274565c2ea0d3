// The Practise page: the review queue (review.js), one exercise at a time, each
// with fresh numbers. The exercise itself is taken from its chapter page
// (exercise-card.js), graded and recorded the same way as there.

import { ATTR } from "./contract.js";
import { initExercise } from "./exercise.js";
import { showExerciseCard } from "./exercise-card.js";
import { el } from "./dom.js";
import { listPage, reviewedIds } from "./exercise-list.js";
import { dueLine } from "./progress-view.js";
import { dueIds, inQueue } from "./review.js";
import { freshVariant } from "./variants.js";

// What is new about a review, by kind (a Debug program is the same: find its bug again).
const FRESH = { derive: ", with new numbers.", build: ", with new hidden tests." };

/** The next exercise to serve: the longest overdue, else (`anyway`) the next to fall due or any. */
function pick(manifest, progress, skip, anyway) {
  const ids = reviewedIds(manifest);
  const due = dueIds(progress, ids).filter((id) => id !== skip);
  if (due.length || !anyway) return due[0] ?? null;
  const queued = ids.filter((id) => id !== skip && inQueue(progress.get(id)))
    .sort((a, b) => (progress.get(a).due ?? 0) - (progress.get(b).due ?? 0));
  const fresh = ids.filter((id) => id !== skip && !inQueue(progress.get(id)));
  return queued[0] ?? fresh[Math.floor(Math.random() * fresh.length)] ?? null;
}

export async function initPractise(shared, siteRoot) {
  const page = await listPage("data-wb-practise", siteRoot);
  if (!page) return;
  const { root, manifest } = page;
  const { progress } = shared;
  const status = el("p", { className: "wb-practise-status", role: "status" });
  const next = el("button", { type: "button", className: "md-button md-button--primary",
    textContent: "Next exercise" });
  next.dataset.wbAction = "next";
  const card = el("div", { className: "wb-practise-card" });
  root.replaceChildren(status, card, el("div", { className: "wb-practise-controls" }, next));
  let current = null;

  const say = () => {
    const { text } = dueLine(manifest, progress);
    status.textContent = current ? `${text} Now: exercise ${current}.` : text;
    const others = dueIds(progress, reviewedIds(manifest)).filter((id) => id !== current).length;
    next.textContent = others ? "Next due exercise" : "Practise another";
  };

  async function serve(id) {
    current = id;
    if (!id) {
      card.replaceChildren(el("p", { textContent: "There is nothing to practise yet." }));
      return say();
    }
    card.replaceChildren(el("p", { className: "wb-practise-loading", textContent: `Loading exercise ${id}…` }));
    try {
      const node = await showExerciseCard(card, manifest, id, siteRoot,
        { from: (n) => FRESH[n.getAttribute(ATTR.kind)] ?? "." });
      initExercise(node, { ...shared, start: freshVariant() });
    } catch (err) {
      card.replaceChildren(el("p", { textContent: `Exercise ${id} could not be loaded (${err.message}). Try the next `
        + `one, or reload when you are online.` }));
    }
    say();
  }

  next.addEventListener("click", () => serve(pick(manifest, progress, current, true)));
  progress.onChange(() => root.isConnected && say());
  await serve(pick(manifest, progress, null, false));
  if (!current) {
    card.replaceChildren(el("p", { textContent:
      "Press “Practise another” to start with an exercise of your choosing: the one due soonest, or a new one." }));
  }
}
