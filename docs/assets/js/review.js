// What an attempt means for progress, and when an exercise comes back for
// review. Pure functions of a progress record (progress.js), so the chapter
// pages, the Practise page and the tests share one rule.
//
// Per exercise the record keeps, by variant number (0 = the workbook's own
// numbers): `done` (answered correctly), `clean` (answered correctly without
// revealing that variant's derivation first), `missed` (the first answer was
// wrong, or the derivation was opened before any answer), `revealedIn` and
// `carried` (an answer right only given the learner's own wrong earlier value,
// from an earlier exercise or an earlier step), `stepped` (worked with checked
// steps) and `steppedDone` (answered correctly after working with steps, the
// derivation not revealed: solved, but not clean). A bug hunt (Debug) whose
// first line picked in a variant was wrong is not clean either when solved: each
// wrong line says so, and trying the lines one by one finds any bug.
// Solved: one clean variant, or one solved with steps. Mastered: MASTERED
// different clean variants (steps do not count towards it).
//
// Review (Leitner boxes 1-5): only the first answer to each variant moves an
// exercise. A clean first answer moves it one box up (a first one ever lands
// in box 2); a miss puts it back in box 1; a first answer solved with steps
// keeps the exercise in its box (box 1 if it had none). An exercise is due INTERVAL_MS[box]
// after its last move: box 1 after 10 minutes, then 1, 3, 8 and 21 days.

import { TAG } from "./contract.js";

export const MASTERED = 3;
const MINUTE = 60_000;
// Tags of an answer that points back to the learner's own wrong earlier value (carried, or left undefined by it).
const BACK_TO_EARLIER = [TAG.carried, TAG.undefined];
const DAY = 86_400_000;
export const INTERVAL_MS = [0, 10 * MINUTE, DAY, 3 * DAY, 8 * DAY, 21 * DAY];
export const TOP_BOX = INTERVAL_MS.length - 1;
export const KEEP = 100; // the most variants a list remembers

const has = (list, v) => Array.isArray(list) && list.includes(v);
const add = (list, v) => (has(list, v) ? list : [...(list || []), v].slice(-KEEP));

const move = (box, now) => ({ box, due: now + INTERVAL_MS[box], reviewed: now });

const first = (record, v) => !has(record.done, v) && !has(record.missed, v);

/**
 * The progress patch for a graded answer ("correct" or "incorrect") to variant `v`.
 * An answer carried forward (tag "carried": right given the learner's own wrong
 * value from an earlier exercise) is neither a solve nor a miss: it is kept in
 * `carried` and moves nothing in the review queue. `guessable` (a Debug exercise):
 * a correct answer after a wrong one in the variant is done, not clean.
 */
export function afterGrade(record, v, status, { schedule = true, now = Date.now(), tag = "", guessable = false } = {}) {
  if (status === "incorrect" && BACK_TO_EARLIER.includes(tag)) return { carried: add(record.carried, v) };
  const patch = {};
  if (status === "correct") {
    const helped = has(record.stepped, v) && !has(record.revealedIn, v);
    const box = Math.max(1, record.box || 1);
    if (schedule && first(record, v)) Object.assign(patch, move(helped ? box : Math.min(TOP_BOX, box + 1), now));
    patch.done = add(record.done, v);
    if (helped) patch.steppedDone = add(record.steppedDone, v);
    else if (!has(record.revealedIn, v) && !(guessable && has(record.missed, v))) patch.clean = add(record.clean, v);
  } else if (status === "incorrect" && first(record, v)) {
    patch.missed = add(record.missed, v);
    if (schedule) Object.assign(patch, move(1, now));
  }
  return patch;
}

/**
 * The progress patch for a checked step of variant `v` graded `status`: the variant was worked
 * with steps; a step carried from the learner's own wrong value is also kept in `carried`.
 * Neither a solve nor a miss, and the review queue does not move.
 */
export function afterStep(record, v, status, tag = "") {
  if (status !== "correct" && status !== "incorrect") return {};
  const carried = BACK_TO_EARLIER.includes(tag) ? { carried: add(record.carried, v) } : {};
  return { stepped: add(record.stepped, v), ...carried };
}

/** The progress patch for opening variant `v`'s derivation. */
export function afterReveal(record, v, { schedule = true, now = Date.now() } = {}) {
  const patch = { revealed: true, revealedIn: add(record.revealedIn, v) };
  if (first(record, v)) {
    patch.missed = add(record.missed, v);
    if (schedule) Object.assign(patch, move(1, now));
  }
  return patch;
}

export const isSolved = (r) => (r.clean?.length ?? 0) > 0 || (r.steppedDone?.length ?? 0) > 0;
export const isSolvedAfterReveal = (r) => !isSolved(r) && (r.done?.length ?? 0) > 0;
export const isMastered = (r) => (r.clean?.length ?? 0) >= MASTERED;
export const inQueue = (r) => Number.isInteger(r.box) && r.box >= 1;
export const isDue = (r, now = Date.now()) => inQueue(r) && (r.due ?? 0) <= now;

/** The ids of `ids` that are due, the longest overdue first. */
export function dueIds(progress, ids, now = Date.now()) {
  return ids.filter((id) => isDue(progress.get(id), now))
    .sort((a, b) => (progress.get(a).due ?? 0) - (progress.get(b).due ?? 0));
}

/** When the next of `ids` falls due (ms), or null if none is in the queue. */
export function nextDue(progress, ids) {
  const times = ids.map((id) => progress.get(id)).filter(inQueue).map((r) => r.due ?? 0);
  return times.length ? Math.min(...times) : null;
}

/** Version-1 records (one solved mark, no variants) in version 2's terms. */
export function migrateRecord(r, now = Date.now()) {
  const out = { ...r, variant: 0 };
  if (r.solved) out.done = [0];
  if (r.solved && !r.solvedAfterReveal) out.clean = [0];
  if (r.revealed) out.revealedIn = [0];
  const cleanFirstTry = r.solved && !r.solvedAfterReveal && (r.attempts ?? 1) <= 1;
  if (!cleanFirstTry && ((r.attempts ?? 0) > 0 || r.revealed)) out.missed = [0];
  if (r.solved || (r.attempts ?? 0) > 0) {
    const box = cleanFirstTry ? 2 : 1;
    Object.assign(out, { box, due: Math.min(now, r.updated ?? now) + INTERVAL_MS[box] });
  }
  return out;
}
