// An assignment link (docs/teaching/assignments.md): the class code, the exercises and an
// optional due date, in the address's hash (#class=ROB101&ex=0.1,0.2&due=2026-12-01), so
// that no server ever sees them. Read and written here only; the learner's name or student
// number is kept on their device (studentKey), never in the link.

import { tidy } from "./assignment-hash.js";
import { LIMIT } from "./contract.js";

export const CLASS_CAP = LIMIT.classCode; // characters of a class code
export const STUDENT_CAP = LIMIT.student; // characters of a name or student number
const DATE = /^(\d{4})-(\d{2})-(\d{2})$/;

/** Whether `text` is a day of the calendar written YYYY-MM-DD (2026-02-30 is not). */
export function isDate(text) {
  const m = DATE.exec(String(text));
  if (!m) return false;
  const [year, month, day] = m.slice(1).map(Number);
  const date = new Date(Date.UTC(year, month - 1, day));
  return date.getUTCFullYear() === year && date.getUTCMonth() === month - 1 && date.getUTCDate() === day;
}

/** The class code as records and hand-ins key it (the hash's tidying). */
export const classKey = (code) => tidy(code);

/** The link to the assignment page for {code, ids, due}. */
export function assignmentHref(siteRoot, { code, ids, due }) {
  const params = new URLSearchParams({ class: code, ex: ids.join(",") });
  if (due) params.set("due", due);
  const url = new URL("assignment/", siteRoot);
  url.hash = params.toString();
  return url.href;
}

/**
 * The assignment a link holds: {ok: true, code, ids, due} or {ok: false, reason} (a
 * sentence for the page). `known`: the site's exercise ids, in the book's order.
 */
export function readAssignment(hash, known) {
  const params = new URLSearchParams(String(hash).replace(/^#/, ""));
  const code = classKey(params.get("class") ?? "");
  if (!code) {
    return { ok: false, reason: "This link names no class code: ask your teacher for the assignment's link again." };
  }
  if (code.length > CLASS_CAP) return { ok: false,
    reason: `This link's class code is longer than ${CLASS_CAP} characters.` };
  const asked = (params.get("ex") ?? "").split(",").map((s) => s.trim()).filter(Boolean);
  const unknown = asked.filter((id) => !known.includes(id));
  if (unknown.length) return { ok: false,
    reason: `This link sets exercise ${unknown.slice(0, 3).map((id) => `“${id.slice(0, 12)}”`).join(", ")}, which this `
    + `workbook does not have.` };
  if (!asked.length) return { ok: false, reason: "This link sets no exercises." };
  const ids = known.filter((id) => asked.includes(id));
  const due = params.get("due") || null;
  if (due !== null && !isDate(due)) {
    return { ok: false, reason: `This link's due date “${due.slice(0, 20)}” is not a day of the calendar (a date reads `
      + `like 2026-12-01): ask your teacher for the link again.` };
  }
  return { ok: true, code, ids, due };
}

/** Where the learner's name or student number is kept (this site, this browser). */
export const studentKey = (siteRoot) =>
  `robotics-workbook:${new URL(siteRoot).pathname.replace(/\/+$/, "") || "/"}:student`;

export function savedStudent(siteRoot) {
  try {
    const value = localStorage.getItem(studentKey(siteRoot));
    return value && tidy(value) ? tidy(value).slice(0, STUDENT_CAP) : null;
  } catch {
    return null;
  }
}

/**
 * True the first time it is asked in this browser (then never again): before records were kept
 * per learner, the assignment page kept its answers in the browser's one record, for the
 * student it last knew. That student takes them into their own record, once.
 */
export function adoptOnce(siteRoot) {
  const key = studentKey(siteRoot).replace(/:student$/, ":records-per-learner");
  try {
    if (localStorage.getItem(key)) return false;
    localStorage.setItem(key, "1");
    return true;
  } catch {
    return false;
  }
}

/** Keep the id; false when this browser's storage refuses (the page keeps it for this visit). */
export function saveStudent(siteRoot, id) {
  try {
    localStorage.setItem(studentKey(siteRoot), id);
    return true;
  } catch {
    return false;
  }
}
