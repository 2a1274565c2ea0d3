// The learner's assignment page (docs/assignment.md), opened from an assignment link
// (assignment-link.js). The learner gives a name or student number once (kept in this
// browser); every exercise set is then shown here, taken from its chapter page as the
// Practise page does (exercise-card.js), a Derive exercise at the variant
// assignedVariant(class, student, id): the assignment's numbers, the ones that count. "New
// numbers" still draws practice numbers (not counted); "Back to your assignment's numbers"
// brings the assigned ones back.
// One learner, one record: each student named here works in a record of their own in this
// browser (progress.js `learner`, keyed by a hash of the folded id), so a second student on
// a shared computer never sees, hands in or is credited with the first's work. Each graded
// attempt at the assignment's numbers (attempt.js) is kept in that record (`assigned`,
// assignment-schema.js); "Hand in" saves the file the teacher's class page reads (hand-in.js).

import { ATTR, COURSE, ROLE, RUNTIME, ownRole } from "./contract.js";
import { initExercise } from "./exercise.js";
import { showExerciseCard } from "./exercise-card.js";
import { el } from "./dom.js";
import { listPage } from "./exercise-list.js";
import { assignedVariant, learnerKey, studentTag, tidy } from "./assignment-hash.js";
import { addAttempt } from "./assignment-schema.js";
import { onAttempt } from "./attempt.js";
import { STUDENT_CAP, adoptOnce, readAssignment, savedStudent, saveStudent } from "./assignment-link.js";
import { buildHandIn, handInName } from "./hand-in.js";
import { download, showProgressProblems } from "./notice.js";
import { Progress } from "./progress.js";

const { attr: A, action: ACTION, field: FIELD } = COURSE;
const records = new Map(); // learner key -> Progress: one store per learner for this page's life
let stopRecording = () => {};

/** The learner's own record store; the first time, the assignments' answers kept before records were per learner come
 * along (adoptOnce). */
async function ownRecord(siteRoot, shared, student, first) {
  const key = await learnerKey(student);
  if (!records.has(key)) {
    const mine = new Progress(siteRoot, { learner: key });
    records.set(key, mine);
    // The page kept the student it last knew and their assignment answers in the browser's one record: that
    // student's own, once; any other student starts empty.
    if (first && adoptOnce(siteRoot)) {
      const carried = Object.entries(shared.progress.all()).filter(([, r]) => r.assigned)
        .map(([id, r]) => [id, { assigned: r.assigned }]);
      if (carried.length) mine.merge(Object.fromEntries(carried));
    }
    showProgressProblems(mine);
  }
  return records.get(key);
}

function askStudent(root, siteRoot, then) {
  const input = el("input", { type: "text", id: COURSE.id.wbStudentId, maxLength: STUDENT_CAP, autocomplete: "off" });
  input.setAttribute(A.field, FIELD.student);
  const say = el("p", { role: "status", className: "wb-course-status" });
  const form = el("form", { className: "wb-student-form" },
    el("label", { htmlFor: input.id, textContent: "Your name or student number (as your teacher asked)" }), input,
    el("p", { className: "wb-course-help",
      textContent: "Asked once and kept in this browser only. Your numbers come from it: type it the same way on "
        + "every device (capital letters and extra spaces do not matter)." }),
    el("div", { className: "wb-course-actions" },
      el("button", { type: "submit", className: "md-button md-button--primary", textContent: "Start" })), say);
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    const id = tidy(input.value);
    if (!id) {
      say.textContent = "Type your name or student number first.";
      input.setAttribute("aria-invalid", "true");
      return;
    }
    if (!saveStudent(siteRoot, id)) say.textContent =
      "This browser does not let the page keep it: you will be asked again next time.";
    then(id);
  });
  root.replaceChildren(form);
  input.focus();
}

/** Show the assigned variant as such: the label says these numbers count, or that these are practice numbers. */
function markVariant(node, assigned, back) {
  const label = ownRole(node, ROLE.variantLabel);
  const mine = Number(node.getAttribute(ATTR.variant)) === assigned;
  node.setAttribute(A.assigned, String(mine));
  if (label) label.textContent = mine ? "Your assignment's numbers: these count" :
    "Practice numbers (not counted): your assignment's are one click away";
  back.hidden = mine;
}

/** The last answer graded for class `key`'s numbers of exercise `id` (the variant `variant`), if any. */
function lastAssigned(progress, key, id, variant) {
  const entry = progress.get(id).assigned?.[key];
  return entry?.variant === variant ? entry.attempts.at(-1)?.answer ?? null : null;
}

async function showExercise(slot, manifest, id, siteRoot, mine, variant, key) {
  const back = el("button", { type: "button", className: "md-button", textContent: "Back to your assignment's numbers",
    hidden: true });
  back.setAttribute(A.action, ACTION.assignedNumbers);
  const node = await showExerciseCard(slot, manifest, id, siteRoot, { after: [back] });
  if (variant) {
    new MutationObserver(() => markVariant(node, variant, back)).observe(node, { attributes: true,
      attributeFilter: [ATTR.variant] });
    back.addEventListener("click", () => showExercise(slot, manifest, id, siteRoot, mine, variant, key)
      .then(() => slot.querySelector("h2")?.focus?.()));
  }
  // A reload, or the way back from practice numbers, shows the last answer given to the assignment's numbers.
  initExercise(node,
    { ...mine, ...(variant ? { start: variant, resume: lastAssigned(mine.progress, key, id, variant) } : {}) });
}

/** The grader's {version, bank}, if it is running and can say ({"op": "version"}); null otherwise (a hand-in never
 * waits for it). */
async function graderVersion(runtime) {
  if (document.documentElement.getAttribute(ATTR.runtime) !== RUNTIME.ready) return null;
  try {
    const reply = await runtime.request({ op: "version" });
    return reply.ok && reply.value && typeof reply.value === "object" ? reply.value : null;
  } catch {
    return null;
  }
}

async function handIn(mine, assignment, student) {
  const data = buildHandIn({ progress: mine.progress, assignment, student, grader: await graderVersion(mine.runtime) });
  const name = handInName(assignment.code, student, await studentTag(student));
  download(name, JSON.stringify(data, null, 1));
  return name;
}

export async function initAssignment(shared, siteRoot) {
  const page = await listPage(A.assignment, siteRoot);
  if (!page) return;
  const { root, manifest } = page;
  const known = manifest.chapters.flatMap((c) => c.ids);
  const assignment = readAssignment(location.hash, known);
  if (!assignment.ok) {
    root.replaceChildren(el("p", { className: "wb-course-problem", textContent: assignment.reason }));
    return;
  }
  const start = async (student, { first = false } = {}) => {
    stopRecording();
    const drawing = new Set(manifest.variants || []);
    const variants = new Map();
    for (const id of assignment.ids) variants.set(id, drawing.has(id)
      ? await assignedVariant(assignment.code, student, id) : 0);
    const mine = { ...shared, progress: await ownRecord(siteRoot, shared, student, first) };
    // Every graded attempt of this learner's exercises at the assignment's numbers is kept for the hand-in.
    stopRecording = onAttempt(({ id, variant, progress, attempt }) => {
      if (progress !== mine.progress || !variants.has(id) || variants.get(id) !== variant) return;
      progress.update(id, { assigned: addAttempt(progress.get(id).assigned, assignment.code, variant, attempt) });
    });
    const change = el("button", { type: "button", className: "md-button", textContent: "Not you? Change the name" });
    change.setAttribute(A.action, ACTION.changeStudent);
    const hand = el("button", { type: "button", className: "md-button md-button--primary", textContent: "Hand in" });
    hand.setAttribute(A.action, ACTION.handIn);
    const said = el("p", { role: "status", className: "wb-course-status" });
    const due = assignment.due ? ` Due ${assignment.due}.` : "";
    const head = el("div", { className: "wb-assignment-head" },
      el("p", {}, el("strong", { textContent: `Class ${assignment.code}` }), `: ${assignment.ids.length} `
      + `exercise${assignment.ids.length === 1 ? "" : "s"}, for `,
        el("strong", { textContent: student }), `.${due}`));
    head.setAttribute(A.student, student);
    const list = el("ol", { className: "wb-assignment-list" });
    const tail = el("div", { className: "wb-assignment-tail" },
      el("p", { textContent: "When you are done, hand in: this saves a file with your answers to these exercises, for "
      + "your teacher. Nothing is sent: give the file to your teacher the way they asked." }),
      el("div", { className: "wb-course-actions" }, hand, change), said);
    root.replaceChildren(head, list, tail);
    hand.addEventListener("click", async () => {
      said.textContent = `Saved ${await handIn(mine, assignment, student)}. Hand that file in.`;
    });
    change.addEventListener("click", () => {
      stopRecording();
      askStudent(root, siteRoot, start);
    });
    for (const id of assignment.ids) {
      const slot = el("li", { className: "wb-practise-card" }, el("p", { textContent: `Loading exercise ${id}…` }));
      slot.setAttribute(A.slot, id);
      list.append(slot);
      showExercise(slot, manifest, id, siteRoot, mine, variants.get(id), assignment.code).catch((err) => {
        slot.replaceChildren(el("p", { textContent: `Exercise ${id} could not be loaded (${err.message}). Reload the `
          + `page to try again.` }));
      });
    }
  };
  const student = savedStudent(siteRoot);
  if (student) await start(student, { first: true });
  else askStudent(root, siteRoot, start);
}
