// A number or an expression in one text field (the grader reads units and forms).
import { ROLE, ownRole } from "../contract.js";

export function init(ctx) {
  const input = ownRole(ctx.el, ROLE.answer);
  return {
    value: () => input.value,
    restore(last) {
      if (typeof last === "string" && !input.value) input.value = last; // what the learner typed meanwhile stays
    },
    clear() {
      input.value = "";
    },
  };
}
