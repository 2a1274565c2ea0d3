// Keyboard paths to the exercises. A chapter page starts with a "Skip to
// exercises" link (docs/hooks/a11y.py) to the list of its exercises under the
// title (docs/hooks/exercises.py); a link of that list brings the keyboard
// focus to the exercise's answer itself, not just its heading. So from page
// load: Tab, Enter, a Tab per exercise, Enter, and the learner is typing.
//
// The same list and the page's table of contents name each exercise by its
// title, which new numbers may change: retitle() keeps them all in step.
//
// Every link to a place on this same page (the table of contents, a heading's
// permalink, a carried answer's "Back to exercise 3.7") is followed here, not by
// the theme's instant navigation, which would fetch the page again and rebuild
// it, losing every verdict, run and open hint on it: moving inside a page
// changes nothing on it. A link to an exercise itself brings the focus to its answer.

import { ATTR, ROLE, ownRole } from "./contract.js";

// Where an answer starts, by kind: the first of these roles an exercise has.
const ANSWER_ROLES = [ROLE.entry, ROLE.answer, ROLE.choice, ROLE.line, ROLE.editor, ROLE.steps, ROLE.check];
const FOCUSABLE = 'input:not([type="hidden"]):not([disabled]), button:not([disabled]), textarea, select, '
  + '[tabindex="0"], [contenteditable="true"]';

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

function jumpTo(id, url = null) {
  const exercise = document.querySelector(`[${ATTR.exercise}="${CSS.escape(id)}"]`);
  if (!exercise) return false;
  const name = document.getElementById(exercise.getAttribute("aria-labelledby"));
  const heading = name?.closest("h1, h2, h3, h4, h5, h6") || name || exercise;
  heading.scrollIntoView({ block: "start" });
  firstControl(exercise)?.focus({ preventScroll: true });
  if (url) history.pushState(null, "", url.href);
  else history.replaceState(history.state, "", `#${heading.id}`);
  return true;
}

/** The address `link` leads to if it is a place on this page (same path, an anchor), else null. */
function inPage(link) {
  if (!link.href || link.target || link.hasAttribute("download")) return null;
  const url = new URL(link.href, location.href);
  if (url.origin !== location.origin || url.pathname !== location.pathname || url.hash.length < 2) return null;
  return url;
}

/** Follow a link to `url`, a place on this page, without reloading or rebuilding anything. */
function moveTo(url) {
  let target;
  try {
    target = document.getElementById(decodeURIComponent(url.hash.slice(1)));
  } catch {
    return false;
  }
  if (!target) return false;
  const drawer = /** @type {HTMLInputElement | null} */ (document.querySelector('input[data-md-toggle="drawer"]'));
  if (drawer?.checked) drawer.click(); // a link in the phone's menu: close it, as a page change would
  if (target.hasAttribute(ATTR.exercise)) return jumpTo(target.getAttribute(ATTR.exercise), url);
  history.pushState(null, "", url.href);
  target.scrollIntoView({ block: "start" });
  return true;
}

function onClick(event) {
  const modified = event.metaKey || event.ctrlKey || event.shiftKey || event.altKey;
  if (event.defaultPrevented || event.button !== 0 || modified) return;
  const link = event.target.closest?.("a[href]");
  if (!link) return;
  if (link.hasAttribute("data-wb-skip")) {
    const first = /** @type {HTMLAnchorElement | null} */ (document.querySelector("#wb-exercises a"));
    if (!first) return;
    first.focus();
  } else if (link.hasAttribute("data-wb-jump")) {
    if (!jumpTo(link.dataset.wbJump)) return;
  } else {
    const url = inPage(link);
    if (!url || !moveTo(url)) return;
  }
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
