// Derive: the answer area comes from the exercise's answer kind (a number, a
// matrix, a formula: docs/assets/js/answer-kinds/<kind>.js); this module submits it.
import { ATTR } from "../contract.js";

export async function init(ctx) {
  const answerKind = ctx.el.getAttribute(ATTR.answerKind);
  const { init: initAnswer } = await import(`../answer-kinds/${answerKind}.js`);
  const field = initAnswer(ctx);
  const saved = ctx.progress.get(ctx.id);
  if (saved.last !== undefined) field.restore(saved.last);
  ctx.el.querySelector("form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = field.value();
    const reply = await ctx.submit("grade", { answer }, { saved: { last: answer } });
    field.show?.(reply);
  });
}
