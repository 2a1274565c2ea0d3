// The class page (docs/class.md): a teacher drops hand-in files (or progress exports);
// everything stays in this browser. Each is read (class-grade.js; a malformed or hostile
// file is named and skipped), every recorded answer re-graded by the grader (a Build
// solve's code run again in the sandbox, as on a chapter page), the files grouped into one
// row per student (class-rows.js), and the page shows the table (class-table.js), which
// exercises worked (class-stats.js), the class's most common mistakes and two CSVs
// (class-csv.js): the long table and the gradebook.

import { fold } from "./assignment-hash.js";
import { gradeLearner, problemOf, readLearner } from "./class-grade.js";
import { groupRows } from "./class-rows.js";
import { legend, rowElement, sortRows, tableRegion } from "./class-table.js";
import { classStats, statsTable } from "./class-stats.js";
import { toCSV, toGradebook } from "./class-csv.js";
import { el } from "./dom.js";
import { listPage } from "./exercise-list.js";
import { download } from "./notice.js";
import { withSandbox } from "./sandbox-client.js";

const LEARNERS_AT_ONCE = 4; // files graded side by side: the grader answers one while the sandbox runs another's code
// students shown at once: a bigger class is paged (a table of 1,000 rows lays out in one long task)
const PAGE_ROWS = 100;
const giveWay = () => (globalThis.scheduler?.yield ? globalThis.scheduler.yield()
  : new Promise((r) => setTimeout(r, 0)));

function renderMistakes(rows, ids) {
  const section = el("div", { className: "wb-class-mistakes" });
  let any = false;
  for (const id of ids) {
    const counts = new Map(); // key -> {text, answers, learners, recorded}
    const count = (key, text) => {
      const m = counts.get(key) ?? counts.set(key, { text, answers: 0, learners: 0, recorded: 0 }).get(key);
      if (m.text === key && text !== key) m.text = text; // a recorded slip id first seen, its words later
      return m;
    };
    // recorded name -> slip id
    const byName = new Map(rows.flatMap(({ learner: l }) => Object.entries(l.cells[id]?.slipNames ?? {})));
    for (const { learner: l } of rows) {
      const c = l.cells[id];
      if (!c) continue;
      for (const [key, n] of Object.entries(c.slips)) {
        const m = count(key, c.slipText[key] ?? key);
        m.answers += n;
        m.learners += 1;
      }
      for (const [name, n] of Object.entries(c.recordedSlips)) count(byName.get(name) ?? name, name).recorded += n;
    }
    if (!counts.size) continue;
    any = true;
    const body = [...counts].sort(([a, x], [b, y]) => y.learners - x.learners || y.answers - x.answers
      || y.recorded - x.recorded || (a < b ? -1 : 1))
      .map(([key, m]) => {
        const tr = el("tr", {}, el("th", { scope: "row", textContent: m.text }),
          el("td", { textContent: String(m.learners) }),
          el("td", { textContent: String(m.answers) }), el("td", { textContent: String(m.recorded) }));
        tr.dataset.wbSlip = key;
        return tr;
      });
    const table = el("table", { className: "wb-class-slips" },
      el("caption", { textContent: `Exercise ${id}` }),
      el("thead", {}, el("tr", {}, ...["Slip", "Students (re-graded)", "Answers (re-graded)",
      "All recorded wrong answers"].map((t) => el("th", { scope: "col", textContent: t })))),
      el("tbody", {}, ...body));
    table.dataset.wbMistakes = id;
    const wrap = el("div", { className: "wb-class-scroll", tabIndex: 0, role: "region" }, table);
    wrap.setAttribute("aria-label", `Mistakes in exercise ${id}`);
    section.append(wrap);
  }
  if (!any) section.append(el("p", { textContent: "No named slips among the answers handed in." }));
  return section;
}

/** The grader's own words for which grader it is ({"op": "version"}), for the page to name; and {version, bank} or
 * null. */
async function graderVersion(runtime) {
  const reply = await runtime.request({ op: "version" });
  if (!reply.ok) return { text: "Re-graded here by the workbook's grader (its version could not be read).",
    grader: null };
  const { version, bank } = reply.value;
  return { text: `Re-graded here by the workbook's grader version ${version}, `
    + `${bank ? `bank ${bank}` : "its bank's hash not known in this start (compiled files only)"}.`,
    grader: bank ? { version, bank } : null };
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
    el("label", { htmlFor: input.id, textContent:
    "Hand-in files or progress exports (choose several, or drop them here)" }), input);
  const status = el("p", { role: "status", className: "wb-course-status" });
  const version = el("p", { className: "wb-class-version" });
  version.dataset.wbGrader = "";
  const problems = el("ul", { className: "wb-class-problems" });
  problems.dataset.wbProblems = "";
  const button = (text, action) => {
    const b = el("button", { type: "button", className: "md-button", textContent: text, hidden: true });
    b.dataset.wbAction = action;
    return b;
  };
  const csv = button("Download the table (CSV)", "csv");
  const gradebook = button("Download the gradebook (CSV, one row per student)", "gradebook");
  const results = el("div", { className: "wb-class-results" });
  root.replaceChildren(zone, status, version, problems,
    el("div", { className: "wb-course-actions" }, csv, gradebook), results);
  const state = { learners: [], rows: [], ids: [], sort: { key: "student", dir: 1 }, trs: new Map(), seq: 0, page: 0 };
  const pager = el("nav", { className: "wb-class-pager", hidden: true });
  pager.setAttribute("aria-label", "Pages of students");
  const shown = el("span", { role: "status" });
  const previous = el("button", { type: "button", className: "md-button", textContent: `Previous ${PAGE_ROWS}` });
  const next = el("button", { type: "button", className: "md-button", textContent: `Next ${PAGE_ROWS}` });
  previous.dataset.wbAction = "previous-students";
  next.dataset.wbAction = "next-students";
  pager.append(previous, shown, next);
  let drawn = Promise.resolve();
  const pageOf = () => {
    const pages = Math.max(1, Math.ceil(state.rows.length / PAGE_ROWS));
    state.page = Math.min(Math.max(0, state.page), pages - 1);
    const from = state.page * PAGE_ROWS;
    const to = Math.min(state.rows.length, from + PAGE_ROWS);
    pager.hidden = pages === 1;
    shown.textContent = `Students ${from + 1}–${to} of ${state.rows.length}`;
    previous.disabled = state.page === 0;
    next.disabled = state.page === pages - 1;
    // A row's <tr> is built when its page is first shown (a class of 1,000 builds 100 at a time).
    return sortRows(state.rows, state.ids, state.sort).slice(from, to).map((r) => state.trs.get(r.key)
      ?? state.trs.set(r.key, rowElement(r, state.ids)).get(r.key));
  };
  const placeRows = () => results.querySelector(".wb-class-table tbody")?.replaceChildren(...pageOf());
  const turn = (by) => {
    state.page += by;
    placeRows();
  };
  previous.addEventListener("click", () => turn(-1));
  next.addEventListener("click", () => turn(1));
  const draw = async () => {
    state.rows = groupRows(state.learners, await named);
    state.ids = order.filter((id) => state.learners.some((l) => l.cells[id]));
    if (!state.rows.length) return results.replaceChildren();
    state.trs = new Map();
    await giveWay();
    const stats = el("div", { className: "wb-class-worked" },
      el("p", { textContent: "Working out which exercises worked…" }));
    const mistakes = el("div", {}, el("p", { textContent: "Counting the mistakes…" }));
    results.replaceChildren(el("h2", { textContent: "Students and exercises" }), legend(),
      tableRegion(state, pageOf()), pager,
      el("h2", { textContent: "Which exercises worked" }), stats,
      el("h2", { textContent: "Most common mistakes" }), mistakes);
    csv.hidden = gradebook.hidden = false;
    await giveWay(); // the table is laid out in a task of its own
    mistakes.replaceWith(renderMistakes(state.rows, state.ids));
    await giveWay();
    const started = performance.now();
    stats.replaceChildren(statsTable(await classStats(state.rows, state.ids)));
    root.dataset.wbStatsMs = String(Math.round(performance.now() - started));
  };
  state.resort = (key) => {
    state.sort = { key, dir: state.sort.key === key ? -state.sort.dir : 1 };
    for (const th of results.querySelectorAll(".wb-class-table thead th")) {
      const k = th.querySelector("[data-wb-sort]")?.dataset.wbSort;
      th.setAttribute("aria-sort", k === key ? (state.sort.dir > 0 ? "ascending" : "descending") : "none");
    }
    placeRows();
  };
  const runtime = withSandbox(shared.runtime); // Build code runs in the sandbox worker, one learner's at a time
  const named = graderVersion(shared.runtime).then(({ text, grader }) => {
    version.textContent = text;
    return grader;
  });
  async function takeOne(file, progress) {
    try {
      const learner = readLearner(file.name, await file.text(), known);
      Object.assign(learner, { file: file.name, seq: state.seq++, idKey: learner.kind === "hand-in"
        ? await fold(learner.student) : null });
      const onRun = (id, text) => {
        status.textContent = `${progress()} Running ${learner.student}’s code for exercise ${id}`
          + `${text ? `: ${text}` : "…"}`;
      };
      learner.cells = await gradeLearner(learner, drawing, runtime, onRun);
      state.learners.push(learner);
    } catch (err) {
      problems.append(el("li", { textContent: `${file.name} ${problemOf(err)}: skipped.` }));
    }
  }
  async function take(files) {
    delete root.dataset.wbStatsMs;
    const started = performance.now();
    let next = 0;
    let done = 0;
    const progress = () => `Reading and re-grading ${files.length} file${files.length === 1 ? "" : "s"} `
      + `(${done} done)…`;
    const lane = async () => {
      while (next < files.length) {
        const file = files[next++];
        status.textContent = progress();
        await takeOne(file, progress);
        done++;
      }
    };
    await Promise.all(Array.from({ length: Math.min(LEARNERS_AT_ONCE, files.length) }, lane));
    const seconds = ((performance.now() - started) / 1000).toFixed(1);
    status.textContent = `${state.learners.length} file${state.learners.length === 1 ? "" : "s"} read and re-graded `
      + `(${files.length} handed to the page in ${seconds} s); drawing the table…`;
    drawn = drawn.then(draw);
    await drawn;
    status.textContent = `${state.learners.length} file${state.learners.length === 1 ? "" : "s"} read and `
      + `re-graded, ${state.rows.length} student${state.rows.length === 1 ? "" : "s"} (${files.length} `
      + `file${files.length === 1 ? "" : "s"} handed to the page in ${seconds} s).`;
    root.dataset.wbSeconds = seconds;
    root.dataset.wbRows = String(state.rows.length);
    root.dataset.wbVerified = String(state.rows.reduce((n, r) => n + Object.values(r.learner.cells)
      .filter((c) => c.verified).length, 0));
    root.dataset.wbGraded = String(state.learners.length);
  }
  // the bench hands files in this way
  /** @type {HTMLElement & { wbTake?: typeof take }} */ (root).wbTake = take;
  input.addEventListener("change", () => take([...input.files]));
  zone.addEventListener("dragover", (event) => event.preventDefault());
  zone.addEventListener("drop", (event) => {
    event.preventDefault();
    take([...event.dataTransfer.files]);
  });
  csv.addEventListener("click", () => download("class-results.csv", toCSV(state.learners, state.ids), "text/csv"));
  gradebook.addEventListener("click",
    () => download("class-gradebook.csv", toGradebook(state.rows, state.ids), "text/csv"));
}
