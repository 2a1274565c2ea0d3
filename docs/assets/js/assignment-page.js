// The learner's assignment page (docs/assignment.md), opened from an assignment link
// (assignment-link.js). The learner gives a name or student number once (kept in this
// browser); every exercise set is then shown here, taken from its chapter page as the
// Practise page does, a Derive exercise at the variant assignedVariant(class, student, id):
// the assignment's numbers, the ones that count. "New numbers" still draws practice numbers
// (not counted); "Back to your assignment's numbers" brings the assigned ones back.
// Each graded answer to the assignment's numbers is kept in the progress record
// (`assigned`, assignment-schema.js); "Hand in" saves the file the teacher's class page reads.

import { ATTR, ROLE, ownRole } from "./contract.js";
import { initExercise } from "./exercise.js";
import { el, listPage } from "./progress-view.js";
import { assignedVariant, tidy } from "./assignment-hash.js";
import { addAttempt } from "./assignment-schema.js";
import { readAssignment, savedStudent, saveStudent, STUDENT_CAP } from "./assignment-link.js";
import { download } from "./notice.js";

export const HAND_IN_FORMAT = "robotics-math-workbook-hand-in";
export const HAND_IN_VERSION = 1;
const pages = new Map();

function chapterPage(href) {
  if (!pages.has(href)) {
    const loading = fetch(href).then((r) => (r.ok ? r.text() : Promise.reject(new Error(`the page answered ${r.status}`))))
      .then((text) => new DOMParser().parseFromString(text, "text/html"));
    loading.catch(() => pages.delete(href));
    pages.set(href, loading);
  }
  return pages.get(href);
}

/** The runtime, with every graded answer to an assignment's own numbers kept in `assigned`. */
function recording(runtime, progress, key, variants) {
  const request = async (request, options) => {
      const reply = await runtime.request(request, options);
      const v = request.variant ?? 0;
      if (request.op === "grade" && request.step == null && variants.has(request.exercise) && variants.get(request.exercise) === v
          && reply.ok && ["correct", "incorrect"].includes(reply.value.status)) {
        const { status, tag, data } = reply.value;
        const attempt = { answer: request.answer, status, at: Date.now(), ...(tag ? { tag } : {}), ...(data?.slip ? { slip: data.slip } : {}),
          ...(request.steps && Object.keys(request.steps).length ? { steps: request.steps } : {}), ...(request.given ? { given: request.given } : {}) };
        const record = progress.get(request.exercise);
        progress.update(request.exercise, { assigned: addAttempt(record.assigned, key, v, attempt) });
      }
      return reply;
  };
  // Everything else is the runtime's own (its methods bound to it).
  return new Proxy(runtime, { get: (target, name) => (name === "request" ? request : typeof target[name] === "function" ? target[name].bind(target) : target[name]) });
}

function askStudent(root, siteRoot, then) {
  const input = el("input", { type: "text", id: "wb-student-id", maxLength: STUDENT_CAP, autocomplete: "off" });
  input.dataset.wbField = "student";
  const say = el("p", { role: "status", className: "wb-course-status" });
  const form = el("form", { className: "wb-student-form" },
    el("label", { htmlFor: input.id, textContent: "Your name or student number (as your teacher asked)" }), input,
    el("p", { className: "wb-course-help", textContent: "Asked once and kept in this browser only. Your numbers come from it: type it the same way on every device (capital letters and extra spaces do not matter)." }),
    el("div", { className: "wb-course-actions" }, el("button", { type: "submit", className: "md-button md-button--primary", textContent: "Start" })), say);
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    const id = tidy(input.value);
    if (!id) {
      say.textContent = "Type your name or student number first.";
      input.setAttribute("aria-invalid", "true");
      return;
    }
    if (!saveStudent(siteRoot, id)) say.textContent = "This browser does not let the page keep it: you will be asked again next time.";
    then(id);
  });
  root.replaceChildren(form);
  input.focus();
}

/** Show the assigned variant as such: the label says these numbers count, or that these are practice numbers. */
function markVariant(node, assigned, back) {
  const label = ownRole(node, ROLE.variantLabel);
  const now = Number(node.getAttribute(ATTR.variant));
  const mine = now === assigned;
  node.dataset.wbAssigned = String(mine);
  if (label) label.textContent = mine ? "Your assignment's numbers: these count" : "Practice numbers (not counted): your assignment's are one click away";
  back.hidden = mine;
}

/** The last answer graded for class `key`'s numbers of exercise `id` (the variant `variant`), if any. */
function lastAssigned(progress, key, id, variant) {
  const entry = progress.get(id).assigned?.[key];
  return entry?.variant === variant ? entry.attempts.at(-1)?.answer ?? null : null;
}

async function showExercise(slot, manifest, id, siteRoot, shared, variant, key) {
  const chapter = manifest.chapters.find((c) => c.ids.includes(id));
  const href = new URL(chapter.url, siteRoot).href;
  const doc = await chapterPage(href);
  const found = doc.querySelector(`[${ATTR.exercise}="${CSS.escape(id)}"]`);
  if (!found) throw new Error(`exercise ${id} is not on its chapter page`);
  const node = document.importNode(found, true);
  const heading = el("h2", { id: `${node.id}-title` }, el("span", { id: `${node.id}-name`, textContent: `${id} · ${manifest.titles?.[id] ?? ""}` }));
  const from = el("p", { className: "wb-practise-from" }, "From ", el("a", { href: `${href}#${node.id}-title`, textContent: chapter.title }), ".");
  const back = el("button", { type: "button", className: "md-button", textContent: "Back to your assignment's numbers", hidden: true });
  back.dataset.wbAction = "assigned-numbers";
  slot.replaceChildren(heading, from, node, back);
  if (variant) {
    new MutationObserver(() => markVariant(node, variant, back)).observe(node, { attributes: true, attributeFilter: [ATTR.variant] });
    back.addEventListener("click", () => showExercise(slot, manifest, id, siteRoot, shared, variant, key).then(() => slot.querySelector("h2")?.focus?.()));
  }
  // A reload, or the way back from practice numbers, shows the last answer given to the assignment's numbers.
  initExercise(node, { ...shared, ...(variant ? { start: variant, resume: lastAssigned(shared.progress, key, id, variant) } : {}) });
}

function handIn(progress, assignment, student) {
  const records = {};
  for (const id of assignment.ids) {
    const r = progress.get(id);
    if (Object.keys(r).length) records[id] = structuredClone(r);
  }
  const data = { format: HAND_IN_FORMAT, version: HAND_IN_VERSION, handedIn: new Date().toISOString(), student,
    assignment: { class: assignment.code, exercises: assignment.ids, due: assignment.due }, records };
  const safe = (t) => t.replace(/[^A-Za-z0-9._-]+/g, "-").slice(0, 40);
  const name = `hand-in-${safe(assignment.code)}-${safe(student)}.json`;
  download(name, JSON.stringify(data, null, 1));
  return name;
}

export async function initAssignment(shared, siteRoot) {
  const page = await listPage("data-wb-assignment", siteRoot);
  if (!page) return;
  const { root, manifest } = page;
  const known = manifest.chapters.flatMap((c) => c.ids);
  const assignment = readAssignment(location.hash, known);
  if (!assignment.ok) {
    root.replaceChildren(el("p", { className: "wb-course-problem", textContent: assignment.reason }));
    return;
  }
  const start = async (student) => {
    const drawing = new Set(manifest.variants || []);
    const variants = new Map();
    for (const id of assignment.ids) variants.set(id, drawing.has(id) ? await assignedVariant(assignment.code, student, id) : 0);
    const runtime = recording(shared.runtime, shared.progress, assignment.code, variants);
    const mine = { ...shared, runtime };
    const change = el("button", { type: "button", className: "md-button", textContent: "Not you? Change the name" });
    const hand = el("button", { type: "button", className: "md-button md-button--primary", textContent: "Hand in" });
    hand.dataset.wbAction = "hand-in";
    const said = el("p", { role: "status", className: "wb-course-status" });
    const due = assignment.due ? ` Due ${assignment.due}.` : "";
    const head = el("div", { className: "wb-assignment-head" },
      el("p", {}, el("strong", { textContent: `Class ${assignment.code}` }), `: ${assignment.ids.length} exercise${assignment.ids.length === 1 ? "" : "s"}, for `,
        el("strong", { textContent: student }), `.${due}`));
    head.dataset.wbStudent = student;
    const list = el("ol", { className: "wb-assignment-list" });
    const tail = el("div", { className: "wb-assignment-tail" },
      el("p", { textContent: "When you are done, hand in: this saves a file with your answers to these exercises, for your teacher. Nothing is sent: give the file to your teacher the way they asked." }),
      el("div", { className: "wb-course-actions" }, hand, change), said);
    root.replaceChildren(head, list, tail);
    hand.addEventListener("click", () => { said.textContent = `Saved ${handIn(shared.progress, assignment, student)}. Hand that file in.`; });
    change.addEventListener("click", () => askStudent(root, siteRoot, start));
    for (const id of assignment.ids) {
      const slot = el("li", { className: "wb-practise-card" }, el("p", { textContent: `Loading exercise ${id}…` }));
      slot.dataset.wbSlot = id;
      list.append(slot);
      showExercise(slot, manifest, id, siteRoot, mine, variants.get(id), assignment.code).catch((err) => {
        slot.replaceChildren(el("p", { textContent: `Exercise ${id} could not be loaded (${err.message}). Reload the page to try again.` }));
      });
    }
  };
  const student = savedStudent(siteRoot);
  if (student) await start(student);
  else askStudent(root, siteRoot, start);
}
