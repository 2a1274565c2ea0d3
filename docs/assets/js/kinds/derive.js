// Derive: the answer area comes from the exercise's answer kind (a number, a
// matrix, a formula: docs/assets/js/answer-kinds/<kind>.js); the numbers come
// from the variant on screen (variants.js); this module submits the answer, with
// the learner's earlier answers it builds on (carry.js) and the answers to its
// checked steps (steps.js).
import { ATTR, ownQuery } from "../contract.js";
import { givenFor, showCarried } from "../carry.js";
import { initVariants } from "../variants.js";
import { afterFinal, initSteps } from "../steps.js";

export async function init(ctx) {
  const answerKind = ctx.el.getAttribute(ATTR.answerKind);
  const { init: initAnswer } = await import(`../answer-kinds/${answerKind}.js`);
  const field = initAnswer(ctx);
  ctx.field = field;
  ctx.given = () => givenFor(ctx);
  ctx.steps = initSteps(ctx); // "Work it in steps", when the exercise has checked steps
  if (ctx.el.hasAttribute(ATTR.templates)) await initVariants(ctx, { start: ctx.start ?? null });
  const saved = ctx.progress.get(ctx.id);
  if (ctx.start == null) {
    if (saved.last !== undefined && ctx.variant === (saved.variant ?? 0)) field.restore(saved.last);
    await ctx.steps?.restore();
  } else if (ctx.resume != null && ctx.variant === ctx.start) field.restore(ctx.resume);
  ownQuery(ctx.el, "form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = field.value();
    const steps = ctx.steps?.answers();
    // The record's `last` is the chapter's answer, to its own numbers: an answer to numbers a page forced
    // (the Practise page's review, an assignment's) is not put there, or the chapter would show it. The
    // record's variant names the numbers `last` answered: another tab may have drawn others meanwhile.
    const recorded = ctx.progress.get(ctx.id).variant ?? 0;
    const saved = ctx.start != null ? {} : recorded === ctx.variant ? { last: answer } : { last: answer,
      variant: ctx.variant };
    const reply = await ctx.submit("grade", { answer, given: givenFor(ctx), ...(steps && Object.keys(steps).length
      ? { steps } : {}) },
      { saved });
    field.show?.(reply);
    showCarried(ctx.el, reply);
    afterFinal(ctx, reply);
  });
}
