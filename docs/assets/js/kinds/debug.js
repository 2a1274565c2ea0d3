// Debug: a listbox of code lines; one line is selected at a time, by click or keyboard.
// A correct answer's explanation comes with the symptom's figure (role "symptom",
// drawn at build time and hidden until then), if the exercise has one.
import { ATTR, ROLE, STATUS, ownQuery, ownRole, ownRoles } from "../contract.js";

export function init(ctx) {
  const form = ownQuery(ctx.el, "form");
  const lines = ownRoles(ctx.el, ROLE.line);
  const number = (line) => Number(line.getAttribute(ATTR.line));
  let selected = null;
  const select = (line) => {
    selected = line;
    for (const l of lines) {
      l.classList.toggle("is-selected", l === line);
      l.setAttribute("aria-selected", String(l === line));
      l.tabIndex = l === line ? 0 : -1;
    }
  };
  const symptom = ownRole(ctx.el, ROLE.symptom);
  const saved = ctx.progress.get(ctx.id);
  // A review (the Practise page) starts with no line picked: the bug is to be found again.
  const restored = ctx.start == null && lines.find((l) => number(l) === Number(saved.last));
  if (restored) select(restored);
  const onKey = (line, event) => {
    const i = lines.indexOf(line);
    const moves = { ArrowDown: i + 1, ArrowUp: i - 1, Home: 0, End: lines.length - 1 };
    if (event.key in moves) {
      event.preventDefault();
      const target = lines[Math.max(0, Math.min(lines.length - 1, moves[event.key]))];
      line.tabIndex = -1;
      target.tabIndex = 0;
      target.focus();
    } else if (event.key === " " || event.key === "Enter") {
      event.preventDefault();
      select(line);
      if (event.key === "Enter") form.requestSubmit();
    }
  };
  for (const line of lines) {
    line.addEventListener("click", () => select(line));
    line.addEventListener("keydown", (event) => onKey(line, event));
  }
  form.addEventListener("submit", async (event) => {
    event.preventDefault();
    const answer = selected ? number(selected) : null; // none picked: the grader says what to do
    const reply = await ctx.submit("grade", { answer }, { saved: { last: answer } });
    if (symptom) symptom.hidden = !(reply.ok && reply.value.status === STATUS.correct);
  });
}
