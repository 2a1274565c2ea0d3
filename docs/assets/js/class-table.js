// The class page's table (class-page.js): one compact row per student, a score (solved / set),
// the hand-in's time, and one mark per exercise that reads at a glance: a symbol and a colour
// (never the colour alone), its words for a screen reader, and the cell's details on demand
// (each mark a button: its box is built when pressed, so 1,000 rows stay light). The header row and the first column
// stay in view while the table scrolls inside its own focusable region.

import { el } from "./dom.js";

export const MARKS = {
  verified: { symbol: "✓", text: "solved, verified" },
  "not-verified": { symbol: "⚠", text: "not verified" },
  unsolved: { symbol: "✗", text: "not solved" },
  "not-set": { symbol: "–", text: "not set" },
};
export const CHANGED = { symbol: "Δ", text: "changed since hand-in" };
/** A symbol a screen reader skips (its words are beside it). */
function symbol(text, className = "wb-class-symbol") {
  const span = el("span", { className, textContent: text });
  span.setAttribute("aria-hidden", "true");
  return span;
}
const FLAG_SYMBOL = { duplicate: "⊕", "same-file-name": "≡", "other-class": "≠", progress: "⤓", late: "!",
  "other-grader": "†" }; // not Δ, which marks a cell changed since hand-in

/** The table's cell text and its state, for a learner's exercise. */
export function cellState(c) {
  const state = !c ? "not-set" : c.verified ? "verified" : c.claimed ? "not-verified" : "unsolved";
  return { state, text: MARKS[state].text };
}

export const scoreOf = (l, ids) => ids.filter((id) => l.cells[id]?.verified).length;
export const setOf = (l, ids) => ids.filter((id) => l.cells[id]).length;

const TIME = new Intl.DateTimeFormat(undefined, { month: "short", day: "numeric", hour: "2-digit", minute: "2-digit" });
export const shownTime = (iso) => (iso ? TIME.format(new Date(iso)) : "—");

function detailLines(c) {
  const bits = [`${c.attempts} attempt${c.attempts === 1 ? "" : "s"}`];
  if (c.toSolve) bits.push(`solved at attempt ${c.toSolve}`);
  if (c.hinted) bits.push("hint");
  if (c.revealed) bits.push("derivation");
  if (c.stepped) bits.push("steps");
  if (c.carried) bits.push("carried");
  const out = [bits.join(", ")];
  if (c.changed) {
    out.push(`${CHANGED.symbol} ${CHANGED.text}: ${c.changes.length ? c.changes.map((x) => `an answer the student's `
      + `page marked ${x.was} grades ${x.now} now`).join("; ")
      : "the student's page showed it solved, its code does not pass now"}`);
  }
  for (const [key, n] of Object.entries(c.slips)) out.push(`slip${n > 1 ? ` (${n}×)` : ""}: ${(c.slipText[key] ?? key)
    .replace(/^slip: /, "")}`);
  if (c.note) out.push(c.note);
  return out;
}

/** A button that opens its cell's details (built when pressed, `toggleCell`). */
function opener(...children) {
  const button = el("button", { type: "button", className: "wb-class-open" }, ...children);
  button.setAttribute("aria-expanded", "false");
  return button;
}

function markCell(l, id, label) {
  const c = l.cells[id];
  const { state, text } = cellState(c);
  const td = el("td", {});
  td.dataset.wbCell = state;
  td.dataset.wbExercise = id;
  const mark = [symbol(MARKS[state].symbol), el("span", { className: "wb-sr-only",
    textContent: `${label}, ${id}: ${text}` })];
  if (c?.changed) {
    td.dataset.wbChanged = "true";
    mark.push(symbol(CHANGED.symbol, "wb-class-changed"), el("span", { className: "wb-sr-only",
      textContent: `, ${CHANGED.text}` }));
  }
  td.append(c ? opener(...mark) : el("span", { className: "wb-class-mark" }, ...mark));
  return td;
}

function studentCell(row) {
  const th = el("th", { scope: "row" });
  const name = el("span", { className: "wb-class-name", textContent: row.label });
  if (!row.flags.length) {
    th.append(name);
    return th;
  }
  const badges = row.flags.filter((f) => f.kind !== "late").map((f) => { // late: in the hand-in's column
    const b = symbol(FLAG_SYMBOL[f.kind], "wb-class-flag");
    b.dataset.wbFlag = f.kind;
    return b;
  });
  th.append(opener(name, ...badges, el("span", { className: "wb-sr-only",
    textContent: ` (${row.flags.map((f) => f.kind.replace(/-/g, " ")).join(", ")})` })));
  th.dataset.wbFlags = row.flags.map((f) => f.kind).join(" ");
  return th;
}

/** The details of the cell `button` opens: a student's flags and other files, or an exercise's mark. */
function detailsOf(row, ids, id) {
  if (!id) {
    const older = row.others.map((o) => el("li",
      { textContent: `${o.file}: handed in ${shownTime(o.handedIn)}, ${scoreOf(o, ids)} of `
        + `${setOf(o, ids)} solved (${ids.filter((x) => o.cells[x])
          .map((x) => `${x} ${MARKS[cellState(o.cells[x]).state].symbol}`).join(", ")})` }));
    return [el("p", { className: "wb-class-pop-title", textContent: `${row.label}: ${row.learner.file}` }), el("ul", {},
      ...row.flags.map((f) => el("li", { textContent: f.text }))),
      ...(older.length ? [el("p", { textContent: "Its other files:" }), el("ul", {}, ...older)] : [])];
  }
  const c = row.learner.cells[id];
  return [el("p", { className: "wb-class-pop-title", textContent: `${row.label} · ${id}: ${cellState(c).text}` }),
    ...detailLines(c).map((t) => el("p", { className: "wb-class-detail", textContent: t }))];
}

/**
 * Open (or close) the details of the cell whose button is `button`, in a box under it (on a phone, a
 * sheet along the screen's bottom: course.css), brought into view; one at a time (Escape closes it:
 * tableRegion).
 */
export function toggleCell(button, row, ids) {
  const cell = button.parentElement;
  const open = cell.querySelector(".wb-class-pop");
  for (const other of button.closest("table").querySelectorAll(".wb-class-pop")) closeCell(other);
  if (open) return;
  const pop = el("div", { className: "wb-class-pop" }, ...detailsOf(row, ids, cell.dataset.wbExercise));
  cell.classList.add("wb-class-opened");
  cell.append(pop);
  button.setAttribute("aria-expanded", "true");
  pop.scrollIntoView({ block: "nearest", inline: "nearest" }); // a cell low in the table opened below the screen
}

function closeCell(pop) {
  const cell = pop.parentElement;
  cell.classList.remove("wb-class-opened");
  cell.querySelector(".wb-class-open")?.setAttribute("aria-expanded", "false");
  pop.remove();
}

/** The <tr> of a row. */
export function rowElement(row, ids) {
  const l = row.learner;
  const handed = el("td", { className: "wb-class-time" }, el("span", { textContent: shownTime(l.handedIn) }));
  if (l.late) handed.append(" ", el("strong", { className: "wb-class-late", textContent: "late" }));
  handed.dataset.wbHandedIn = l.handedIn ?? "";
  if (l.late !== null && l.late !== undefined) handed.dataset.wbLate = String(l.late);
  const score = el("td", { className: "wb-class-score", textContent: `${scoreOf(l, ids)} / ${setOf(l, ids)}` });
  score.dataset.wbScore = String(scoreOf(l, ids));
  const tr = el("tr", {}, studentCell(row), score, handed, ...ids.map((id) => markCell(l, id, row.label)));
  tr.dataset.wbStudent = row.label;
  tr.dataset.wbRow = row.key;
  tr.dataset.wbKind = l.kind;
  return tr;
}

const ORDER = ["verified", "not-verified", "unsolved", "not-set"];

/** `rows` sorted by `sort` ({key, dir}): "student", "score", "handed-in" or an exercise id. */
export function sortRows(rows, ids, sort) {
  const value = (r, key) => (key === "student" ? r.label.toLowerCase() : key === "score" ? scoreOf(r.learner, ids)
    : key === "handed-in" ? r.learner.handedIn ?? "" : ORDER.indexOf(cellState(r.learner.cells[key]).state));
  return [...rows].sort((a, b) => {
    const [x, y] = [value(a, sort.key), value(b, sort.key)];
    return (x < y ? -1 : x > y ? 1 : a.label.localeCompare(b.label)) * sort.dir;
  });
}

function sortButton(label, key, sorter) {
  const button = el("button", { type: "button", className: "wb-sort", textContent: label });
  button.dataset.wbSort = key;
  button.addEventListener("click", () => sorter(key));
  return button;
}

/** The table's region: head, body (`trs`, in order) and the rates of each exercise. */
export function tableRegion(state, trs) {
  const { rows, ids, sort } = state;
  const aria = (key) => (sort.key === key ? (sort.dir > 0 ? "ascending" : "descending") : "none");
  const th = (label, key) => {
    const cell = el("th", { scope: "col" }, sortButton(label, key, state.resort));
    cell.setAttribute("aria-sort", aria(key));
    return cell;
  };
  const head = el("tr", {}, th("Student", "student"), th("Score", "score"), th("Handed in", "handed-in"),
    ...ids.map((id) => th(id, id)));
  const rate = (id) => {
    const set = rows.filter((r) => r.learner.cells[id]);
    const n = set.filter((r) => r.learner.cells[id].verified).length;
    return set.length ? `${n} of ${set.length} (${Math.round((100 * n) / set.length)}%)` : "—";
  };
  const foot = el("tr", {}, el("th", { scope: "row", textContent: "Solved, verified" }), el("td", {}), el("td", {}),
    ...ids.map((id) => {
    const td = el("td", { textContent: rate(id) });
    td.dataset.wbRate = id;
    return td;
  }));
  const table = el("table", { className: "wb-class-table" },
    el("caption", { textContent: `${rows.length} student${rows.length === 1 ? "" : "s"} × ${ids.length} `
    + `exercise${ids.length === 1 ? "" : "s"}` }),
    el("thead", {}, head), el("tbody", {}, ...trs), el("tfoot", {}, foot));
  table.addEventListener("click", (event) => {
    const button = event.target.closest?.(".wb-class-open");
    const row = button && state.rows.find((r) => r.key === button.closest("tr").dataset.wbRow);
    if (row) toggleCell(button, row, ids);
  });
  table.addEventListener("keydown", (event) => {
    const pop = event.key === "Escape" && table.querySelector(".wb-class-pop");
    if (!pop) return;
    const button = pop.parentElement.querySelector(".wb-class-open");
    closeCell(pop);
    button?.focus();
  });
  const region = el("div", { className: "wb-class-scroll wb-class-grid", tabIndex: 0, role: "region" }, table);
  region.setAttribute("aria-label", "The class's results");
  return region;
}

/** The key to the marks, above the table. */
export function legend() {
  const item = (mark, text, state) => {
    const li = el("li", {}, symbol(mark), ` ${text}`);
    if (state) li.dataset.wbCell = state;
    return li;
  };
  return el("ul", { className: "wb-class-legend" },
    el("li", { textContent: "Press a column's heading to sort by it, a mark for its details." }),
    ...Object.entries(MARKS).map(([state, m]) => item(m.symbol, m.text, state)),
    item(CHANGED.symbol, `${CHANGED.text}: a re-graded verdict differs from the one the student's page showed`),
    item("late", "handed in after the due date, by the student's clock"),
    item(FLAG_SYMBOL.duplicate, "more than one file"),
    item(FLAG_SYMBOL["other-class"], "another class code"), item(FLAG_SYMBOL.progress, "a progress export"),
    item(FLAG_SYMBOL["same-file-name"], "a file name another student's file had"),
    item(FLAG_SYMBOL["other-grader"], "beside a name: the student's page graded with another grader version"));
}
