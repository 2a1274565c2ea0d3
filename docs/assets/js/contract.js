// The page contract, as JavaScript names. esbuild bundles the same JSON file the
// grading package reads (pyodide_pkg/workbook/contract.json): names and limits only, so
// the page and both workers ship no prose; CONTRACT.md explains every entry.
import contract from "../../../pyodide_pkg/workbook/contract.json" with { type: "json" };

const names = (values) =>
  Object.freeze(Object.fromEntries(values.map((v) => [v.replace(/-(\w)/g, (_, c) => c.toUpperCase()), v])));

export const ATTR = Object.freeze({ ...contract.attributes });
export const ROLE = names(contract.roles);
export const STATE = names(contract.states);
export const STATUS = names(contract.statuses);
export const TAG = names(contract.tags);
export const ERROR = names(contract.errors);
export const RUNTIME = names(contract.runtimeStates);
export const OFFLINE = names(contract.offlineStates);
export const LMS = names(contract.lmsStates); // <html data-workbook-lms>: the SCORM session (lms/session.js)
export const BOOT_PHASE = names(contract.bootPhases);
export const KINDS = Object.freeze([...contract.kinds]);
export const ANSWER_KINDS = Object.freeze([...contract.answerKinds]);
export const REVIEW_KINDS = Object.freeze([...contract.reviewKinds]); // the kinds that join the review queue
/** Numbers the grader enforces too: the largest variant, steps and earlier answers a request carries, an entry's
 *  characters. */
export const LIMIT = Object.freeze({ ...contract.limits });
/** The course pages' stable names (CONTRACT.md, "Assignments and the class page"): attributes, actions, fields,
 *  cell states, ids. */
export const COURSE = Object.freeze({
  attr: Object.freeze({ ...contract.course.attributes }),
  action: names(contract.course.actions),
  field: names(contract.course.fields),
  cell: names(contract.course.cells),
  id: names(contract.course.ids),
});

/** `[data-role="NAME"]`, optionally with more attribute tests. */
export const byRole = (role, extra = "") => `[${ATTR.role}="${role}"]${extra}`;
/** The first (or every) element with `role` inside `el`. */
export const findRole = (el, role, extra) => el.querySelector(byRole(role, extra));
export const findRoles = (el, role, extra) => [...el.querySelectorAll(byRole(role, extra))];
/** @typedef {{ documentElement: { setAttribute(name: string, value: string): void } }} RootDocument */
/** Set <html data-workbook-runtime|offline>: the page's (workers import this module for its names alone). */
export const setRootState = (which, value) =>
  /** @type {{ document: RootDocument }} */ (/** @type {unknown} */ (globalThis)).document.documentElement
    .setAttribute(ATTR[which], value);
// An exercise's checked steps (role work-steps) hold answer widgets of their own, which reuse the
// answer roles (answer, entry, ...). The exercise's OWN answer, check, feedback and other parts
// are those outside any steps panel inside `el`; for a step's element, its own parts.
// The panel itself is the exercise's.
const panelOf = (node) => node.parentElement?.closest(byRole(ROLE.workSteps)) ?? null;
/** The first (or every) element with `role` that belongs to `el` itself, not to a step panel inside it. */
export const ownRoles = (el, role, extra) => findRoles(el, role, extra).filter((node) => panelOf(node) === panelOf(el));
export const ownRole = (el, role, extra) => ownRoles(el, role, extra)[0] ?? null;
/** `el`'s own first element matching a CSS selector (the answer form, a label), outside any steps panel inside it. */
export const ownQuery = (el, selector) =>
  [...el.querySelectorAll(selector)].find((node) => panelOf(node) === panelOf(el)) ?? null;
