// "Work it in steps" (CONTRACT.md, "Checked steps"). A Derive exercise with
// data-steps has a button (work-steps-open) and a panel (work-steps) whose list
// waits in a <template> until it first opens. Each step (work-step, with
// data-step-name) is an answer widget of its own answer kind, with its own
// Check and feedback: its request names the step and carries the learner's
// answers to the earlier steps, so the grader can carry a wrong one forward.
// The steps on screen, with their verdicts, are kept in the progress record
// (stepWork) for the variant on screen; new numbers clear them.

import { ATTR, ROLE, STATE, STATUS, findRoles, ownQuery, ownRole } from "./contract.js";
import { backTo, showCarried as showCarriedFrom } from "./carry.js";
import { feedbackOf, showReply } from "./feedback.js";
import { firstControl } from "./jump.js";
import { afterStep } from "./review.js";

/** Whether a widget's value holds anything typed (a text, or a grid with one entry filled). */
const typed = (value) =>
  (Array.isArray(value) ? value.flat().some((t) => String(t).trim()) : String(value ?? "").trim() !== "");

/** The way back to an earlier step: a button that opens the steps and puts the focus in that step's input
 * (a button, not an in-page link: the theme's instant navigation would take the link's click over). */
function stepLink(steps, name, text) {
  const button = document.createElement("button");
  button.type = "button";
  button.className = "wb-link-button";
  button.setAttribute(ATTR.role, ROLE.carriedFrom);
  button.textContent = text;
  button.addEventListener("click", () => steps.focus(name));
  return button;
}

class Steps {
  constructor(ctx, button, panel) {
    this.ctx = ctx;
    /** @type {HTMLButtonElement} */
    this.button = button;
    /** @type {HTMLElement} */
    this.panel = panel;
    /** @type {Map<string, any>} a step's name -> its widget */
    this.fields = new Map();
    /** @type {Promise<void> | null} */
    this.built = null;
    button.addEventListener("click", () => (this.isOpen() ? this.close() : this.open()));
  }

  names() {
    return (this.ctx.el.getAttribute(ATTR.steps) || "").split(" ").filter(Boolean);
  }

  item(name) {
    return findRoles(this.panel, ROLE.workStep).find((li) => li.getAttribute(ATTR.stepName) === name) ?? null;
  }

  isOpen() {
    return !this.panel.hidden;
  }

  /** Put the list on the page (once) and wire each step's widget. */
  build() {
    this.built ??= (async () => {
      const template = /** @type {HTMLTemplateElement} */ (this.panel.querySelector(":scope > template"));
      this.panel.append(template.content.cloneNode(true));
      for (const li of findRoles(this.panel, ROLE.workStep)) await this.wire(li);
    })();
    return this.built;
  }

  async wire(li) {
    const name = li.getAttribute(ATTR.stepName);
    const { init } = await import(`./answer-kinds/${li.getAttribute(ATTR.answerKind)}.js`);
    // The step's widget sees the exercise's context (runtime, id, the variant on screen) with its own element.
    const stepCtx = Object.create(this.ctx, { el: { value: li }, step: { value: name } });
    const field = init(stepCtx);
    this.fields.set(name, field);
    const form = ownQuery(li, "form");
    form.dataset.wbReady = "true"; // the page's early-submit guard (docs/overrides/main.html) lets it through
    form.addEventListener("submit", (event) => {
      event.preventDefault();
      this.check(name);
    });
  }

  async open({ focus = null } = {}) {
    await this.build();
    this.panel.hidden = false;
    this.button.setAttribute("aria-expanded", "true");
    this.button.textContent = "Hide the steps";
    this.showOffer();
    if (focus) this.focus(focus);
  }

  close() {
    this.panel.hidden = true;
    this.button.setAttribute("aria-expanded", "false");
    this.button.textContent = "Work it in steps";
    this.showOffer();
  }

  /** The offer to start the steps stands only while they are closed (never beside "Hide the steps"). */
  showOffer() {
    const offer = ownRole(this.ctx.el, ROLE.workStepsOffer);
    if (offer) offer.parentElement.hidden = this.isOpen();
  }

  /** Open the steps and put the focus in step `name`'s input. */
  async focus(name) {
    if (!this.isOpen()) await this.open();
    const li = this.item(name);
    const target = li && firstControl(li);
    target?.focus();
    target?.select?.();
  }

  /** The learner's answers to the steps, by name: those before `before` (all when null), typed ones only. */
  answers(before = null) {
    const out = {};
    for (const name of this.names()) {
      if (name === before) break;
      const value = this.fields.get(name)?.value();
      if (value !== undefined && typed(value)) out[name] = value;
    }
    return out;
  }

  async check(name) {
    const { ctx } = this;
    const li = this.item(name);
    const field = this.fields.get(name);
    const answer = field.value();
    const payload = { step: name, answer, steps: this.answers(name), given: ctx.given?.() };
    const reply = await ctx.submit("grade", payload, { on: li });
    if (!reply) return; // new numbers came while it was graded: this verdict is stale
    field.show?.(reply);
    this.showCarried(li, reply);
    if (reply.ok) this.save(name, answer, reply.value);
  }

  /**
   * A carried verdict's way back: to the learner's earlier step (here), or to an earlier
   * exercise (carry.js; the exercise's own answer has had that already). True for a step.
   */
  showCarried(el, reply) {
    if (el !== this.ctx.el) showCarriedFrom(el, reply);
    const carried = backTo(reply);
    if (!carried?.step) return false;
    if (el !== this.ctx.el) el.setAttribute(ATTR.carried, carried.step); // an exercise's data-carried names an exercise
    const p = document.createElement("p");
    p.append(stepLink(this, carried.step, carried.link));
    feedbackOf(el).append(p);
    return true;
  }

  save(name, answer, verdict) {
    const { ctx } = this;
    const { variant } = ctx;
    const record = ctx.progress.get(ctx.id);
    const kept = record.stepWork?.variant === variant ? record.stepWork.steps : {};
    const carried = backTo({ ok: true, value: verdict }) ?? undefined;
    const step = {
      answer, status: verdict.status, message: verdict.message, ...(verdict.tag ? { tag: verdict.tag } : {}),
      ...(carried ? { carried } : {}) };
    // The Practise page (ctx.start) shows its own numbers: the chapter's steps on screen stay as they were.
    const onScreen = ctx.start == null ? { stepWork: { variant, steps: { ...kept, [name]: step } } } : {};
    ctx.progress.update(ctx.id, { ...afterStep(record, variant, verdict.status, verdict.tag), ...onScreen });
  }

  /** The steps kept for the variant on screen: answers and verdicts back, the panel open. */
  async restore() {
    const work = this.ctx.progress.get(this.ctx.id).stepWork;
    if (!work || work.variant !== this.ctx.variant || !Object.keys(work.steps).length) return;
    await this.open();
    for (const [name, step] of Object.entries(work.steps)) {
      const li = this.item(name);
      if (!li) continue;
      this.fields.get(name).restore(step.answer);
      if (!step.status) continue;
      const value = {
        status: step.status, tag: step.tag ?? null, message: step.message ?? "", data: { carried: step.carried } };
      const reply = { ok: true, value };
      showReply(li, reply);
      this.showCarried(li, reply);
    }
  }

  /** New numbers: every step empty, no verdict. */
  clear() {
    for (const li of findRoles(this.panel, ROLE.workStep)) {
      this.fields.get(li.getAttribute(ATTR.stepName))?.clear();
      li.setAttribute(ATTR.state, STATE.unanswered);
      for (const name of [ATTR.tag, ATTR.carried, "aria-busy"]) li.removeAttribute(name);
      feedbackOf(li).replaceChildren();
    }
  }

  /** After a wrong final answer: offer the first step to look at (data.steps), which opens there. */
  offer(verdict) {
    const first = verdict?.status === STATUS.incorrect ? verdict.data?.steps : null;
    if (!first) return;
    const button = document.createElement("button");
    button.type = "button";
    button.className = "md-button wb-help-button";
    button.setAttribute(ATTR.role, ROLE.workStepsOffer);
    button.textContent = `Work it in steps — start with step ${first.number} (${first.label})`;
    button.addEventListener("click", () => this.focus(first.first));
    const p = document.createElement("p");
    p.append(button);
    ownRole(this.ctx.el, ROLE.feedback).append(p);
    this.showOffer();
  }
}

/** Wire an exercise's checked steps, if it has any: the controller (ctx.steps), or null. */
export function initSteps(ctx) {
  const button = ownRole(ctx.el, ROLE.workStepsOpen);
  const panel = ownRole(ctx.el, ROLE.workSteps);
  if (!button || !panel) return null;
  return new Steps(ctx, button, panel);
}

/** After the final answer's reply: a link back to a wrong step it follows from, or the offer of the first step. */
export function afterFinal(ctx, reply) {
  if (!ctx.steps || !reply.ok) return;
  if (!ctx.steps.showCarried(ctx.el, reply)) ctx.steps.offer(reply.value);
}
