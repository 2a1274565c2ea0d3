// The class page's two downloads (class-page.js): the long table (one line per student and
// exercise, every detail) and the gradebook (one line per student, in a form Moodle's grade
// import and Canvas's gradebook import read: README "Grades into your gradebook").
// Cells are safe in every locale: a field holding the comma, the semicolon (the list
// separator of many locales' spreadsheets), a tab, a quote or a line break is quoted; a
// field a spreadsheet would run as a formula starts with an apostrophe.

const yes = (b) => (b ? "yes" : "no");

export function csvQuote(v) {
  const text = String(v ?? "");
  const safe = /^[=+\-@\t\r]/.test(text) ? `'${text}` : text; // a spreadsheet must not run a cell as a formula
  return /[",;\t\n\r]/.test(safe) ? `"${safe.replace(/"/g, '""')}"` : safe;
}

const line = (cells) => cells.map(csvQuote).join(",");
const lines = (rows) => `${rows.map(line).join("\r\n")}\r\n`;

export const LONG_COLUMNS = ["student", "file", "class", "handedIn", "late", "exercise", "variant", "solved (claimed)",
  "verified", "changed since hand-in", "attempts", "hint", "derivation", "steps", "carried", "note"];

/** One line per learner (every file's, the rows' other files too) and exercise set. */
export function toCSV(learners, ids) {
  const out = [LONG_COLUMNS];
  for (const l of learners) {
    for (const id of ids) {
      const c = l.cells[id];
      if (!c) continue;
      out.push([l.student, l.file, l.code ?? "", l.handedIn ?? "", l.late ? "yes" : l.late === false ? "no" : "", id,
        c.variant, yes(c.claimed), yes(c.verified), yes(c.changed), c.attempts, yes(c.hinted), yes(c.revealed),
        yes(c.stepped), yes(c.carried), c.note]);
    }
  }
  return lines(out);
}

/** The mark a gradebook gets for a cell: 1 solved (verified), 0 set and not, empty when not set. */
export const gradeMark = (c) => (c ? (c.verified ? 1 : 0) : "");

// Canvas's names for the columns that say who a row is (Student, SIS User ID, SIS Login ID, Section); Moodle maps any.
export const GRADEBOOK_COLUMNS = [
  "Student", "SIS User ID", "SIS Login ID", "Section", "Handed in", "Late", "Score", "Out of",
];

/** One line per student (the shown file of each hand-in's row; a progress export names no student and is left out):
 *  id, name, class, handed in, late, score, each exercise's mark. */
export function toGradebook(rows, ids) {
  const out = [[...GRADEBOOK_COLUMNS, ...ids.map((id) => `Exercise ${id}`)]];
  for (const { learner: l } of rows) {
    if (l.kind !== "hand-in") continue;
    const set = ids.filter((id) => l.cells[id]);
    out.push([l.name ?? l.student, l.student, l.student, l.code ?? "", l.handedIn ?? "",
      l.late ? "yes" : l.late === false ? "no" : "",
      set.filter((id) => l.cells[id].verified).length, set.length, ...ids.map((id) => gradeMark(l.cells[id]))]);
  }
  return lines(out);
}
