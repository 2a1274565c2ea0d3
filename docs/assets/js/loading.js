// A start that explains itself: when an exercise waits for a Python worker to
// start, its feedback says what is happening, with a progress bar fed by the
// worker's own reports (boot.js, boot-steps.js, through runtime.js's events):
// the runtime's bytes as they arrive, then each step of the start by name.
// Two workers are waited for: the grader (a Check pressed while
// <html data-workbook-runtime> is "loading": the exercise's data-state is
// "pending"), and the sandbox that runs Build code (a Run before it has started:
// build.js calls showSandboxStart). The reply replaces the message the moment it
// comes (feedback.js).
//
// The bar measures the whole wait, not only the bytes: the download fills the
// first DOWNLOAD_SHARE of it, each step of the start its own span after that
// (SPAN). Within a step that gives no counts (compiling, restoring, importing),
// and while no byte arrives, the bar creeps towards the end of the step's span,
// ever more slowly (it never reaches it before the step ends), and the text says
// the step's name and, after a second, how long it has lasted: the bar never
// stands still without the message saying what is going on.

import { ATTR, BOOT_PHASE, OFFLINE, ROLE, RUNTIME, STATE, byRole, findRole } from "./contract.js";
import { BOOT_STEP } from "./boot-steps.js";
import { feedbackOf } from "./feedback.js";
import { formatSize } from "./offline-ui.js";
import { el } from "./dom.js";

const STEPS = [
  [BOOT_PHASE.download, "Download"],
  [BOOT_PHASE.start, "Start Python"],
  [BOOT_PHASE.ready, "Ready"],
];

const DOWNLOAD_SHARE = 0.6;
// Each step of the start: its span of the bar, and about how long it takes (ms), which sets how fast
// the bar creeps through the span (a third of the way in that time, two thirds in three times that).
const SPAN = {
  [BOOT_STEP.compile]: [0.6, 0.7, 2000],
  [BOOT_STEP.restore]: [0.7, 0.85, 1500],
  [BOOT_STEP.boot]: [0.7, 0.85, 3000],
  [BOOT_STEP.import]: [0.85, 0.99, 2000],
};
const DOWNLOAD_CREEP_MS = 30_000; // with no byte for a while, the bar still moves, slowly
const TICK_MS = 250;
const SCALE = 1000; // the bar's max

/** What each worker's start looks like to the learner. */
const WHO = {
  grader: {
    title: () => (stored() ? "Loading the grader…" : "Loading the grader: this happens on the first visit only."),
    label: "Loading the grader",
    import: "Loading the grading package…",
    ready: "Ready: checking your answer…",
  },
  sandbox: {
    title: () => "Starting the sandbox that runs your code: once per visit to a page with Build exercises.",
    label: "Starting the sandbox for your code",
    import: "Preparing the sandbox…",
    ready: "Ready: running your code…",
  },
};

const STEP_TEXT = {
  [BOOT_STEP.compile]: "Compiling the Python runtime…",
  [BOOT_STEP.restore]: "Restoring Python from its saved state…",
  [BOOT_STEP.boot]: "Starting the Python interpreter…",
};

/** Per worker: its last report, when what it reports last changed, and where the bar is. */
const fresh = () => ({
  phase: BOOT_PHASE.download, step: BOOT_STEP.download, loaded: 0, total: 0, changed: performance.now(), value: 0 });
const starts = { grader: fresh(), sandbox: fresh() };
let ticker = null;

const loading = () => document.documentElement.getAttribute(ATTR.runtime) === RUNTIME.loading;
const stored = () => document.documentElement.getAttribute(ATTR.offline) === OFFLINE.ready;

function update(who, { phase, loaded = 0, total = 0, step }) {
  const start = starts[who];
  const now = performance.now();
  const shown = step || (phase === BOOT_PHASE.start ? BOOT_STEP.compile : BOOT_STEP.download);
  if (phase === BOOT_PHASE.download && start.phase !== BOOT_PHASE.download) starts[who] = { ...fresh(), changed: now };
  const next = starts[who];
  if (next.phase !== phase || next.step !== shown || next.loaded !== loaded) next.changed = now;
  Object.assign(next, { phase, step: shown, loaded, total });
}

/** Where the bar stands for this start now (0-1): what was counted, then the creep; never back. */
function position(start, now) {
  if (start.phase === BOOT_PHASE.ready) return 1;
  let real, end, ms;
  if (!SPAN[start.step]) {
    real = start.total ? (Math.min(start.loaded, start.total) / start.total) * DOWNLOAD_SHARE : 0;
    [end, ms] = [DOWNLOAD_SHARE, DOWNLOAD_CREEP_MS];
  } else {
    [real, end, ms] = SPAN[start.step];
  }
  const creep = real + (end - real) * (1 - Math.exp(-(now - start.changed) / ms));
  start.value = Math.max(start.value, creep);
  return start.value;
}

function describe(who, start, now) {
  const { phase, step, loaded, total } = start;
  if (phase === BOOT_PHASE.ready) return [WHO[who].ready, ""];
  if (phase === BOOT_PHASE.download && !SPAN[step]) {
    const text = total
      ? `Downloading the Python runtime · ${formatSize(loaded)} of ${formatSize(total)}`
      : "Downloading the Python runtime…";
    return [text, ""];
  }
  const text = step === BOOT_STEP.import ? WHO[who].import : STEP_TEXT[step] || "Starting Python…";
  const seconds = Math.floor((now - start.changed) / 1000);
  return [text, seconds >= 1 ? ` ${seconds} s` : ""];
}

function panel(who) {
  const box = el("div", { className: "wb-loading" });
  box.setAttribute(ATTR.role, ROLE.runtimeStatus);
  box.dataset.wbWaitsFor = who;
  const title = el("p", { className: "wb-loading-title" });
  const detail = el("p", { className: "wb-loading-detail" }, el("span"), el("span", { className: "wb-loading-time" }));
  detail.lastChild.setAttribute("aria-hidden", "true"); // the seconds are seen, not read out every second
  const bar = el("progress");
  bar.setAttribute(ATTR.role, ROLE.runtimeProgress);
  bar.setAttribute("aria-label", WHO[who].label);
  bar.max = SCALE;
  const steps = el("ol", { className: "wb-loading-steps" }, ...STEPS.map(([phase, label]) => {
    const item = el("li", { textContent: label });
    item.setAttribute(ATTR.phase, phase);
    return item;
  }));
  box.append(title, bar, detail, steps);
  return box;
}

const setText = (node, text) => node.textContent !== text && (node.textContent = text);

function draw(box, now = performance.now()) {
  const who = box.dataset.wbWaitsFor;
  const start = starts[who];
  if (box.getAttribute(ATTR.phase) !== start.phase) box.setAttribute(ATTR.phase, start.phase);
  setText(box.querySelector(".wb-loading-title"), WHO[who].title());
  const [text, time] = describe(who, start, now);
  const [line, clock] = box.querySelector(".wb-loading-detail").children;
  setText(line, text);
  setText(clock, time);
  findRole(box, ROLE.runtimeProgress).value = position(start, now) * SCALE;
  const at = STEPS.findIndex(([phase]) => phase === start.phase);
  if (box.dataset.wbAt === String(at)) return; // the steps' marks change with the phase only
  box.dataset.wbAt = String(at);
  box.querySelectorAll("li").forEach((item, i) => {
    if (i === at) item.setAttribute("aria-current", "step");
    else item.removeAttribute("aria-current");
    item.classList.toggle("wb-done", i < at);
  });
}

function redrawAll() {
  const now = performance.now();
  let waiting = false;
  for (const box of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll(byRole(ROLE.runtimeStatus)))) {
    draw(box, now);
    waiting ||= starts[box.dataset.wbWaitsFor].phase !== BOOT_PHASE.ready;
  }
  if (!waiting && ticker) {
    clearInterval(ticker);
    ticker = null;
  }
}

function showIn(exercise, who) {
  const feedback = feedbackOf(exercise); // an exercise's own feedback, or a checked step's
  if (!feedback) return;
  let box = findRole(feedback, ROLE.runtimeStatus);
  if (!box || box.dataset.wbWaitsFor !== who) {
    box = panel(who);
    feedback.replaceChildren(box);
  }
  draw(box);
  ticker ||= setInterval(redrawAll, TICK_MS);
}

/** A Build run waits for the sandbox to start (sandbox-client.js asks): say so in its feedback. */
export function showSandboxStart(exercise) {
  showIn(exercise, "sandbox");
}

export function initLoading() {
  new MutationObserver((records) => {
    if (!loading()) return;
    for (const record of records) {
      const target = /** @type {Element} */ (record.target); // attribute changes: always an element
      const waits = target.hasAttribute(ATTR.exercise) || target.getAttribute(ATTR.role) === ROLE.workStep;
      if (target.getAttribute(ATTR.state) === STATE.pending && waits) showIn(target, "grader");
    }
  }).observe(document.body, { attributes: true, subtree: true, attributeFilter: [ATTR.state] });
  for (const [who, name] of [["grader", "workbook:boot"], ["sandbox", "workbook:sandbox-boot"]]) {
    document.addEventListener(name, (/** @type {CustomEvent} */ event) => {
      update(who, event.detail);
      redrawAll();
    });
  }
}
