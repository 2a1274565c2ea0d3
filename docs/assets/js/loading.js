// A start that explains itself: when an exercise waits for the grader (its
// data-state is "pending" while <html data-workbook-runtime> is "loading"),
// its feedback says what is happening, with a progress bar fed by the worker's
// real byte counts (boot.js, through runtime.js's "workbook:boot" events):
// download, then start, then ready. The reply replaces it the moment the
// grader answers (feedback.js).

import { ATTR, BOOT_PHASE, OFFLINE, ROLE, RUNTIME, STATE, byRole, findRole } from "./contract.js";
import { feedbackOf } from "./feedback.js";
import { formatSize } from "./offline-ui.js";
import { el } from "./progress-view.js";

const STEPS = [
  [BOOT_PHASE.download, "Download"],
  [BOOT_PHASE.start, "Start Python"],
  [BOOT_PHASE.ready, "Ready"],
];

let boot = { phase: BOOT_PHASE.download, loaded: 0, total: 0 };

const loading = () => document.documentElement.getAttribute(ATTR.runtime) === RUNTIME.loading;
const stored = () => document.documentElement.getAttribute(ATTR.offline) === OFFLINE.ready;

function describe({ phase, loaded, total }) {
  if (phase === BOOT_PHASE.ready) return "Ready: checking your answer…";
  if (phase === BOOT_PHASE.start) return "Starting Python…";
  return total ? `Downloading the Python runtime · ${formatSize(loaded)} of ${formatSize(total)}` : "Downloading the Python runtime…";
}

function panel() {
  const box = el("div", { className: "wb-loading" });
  box.setAttribute(ATTR.role, ROLE.runtimeStatus);
  const title = el("p", { className: "wb-loading-title" });
  const detail = el("p", { className: "wb-loading-detail" });
  const bar = el("progress");
  bar.setAttribute(ATTR.role, ROLE.runtimeProgress);
  bar.setAttribute("aria-label", "Loading the grader");
  const steps = el("ol", { className: "wb-loading-steps" }, ...STEPS.map(([phase, label]) => {
    const item = el("li", { textContent: label });
    item.setAttribute(ATTR.phase, phase);
    return item;
  }));
  box.append(title, bar, detail, steps);
  return box;
}

function draw(box) {
  box.setAttribute(ATTR.phase, boot.phase);
  const title = box.querySelector(".wb-loading-title");
  const text = stored() ? "Loading the grader…" : "Loading the grader: this happens on the first visit only.";
  if (title.textContent !== text) title.textContent = text;
  const detail = box.querySelector(".wb-loading-detail");
  const line = describe(boot);
  if (detail.textContent !== line) detail.textContent = line;
  const bar = findRole(box, ROLE.runtimeProgress);
  // Bytes, then the start as the last tenth of the bar.
  const total = boot.total || 1;
  bar.max = total;
  bar.value = boot.phase === BOOT_PHASE.download ? Math.min(boot.loaded, total * 0.9) : boot.phase === BOOT_PHASE.start ? total * 0.95 : total;
  const at = STEPS.findIndex(([phase]) => phase === boot.phase);
  box.querySelectorAll("li").forEach((item, i) => {
    if (i === at) item.setAttribute("aria-current", "step");
    else item.removeAttribute("aria-current");
    item.classList.toggle("wb-done", i < at);
  });
}

function showIn(exercise) {
  const feedback = feedbackOf(exercise); // an exercise's own feedback, or a checked step's
  if (!feedback) return;
  let box = findRole(feedback, ROLE.runtimeStatus);
  if (!box) {
    box = panel();
    feedback.replaceChildren(box);
  }
  draw(box);
}

function redrawAll() {
  for (const box of document.querySelectorAll(byRole(ROLE.runtimeStatus))) draw(box);
}

export function initLoading() {
  new MutationObserver((records) => {
    if (!loading()) return;
    for (const { target } of records) {
      const waits = target.hasAttribute(ATTR.exercise) || target.getAttribute(ATTR.role) === ROLE.workStep;
      if (target.getAttribute(ATTR.state) === STATE.pending && waits) showIn(target);
    }
  }).observe(document.body, { attributes: true, subtree: true, attributeFilter: [ATTR.state] });
  document.addEventListener("workbook:boot", (event) => {
    boot = event.detail;
    redrawAll();
  });
}
