// Which exercises worked (class-page.js), after Moodle's quiz statistics: per exercise, the
// share of the students it was set for who solved it (verified), the median attempt at which
// they solved it, the share that opened the hint and the derivation, the most common named
// slips of the answers re-graded, and two discrimination indices of solving it against the
// rest of the score (the score without this exercise): the point-biserial correlation and the
// upper-lower 27 % difference. An exercise the strongest students (by the rest of the score)
// solve less often than the weakest is flagged. Per step, where answers were worked in steps:
// how often each step was the first wrong one. Computed an exercise at a time, giving the
// event loop back in between (no long task, whatever the class's size).

import { el } from "./dom.js";

const giveWay = () => (globalThis.scheduler?.yield ? globalThis.scheduler.yield()
  : new Promise((r) => setTimeout(r, 0)));

export function median(values) {
  if (!values.length) return null;
  const s = [...values].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
}

/** Point-biserial correlation of 0/1 `hits` with `scores`; null when either does not vary. */
export function pointBiserial(hits, scores) {
  const n = hits.length;
  const ones = hits.filter(Boolean).length;
  if (n < 2 || ones === 0 || ones === n) return null;
  const mean = scores.reduce((a, b) => a + b, 0) / n;
  const sd = Math.sqrt(scores.reduce((a, b) => a + (b - mean) ** 2, 0) / n);
  if (sd === 0) return null;
  const m1 = scores.filter((_, i) => hits[i]).reduce((a, b) => a + b, 0) / ones;
  const m0 = scores.filter((_, i) => !hits[i]).reduce((a, b) => a + b, 0) / (n - ones);
  const p = ones / n;
  return ((m1 - m0) / sd) * Math.sqrt(p * (1 - p));
}

/** Share solved in the top 27 % by `scores` minus the share in the bottom 27 % (ties by order given); null under 4
 * students. */
export function upperLower(hits, scores) {
  const n = hits.length;
  if (n < 4) return null;
  const k = Math.max(1, Math.round(0.27 * n));
  const order = hits.map((h, i) => [scores[i], h ? 1 : 0]).sort((a, b) => a[0] - b[0]);
  const share = (part) => part.reduce((a, [, h]) => a + h, 0) / part.length;
  return share(order.slice(n - k)) - share(order.slice(0, k));
}

/** Add one student's counts ({key: answers}) to `tally` (key -> {learners, answers, ...words(key)}). */
function count(tally, counts, words) {
  for (const [key, n] of Object.entries(counts)) {
    const m = tally.get(key) ?? { learners: 0, answers: 0, ...words(key) };
    m.learners += 1;
    m.answers += n;
    tally.set(key, m);
  }
}

/** A tally's entries, the most students first (then the most answers, then by key), as {key, ...}. */
const byReach = (tally) => [...tally]
  .sort(([a, x], [b, y]) => y.learners - x.learners || y.answers - x.answers || (a < b ? -1 : 1))
  .map(([key, m]) => ({ key, ...m }));

/** "(3 students, 4 answers)" */
const reach = (m) => `(${m.learners} student${m.learners === 1 ? "" : "s"}, `
  + `${m.answers} answer${m.answers === 1 ? "" : "s"})`;

/** The statistics of one exercise over `rows` (the shown file of each student). */
export function exerciseStats(rows, ids, id) {
  const set = rows.map((r) => r.learner).filter((l) => l.cells[id]);
  const cells = set.map((l) => l.cells[id]);
  const hits = cells.map((c) => c.verified);
  const rest = set.map((l) => ids.filter((other) => other !== id && l.cells[other]?.verified).length);
  const share = (f) => (cells.length ? cells.filter(f).length / cells.length : null);
  const slips = new Map();
  const steps = new Map();
  let withSteps = 0;
  for (const c of cells) {
    count(slips, c.slips, (key) => ({ text: c.slipText[key] ?? key }));
    withSteps += c.withSteps;
    count(steps, c.firstWrongStep, (step) => ({ label: c.stepLabels[step] ?? step }));
  }
  const ul = upperLower(hits, rest);
  return {
    id, set: cells.length, solved: share((c) => c.verified),
    toSolve: median(cells.filter((c) => c.verified && c.toSolve).map((c) => c.toSolve)),
    hinted: share((c) => c.hinted), revealed: share((c) => c.revealed), pointBiserial: pointBiserial(hits, rest),
    upperLower: ul,
    flagged: ul !== null && ul < 0,
    slips: byReach(slips).slice(0, 3),
    withSteps, steps: byReach(steps),
  };
}

/** Every exercise's statistics, an exercise per task. */
export async function classStats(rows, ids) {
  const out = [];
  for (const id of ids) {
    out.push(exerciseStats(rows, ids, id));
    await giveWay();
  }
  return out;
}

const pct = (x) => (x === null ? "—" : `${Math.round(100 * x)}%`);
const num = (x, d = 2) => (x === null ? "—" : x.toFixed(d).replace("-", "−"));

/** The table of statistics. */
export function statsTable(stats) {
  const heads = ["Exercise", "Set for", "Solved", "Median attempts to solve", "Opened the hint",
    "Opened the derivation", "Discrimination (point-biserial)", "Upper − lower 27 %", "Most common slips"];
  const body = stats.map((s) => {
    const name = el("th", { scope: "row", textContent: s.id });
    if (s.flagged) {
      const flag = el("span", { className: "wb-class-warn",
        textContent: " ⚑ the strongest students miss it more than the weakest" });
      name.append(flag);
    }
    const slips = s.slips.length ? el("ul", {}, ...s.slips.map((m) => {
      const li = el("li", { textContent: `${m.text} ${reach(m)}` });
      li.dataset.wbSlip = m.key;
      return li;
    })) : "—";
    const steps = s.steps.length ? el("div", { className: "wb-class-detail" },
      el("p", { textContent: `The first wrong step, over ${s.withSteps} answer${s.withSteps === 1 ? "" : "s"} `
        + "worked in steps:" }),
      el("ul", {}, ...s.steps.map((m) => {
        const li = el("li", { textContent: `${m.label} ${reach(m)}` });
        li.dataset.wbStep = m.key;
        return li;
      }))) : "";
    const tr = el("tr", {}, name, ...[String(s.set), pct(s.solved), s.toSolve === null ? "—" : String(s.toSolve),
      pct(s.hinted), pct(s.revealed),
      num(s.pointBiserial), num(s.upperLower)].map((t) => el("td", { textContent: t })), el("td", {}, slips, steps));
    tr.dataset.wbStats = s.id;
    if (s.flagged) tr.dataset.wbFlagged = "true";
    return tr;
  });
  const table = el("table", { className: "wb-class-slips wb-class-stats" },
    el("caption", { textContent: "Per exercise, over the students it was set for (each student's shown file)." }),
    el("thead", {}, el("tr", {}, ...heads.map((t) => el("th", { scope: "col", textContent: t })))),
    el("tbody", {}, ...body));
  const wrap = el("div", { className: "wb-class-scroll", tabIndex: 0, role: "region" }, table);
  wrap.setAttribute("aria-label", "Which exercises worked");
  return wrap;
}
