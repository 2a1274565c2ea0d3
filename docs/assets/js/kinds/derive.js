// Derive: one answer field; the grader reads numbers, expressions and units.
import { ROLE, findRole } from "../contract.js";

export function init(ctx) {
  const input = findRole(ctx.el, ROLE.answer);
  const saved = ctx.progress.get(ctx.id);
  if (typeof saved.last === "string") input.value = saved.last;
  input.form.addEventListener("submit", (event) => {
    event.preventDefault();
    ctx.submit("grade", { answer: input.value }, { saved: { last: input.value } });
  });
}
