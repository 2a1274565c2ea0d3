// Entry point of the page side. Starts (or adopts) the grading worker once per
// tab, and initialises every exercise on every page, including pages reached by
// mkdocs-material's instant navigation.

import { ATTR, ERROR, ROLE, RUNTIME, STATE, ownRole, setRootState } from "./contract.js";
import { initExercise } from "./exercise.js";
import { Progress } from "./progress.js";
import { Runtime } from "./runtime.js";
import { initFigures } from "./figures.js";
import { initProgressPage } from "./progress-ui.js";
import { initPractise } from "./practise.js";
import { registerOffline } from "./offline.js";
import { checkScrollRegionsNow, initScrollRegions } from "./a11y.js";
import { initLoading } from "./loading.js";
import { initJumps } from "./jump.js";
import { initDrawer } from "./drawer.js";
import { clearNotice, showNotice, showProgressProblems } from "./notice.js";
import { strayVariantLinks, strayVariantTargets } from "./variants.js";
import { loadManifest } from "./progress-view.js";
import { initCourse } from "./course.js"; // the teacher's, assignment and class pages

const siteRoot = window.__workbookBase || new URL("../../", import.meta.url).href;
const progress = new Progress(siteRoot);

const exercises = () => document.querySelectorAll(`[${ATTR.exercise}]`);

function showRuntimeProblem(message) {
  for (const el of exercises()) {
    const box = ownRole(el, ROLE.feedback);
    if (box && !box.textContent) {
      const p = document.createElement("p");
      p.className = "wb-runtime-problem";
      p.textContent = message;
      box.replaceChildren(p);
    }
  }
}

let runtime = null;
if (typeof Worker === "undefined") {
  setRootState("runtime", RUNTIME.failed);
} else {
  const early = window.__workbookEarly || null;
  window.__workbookEarly = null;
  runtime = new Runtime(new URL("assets/dist/worker.js", siteRoot), early);
  runtime.announce([...exercises()].map((el) => el.getAttribute(ATTR.exercise)));
}
window.workbook = { runtime, progress, checkScrollRegionsNow };
registerOffline(siteRoot, progress);
initLoading();
initScrollRegions();
initJumps();

const NO_WORKER = "This browser cannot run the Python grader (no Web Worker support).";
const shared = {
  runtime: runtime || { request: async () => ({ ok: false, error: { kind: ERROR.runtime, message: NO_WORKER } }) },
  progress,
  renderMath,
};

// KaTeX typesets the page in slices of about 25 ms, yielding in between, so a
// chapter full of formulas never blocks the main thread (no long task).
const SLICE_MS = 25;
const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

async function renderMath(scope) {
  const katex = window.katex;
  if (!katex) return;
  let sliceStart = performance.now();
  for (const el of scope.querySelectorAll(".arithmatex")) {
    if (el.dataset.rendered) continue;
    if (performance.now() - sliceStart > SLICE_MS) {
      await nextTask();
      sliceStart = performance.now();
      if (el.dataset.rendered || !el.isConnected) continue;
    }
    const tex = el.textContent.trim();
    const display = el.tagName === "DIV";
    const body = display ? tex.replace(/^\\\[|\\\]$/g, "") : tex.replace(/^\\\(|\\\)$/g, "");
    try {
      katex.render(body, el, { displayMode: display, throwOnError: false });
      el.dataset.rendered = "true";
    } catch {
      /* leave the TeX source visible */
    }
  }
}

// A ?variant= for an exercise of another chapter: the notice links to it there.
async function linkStray(box) {
  const ids = [...exercises()].map((el) => el.getAttribute(ATTR.exercise));
  const targets = strayVariantTargets(ids, await loadManifest(siteRoot), siteRoot);
  if (!box?.isConnected || !targets.length) return;
  const list = document.createElement("ul");
  for (const { href, text } of targets) {
    const li = document.createElement("li");
    li.append(Object.assign(document.createElement("a"), { href, textContent: text }));
    list.append(li);
  }
  box.append(list);
}

function initPage() {
  initDrawer(); // the page's menu is new after an instant navigation
  renderMath(document);
  for (const el of exercises()) {
    try {
      initExercise(el, shared);
    } catch (err) {
      // One exercise that cannot start must not stop the others.
      el.setAttribute(ATTR.state, STATE.error);
      ownRole(el, ROLE.feedback)?.replaceChildren(Object.assign(document.createElement("p"), { textContent: `This exercise could not start: ${err.message}` }));
    }
  }
  initFigures(document, shared.runtime);
  if (!runtime) showRuntimeProblem(NO_WORKER);
  else if (runtime.failure) showRuntimeProblem(runtime.failure);
  showProgressProblems(progress);
  const stray = strayVariantLinks([...exercises()].map((el) => el.getAttribute(ATTR.exercise)));
  if (stray.length && exercises().length) linkStray(showNotice("variant-link", "This link", stray.join(" ")));
  initProgressPage(progress, siteRoot);
  initPractise(shared, siteRoot);
  initCourse(shared, siteRoot);
}

document.addEventListener("workbook:runtime", (event) => {
  if (event.detail === RUNTIME.failed) showRuntimeProblem(runtime.failure);
});
document.addEventListener("workbook:progress-problem", () => showProgressProblems(progress));
document.addEventListener("workbook:progress-saved", () => ["full", "blocked"].forEach((kind) => clearNotice(`progress-${kind}`)));

// mkdocs-material emits every page (the first and each instant navigation) on document$.
if (window.document$ && typeof window.document$.subscribe === "function") {
  window.document$.subscribe(() => initPage());
} else if (document.readyState === "loading") {
  document.addEventListener("DOMContentLoaded", initPage);
} else {
  initPage();
}
