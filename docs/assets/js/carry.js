// Error carried forward (CONTRACT.md, "Chains"). An exercise that builds on
// earlier ones names them in data-uses; each grade request carries the
// learner's last answers to them (from the progress records), and the grader
// decides whether this answer follows from a wrong one. Its verdict then says
// so (tag "carried"); this module marks the element with data-carried and puts
// the grader's link back to the earlier exercise under the message.

import { ATTR, ROLE, TAG } from "./contract.js";
import { feedbackOf } from "./feedback.js";
import { variantHref } from "./variants.js";

/** {ID: {answer, variant}} of the learner's last graded answers to the exercises this one uses, or undefined. */
export function givenFor(ctx) {
  const given = {};
  for (const id of (ctx.el.getAttribute(ATTR.uses) || "").split(" ").filter(Boolean)) {
    const record = ctx.progress.get(id);
    if (record.last !== undefined && record.last !== null) given[id] = { answer: record.last, variant: record.variant ?? 0 };
  }
  return Object.keys(given).length ? given : undefined;
}

/** After a reply: data-carried and the link back, or neither. */
export function showCarried(el, reply) {
  const carried = reply.ok && reply.value.tag === TAG.carried ? reply.value.data?.carried : null;
  if (!carried?.from) { // none, or carried from a step of this exercise (steps.js shows that one)
    el.removeAttribute(ATTR.carried);
    return;
  }
  el.setAttribute(ATTR.carried, carried.from);
  const source = document.querySelector(`[${ATTR.exercise}="${CSS.escape(carried.from)}"]`);
  if (!source) return;
  const link = document.createElement("a");
  link.setAttribute(ATTR.role, ROLE.carriedFrom);
  link.href = variantHref(carried.from, carried.variant, source.id);
  link.textContent = carried.link;
  const p = document.createElement("p");
  p.append(link);
  feedbackOf(el).append(p);
}
