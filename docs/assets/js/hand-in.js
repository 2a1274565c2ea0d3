// The hand-in file (CONTRACT.md, "Assignments and the class page"): what the assignment page
// saves for the teacher (assignment-page.js) and the class page reads (class-grade.js).
//   {format, version: 1, handedIn (ISO time, the student's clock), student, assignment:
//    {class, exercises, due}, grader?: {version, bank}, records: {ID: record}}
// `records` holds the records of the set exercises only, checked as an import's are; `grader`
// names the grader the student's page graded with, when it can say. No DOM here.

import { LIMIT } from "./contract.js";
import { classKey } from "./assignment-link.js";
import { cleanRecord } from "./progress-schema.js";
import { isObject, isShort } from "./record-checks.js";

export const HAND_IN_FORMAT = "robotics-math-workbook-hand-in";
export const HAND_IN_VERSION = 1;
const MAX_SET = 200; // exercises one assignment sets

/** The file's name: the class code, the id as far as a file name can show it, and the id's tag (studentTag). */
export function handInName(code, student, tag) {
  const safe = (t) => t.normalize("NFKD").replace(/\p{M}+/gu, "").replace(/[^A-Za-z0-9._-]+/g, "-")
    .replace(/^-+|-+$/g, "").slice(0, 40);
  return `hand-in-${[safe(code), safe(student), tag].filter(Boolean).join("-")}.json`;
}

/**
 * The hand-in of `student` for `assignment` ({code, ids, due}), from their record store
 * `progress` (their own: assignment-page.js), at `now`; `grader` is the grader's {version,
 * bank} or null.
 */
export function buildHandIn({ progress, assignment, student, grader = null, now = new Date() }) {
  const records = {};
  for (const id of assignment.ids) {
    const r = progress.get(id);
    if (Object.keys(r).length) records[id] = structuredClone(r);
  }
  return { format: HAND_IN_FORMAT, version: HAND_IN_VERSION, handedIn: now.toISOString(), student,
    assignment: { class: assignment.code, exercises: assignment.ids, due: assignment.due ?? null },
    ...(grader ? { grader } : {}), records };
}

const isoTime = (v) => (isShort(v, 40) && Number.isFinite(Date.parse(v)) ? new Date(Date.parse(v))
  .toISOString() : null);
const isGrader = (v) => isObject(v) && Object.keys(v).length <= 4 && Object.values(v).every((x) => isShort(x, 80));

/**
 * A parsed hand-in (`data`, with format HAND_IN_FORMAT) read: {ok: true, learner: {kind:
 * "hand-in", student, code, ids, due, handedIn, grader, records}} or {ok: false, reason} (the
 * words after the file's name, for the page). `known`: the site's exercise ids (a Set).
 */
export function readHandIn(data, known) {
  const no = (reason) => ({ ok: false, reason });
  if (data.version !== HAND_IN_VERSION) {
    return no(`is a hand-in of version ${String(data.version).slice(0, 10)}, which this page does not read`);
  }
  const a = data.assignment;
  if (!isObject(a) || typeof a.class !== "string" || !classKey(a.class) || a.class.length > LIMIT.classCode) return no(
    "names no class code");
  if (typeof data.student !== "string" || !data.student.trim() || data.student.length > LIMIT.student) return no(
    "names no student");
  if (!Array.isArray(a.exercises) || !a.exercises.length || a.exercises.length > MAX_SET
    || !a.exercises.every((id) => typeof id === "string" && known.has(id))) {
    return no("sets exercises this workbook does not have");
  }
  if (!isObject(data.records)) return no("holds no records");
  const records = {};
  for (const [id, raw] of Object.entries(data.records)) {
    if (!a.exercises.includes(id)) {
      return no(`holds a record of exercise “${id.slice(0, 12)}”, which the assignment does not set`);
    }
    try {
      records[id] = cleanRecord(id, raw);
    } catch (err) {
      return no(`holds a record that is not valid: ${err.message}`);
    }
  }
  return { ok: true, learner: { kind: "hand-in", student: data.student.trim(), code: classKey(a.class),
    ids: [...new Set(a.exercises)],
    due: typeof a.due === "string" ? a.due.slice(0, 10) : null, handedIn: isoTime(data.handedIn),
    grader: isGrader(data.grader) ? data.grader : null, records } };
}
