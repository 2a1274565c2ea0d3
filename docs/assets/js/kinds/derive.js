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
  if (saved.last !== undefined && ctx.start == null && ctx.variant === (saved.variant ?? 0)) field.restore(saved.last);
  if (ctx.start == null) await ctx.steps?.restore();
  ownQuery(ctx.el, "form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = field.value();
    const steps = ctx.steps?.answers();
    const reply = await ctx.submit("grade", { answer, given: givenFor(ctx), ...(steps && Object.keys(steps).length ? { steps } : {}) },
      { saved: { last: answer } });
    field.show?.(reply);
    showCarried(ctx.el, reply);
    afterFinal(ctx, reply);
  });
}
