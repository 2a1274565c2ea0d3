// Wires each exercise element (CONTRACT.md) to the runtime and the progress
// store: the parts every kind shares (state, attempts, hint and derivation); the
// kind's own widget is docs/assets/js/kinds/<kind>.js, loaded by name.

import { ATTR, REVIEW_KINDS, ROLE, STATE, ownQuery, ownRole } from "./contract.js";
import { setPending, showMessage, showReply } from "./feedback.js";
import { afterGrade, afterReveal } from "./review.js";
import { countSlip } from "./assignment-schema.js";

/** Text from base64 of its UTF-8 bytes (the derivation, the variant templates). */
export function decodeBase64(text) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  return new TextDecoder().decode(bytes);
}

// A graded attempt (not an invalid input or an error) counts; the first correct
// one marks the exercise solved, noting whether the solution was revealed first.
// What it means per variant, and for the review queue, is review.js's rule.
function recordAttempt(ctx, reply, extra = {}) {
  const { id, progress } = ctx;
  const status = reply.ok ? reply.value.status : null;
  if (status !== STATE.correct && status !== STATE.incorrect) return;
  const before = progress.get(id);
  const variant = ctx.variant ?? 0;
  const patch = { ...extra, attempts: (before.attempts || 0) + 1, ...afterGrade(before, variant, status, { schedule: ctx.reviewed, tag: reply.value.tag, guessable: ctx.guessable }) };
  const slip = reply.value.data?.slip; // a named slip (CONTRACT.md): counted for the class page
  if (status === STATE.incorrect && slip) patch.slips = countSlip(before.slips, slip);
  if (status === STATE.correct && !before.solved) {
    patch.solved = true;
    patch.solvedAfterReveal = Boolean(before.revealedIn?.includes(variant) ?? before.revealed);
  }
  progress.update(id, patch);
}

/** Send one request for this exercise and show its reply; `op` is "grade" or "run". */
async function submit(ctx, op, payload, { limitMs, onProgress, onWait, saved = {} } = {}) {
  setPending(ctx.el);
  const reply = await ctx.runtime.request({ op, exercise: ctx.id, ...payload }, { limitMs, onProgress, onWait });
  showReply(ctx.el, reply);
  recordAttempt(ctx, reply, saved);
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
        panel.innerHTML = `<p class="admonition-title">${panel.dataset.title}</p>${decodeBase64(panel.dataset.content)}`;
        panel.dataset.rendered = "true";
        ctx.renderMath?.(panel);
      }
      if (toggle(revealButton, panel, showLabel, hideLabel)) {
        const record = progress.get(id);
        const variant = ctx.variant ?? 0;
        if (!record.revealedIn?.includes(variant)) progress.update(id, afterReveal(record, variant, { schedule: ctx.reviewed }));
      }
    });
  }
}

// The page's head holds back a Check pressed before the widget was ready
// (docs/overrides/main.html); now that it is, check that answer.
function replayEarlySubmit(el) {
  const form = ownQuery(el, "form");
  if (!form) return;
  form.dataset.wbReady = "true";
  const early = window.__workbookSubmits || [];
  const at = early.indexOf(form);
  if (at >= 0) {
    early.splice(at, 1);
    form.requestSubmit();
  }
}

/** Start one exercise element once (pages come back with instant navigation). */
export function initExercise(el, shared) {
  if (el.dataset.wbReady) return;
  el.dataset.wbReady = "true";
  const kind = el.getAttribute(ATTR.kind);
  // The variant: a Derive exercise's numbers (variants.js sets it), a Build exercise's hidden
  // tests (a review on the Practise page starts a fresh seed), and what a review's answers count for.
  const ctx = { ...shared, el, id: el.getAttribute(ATTR.exercise), variant: shared.start ?? 0 };
  ctx.reviewed = REVIEW_KINDS.includes(kind); // Derive, Build and Debug join the review queue
  ctx.guessable = kind === "debug"; // a bug found after wrong lines is solved, not clean (review.js)
  ctx.submit = (op, payload, options) => submit(ctx, op, { ...payload, variant: ctx.variant }, options);
  const saved = ctx.progress.get(ctx.id);
  const onScreen = shared.start ?? saved.variant ?? 0;
  if (onScreen === 0 && (saved.done ? saved.done.includes(0) : saved.solved)) {
    el.setAttribute(ATTR.state, STATE.correct);
    showMessage(el, saved.solvedAfterReveal ? "Solved earlier (after revealing the solution)." : "Solved earlier.");
  }
  initHelp(ctx);
  import(`./kinds/${kind}.js`)
    .then((module) => module.init(ctx))
    .then(() => replayEarlySubmit(el))
    .catch((err) => {
      el.setAttribute(ATTR.state, STATE.error);
      showMessage(el, `This exercise could not start: ${err.message}`);
    });
}
