// The teacher's page (docs/teach.md): choose exercises (a chapter at a time or one by one),
// a class code and an optional due date; it writes the assignment link (assignment-link.js).
// Nothing is sent anywhere: the link is made in this page.

import { assignmentHref, CLASS_CAP } from "./assignment-link.js";
import { el, listPage } from "./progress-view.js";

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

// An exercise whose right answer is the same for every student (manifest.sameAnswer, from the bank)
// says so beside its box, with the reason: per-student numbers do not stop copying there.
function sameNote(why) {
  if (!why) return "";
  const note = el("span", { className: "wb-teach-same", textContent: ` (same answer for every student: ${why})` });
  note.dataset.wbSameAnswer = "";
  return note;
}

function chapterBox(chapter, titles, same) {
  const all = el("input", { type: "checkbox", id: uid("chapter") });
  all.dataset.wbChapter = chapter.url;
  const boxes = chapter.ids.map((id) => {
    const box = el("input", { type: "checkbox", value: id, id: uid("ex") });
    box.dataset.wbExercise = id;
    return el("li", {}, box, el("label", { htmlFor: box.id, textContent: ` ${id} · ${titles?.[id] ?? ""}` }, sameNote(same?.[id])));
  });
  const inputs = () => [...list.querySelectorAll("input[data-wb-exercise]")];
  const list = el("ul", { className: "wb-teach-exercises" }, ...boxes);
  all.addEventListener("change", () => inputs().forEach((b) => { b.checked = all.checked; }));
  list.addEventListener("change", () => {
    const n = inputs().filter((b) => b.checked).length;
    all.checked = n === chapter.ids.length;
    all.indeterminate = n > 0 && n < chapter.ids.length;
  });
  return el("fieldset", { className: "wb-teach-chapter" },
    el("legend", {}, all, el("label", { htmlFor: all.id, textContent: ` ${chapter.title} (the whole chapter)` })), list);
}

export async function initTeach(siteRoot) {
  const page = await listPage("data-wb-teach", siteRoot);
  if (!page) return;
  const { root, manifest } = page;
  const code = el("input", { type: "text", maxLength: CLASS_CAP, autocomplete: "off", required: true });
  code.dataset.wbField = "class";
  const due = el("input", { type: "date" });
  due.dataset.wbField = "due";
  const chapters = manifest.chapters.map((c) => chapterBox(c, manifest.titles, manifest.sameAnswer));
  const make = el("button", { type: "submit", className: "md-button md-button--primary", textContent: "Make the link" });
  const status = el("p", { role: "status", className: "wb-course-status" });
  const out = el("input", { type: "text", readOnly: true, id: uid("link") });
  out.dataset.wbField = "link";
  const copy = el("button", { type: "button", className: "md-button", textContent: "Copy the link" });
  const result = el("div", { className: "wb-teach-result", hidden: true },
    el("label", { htmlFor: out.id, textContent: "The assignment link" }), out, el("div", { className: "wb-course-actions" }, copy));
  const form = el("form", { className: "wb-teach-form", noValidate: true },
    field("Class code", code, "Any text that names this class and assignment, e.g. ROB101-week3. Each student's numbers come from it: a new code gives everyone new numbers."),
    field("Due date (optional)", due, "Shown to the learners; the workbook does not lock anything after it."),
    el("h2", { textContent: "Exercises" }), ...chapters,
    el("div", { className: "wb-course-actions" }, make), status, result);
  root.replaceChildren(form);
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    const ids = [...form.querySelectorAll("input[data-wb-exercise]:checked")].map((b) => b.value);
    const problems = [];
    if (!code.value.trim()) problems.push("Give the class code.");
    if (!ids.length) problems.push("Choose at least one exercise.");
    code.setAttribute("aria-invalid", String(!code.value.trim()));
    if (problems.length) {
      status.textContent = problems.join(" ");
      result.hidden = true;
      return;
    }
    out.value = assignmentHref(siteRoot, { code: code.value.trim(), ids, due: due.value || null });
    result.hidden = false;
    status.textContent = `The link sets ${ids.length} exercise${ids.length === 1 ? "" : "s"}. Send it to your class; each student gets their own numbers.`;
  });
  copy.addEventListener("click", () => {
    out.select();
    navigator.clipboard?.writeText(out.value).then(() => { status.textContent = "Link copied."; }, () => { status.textContent = "Select the link and copy it."; });
  });
}
