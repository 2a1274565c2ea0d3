// Design: reorder steps by the move buttons (keyboard and touch) or by drag and drop.
import { ATTR, ROLE, byRole, ownQuery, ownRole, ownRoles } from "../contract.js";
import { showMessage } from "../feedback.js";

export function init(ctx) {
  const list = ownRole(ctx.el, ROLE.steps);
  const steps = () => ownRoles(list, ROLE.step);
  const order = () => steps().map((s) => s.getAttribute(ATTR.step));
  const saved = ctx.progress.get(ctx.id);
  const savedOrder = saved.draftOrder || saved.last;
  if (Array.isArray(savedOrder)) {
    const byKey = new Map(steps().map((s) => [s.getAttribute(ATTR.step), s]));
    if (savedOrder.length === byKey.size && savedOrder.every((k) => byKey.has(k))) {
      for (const k of savedOrder) list.append(byKey.get(k));
    }
  }
  const announce = (step) => {
    const text = step.querySelector(".wb-step-text").textContent;
    showMessage(ctx.el, `“${text}” is now step ${steps().indexOf(step) + 1} of ${steps().length}.`);
  };
  const move = (step, delta) => {
    const all = steps();
    const j = all.indexOf(step) + delta;
    if (j < 0 || j >= all.length) return;
    if (delta < 0) list.insertBefore(step, all[j]);
    else list.insertBefore(all[j], step);
    ctx.progress.update(ctx.id, { draftOrder: order() });
    announce(step);
  };
  list.addEventListener("click", (event) => {
    const button = event.target.closest(`${byRole(ROLE.moveUp)},${byRole(ROLE.moveDown)}`);
    if (!button) return;
    move(button.closest(byRole(ROLE.step)), button.getAttribute(ATTR.role) === ROLE.moveUp ? -1 : 1);
    button.focus();
  });
  initDrag(list, announce);
  ownQuery(ctx.el, "form").addEventListener("submit", (event) => {
    event.preventDefault();
    const answer = order();
    ctx.submit("grade", { answer }, { saved: { last: answer } });
  });
}

// HTML5 drag and drop; the buttons are the keyboard and touch path.
function initDrag(list, announce) {
  let dragged = null;
  list.addEventListener("dragstart", (event) => {
    dragged = event.target.closest(byRole(ROLE.step));
    if (!dragged) return;
    dragged.classList.add("is-dragging");
    event.dataTransfer.effectAllowed = "move";
    event.dataTransfer.setData("text/plain", dragged.getAttribute(ATTR.step));
  });
  list.addEventListener("dragover", (event) => {
    if (!dragged) return;
    event.preventDefault();
    const over = event.target.closest(byRole(ROLE.step));
    if (!over || over === dragged) return;
    const rect = over.getBoundingClientRect();
    list.insertBefore(dragged, event.clientY > rect.top + rect.height / 2 ? over.nextSibling : over);
  });
  list.addEventListener("dragend", () => {
    if (!dragged) return;
    dragged.classList.remove("is-dragging");
    announce(dragged);
    dragged = null;
  });
}
