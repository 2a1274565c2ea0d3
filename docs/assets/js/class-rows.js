// The class page's rows (class-page.js): one row per student, whatever files came in.
// Hand-ins of one student (the same class code and the same id after the assignment's own
// folding, assignment-hash.js fold(): `idKey`, set as the file is read) are one row, showing the newest file (by its
// hand-in time, then its latest answer) with the others listed in it; two students whose files had the same
// name are two rows; a hand-in for another class code than most files' is flagged, and so is
// a progress export (it names no class or student: its row is named after the file).

import { lateOf } from "./class-grade.js";

const latestAnswer = (l) => Math.max(0, ...Object.values(l.records).map((r) => (Number.isFinite(r?.updated)
  ? r.updated : 0)));
const newestFirst = (a, b) => (Date.parse(b.handedIn ?? "") || 0) - (Date.parse(a.handedIn ?? "") || 0)
  || latestAnswer(b) - latestAnswer(a) || b.seq - a.seq;

/** The row key of a learner: a hand-in's class and folded id (`idKey`); a progress export is its own. */
export const rowKey = (l) => (l.kind === "hand-in" ? `hand-in\n${l.code}\n${l.idKey}` : `progress\n${l.seq}`);

/** The class code most hand-ins are for (the first read of the most frequent), or null. */
export function mainClass(learners) {
  const counts = new Map();
  for (const l of learners) if (l.kind === "hand-in") counts.set(l.code, (counts.get(l.code) ?? 0) + 1);
  let best = null;
  for (const [code, n] of counts) if (best === null || n > counts.get(best)) best = code;
  return best;
}

/**
 * Rows {key, learner (shown), others (older files, newest first), flags: [{kind, text}]} from
 * every learner read (each with `file`, `seq`, `cells`). Flag kinds: "duplicate", "same-file-name",
 * "other-class", "progress", "late", "other-grader" (the hand-in names the grader the student's
 * page used, and it is not `grader`, the one that re-graded it here).
 */
export function groupRows(learners, grader = null) {
  const groups = new Map();
  for (const l of learners) {
    const key = rowKey(l);
    groups.set(key, [...(groups.get(key) ?? []), l]);
  }
  const main = mainClass(learners);
  const byFile = new Map();
  for (const l of learners) byFile.set(l.file, [...(byFile.get(l.file) ?? []), l]);
  const rows = [];
  for (const [key, files] of groups) {
    const [learner, ...others] = [...files].sort(newestFirst);
    const flags = [];
    for (const l of files) l.late = lateOf(l.handedIn, l.due);
    if (others.length) {
      flags.push({ kind: "duplicate", text: `${files.length} files for this student: the newest (${learner.file}) is `
        + `shown; also ${others.map((o) => o.file).join(", ")}` });
    }
    const namesakes = new Set(files.flatMap((l) => byFile.get(l.file).filter((o) => rowKey(o) !== key)
      .map((o) => o.student)));
    if (namesakes.size) flags.push({ kind: "same-file-name",
      text: `the file name ${learner.file} was also another student's (${[...namesakes].join(", ")}): both are kept` });
    if (learner.kind === "hand-in" && main !== null && learner.code !== main) {
      flags.push({ kind: "other-class", text: `a hand-in for class “${learner.code}”, not “${main}” like most files` });
    }
    if (learner.kind === "progress") flags.push({ kind: "progress",
      text: "a progress export, not a hand-in: no class code or student id; its last answers are graded at the numbers "
      + "they were given for" });
    const then = learner.grader;
    if (grader && then && (then.version !== grader.version || then.bank !== grader.bank)) {
      flags.push({ kind: "other-grader",
        text: `graded on the student's page by grader ${then.version}, bank ${then.bank}; re-graded here `
        + `by ${grader.version}, bank ${grader.bank}` });
    }
    if (learner.late) flags.push({ kind: "late",
      text: `handed in after the due date (${learner.due}), by the student's clock` });
    rows.push({ key, learner, others, flags });
  }
  // Progress exports of the same file name: told apart by a number.
  const seen = new Map();
  for (const row of rows) {
    const n = (seen.get(row.learner.student) ?? 0) + 1;
    seen.set(row.learner.student, n);
    row.label = n > 1 ? `${row.learner.student} (${n})` : row.learner.student;
  }
  return rows;
}
