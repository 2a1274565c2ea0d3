// Variants of a Derive exercise (CONTRACT.md, "Variants"). The grader draws the
// numbers and fills the exercise's own templates (data-templates) with them; this
// module puts the result on the page: statement, hint, derivation, answer label
// and title, typeset, then data-variant last (so a watcher knows the draw is
// complete). The variant on screen is in the address (?variant=0.4-1234), so a
// link opens exactly it, and in the progress record, so a reload keeps it.

import { ATTR, LIMIT, ROLE, STATE, ownQuery, ownRole } from "./contract.js";
import { decodeBase64 } from "./exercise.js";
import { showMessage } from "./feedback.js";
import { retitle } from "./jump.js";
import { groupDigits } from "./number-text.js";

const PARAM = "variant";
export const MAX_VARIANT = LIMIT.variant;

const encode = (text) => btoa(Array.from(new TextEncoder().encode(text), (b) => String.fromCharCode(b)).join(""));

const idOf = (value) => value.slice(0, Math.max(0, value.lastIndexOf("-")));
const numberIn = (value) => {
  const n = value.slice(value.lastIndexOf("-") + 1);
  return /^\d{1,6}$/.test(n) ? Number(n) : null;
};
const quote = (text) => `“${text.length > 40 ? `${text.slice(0, 40)}…` : text}”`;

/** The variant a link asks for, for exercise `id` (?variant=ID-N), or null. */
export function linkedVariant(id, href = location.href) {
  for (const value of new URL(href).searchParams.getAll(PARAM)) {
    if (idOf(value) === id && numberIn(value) !== null) return numberIn(value);
  }
  return null;
}

/** A link's ?variant= for exercise `id` that names no set of numbers (the text), or null. */
function badLinkedVariant(id, href = location.href) {
  const values = new URL(href).searchParams.getAll(PARAM).filter((v) => idOf(v) === id);
  return values.length && values.every((v) => numberIn(v) === null) ? values[0] : null;
}

/**
 * What is wrong with the address's ?variant= values that name no exercise on
 * this page (`ids`): sentences for the page, none if all is well.
 */
export function strayVariantLinks(ids, href = location.href) {
  const here = new Set(ids);
  return new URL(href).searchParams.getAll(PARAM).filter((v) => !here.has(idOf(v))).map((v) => (idOf(v)
    ? `The address asks for new numbers for exercise ${quote(idOf(v))}, which is not on this page.`
    : `The address's “variant=${quote(v).slice(1, -1)}” does not name an exercise: a link to new numbers reads like `
      + "“variant=0.4-1234” (exercise 0.4, set 1234)."));
}

/**
 * The ?variant= values that name an exercise of another page, each as a link to
 * it on its chapter page with the same numbers (the chapters from `manifest`,
 * assets/exercises.json; urls relative to `siteRoot`).
 */
export function strayVariantTargets(ids, manifest, siteRoot, href = location.href) {
  const here = new Set(ids);
  const out = [];
  for (const value of new URL(href).searchParams.getAll(PARAM)) {
    const id = idOf(value);
    const chapter = id && !here.has(id) && numberIn(value) !== null
      && manifest?.chapters?.find((c) => c.ids.includes(id));
    if (!chapter) continue;
    const url = new URL(chapter.url, siteRoot);
    url.searchParams.append(PARAM, value);
    url.hash = `ex-${id.replaceAll(".", "-")}`;
    out.push({ id, href: url.href, text: `Open exercise ${id} with these numbers (${chapter.title})` });
  }
  return out;
}

/** `href` with exercise `id` at variant `n` (0 drops it) and its anchor. */
export function variantHref(id, n, anchor, href = location.href) {
  const url = new URL(href);
  const others = url.searchParams.getAll(PARAM).filter((v) => v.slice(0, v.lastIndexOf("-")) !== id);
  url.searchParams.delete(PARAM);
  for (const v of others) url.searchParams.append(PARAM, v);
  if (n) url.searchParams.append(PARAM, `${id}-${n}`);
  url.hash = anchor;
  return url.href;
}

/** A fresh variant number, never `current`. */
export const freshVariant = (current = 0) => {
  const pick = 1 + Math.floor(Math.random() * MAX_VARIANT);
  return pick === current ? (pick % MAX_VARIANT) + 1 : pick;
};

function closePanel(ctx, role, buttonRole) {
  const panel = ownRole(ctx.el, role);
  const button = ownRole(ctx.el, buttonRole);
  if (!panel || !button) return panel;
  panel.hidden = true;
  button.setAttribute("aria-expanded", "false");
  button.textContent = button.textContent.replace(/^Hide/, "Show");
  return panel;
}

function setTitle(ctx, title) {
  const name = document.getElementById(`${ctx.el.id}-name`); // the heading's text (docs/hooks/exercises.py)
  if (!title || !name) return;
  name.textContent = `${ctx.id} · ${title}`;
  retitle(`${ctx.el.id}-title`, ctx.id, title); // the list of exercises and the table of contents
}

function showControls(ctx, n) {
  const { el, id } = ctx;
  // The Practise page always shows new numbers: it offers no way back to the book's.
  ownRole(el, ROLE.originalVariant).hidden = n === 0 || !ctx.remember;
  ownRole(el, ROLE.variantLabel).textContent = n === 0 ? "The workbook's numbers" : "New numbers, drawn for you";
  const link = ownRole(el, ROLE.variantLink);
  link.hidden = n === 0 || !ctx.remember;
  link.href = variantHref(id, n, el.id);
}

/**
 * Draw variant `n` and put it on the page. `remember`: also into the address
 * and the progress record (not on the Practise page); the record's answer and
 * step work go with numbers the learner leaves, and stay with the numbers the
 * record already holds (a reload brings them back). Resolves to true once the
 * variant is on screen, false if the grader could not draw it (the numbers on
 * screen then stay, and say so).
 */
export async function showVariant(ctx, n, { remember = true } = {}) {
  const { el } = ctx;
  const texts = JSON.parse(decodeBase64(el.getAttribute(ATTR.templates)));
  el.setAttribute("aria-busy", "true");
  const reply = await ctx.runtime.request({ op: "draw", exercise: ctx.id, variant: n, texts });
  el.removeAttribute("aria-busy");
  if (!reply.ok) {
    showMessage(el, `New numbers could not be drawn: ${reply.error.message} The numbers on screen stay.`);
    return false;
  }
  const v = reply.value;
  el.querySelector(".wb-prompt").innerHTML = v.prompt;
  const hint = closePanel(ctx, ROLE.hintPanel, ROLE.hint);
  if (hint) hint.innerHTML = `<p class="admonition-title">Hint</p>${v.hint}`;
  const solution = closePanel(ctx, ROLE.solutionPanel, ROLE.reveal);
  if (solution) {
    solution.dataset.content = encode(v.solution);
    delete solution.dataset.rendered;
    solution.replaceChildren();
  }
  const label = ownQuery(el, "label.wb-label");
  if (label) label.innerHTML = v.label;
  setTitle(ctx, v.title);
  ctx.field?.clear();
  ctx.steps?.clear();
  ownRole(el, ROLE.feedback).replaceChildren();
  el.removeAttribute(ATTR.tag);
  await ctx.renderMath?.(el);
  ctx.variant = v.variant;
  const record = ctx.progress.get(ctx.id);
  el.setAttribute(ATTR.state, record.done?.includes(v.variant) ? STATE.correct : STATE.unanswered);
  showControls(ctx, v.variant);
  if (remember) {
    if ((record.variant ?? 0) !== v.variant) {
      // null, not absent: an older copy must not bring the old answer back.
      ctx.progress.update(ctx.id, { variant: v.variant, last: null, stepWork: null });
    }
    history.replaceState(history.state, "", variantHref(ctx.id, v.variant, el.id));
  }
  el.setAttribute(ATTR.variant, String(v.variant));
  return true;
}

/**
 * Wire the controls, and bring back the variant a link asks for or the one
 * left on screen last time. `start` (the Practise page) forces a variant.
 */
export async function initVariants(ctx, { start = null } = {}) {
  const { el } = ctx;
  ctx.variant = 0;
  const remember = start === null;
  ctx.remember = remember;
  ownRole(el, ROLE.newVariant)
    .addEventListener("click", () => showVariant(ctx, freshVariant(ctx.variant), { remember }));
  ownRole(el, ROLE.originalVariant).addEventListener("click", () => showVariant(ctx, 0, { remember }));
  ownRole(el, ROLE.variantLink).addEventListener("click", (event) => {
    event.preventDefault();
    const href = event.currentTarget.href;
    navigator.clipboard?.writeText(href).then(
      () => showMessage(el, "Link copied: it opens this exercise with these numbers."),
      () => showMessage(el, `Link to these numbers: ${href}`),
    );
  });
  const wanted = start ?? linkedVariant(ctx.id) ?? ctx.progress.get(ctx.id).variant ?? 0;
  const bad = remember ? badLinkedVariant(ctx.id) : null;
  showControls(ctx, 0);
  let shown = true;
  if (wanted) {
    ownRole(el, ROLE.variantLabel).textContent = "Drawing new numbers…";
    shown = await showVariant(ctx, wanted, { remember });
  }
  if (bad !== null) {
    const now = ctx.variant ? "the numbers you had here last time are shown" : "the workbook's numbers are shown";
    const asked = quote(bad.slice(bad.lastIndexOf("-") + 1));
    showMessage(el, `This page's address asks for numbers ${asked} for this exercise, `
      + `but a set of numbers is a whole number from 1 to ${groupDigits(MAX_VARIANT)} `
      + `(as in “variant=${ctx.id}-1234”): ${now}.`);
  }
  return shown;
}
