// Error carried forward (CONTRACT.md, "Chains"). An exercise that builds on
// earlier ones names them in data-uses; each grade request carries the
// learner's last answers to them (from the progress records), and the grader
// decides whether this answer follows from a wrong one. Its verdict then says
// so (tag "carried"); this module marks the element with data-carried and puts
// the grader's link back to the earlier exercise under the message.

import { ATTR, LIMIT, ROLE, TAG } from "./contract.js";
import { feedbackOf } from "./feedback.js";
import { variantHref } from "./variants.js";

const usesOf = (el) => (el?.getAttribute(ATTR.uses) || "").split(" ").filter(Boolean);

/**
 * {ID: {answer, variant}} of the learner's last graded answers to the exercises this one
 * uses, and to those they use in turn (so the grader can name where a slip started), or undefined.
 */
export function givenFor(ctx) {
  const given = {};
  const queue = usesOf(ctx.el);
  while (queue.length && Object.keys(given).length < LIMIT.given) {
    const id = queue.shift();
    if (id in given) continue;
    const record = ctx.progress.get(id);
    if (record.last === undefined || record.last === null) continue;
    given[id] = { answer: record.last, variant: record.variant ?? 0 };
    queue.push(...usesOf(document.querySelector(`[${ATTR.exercise}="${CSS.escape(id)}"]`)));
  }
  return Object.keys(given).length ? given : undefined;
}

/** Where a verdict points back to (tag carried or undefined: `data.carried`), or null. */
export function backTo(reply) {
  return reply.ok && [TAG.carried, TAG.undefined].includes(reply.value.tag) ? reply.value.data?.carried ?? null : null;
}

/** After a reply: data-carried and the link back, or neither. */
export function showCarried(el, reply) {
  const carried = backTo(reply);
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
