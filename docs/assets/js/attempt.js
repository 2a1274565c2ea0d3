// One graded attempt, made once: a Check whose answer the grader graded correct or
// incorrect, or a Build run that it judged (an invalid input or an error is no attempt).
// recordGraded() turns the request and its reply into the attempt, counts it in the
// exercise's record (attempts, solved, the review schedule, the named slip) and tells every
// listener (onAttempt): the assignment page keeps it among the assignment's attempts
// (assignment-page.js), the LMS session reports it (lms/session.js). No DOM here.

import { LIMIT, STATE } from "./contract.js";
import { afterGrade } from "./review.js";
import { countSlip } from "./assignment-schema.js";

const listeners = new Set();

// A named slip is kept by the bank's stable id (data.slipId, e.g. "6.3/cos-minus-one"), the key the class page
// counts re-graded answers by; a verdict without one keeps the name the grader derives (data.slip).
const slipKey = (data) => data?.slipId || data?.slip || null;

/** Call `listener({id, variant, progress, attempt})` after every graded attempt; returns the way to stop. */
export function onAttempt(listener) {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/**
 * The attempt a reply to `request` makes, or null: {answer | code, status, at, tag?, slip?, steps?, given?}
 * (assignment-schema.js checks it). A Build run keeps the code it ran when it fits LIMIT.code.
 */
export function attemptOf(request, reply, at = Date.now()) {
  const status = reply?.ok ? reply.value.status : null;
  if (status !== STATE.correct && status !== STATE.incorrect) return null;
  const { tag, data } = reply.value;
  const what = request.op === "run"
    ? (typeof request.code === "string" && request.code.length <= LIMIT.code ? { code: request.code } : {})
    : { answer: request.answer };
  const filled = (v) => v && Object.keys(v).length > 0;
  const slip = slipKey(data);
  return { ...what, status, at, ...(tag ? { tag } : {}), ...(slip ? { slip } : {}),
    ...(filled(request.steps) ? { steps: request.steps } : {}),
    ...(filled(request.given) ? { given: request.given } : {}) };
}

/**
 * Count a reply to the exercise `ctx` (exercise.js) as an attempt, if it is one: the listeners
 * hear it first, then the exercise's record takes it with `extra` (what the kind keeps, e.g. the
 * last answer). A correct attempt marks the exercise solved, noting whether the solution was
 * revealed first; what it means per variant and for the review queue is review.js's rule.
 */
export function recordGraded(ctx, request, reply, extra = {}) {
  const attempt = attemptOf(request, reply);
  if (!attempt) return null;
  const { id, progress, variant } = ctx;
  for (const listener of listeners) listener({ id, variant, progress, attempt });
  const before = progress.get(id);
  /** @type {Record<string, any>} the record's new fields */
  const patch = { ...extra, attempts: (before.attempts || 0) + 1,
    ...afterGrade(before, variant, attempt.status,
      { schedule: ctx.reviewed, tag: attempt.tag ?? "", guessable: ctx.guessable }) };
  // for the class page
  if (attempt.status === STATE.incorrect && attempt.slip) patch.slips = countSlip(before.slips, attempt.slip);
  if (attempt.status === STATE.correct && !before.solved) {
    patch.solved = true;
    patch.solvedAfterReveal = Boolean(before.revealedIn?.includes(variant) ?? before.revealed);
  }
  progress.update(id, patch);
  return attempt;
}
