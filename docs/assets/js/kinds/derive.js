// Derive: the answer area comes from the exercise's answer kind (a number, a
// matrix, a formula: docs/assets/js/answer-kinds/<kind>.js); the numbers come
// from the variant on screen (variants.js); this module submits the answer, with
// the learner's earlier answers it builds on (carry.js).
import { ATTR } from "../contract.js";
import { givenFor, showCarried } from "../carry.js";
import { initVariants } from "../variants.js";

export async function init(ctx) {
  const answerKind = ctx.el.getAttribute(ATTR.answerKind);
  const { init: initAnswer } = await import(`../answer-kinds/${answerKind}.js`);
  const field = initAnswer(ctx);
  ctx.field = field;
  if (ctx.el.hasAttribute(ATTR.templates)) await initVariants(ctx, { start: ctx.start ?? null });
  const saved = ctx.progress.get(ctx.id);
  if (saved.last !== undefined && ctx.start == null && ctx.variant === (saved.variant ?? 0)) field.restore(saved.last);
  ctx.el.querySelector("form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = field.value();
    const reply = await ctx.submit("grade", { answer, given: givenFor(ctx) }, { saved: { last: answer } });
    field.show?.(reply);
    showCarried(ctx.el, reply);
  });
}
