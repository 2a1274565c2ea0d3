// Trace: one radio option; the reply explains the option picked.
import { ROLE, ownQuery, ownRoles } from "../contract.js";

export function init(ctx) {
  const choices = ownRoles(ctx.el, ROLE.choice);
  const saved = ctx.progress.get(ctx.id);
  // The stored pick comes back unless the learner picked one before this script started.
  if (!choices.some((c) => c.checked)) for (const c of choices) if (c.value === saved.last) c.checked = true;
  ownQuery(ctx.el, "form").addEventListener("submit", (event) => {
    event.preventDefault();
    const answer = choices.find((c) => c.checked)?.value ?? null; // none picked: the grader says what to do
    ctx.submit("grade", { answer }, { saved: { last: answer } });
  });
}
