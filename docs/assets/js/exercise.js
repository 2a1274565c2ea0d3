// Wires each exercise element (CONTRACT.md) to the runtime and the progress
// store: the parts every kind shares (state, attempts, hint and derivation); the
// kind's own widget is docs/assets/js/kinds/<kind>.js, loaded by name.

import { ATTR, REVIEW_KINDS, ROLE, STATE, ownQuery, ownRole } from "./contract.js";
import { setPending, showMessage, showReply } from "./feedback.js";
import { afterReveal } from "./review.js";
import { recordGraded } from "./attempt.js";

/** Text from base64 of its UTF-8 bytes (the derivation, the variant templates). */
export function decodeBase64(text) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  return new TextDecoder().decode(bytes);
}

/**
 * Send one request for this exercise and show its reply, on the exercise or, with `on`, on one of
 * its checked steps (steps.js); every request of an exercise goes through here, with the variant on
 * screen. An exercise's graded attempt is recorded. A step's reply that comes back after new numbers
 * were drawn is stale: it is dropped (null), and steps.js records the step's own verdicts. With `via`, the
 * request goes through another runtime than the page's (kinds/build.js: the one whose runs go to the sandbox).
 * @param {any} ctx the exercise's context (initExercise)
 * @param {string} op
 * @param {object} payload
 * @param {{ limitMs?: number, onProgress?: Function, onWait?: Function, saved?: object, on?: HTMLElement,
 *   via?: any }} [options]
 */
async function submit(ctx, op, payload,
  { limitMs, onProgress, onWait, saved = {}, on = ctx.el, via = ctx.runtime } = {}) {
  const { variant } = ctx;
  setPending(on);
  const reply = await via.request({ op, exercise: ctx.id, ...payload, variant }, { limitMs, onProgress, onWait });
  const step = on !== ctx.el;
  if (step && variant !== ctx.variant) return null;
  showReply(on, reply);
  if (!step) recordGraded(ctx, { op, ...payload }, reply, saved); // a graded attempt counts (attempt.js)
  return reply;
}

function toggle(button, panel, showLabel, hideLabel) {
  const open = panel.hidden;
  panel.hidden = !open;
  button.setAttribute("aria-expanded", String(open));
  button.textContent = open ? hideLabel : showLabel;
  return open;
}

function initHelp(ctx) {
  const { el, id, progress } = ctx;
  const hintButton = ownRole(el, ROLE.hint);
  const revealButton = ownRole(el, ROLE.reveal);
  if (hintButton) {
    const panel = ownRole(el, ROLE.hintPanel);
    hintButton.addEventListener("click", () => {
      if (toggle(hintButton, panel, "Show hint", "Hide hint")) progress.update(id, { hinted: true });
    });
  }
  if (revealButton) {
    const panel = ownRole(el, ROLE.solutionPanel);
    const showLabel = revealButton.textContent;
    const hideLabel = showLabel.replace("Show", "Hide");
    revealButton.addEventListener("click", () => {
      if (!panel.dataset.rendered) {
        panel.innerHTML = `<p class="admonition-title">${panel.dataset.title}</p>${decodeBase64(
          panel.dataset.content)}`;
        panel.dataset.rendered = "true";
        ctx.renderMath?.(panel);
      }
      if (toggle(revealButton, panel, showLabel, hideLabel)) {
        const record = progress.get(id);
        const { variant } = ctx;
        if (!record.revealedIn?.includes(variant)) progress.update(id, afterReveal(record, variant,
          { schedule: ctx.reviewed }));
      }
    });
  }
}

// The page's head holds back a Check pressed before the widget was ready
// (docs/overrides/main.html); now that it is, check that answer, unless the
// widget's start changed the numbers it answered (numbers drawn earlier came
// back, an address or a page asked for others): it answered numbers no longer
// on screen.
function replayEarlySubmit(el, numbersBefore) {
  const form = ownQuery(el, "form");
  if (!form) return;
  form.dataset.wbReady = "true";
  const early = window.__workbookSubmits || [];
  const at = early.indexOf(form);
  if (at >= 0) {
    early.splice(at, 1);
    if (el.getAttribute(ATTR.variant) !== numbersBefore) {
      showMessage(el, "Not checked: this exercise's numbers changed as it started, so the answer you typed was for "
        + "other numbers. Check your answer to these.");
      return;
    }
    form.requestSubmit();
  }
}

/**
 * One exercise's context, with every field that any module reads or sets declared here: it is
 * sealed, so a module can change a field but never add one. `shared` is the page's (main.js;
 * practise.js and assignment-page.js add `start`, and the latter its own `runtime`).
 */
function exerciseContext(el, shared) {
  const kind = el.getAttribute(ATTR.kind);
  const ctx = Object.seal({
    el,
    id: el.getAttribute(ATTR.exercise),
    runtime: shared.runtime, // the grader; kinds/build.js wraps it so that a run goes through the sandbox
    progress: shared.progress,
    renderMath: shared.renderMath,
    start: shared.start ?? null, // a variant the page forces (a review on the Practise page, an assignment), else null
    // The variant on screen: a Derive exercise's numbers (variants.js changes it), a Build exercise's
    // hidden tests (a review starts a fresh seed), and what a review's answers count for.
    variant: shared.start ?? 0,
    // The answer to put back in the variant `start` forces (the assignment page: the last one
    // graded for the assignment's numbers), else null; the chapter's own is the record's `last`.
    resume: shared.resume ?? null,
    remember: false, // variants.js: whether the variant on screen is kept (in the record and the address)
    reviewed: REVIEW_KINDS.includes(kind), // Derive, Build and Debug join the review queue
    guessable: kind === "debug", // a bug found after wrong lines is solved, not clean (review.js)
    submit: null, // (op, payload, options) => reply: the one way a request of this exercise is sent
    field: null, // kinds/derive.js: the answer kind's widget
    given: null, // kinds/derive.js: () => the earlier answers this exercise builds on (carry.js)
    steps: null, // kinds/derive.js: the checked steps (steps.js), when the exercise has them
    step: undefined, // a step's own context (steps.js) names its step; the exercise's has none
  });
  ctx.submit = (op, payload, options) => submit(ctx, op, payload, options);
  return ctx;
}

/** Start one exercise element once (pages come back with instant navigation). */
export function initExercise(el, shared) {
  if (el.dataset.wbReady) return;
  el.dataset.wbReady = "true";
  const kind = el.getAttribute(ATTR.kind);
  const ctx = exerciseContext(el, shared);
  const saved = ctx.progress.get(ctx.id);
  const onScreen = shared.start ?? saved.variant ?? 0;
  if (onScreen === 0 && (saved.done ? saved.done.includes(0) : saved.solved)) {
    el.setAttribute(ATTR.state, STATE.correct);
    showMessage(el, saved.solvedAfterReveal ? "Solved earlier (after revealing the solution)." : "Solved earlier.");
  }
  initHelp(ctx);
  const numbersBefore = el.getAttribute(ATTR.variant); // the numbers a Check pressed before the widget started answered
  import(`./kinds/${kind}.js`)
    .then((module) => module.init(ctx))
    .then(() => replayEarlySubmit(el, numbersBefore))
    .catch((err) => {
      el.setAttribute(ATTR.state, STATE.error);
      showMessage(el, `This exercise could not start: ${err.message}`);
    });
}
