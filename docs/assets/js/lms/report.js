// What a chapter SCO reports to the LMS, as [element, value] pairs for SCORM 1.2 or
// 2004: pure functions of the progress records, so the same rule serves every
// commit and the tests.
//
// - Score: raw = the chapter's exercises solved, min 0, max = its exercises (2004:
//   scaled = raw / max too). Mastery (three different clean variants) does not add
//   to the score: each exercise's objective carries it, raw = its clean variants
//   up to 3, max 3.
// - Completed when every exercise of the chapter is solved. Passed then too, or
//   earlier when the LMS sets a mastery score (1.2 cmi.student_data.mastery_score,
//   0-100; 2004 cmi.scaled_passing_score, 0-1) and the share solved reaches it.
//   Never "failed": the learner can always go on.
// - One objective and one interaction per exercise, in the chapter's order: the
//   index of exercise i is i in both lists (SCORM lists are filled in order).

import { MASTERED, isSolved } from "../review.js";

export const objectiveId = (id) => `exercise-${id}`;

/** "HHHH:MM:SS.SS" (SCORM 1.2 CMITimespan) of `ms`. */
export function timespan12(ms) {
  const cs = Math.max(0, Math.round(ms / 10));
  const h = Math.floor(cs / 360000);
  const m = Math.floor(cs / 6000) % 60;
  const s = (cs % 6000) / 100;
  return `${String(Math.min(h, 9999)).padStart(4, "0")}:${String(m).padStart(2, "0")}:${s.toFixed(2).padStart(5, "0")}`;
}

/** "PT1H2M3.4S" (SCORM 2004 timeinterval) of `ms`. */
export function duration2004(ms) {
  const cs = Math.max(0, Math.round(ms / 10));
  const h = Math.floor(cs / 360000);
  const m = Math.floor(cs / 6000) % 60;
  const s = (cs % 6000) / 100;
  return `PT${h ? `${h}H` : ""}${m ? `${m}M` : ""}${Number(s.toFixed(2))}S`;
}

/** The learner's last answer as text: a formula or number as typed, a grid row by row, steps in order, Build code. */
export function answerText(record) {
  const last = record.last ?? record.code;
  if (last === undefined || last === null) return "";
  if (Array.isArray(last)) {
    return Array.isArray(last[0]) ? `[${last.map((row) => row.join(", ")).join("; ")}]` : last.join(" → ");
  }
  return String(last);
}

/** The chapter's totals: {solved, total, complete, passed}; `threshold` in [0, 1] or null. */
export function standing(records, ids, threshold = null) {
  const solved = ids.filter((id) => isSolved(records[id] || {})).length;
  const total = ids.length;
  const complete = total > 0 && solved === total;
  const passed = complete || (threshold !== null && total > 0 && solved / total >= threshold);
  return { solved, total, complete, passed };
}

const objectiveStatus = (r) => {
  if (isSolved(r)) return "passed";
  return (r.attempts ?? 0) > 0 || r.revealed || r.hinted ? "incomplete" : "not attempted";
};

/** The chapter's own elements (score, status) for `version`. */
export function chapterValues(version, records, ids, threshold) {
  const { solved, total, complete, passed } = standing(records, ids, threshold);
  if (version === "1.2") {
    return [
      ["cmi.core.score.min", 0], ["cmi.core.score.max", total], ["cmi.core.score.raw", solved],
      ["cmi.core.lesson_status", passed ? "passed" : complete ? "completed" : "incomplete"],
    ];
  }
  const scaled = total ? Number((solved / total).toFixed(4)) : 0;
  return [
    ["cmi.score.min", 0], ["cmi.score.max", total], ["cmi.score.raw", solved], ["cmi.score.scaled", scaled],
    ["cmi.progress_measure", scaled],
    ["cmi.completion_status", complete ? "completed" : "incomplete"],
    ["cmi.success_status", passed ? "passed" : "unknown"],
  ];
}

/** Exercise `i`'s objective: its id, status and mastery (clean variants, up to MASTERED). */
export function objectiveValues(version, i, id, record = {}) {
  const at = `cmi.objectives.${i}`;
  const clean = Math.min(record.clean?.length ?? 0, MASTERED);
  const status = objectiveStatus(record);
  const score = [[`${at}.score.min`, 0], [`${at}.score.max`, MASTERED], [`${at}.score.raw`, clean]];
  if (version === "1.2") return [[`${at}.id`, objectiveId(id)], ...score, [`${at}.status`, status]];
  return [
    [`${at}.id`, objectiveId(id)], ...score, [`${at}.score.scaled`, Number((clean / MASTERED).toFixed(4))],
    [`${at}.success_status`, status === "passed" ? "passed" : "unknown"],
    [`${at}.completion_status`, status === "passed" ? "completed" : status],
  ];
}

/**
 * Exercise `i`'s interaction: its id and type always; with a check (`check`:
 * {correct, latencyMs, at}) its result, the learner's last answer, the latency (none when
 * `latencyMs` is null: a check of an earlier session) and time.
 */
export function interactionValues(version, i, id, record = {}, check = null) {
  const at = `cmi.interactions.${i}`;
  const base = [[`${at}.id`, objectiveId(id)], [`${at}.type`, version === "1.2" ? "fill-in" : "long-fill-in"]];
  if (!check) return base;
  const answer = answerText(record);
  if (version === "1.2") {
    const when = new Date(check.at);
    const time = [when.getHours(), when.getMinutes(), when.getSeconds()].map((n) => String(n).padStart(2, "0")).join(":");
    return [...base, [`${at}.objectives.0.id`, objectiveId(id)], [`${at}.time`, time],
      [`${at}.student_response`, answer.slice(0, 255)], [`${at}.result`, check.correct ? "correct" : "wrong"],
      ...(check.latencyMs === null ? [] : [[`${at}.latency`, timespan12(check.latencyMs)]])];
  }
  return [...base, [`${at}.objectives.0.id`, objectiveId(id)], [`${at}.timestamp`, `${new Date(check.at).toISOString().slice(0, 22)}Z`],
    [`${at}.learner_response`, answer.slice(0, 4000)], [`${at}.result`, check.correct ? "correct" : "incorrect"],
    ...(check.latencyMs === null ? [] : [[`${at}.latency`, duration2004(check.latencyMs)]]), [`${at}.description`, `Exercise ${id}`]];
}
