// Variants of a Derive exercise (CONTRACT.md, "Variants"). The grader draws the
// numbers and fills the exercise's own templates (data-templates) with them; this
// module puts the result on the page: statement, hint, derivation, answer label
// and title, typeset, then data-variant last (so a watcher knows the draw is
// complete). The variant on screen is in the address (?variant=0.4-1234), so a
// link opens exactly it, and in the progress record, so a reload keeps it.

import { ATTR, ROLE, STATE, findRole } from "./contract.js";
import { decodeBase64 } from "./exercise.js";
import { showMessage } from "./feedback.js";

const PARAM = "variant";
export const MAX_VARIANT = 999_999;

const encode = (text) => btoa(Array.from(new TextEncoder().encode(text), (b) => String.fromCharCode(b)).join(""));

/** The variant a link asks for, for exercise `id` (?variant=ID-N), or null. */
export function linkedVariant(id, href = location.href) {
  for (const value of new URL(href).searchParams.getAll(PARAM)) {
    const cut = value.lastIndexOf("-");
    const n = value.slice(cut + 1);
    if (value.slice(0, cut) === id && /^\d{1,6}$/.test(n)) return Number(n);
  }
  return null;
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
  const panel = findRole(ctx.el, role);
  const button = findRole(ctx.el, buttonRole);
  if (!panel || !button) return panel;
  panel.hidden = true;
  button.setAttribute("aria-expanded", "false");
  button.textContent = button.textContent.replace(/^Hide/, "Show");
  return panel;
}

function setTitle(ctx, title) {
  const heading = document.getElementById(`${ctx.el.id}-title`);
  const text = heading?.firstChild;
  if (title && text?.nodeType === Node.TEXT_NODE) text.textContent = `${ctx.id} · ${title}`;
}

function showControls(ctx, n) {
  const { el, id } = ctx;
  findRole(el, ROLE.originalVariant).hidden = n === 0;
  findRole(el, ROLE.variantLabel).textContent = n === 0 ? "The workbook's numbers" : `New numbers: variant ${n}`;
  const link = findRole(el, ROLE.variantLink);
  link.hidden = n === 0;
  link.href = variantHref(id, n, el.id);
}

/**
 * Draw variant `n` and put it on the page. `remember`: also into the address
 * and the progress record (not on the Practise page). Resolves to true once the
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
  const label = el.querySelector("label.wb-label");
  if (label) label.innerHTML = v.label;
  setTitle(ctx, v.title);
  ctx.field?.clear();
  findRole(el, ROLE.feedback).replaceChildren();
  el.removeAttribute(ATTR.tag);
  await ctx.renderMath?.(el);
  ctx.variant = v.variant;
  const record = ctx.progress.get(ctx.id);
  el.setAttribute(ATTR.state, record.done?.includes(v.variant) ? STATE.correct : STATE.unanswered);
  showControls(ctx, v.variant);
  if (remember) {
    ctx.progress.update(ctx.id, { variant: v.variant, last: undefined });
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
  findRole(el, ROLE.newVariant).addEventListener("click", () => showVariant(ctx, freshVariant(ctx.variant), { remember }));
  findRole(el, ROLE.originalVariant).addEventListener("click", () => showVariant(ctx, 0, { remember }));
  findRole(el, ROLE.variantLink).addEventListener("click", (event) => {
    event.preventDefault();
    const href = event.currentTarget.href;
    navigator.clipboard?.writeText(href).then(
      () => showMessage(el, "Link copied: it opens this exercise with these numbers."),
      () => showMessage(el, `Link to these numbers: ${href}`),
    );
  });
  const wanted = start ?? linkedVariant(ctx.id) ?? ctx.progress.get(ctx.id).variant ?? 0;
  showControls(ctx, 0);
  if (wanted) {
    findRole(el, ROLE.variantLabel).textContent = `Drawing variant ${wanted}…`;
    return showVariant(ctx, wanted, { remember });
  }
  return true;
}
