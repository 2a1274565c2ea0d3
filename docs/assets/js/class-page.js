// The class page (docs/class.md): a teacher drops hand-in files (or progress exports);
// everything stays in this browser. Each is read (class-grade.js; a malformed or hostile
// file is named and skipped), every recorded answer re-graded by the grader (a Build
// solve's code run again in the sandbox, as on a chapter page), and the page
// shows students × exercises, each exercise's rates, the class's most common mistakes and
// a CSV of the table.

import { gradeLearner, problemOf, readLearner } from "./class-grade.js";
import { el, listPage } from "./progress-view.js";
import { download } from "./notice.js";
import { withSandbox } from "./sandbox-client.js";

const COLUMNS = ["student", "file", "class", "exercise", "variant", "solved (claimed)", "verified", "attempts", "hint", "derivation", "steps", "carried", "note"];

/** The table's cell text and its state, for a learner's exercise. */
export function cellState(c) {
  if (!c) return { state: "not-set", text: "not set" };
  if (c.verified) return { state: "verified", text: "solved, verified" };
  if (c.claimed) return { state: "not-verified", text: "not verified" };
  return { state: "unsolved", text: "not solved" };
}

const yes = (b) => (b ? "yes" : "no");
const csvQuote = (v) => {
  const text = String(v ?? "");
  const safe = /^[=+\-@\t\r]/.test(text) ? `'${text}` : text; // a spreadsheet must not run a cell as a formula
  return /[",\n\r]/.test(safe) ? `"${safe.replace(/"/g, '""')}"` : safe;
};

export function toCSV(learners, ids) {
  const lines = [COLUMNS.join(",")];
  for (const l of learners) {
    for (const id of ids) {
      const c = l.cells[id];
      if (!c) continue;
      lines.push([l.student, l.file, l.code ?? "", id, c.variant, yes(c.claimed), yes(c.verified), c.attempts, yes(c.hinted), yes(c.revealed),
        yes(c.stepped), yes(c.carried), c.note].map(csvQuote).join(","));
    }
  }
  return `${lines.join("\r\n")}\r\n`;
}

function detail(c) {
  const bits = [`${c.attempts} attempt${c.attempts === 1 ? "" : "s"}`];
  if (c.hinted) bits.push("hint");
  if (c.revealed) bits.push("derivation");
  if (c.stepped) bits.push("steps");
  if (c.carried) bits.push("carried");
  return bits.join(", ");
}

function sortButton(label, key, sorter) {
  const button = el("button", { type: "button", className: "wb-sort", textContent: label });
  button.dataset.wbSort = key;
  button.addEventListener("click", () => sorter(key));
  return button;
}

function renderTable(state) {
  const { learners, ids, sort } = state;
  const score = (l) => ids.filter((id) => l.cells[id]?.verified).length;
  const value = (l, key) => (key === "student" ? l.student.toLowerCase() : key === "verified" ? score(l)
    : ["verified", "not-verified", "unsolved", "not-set"].indexOf(cellState(l.cells[key]).state));
  const rows = [...learners].sort((a, b) => {
    const [x, y] = [value(a, sort.key), value(b, sort.key)];
    return (x < y ? -1 : x > y ? 1 : a.student.localeCompare(b.student)) * sort.dir;
  });
  const aria = (key) => (sort.key === key ? (sort.dir > 0 ? "ascending" : "descending") : "none");
  const th = (label, key, scope = "col") => {
    const cell = el("th", { scope }, sortButton(label, key, state.resort));
    cell.setAttribute("aria-sort", aria(key));
    return cell;
  };
  const head = el("tr", {}, th("Student", "student"), th("Verified", "verified"), ...ids.map((id) => th(id, id)));
  const body = rows.map((l) => {
    const tr = el("tr", {}, el("th", { scope: "row", textContent: l.student }), el("td", { textContent: `${score(l)} of ${ids.filter((id) => l.cells[id]).length}` }),
      ...ids.map((id) => {
        const c = l.cells[id];
        const { state: s, text } = cellState(c);
        const td = el("td", {}, el("span", { className: "wb-class-mark", textContent: text }));
        td.dataset.wbCell = s;
        td.dataset.wbExercise = id;
        if (c) td.append(el("span", { className: "wb-class-detail", textContent: detail(c) }));
        if (c?.note) td.append(el("span", { className: "wb-class-detail", textContent: c.note }));
        return td;
      }));
    tr.dataset.wbStudent = l.student;
    return tr;
  });
  const rate = (id) => {
    const set = learners.filter((l) => l.cells[id]);
    const n = set.filter((l) => l.cells[id].verified).length;
    return set.length ? `${n} of ${set.length} (${Math.round((100 * n) / set.length)}%)` : "—";
  };
  const foot = el("tr", {}, el("th", { scope: "row", textContent: "Solved, verified" }), el("td", {}), ...ids.map((id) => {
    const td = el("td", { textContent: rate(id) });
    td.dataset.wbRate = id;
    return td;
  }));
  const table = el("table", { className: "wb-class-table" },
    el("caption", { textContent: `${learners.length} learner${learners.length === 1 ? "" : "s"} × ${ids.length} exercise${ids.length === 1 ? "" : "s"}; press a column's heading to sort by it.` }),
    el("thead", {}, head), el("tbody", {}, ...body), el("tfoot", {}, foot));
  const region = el("div", { className: "wb-class-scroll", tabIndex: 0, role: "region" }, table);
  region.setAttribute("aria-label", "The class's results");
  return region;
}

function renderMistakes(learners, ids) {
  const section = el("div", { className: "wb-class-mistakes" });
  let any = false;
  for (const id of ids) {
    const counts = new Map(); // name -> {answers, learners, recorded}
    for (const l of learners) {
      const c = l.cells[id];
      if (!c) continue;
      for (const [name, n] of Object.entries(c.slips)) {
        const m = counts.get(name) ?? { answers: 0, learners: 0, recorded: 0 };
        m.answers += n;
        m.learners += 1;
        counts.set(name, m);
      }
      for (const [name, n] of Object.entries(c.recordedSlips)) {
        const m = counts.get(name) ?? { answers: 0, learners: 0, recorded: 0 };
        m.recorded += n;
        counts.set(name, m);
      }
    }
    if (!counts.size) continue;
    any = true;
    const rows = [...counts].sort(([a, x], [b, y]) => y.learners - x.learners || y.answers - x.answers || y.recorded - x.recorded || (a < b ? -1 : 1))
      .map(([name, m]) => {
        const tr = el("tr", {}, el("th", { scope: "row", textContent: name }), el("td", { textContent: String(m.learners) }),
          el("td", { textContent: String(m.answers) }), el("td", { textContent: String(m.recorded) }));
        tr.dataset.wbSlip = name;
        return tr;
      });
    const table = el("table", { className: "wb-class-slips" },
      el("caption", { textContent: `Exercise ${id}` }),
      el("thead", {}, el("tr", {}, ...["Slip", "Learners (re-graded)", "Answers (re-graded)", "All recorded wrong answers"].map((t) => el("th", { scope: "col", textContent: t })))),
      el("tbody", {}, ...rows));
    table.dataset.wbMistakes = id;
    const wrap = el("div", { className: "wb-class-scroll", tabIndex: 0, role: "region" }, table);
    wrap.setAttribute("aria-label", `Mistakes in exercise ${id}`);
    section.append(wrap);
  }
  if (!any) section.append(el("p", { textContent: "No named slips among the answers handed in." }));
  return section;
}

export async function initClassPage(shared, siteRoot) {
  const page = await listPage("data-wb-class", siteRoot);
  if (!page) return;
  const { root, manifest } = page;
  const order = manifest.chapters.flatMap((c) => c.ids);
  const known = new Set(order);
  const drawing = new Set(manifest.variants || []);
  const input = el("input", { type: "file", multiple: true, accept: ".json,application/json", id: "wb-class-files" });
  const zone = el("div", { className: "wb-class-drop" },
    el("label", { htmlFor: input.id, textContent: "Hand-in files or progress exports (choose several, or drop them here)" }), input);
  const status = el("p", { role: "status", className: "wb-course-status" });
  const problems = el("ul", { className: "wb-class-problems" });
  problems.dataset.wbProblems = "";
  const csv = el("button", { type: "button", className: "md-button", textContent: "Download the table (CSV)", hidden: true });
  csv.dataset.wbAction = "csv";
  const results = el("div", { className: "wb-class-results" });
  root.replaceChildren(zone, status, problems, el("div", { className: "wb-course-actions" }, csv), results);
  const state = { learners: [], ids: [], sort: { key: "student", dir: 1 } };
  const draw = () => {
    state.ids = order.filter((id) => state.learners.some((l) => l.cells[id]));
    if (!state.learners.length) return results.replaceChildren();
    results.replaceChildren(el("h2", { textContent: "Students and exercises" }), renderTable(state),
      el("h2", { textContent: "Most common mistakes" }), renderMistakes(state.learners, state.ids));
    csv.hidden = false;
  };
  state.resort = (key) => {
    state.sort = { key, dir: state.sort.key === key ? -state.sort.dir : 1 };
    draw();
    results.querySelector(`[data-wb-sort="${CSS.escape(key)}"]`)?.focus();
  };
  const runtime = withSandbox(shared.runtime); // Build code runs in the sandbox worker, one learner's at a time
  async function take(files) {
    const started = performance.now();
    let done = 0;
    for (const file of files) {
      const reading = `Reading and re-grading ${file.name} (${++done} of ${files.length})…`;
      status.textContent = reading;
      try {
        const learner = readLearner(file.name, await file.text(), known);
        learner.file = file.name;
        const onRun = (id, text) => {
          status.textContent = `${reading} Running ${learner.student}’s code for exercise ${id}${text ? `: ${text}` : "…"}`;
        };
        learner.cells = await gradeLearner(learner, drawing, runtime, onRun);
        state.learners = state.learners.filter((l) => l.file !== file.name);
        state.learners.push(learner);
      } catch (err) {
        problems.append(el("li", { textContent: `${file.name} ${problemOf(err)}: skipped.` }));
      }
    }
    draw();
    const seconds = ((performance.now() - started) / 1000).toFixed(1);
    status.textContent = `${state.learners.length} learner${state.learners.length === 1 ? "" : "s"} read and re-graded (${files.length} file${files.length === 1 ? "" : "s"} in ${seconds} s).`;
    root.dataset.wbGraded = String(state.learners.length);
    root.dataset.wbSeconds = seconds;
  }
  root.wbTake = take; // the bench hands files in this way
  input.addEventListener("change", () => take([...input.files]));
  zone.addEventListener("dragover", (event) => event.preventDefault());
  zone.addEventListener("drop", (event) => {
    event.preventDefault();
    take([...event.dataTransfer.files]);
  });
  csv.addEventListener("click", () => download("class-results.csv", toCSV(state.learners, state.ids), "text/csv"));
}
