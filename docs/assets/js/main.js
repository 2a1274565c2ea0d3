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
import { loadManifest } from "./exercise-list.js";
import { initCourse } from "./course.js"; // the teacher's, assignment and class pages
import { findApi, findLaunch } from "./lms/api.js";
import { learnerProgress } from "./lms/learner.js";
import { renderMath } from "./math.js";
import { initSearchStart } from "./search-start.js";
import { initApp } from "./app.js";
import { idle } from "./wait.js";

const siteRoot = window.__workbookBase || new URL("../../", import.meta.url).href;
// In an LMS (the SCORM package, lms/): the page keeps the record of the learner the LMS names
// (the launcher's key, never the hosted site's record) and reports through the launcher's one
// session, which merges the LMS's copy of the progress before any exercise is drawn (initPage
// waits for it); the hosted site loads none of it.
const launch = findLaunch(window);
const inLms = Boolean(launch || findApi(window));
const progress = inLms ? learnerProgress(siteRoot, launch) : new Progress(siteRoot);
const lmsSession = inLms ? import("./lms/session.js").then((m) => m.connectLms(progress, launch)) : null;
// The installed app's start URL goes on to the last page read (never in an LMS: it opens its own pages).
if (!inLms) initApp(siteRoot);

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

const PAGE_IDLE_MS = 1000; // Python's start waits for the page's idle moment this long at most
let runtime = null;
if (typeof Worker === "undefined") {
  setRootState("runtime", RUNTIME.failed);
} else {
  const early = window.__workbookEarly || null;
  window.__workbookEarly = null;
  runtime = new Runtime(new URL("assets/dist/worker.js", siteRoot), early);
  runtime.announce([...exercises()].map((el) => el.getAttribute(ATTR.exercise)));
  // The page has started once, after DOMContentLoaded (the theme's own start-up work), the browser is
  // idle: then Python's start may take the CPU (worker.js).
  const started = () => idle(PAGE_IDLE_MS).then(() => runtime.pageStarted());
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", started, { once: true });
  else started();
}
window.workbook = { runtime, progress, checkScrollRegionsNow, lms: null };
lmsSession?.then((session) => { window.workbook.lms = session; }, (err) => {
  showNotice("lms", "Course platform", `The connection to the course's platform could not start `
    + `(${err?.message || err}). Your work is kept in this browser.`);
});
// No service worker in an LMS frame: the LMS serves the package from its own paths.
if (!inLms) registerOffline(siteRoot, progress);
initLoading();
initSearchStart();
initScrollRegions();
initJumps();
// A touch screen gets the symbols row above its keyboard (keypad.js, loaded there only).
if (window.matchMedia?.("(pointer: coarse)").matches || navigator.maxTouchPoints > 0) {
  import("./keypad.js").then((m) => m.initKeypad());
}

const NO_WORKER = "This browser cannot run the Python grader (no Web Worker support).";
const shared = {
  runtime: runtime || { request: async () => ({ ok: false, error: { kind: ERROR.runtime, message: NO_WORKER } }) },
  progress,
  renderMath,
};

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
  setTimeout(() => renderMath(document), 0); // in slices of tasks of its own (math.js), none inside this one
  for (const el of exercises()) {
    try {
      initExercise(el, shared);
    } catch (err) {
      // One exercise that cannot start must not stop the others.
      el.setAttribute(ATTR.state, STATE.error);
      const textContent = `This exercise could not start: ${err.message}`;
      ownRole(el, ROLE.feedback)?.replaceChildren(Object.assign(document.createElement("p"), { textContent }));
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

document.addEventListener("workbook:runtime", (/** @type {CustomEvent} */ event) => {
  if (event.detail === RUNTIME.failed) showRuntimeProblem(runtime.failure);
});
document.addEventListener("workbook:progress-problem", () => showProgressProblems(progress));
document.addEventListener("workbook:progress-saved",
  () => ["full", "blocked"].forEach((kind) => clearNotice(`progress-${kind}`)));

// mkdocs-material emits every page (the first and each instant navigation) on document$, from
// inside its own DOMContentLoaded handler: the page starts in a task of its own after it, so that
// the browser runs two shorter tasks instead of one long one (total blocking time, docs/performance.md).
// Pages emitted before that task runs start once, on the page then shown.
const startPage = () => (lmsSession ? lmsSession.then(initPage, initPage) : initPage());
let startQueued = false;
const startSoon = () => {
  if (startQueued) return;
  startQueued = true;
  setTimeout(() => {
    startQueued = false;
    startPage();
  }, 0);
};
if (window.document$ && typeof window.document$.subscribe === "function") {
  window.document$.subscribe(() => startSoon());
} else if (document.readyState === "loading") {
  document.addEventListener("DOMContentLoaded", startPage);
} else {
  startPage();
}
