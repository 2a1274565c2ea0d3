// The teacher's page (docs/teach.md): choose exercises (a chapter at a time or one by one),
// a class code and an optional due date; it writes the assignment link (assignment-link.js).
// Nothing is sent anywhere: the link is made in this page. Links are made from the site's
// public address (mkdocs.yml site_url, in the page's canonical link) when it is known and not
// this computer's own; a page open at a loopback or file address says its links reach no one.

import { assignmentHref, CLASS_CAP, isDate } from "./assignment-link.js";
import { COURSE } from "./contract.js";
import { el } from "./dom.js";
import { listPage } from "./exercise-list.js";

const { attr: A, field: FIELD } = COURSE;
const LOCAL_HOSTS = new Set(["localhost", "127.0.0.1", "[::1]"]);
/** Whether an address is this computer's own (a file, or a loopback host): no student can open it. */
export const isLocal = (href) => {
  const url = new URL(href);
  return url.protocol === "file:" || LOCAL_HOSTS.has(url.hostname) || /^127\./.test(url.hostname)
    || url.hostname.endsWith(".localhost");
};

/** The site's public root from the page's canonical link (site_url + the page's path), or null. */
function publicRoot(siteRoot) {
  const canonical = /** @type {HTMLLinkElement | null} */ (document.querySelector('link[rel="canonical"]'))?.href;
  const path = new URL(location.href).pathname.slice(new URL(siteRoot).pathname.length);
  if (!canonical || !new URL(canonical).pathname.endsWith(path)) return null;
  const root = new URL(canonical);
  root.pathname = root.pathname.slice(0, root.pathname.length - path.length);
  root.hash = root.search = "";
  return root.href;
}

/** Where links lead, and what the page must say about its own address (null: nothing). */
function linkRoot(siteRoot) {
  const known = publicRoot(siteRoot);
  const root = known && !isLocal(known) ? known : siteRoot;
  if (!isLocal(siteRoot)) return { root: siteRoot, warning: null, local: false };
  if (root !== siteRoot) {
    return { root, local: false, warning: `This page is open at ${siteRoot}, on this computer only. The links it makes `
      + `lead to the site's public address, ${root}, where your students open them.` };
  }
  return { root, local: true, warning: `This page is open at ${siteRoot}, an address on this computer only: links made `
    + `here reach no one else. `
    + "Host the site for your class (GitHub Pages from a fork, any static host, or the SCORM package in your course's "
    + "platform) and make the links there: " };
}

let serial = 0;
const uid = (stem) => `wb-teach-${stem}-${++serial}`;

function field(label, input, help) {
  input.id ||= uid("field");
  const parts = [el("label", { htmlFor: input.id, textContent: label }), input];
  if (help) {
    const note = el("p", { id: uid("help"), className: "wb-course-help", textContent: help });
    input.setAttribute("aria-describedby", note.id);
    parts.push(note);
  }
  return el("div", { className: "wb-course-field" }, ...parts);
}

// An exercise whose right answer students may share (manifest.sameAnswer, from the bank: the same for all, or from a
// short list) says so beside its box, with the reason: per-student numbers do not stop copying there.
function sameNote(why) {
  if (!why) return "";
  const note = el("span", { className: "wb-teach-same", textContent: ` (students may share this answer: ${why})` });
  note.setAttribute(A.sameAnswer, "");
  return note;
}

function chapterBox(chapter, titles, same) {
  const all = el("input", { type: "checkbox", id: uid("chapter") });
  all.setAttribute(COURSE.attr.chapter, chapter.url);
  const boxes = chapter.ids.map((id) => {
    const box = el("input", { type: "checkbox", value: id, id: uid("ex") });
    box.setAttribute(COURSE.attr.exercise, id);
    return el("li", {}, box, el("label", { htmlFor: box.id, textContent: ` ${id} · ${titles?.[id] ?? ""}` },
      sameNote(same?.[id])));
  });
  const inputs = () => [...list.querySelectorAll(`input[${COURSE.attr.exercise}]`)];
  const list = el("ul", { className: "wb-teach-exercises" }, ...boxes);
  all.addEventListener("change", () => inputs().forEach((b) => { b.checked = all.checked; }));
  list.addEventListener("change", () => {
    const n = inputs().filter((b) => b.checked).length;
    all.checked = n === chapter.ids.length;
    all.indeterminate = n > 0 && n < chapter.ids.length;
  });
  return el("fieldset", { className: "wb-teach-chapter" },
    el("legend", {}, all, el("label", { htmlFor: all.id, textContent: ` ${chapter.title} (the whole chapter)` })),
    list);
}

export async function initTeach(siteRoot) {
  const page = await listPage(A.teach, siteRoot);
  if (!page) return;
  const { root, manifest } = page;
  const where = linkRoot(siteRoot);
  const code = el("input", { type: "text", maxLength: CLASS_CAP, autocomplete: "off", required: true });
  code.setAttribute(A.field, FIELD.class);
  const due = el("input", { type: "date" });
  due.setAttribute(A.field, FIELD.due);
  const chapters = manifest.chapters.map((c) => chapterBox(c, manifest.titles, manifest.sameAnswer));
  const make = el("button", { type: "submit", className: "md-button md-button--primary",
    textContent: "Make the link" });
  const status = el("p", { role: "status", className: "wb-course-status" });
  const out = el("input", { type: "text", readOnly: true, id: uid("link") });
  out.setAttribute(A.field, FIELD.link);
  const copy = el("button", { type: "button", className: "md-button", textContent: "Copy the link" });
  copy.setAttribute(A.action, COURSE.action.copyLink);
  const result = el("div", { className: "wb-teach-result", hidden: true },
    el("label", { htmlFor: out.id, textContent: "The assignment link" }), out,
    el("div", { className: "wb-course-actions" }, copy));
  const form = el("form", { className: "wb-teach-form", noValidate: true },
    field("Class code", code, "Any text that names this class and assignment, e.g. ROB101-week3. Each student's "
    + "numbers come from it: a new code gives everyone new numbers."),
    field("Due date (optional)", due, "Shown to the learners; the workbook does not lock anything after it."),
    el("h2", { textContent: "Exercises" }), ...chapters,
    el("div", { className: "wb-course-actions" }, make), status, result);
  const guide = el("a", { href: new URL("teaching/hosting/", siteRoot).href,
    textContent: "Hosting the workbook for a class" });
  const warning = where.warning
    ? el("p", { className: "wb-course-problem" }, where.warning, ...(where.local ? [guide, "."] : [])) : null;
  if (warning) warning.setAttribute(A.hostWarning, where.local ? "local" : "public");
  root.replaceChildren(...(warning ? [warning] : []), form);
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    const ids = [...form.querySelectorAll(`input[${COURSE.attr.exercise}]:checked`)].map((b) => b.value);
    const problems = [];
    if (!code.value.trim()) problems.push("Give the class code.");
    if (!ids.length) problems.push("Choose at least one exercise.");
    // A date field holds "" for a date that is not one (30 February): its badInput says so.
    const badDue = due.validity.badInput || (due.value !== "" && !isDate(due.value));
    if (badDue) problems.push("The due date is not a day of the calendar (e.g. 30 February): choose another, or leave "
      + "it empty.");
    code.setAttribute("aria-invalid", String(!code.value.trim()));
    due.setAttribute("aria-invalid", String(badDue));
    if (problems.length) {
      status.textContent = problems.join(" ");
      result.hidden = true;
      return;
    }
    out.value = assignmentHref(where.root, { code: code.value.trim(), ids, due: due.value || null });
    result.hidden = false;
    const sets = `The link sets ${ids.length} exercise${ids.length === 1 ? "" : "s"}.`;
    status.textContent = where.local
      ? `${sets} It leads to this computer only: make the link again where the site is hosted for your class.`
      : `${sets} Send it to your class; each student gets their own numbers.`;
  });
  copy.addEventListener("click", () => {
    out.select();
    navigator.clipboard?.writeText(out.value).then(() => { status.textContent = "Link copied."; }, () =>
      { status.textContent = "Select the link and copy it."; });
  });
}
