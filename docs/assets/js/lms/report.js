// What a chapter SCO reports to the LMS, as [element, value] pairs for SCORM 1.2 or
// 2004 (versions.js says how each version names them): pure functions of the progress
// records, so the same rule serves every commit and the tests.
//
// - Score: raw = the share of the chapter's exercises solved, on 0-100 (min 0, max 100),
//   as an LMS compares it with a mastery score and grades out of 100; 2004's scaled is the
//   same share on 0-1. Mastery (three different clean variants) does not add to the
//   score: each exercise's objective carries it, raw = its clean variants up to 3, max 3.
// - Completed when every exercise of the chapter is solved. Without a mastery score from
//   the LMS, passed then too (never failed: the learner can always go on). With one
//   (1.2 cmi.student_data.mastery_score, 0-100; 2004 cmi.scaled_passing_score, 0-1),
//   as the standards say: passed when the share solved is at or above it, failed below.
// - One objective and one interaction per exercise, in the chapter's order: the
//   index of exercise i is i in both lists (SCORM lists are filled in order).

import { MASTERED, isSolved } from "../review.js";
import { VERSIONS } from "./versions.js";

export { duration2004, timespan12 } from "./versions.js";

export const objectiveId = (id) => `exercise-${id}`;

/** The learner's last answer as text: a formula or number as typed, a grid row by row, steps in order, Build code. */
export function answerText(record) {
  const last = record.last ?? record.code;
  if (last === undefined || last === null) return "";
  if (Array.isArray(last)) {
    return Array.isArray(last[0]) ? `[${last.map((row) => row.join(", ")).join("; ")}]` : last.join(" → ");
  }
  return String(last);
}

/**
 * The chapter's totals: {solved, total, share, complete, passed, failed}; `threshold` (the LMS's
 * mastery score) in [0, 1], or null when the LMS sets none. `share` is on 0-1, to 4 places.
 */
export function standing(records, ids, threshold = null) {
  const solved = ids.filter((id) => isSolved(records[id] || {})).length;
  const total = ids.length;
  const share = total ? Number((solved / total).toFixed(4)) : 0;
  const complete = total > 0 && solved === total;
  const mastered = threshold !== null && total > 0 && solved / total >= threshold;
  const passed = threshold === null ? complete : mastered;
  return { solved, total, share, complete, passed, failed: threshold !== null && !mastered };
}

const objectiveStatus = (r) => {
  if (isSolved(r)) return "passed";
  return (r.attempts ?? 0) > 0 || r.revealed || r.hinted ? "incomplete" : "not attempted";
};

/** The chapter's own elements (score, status) for `version`. */
export function chapterValues(version, records, ids, threshold) {
  const v = VERSIONS[version];
  const now = standing(records, ids, threshold);
  const raw = now.total ? Number(((100 * now.solved) / now.total).toFixed(2)) : 0;
  const score = v.element.score;
  return [
    [`${score}.min`, 0], [`${score}.max`, 100], [`${score}.raw`, raw],
    ...(v.scaled ? [[`${score}.scaled`, now.share]] : []),
    ...v.status(now),
  ];
}

/** Exercise `i`'s objective: its id, status and mastery (clean variants, up to MASTERED). */
export function objectiveValues(version, i, id, record = {}) {
  const v = VERSIONS[version];
  const at = `cmi.objectives.${i}`;
  const clean = Math.min(record.clean?.length ?? 0, MASTERED);
  return [
    [`${at}.id`, objectiveId(id)], [`${at}.score.min`, 0], [`${at}.score.max`, MASTERED], [`${at}.score.raw`, clean],
    ...(v.scaled ? [[`${at}.score.scaled`, Number((clean / MASTERED).toFixed(4))]] : []),
    ...v.objective(at, objectiveStatus(record)),
  ];
}

/**
 * Exercise `i`'s interaction: its id and type always; with a check (`check`:
 * {correct, latencyMs, at}) its result, the learner's last answer, the latency (none when
 * `latencyMs` is null: a check of an earlier session) and time.
 */
export function interactionValues(version, i, id, record = {}, check = null) {
  const v = VERSIONS[version];
  const is = v.interaction;
  const at = `cmi.interactions.${i}`;
  const base = [[`${at}.id`, objectiveId(id)], [`${at}.type`, is.type]];
  if (!check) return base;
  return [...base, [`${at}.objectives.0.id`, objectiveId(id)], [`${at}.${is.when}`, is.at(check.at)],
    [`${at}.${is.response}`, answerText(record).slice(0, is.responseLength)],
    [`${at}.result`, check.correct ? is.correct : is.wrong],
    ...(check.latencyMs === null ? [] : [[`${at}.latency`, v.elapsed(check.latencyMs)]]),
    ...(is.description ? [[`${at}.description`, `Exercise ${id}`]] : [])];
}
