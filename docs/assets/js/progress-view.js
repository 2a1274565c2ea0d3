// What the progress displays share: the counts of a set of exercises (solved, mastered, due), and
// labelled bars that say what they count. Used by progress-ui.js (at a glance), progress-page.js
// (the "Your progress" page) and practise.js. The exercise list is exercise-list.js's; `el` is dom.js's.

import { el } from "./dom.js";
import { reviewedIds } from "./exercise-list.js";
import { MASTERED, dueIds, isMastered, isSolved, isSolvedAfterReveal, nextDue } from "./review.js";

/**
 * The counts of `ids`. Solved: one variant answered before its derivation was
 * opened (a Build exercise: its tests passed). Mastered: MASTERED different
 * variants solved so, which only the exercises that draw variants
 * (`manifest.variants`: the Derive ones) can be. Due: of those in the review
 * queue (`manifest.reviewed`), the ones whose time has come.
 */
export function tally(manifest, progress, ids) {
  const drawing = new Set(manifest.variants || []);
  const reviewed = new Set(reviewedIds(manifest));
  const count = { solved: 0, afterReveal: 0, mastered: 0, masterable: 0, total: ids.length };
  for (const id of ids) {
    const r = progress.get(id);
    if (isSolved(r)) count.solved++;
    else if (isSolvedAfterReveal(r)) count.afterReveal++;
    if (drawing.has(id)) {
      count.masterable++;
      if (isMastered(r)) count.mastered++;
    }
  }
  const queued = ids.filter((id) => reviewed.has(id));
  count.reviewable = queued.length;
  count.due = dueIds(progress, queued).length;
  count.nextDue = nextDue(progress, queued);
  count.done = ids.length > 0 && count.solved + count.afterReveal === ids.length;
  return count;
}

export const plural = (n, one, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;

/** "in 3 days": how far away a time (ms) is. */
export function when(ms) {
  const minutes = Math.round((ms - Date.now()) / 60_000);
  if (minutes < 60) return `in ${plural(Math.max(1, minutes), "minute")}`;
  const hours = Math.round(minutes / 60);
  if (hours < 36) return `in ${plural(hours, "hour")}`;
  return `in ${Math.round(hours / 24)} days`;
}

let bars = 0;
/** One labelled bar: "Solved [=====    ] 12 of 72 exercises". The visible words are its name and value. */
export function bar(label, value, max, text, kind) {
  const id = `wb-bar-${++bars}`;
  const meter = el("progress", { max: Math.max(1, max), value });
  meter.setAttribute("aria-labelledby", `${id}-label`);
  meter.setAttribute("aria-describedby", `${id}-count`);
  const row = el("span", { className: "wb-bar" },
    el("span", { className: "wb-bar-label", id: `${id}-label`, textContent: label }), meter,
    el("span", { className: "wb-bar-count", id: `${id}-count`, textContent: text }));
  row.dataset.wbBar = kind;
  return row;
}

/** The bars for a count: solved, and (where any can be) mastered. */
export function countBars(count) {
  const extra = count.afterReveal ? ` (+${count.afterReveal} with help)` : "";
  const out = [bar("Solved", count.solved + count.afterReveal,
    count.total, `${count.solved} of ${plural(count.total, "exercise")}${extra}`, "solved")];
  if (count.masterable) {
    out.push(bar("Mastered", count.mastered,
      count.masterable, `${count.mastered} of ${count.masterable} that draw new numbers`, "mastered"));
  }
  return out;
}

export const MASTERY_RULE = "Solved: answered correctly before opening the solution (a Build exercise: all its tests "
  + `pass; a Debug exercise: the buggy line found). Mastered: solved that way with ${MASTERED} different sets of `
  + "numbers, which only the exercises that draw new numbers (the Derive ones) can offer, so they alone count towards "
  + "it. Review: Derive, Build and Debug exercises come back when they are due, Derive ones with new numbers and Build "
  + "ones with new hidden tests.";

export function reviewText(count) {
  if (count.due) return `${plural(count.due, "exercise")} due for review`;
  if (count.nextDue !== null) return `next review ${when(count.nextDue)}`;
  return "nothing queued yet";
}

/** The review queue in a sentence (the home page, the Practise page). */
export function dueLine(manifest, progress) {
  const ids = reviewedIds(manifest);
  const due = dueIds(progress, ids).length;
  const next = nextDue(progress, ids);
  if (due) return { due, text: `${due} exercise${due === 1 ? " is" : "s are"} due for review.` };
  if (next !== null) return { due, text: `Nothing is due for review; the next exercise comes back ${when(next)}.` };
  return { due, text: "Your review queue is empty: exercises join it when you answer them in the chapters." };
}

