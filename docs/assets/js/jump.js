// Keyboard paths to the exercises. A chapter page starts with a "Skip to
// exercises" link (docs/hooks/a11y.py) to the list of its exercises under the
// title (docs/hooks/exercises.py); a link of that list brings the keyboard
// focus to the exercise's answer itself, not just its heading. So from page
// load: Tab, Enter, a Tab per exercise, Enter, and the learner is typing.
//
// The same list and the page's table of contents name each exercise by its
// title, which new numbers may change: retitle() keeps them all in step.

import { ATTR, ROLE, ownRole } from "./contract.js";

// Where an answer starts, by kind: the first of these roles an exercise has.
const ANSWER_ROLES = [ROLE.entry, ROLE.answer, ROLE.choice, ROLE.line, ROLE.editor, ROLE.steps, ROLE.check];
const FOCUSABLE = 'input:not([type="hidden"]):not([disabled]), button:not([disabled]), textarea, select, [tabindex="0"], [contenteditable="true"]';

const visible = (el) => el.getClientRects().length > 0 && !el.closest("[hidden]");

/** The control an exercise's answer starts with (the checked option of a Trace, if one is). */
export function firstControl(exercise) {
  for (const role of ANSWER_ROLES) {
    const area = ownRole(exercise, role);
    if (!area) continue;
    if (role === ROLE.choice) return ownRole(exercise, ROLE.choice, ":checked") || area;
    const target = area.matches(FOCUSABLE) ? area : [...area.querySelectorAll(FOCUSABLE)].find(visible);
    if (target) return target;
  }
  return [...exercise.querySelectorAll(FOCUSABLE)].find(visible) || null;
}

function jumpTo(id) {
  const exercise = document.querySelector(`[${ATTR.exercise}="${CSS.escape(id)}"]`);
  if (!exercise) return false;
  const name = document.getElementById(exercise.getAttribute("aria-labelledby"));
  const heading = name?.closest("h1, h2, h3, h4, h5, h6") || name || exercise;
  heading.scrollIntoView({ block: "start" });
  firstControl(exercise)?.focus({ preventScroll: true });
  history.replaceState(history.state, "", `#${heading.id}`);
  return true;
}

function onClick(event) {
  if (event.defaultPrevented || event.button !== 0 || event.metaKey || event.ctrlKey || event.shiftKey || event.altKey) return;
  const link = event.target.closest?.("a[data-wb-jump], a[data-wb-skip]");
  if (!link) return;
  if (link.hasAttribute("data-wb-skip")) {
    const first = document.querySelector("#wb-exercises a");
    if (!first) return;
    first.focus();
  } else if (!jumpTo(link.dataset.wbJump)) return;
  // The theme's instant navigation would handle the link too: it is done.
  event.preventDefault();
  event.stopPropagation();
}

/** Give exercise `id`'s links (the list under the title, the table of contents) its new title. */
export function retitle(headingId, id, title) {
  // The theme makes in-page links absolute: match the address's end.
  for (const link of document.querySelectorAll(`a[href$="#${CSS.escape(headingId)}"]`)) {
    if (link.closest("h1, h2, h3, h4, h5, h6")) continue; // the heading's own permalink
    const own = link.querySelector("[data-wb-jump-title]");
    if (own) own.textContent = title;
    else (link.querySelector(".md-ellipsis") || link).textContent = `${id} · ${title}`;
  }
}

let started = false;
export function initJumps() {
  if (started) return;
  started = true;
  document.addEventListener("click", onClick, true); // before the theme's own link handling
}
