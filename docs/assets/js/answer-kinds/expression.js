// A formula answer: one text field, and below it the formula as the grader reads
// it, typeset with KaTeX while the learner types (the "read" op) and after a check.
import { ROLE, ownQuery, ownRole } from "../contract.js";

const PAUSE_MS = 300;

export function init(ctx) {
  const input = ownRole(ctx.el, ROLE.answer);
  const reading = ownQuery(ctx.el, ".wb-reading");
  const show = (latex, message) => {
    reading.replaceChildren();
    if (latex && window.katex) {
      const label = document.createElement("span");
      label.textContent = "Read as: ";
      const math = document.createElement("span");
      window.katex.render(latex, math, { throwOnError: false });
      reading.append(label, math);
    } else if (message) reading.textContent = message;
  };
  let timer = null;
  let asked = 0;
  input.addEventListener("input", () => {
    clearTimeout(timer);
    timer = setTimeout(async () => {
      if (!input.value.trim()) return show();
      const mine = ++asked;
      const reply = await ctx.runtime.request(
        { op: "read", exercise: ctx.id, variant: ctx.variant, step: ctx.step, answer: input.value });
      if (mine === asked && reply.ok) show(reply.value.latex, reply.value.message);
    }, PAUSE_MS);
  });
  return {
    value: () => input.value,
    restore(last) {
      if (typeof last === "string" && !input.value) input.value = last; // what the learner typed meanwhile stays
    },
    clear() {
      input.value = "";
      show();
    },
    show(reply) {
      if (reply.ok && reply.value.data?.latex) show(reply.value.data.latex);
    },
  };
}
