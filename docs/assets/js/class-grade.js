// The class page's reading and re-grading (docs/class.md, class-page.js): a file is a
// hand-in (hand-in.js) or a progress export; every recorded answer to the
// assignment's numbers is graded again by the same grader, at the variant recomputed from
// the class code and the student id (never the file's word for it). A claimed Build solve's
// recorded code is run again as a chapter page runs it (sandbox-client.js: the grader's
// cases, the sandbox's run, the grader's judgement; the sandbox replaced after code that was
// not plain or was stopped). A claimed solve whose answers do not grade correct, or whose
// code does not pass, is "not verified".

import { assignedVariant } from "./assignment-hash.js";
import { ERROR } from "./contract.js";
import { isAssigned, isSlips } from "./assignment-schema.js";
import { EXPORT_FORMAT, parseImport } from "./progress-schema.js";
import { HAND_IN_FORMAT, readHandIn } from "./hand-in.js";
import { groupDigits } from "./number-text.js";

export const MAX_FILE_BYTES = 4_000_000; // a hand-in holds a few exercises' records
const has = (list, v) => Array.isArray(list) && list.includes(v);
const isObject = (v) => v !== null && typeof v === "object" && !Array.isArray(v);

class FileProblem extends Error {}

/** One file's text -> a learner {student, code, ids, due, records, kind} or throws FileProblem (its message is for the
 * page). */
export function readLearner(name, text, known) {
  if (typeof text !== "string" || text.length > MAX_FILE_BYTES) {
    throw new FileProblem(`is larger than ${groupDigits(MAX_FILE_BYTES)} characters`);
  }
  let data;
  try {
    data = JSON.parse(text);
  } catch {
    throw new FileProblem("is not JSON");
  }
  if (!isObject(data)) throw new FileProblem("is not a hand-in or a progress export");
  if (data.format === EXPORT_FORMAT) {
    const parsed = parseImport(text, known);
    if (!parsed.ok) throw new FileProblem(`is not a readable progress export: ${parsed.reason}`);
    const ids = [...known].filter((id) => parsed.exercises[id]);
    return { kind: "progress", student: name.replace(/\.json$/i, ""), name: null, code: null, ids, due: null,
      handedIn: isoTime(data.exported), records: parsed.exercises };
  }
  if (data.format !== HAND_IN_FORMAT) throw new FileProblem(
    "is not a hand-in or a progress export (its “format” is missing or different)");
  const read = readHandIn(data, known); // hand-in.js: the format's one home
  if (!read.ok) throw new FileProblem(read.reason);
  return { name: null, ...read.learner };
}

/** An ISO time as the file gives it (the student's clock), or null when absent or not a time. */
function isoTime(v) {
  return typeof v === "string" && v.length <= 40 && Number.isFinite(Date.parse(v))
    ? new Date(Date.parse(v)).toISOString() : null;
}

/**
 * Whether a hand-in at `handedIn` (ISO) is late for `due`: a date (YYYY-MM-DD) is due by its
 * end, 23:59:59 in this browser's time zone; a full ISO time is due at that time. null when
 * either is missing or unreadable.
 */
export function lateOf(handedIn, due) {
  if (!handedIn || !due) return null;
  const end = /^\d{4}-\d{2}-\d{2}$/.test(due) ? new Date(`${due}T23:59:59.999`) : new Date(due);
  return Number.isFinite(end.getTime()) ? Date.parse(handedIn) > end.getTime() : null;
}

export function problemOf(err) {
  return err instanceof FileProblem ? err.message : "could not be read";
}

async function grade(runtime, request) {
  const reply = await runtime.request({ op: "grade", ...request });
  return reply.ok ? reply.value : { error: reply.error };
}

const STOPPED = {
  [ERROR.timeout]: "did not finish in time", [ERROR.crash]: "crashed the sandbox", [ERROR.memory]: "ran out of memory",
};

/**
 * A claimed Build solve: the record's code run again (`runtime` is withSandbox's). Sets the
 * cell's verdict and says why in its note; a record of another kind (the grader's
 * "wrong-op") is left as it is.
 */
async function rerun(cell, runtime, id, v, code, onProgress) {
  const reply = await runtime.request({ op: "run", exercise: id, variant: v, code }, { onProgress });
  if (!reply.ok) {
    if (reply.error.kind === ERROR.wrongOp) return;
    cell.note = STOPPED[reply.error.kind]
      ? `its code, run again here, ${STOPPED[reply.error.kind]}` : `its code could not be run again `
      + `here: ${reply.error.message}`;
    return;
  }
  cell.regraded = true;
  cell.verified = reply.value.status === "correct";
  cell.note = cell.verified ? "its code, run again here, passes" : `its code, run again here: ${reply.value.message}`;
}

/** A re-graded wrong answer's named slip: its key (the bank's stable `slipId`; for a grader without it, the
 *  name the grader derives) and the words to show (the verdict's message, or that name). */
function slipOf(verdict) {
  if (verdict.status !== "incorrect") return null;
  const id = verdict.data?.slipId ?? verdict.data?.slip;
  if (typeof id !== "string" || !id) return null;
  return { key: id, text: verdict.data?.slipId ? verdict.message : verdict.data.slip, name: verdict.data?.slip };
}

async function gradeAttempts(cell, runtime, id, v, attempts) {
  const verdicts = await Promise.all(attempts.map((attempt) => grade(runtime, {
    exercise: id, variant: v, answer: attempt.answer,
    ...(attempt.steps ? { steps: attempt.steps } : {}), ...(attempt.given ? { given: attempt.given } : {}) })));
  verdicts.forEach((verdict, i) => {
    if (verdict.error) {
      cell.note ||= verdict.error.kind === "wrong-op"
        ? "a code exercise: only its recorded code is run again here" : `not re-graded: ${verdict.error.message}`;
      return;
    }
    cell.regraded = true;
    if (verdict.status === "correct" && !cell.verified) {
      cell.verified = true;
      cell.toSolve = i + 1;
    }
    const was = attempts[i].status;
    if ((was === "correct") !== (verdict.status === "correct")) {
      cell.changed = true;
      cell.changes.push({ answer: attempts[i].answer, was, now: verdict.status });
    }
    const slip = slipOf(verdict);
    if (slip) {
      cell.slips[slip.key] = (cell.slips[slip.key] ?? 0) + 1;
      cell.slipText[slip.key] ??= slip.text;
      // the name the student's page recorded it by
      if (typeof slip.name === "string") cell.slipNames[slip.name] = slip.key;
    }
    // data.steps names the step to look at first: counted only where the student typed that step
    const wrong = verdict.status === "incorrect" ? verdict.data?.steps : null;
    const typed = attempts[i].steps?.[wrong?.first];
    if (typeof wrong?.first === "string" && typed !== undefined && typed !== null && typed !== "") {
      cell.firstWrongStep[wrong.first] = (cell.firstWrongStep[wrong.first] ?? 0) + 1;
      cell.stepLabels[wrong.first] ??= typeof wrong.label === "string" ? wrong.label : wrong.first;
    }
    if (attempts[i].steps) cell.withSteps += 1;
  });
}

/**
 * One learner's row: per exercise {variant, claimed, verified, regraded, attempts, toSolve (the
 * attempt that first grades correct now), changed (a re-graded verdict differs from the one the
 * student's page recorded; `changes` lists them), hinted, revealed, stepped, carried,
 * slips: {key: n} (re-graded; `slipText` the words for each), recordedSlips,
 * firstWrongStep: {step: n} (`stepLabels` the step's label for each), withSteps, note}.
 * `drawing`: the ids that draw variants (Derive); `runtime`: the grader with Build runs
 * through the sandbox (withSandbox); `onRun(id, text)`: a Build run starts (text null) or
 * reports progress.
 */
export async function gradeLearner(learner, drawing, runtime, onRun = () => {}) {
  const cells = {};
  await Promise.all(learner.ids.map(async (id) => {
    cells[id] = await gradeCell(learner, id, drawing, runtime, onRun);
  }));
  return Object.fromEntries(learner.ids.map((id) => [id, cells[id]]));
}

async function gradeCell(learner, id, drawing, runtime, onRun) {
  const r = learner.records[id] ?? {};
  const cell = { attempts: 0, claimed: false, verified: false, changed: false, changes: [], toSolve: null,
    hinted: Boolean(r.hinted), slips: {}, slipText: {}, slipNames: {},
    recordedSlips: isSlips(r.slips) ? r.slips : {}, firstWrongStep: {}, stepLabels: {}, withSteps: 0,
    note: "" };
  if (learner.kind === "hand-in") {
    const v = drawing.has(id) ? await assignedVariant(learner.code, learner.student, id) : 0;
    const entry = isAssigned(r.assigned) ? r.assigned[learner.code] : undefined;
    const attempts = entry?.attempts ?? [];
    Object.assign(cell, { variant: v, claimed: has(r.done, v) || attempts.some((t) => t.status === "correct"),
      revealed: has(r.revealedIn, v), stepped: has(r.stepped, v), carried: has(r.carried, v),
      attempts: attempts.length });
    if (entry && entry.variant !== v) cell.note = `the file's answers are for numbers ${entry.variant}, not this `
      + `student's ${v}`;
    // a Build run's attempt holds its code instead (attempt.js)
    const answers = attempts.filter((t) => t.answer !== undefined);
    await gradeAttempts(cell, runtime, id, v, answers);
    if (cell.claimed && !answers.length && has(r.done, v)) {
      // the code that passed
      const code = attempts.findLast((t) => t.status === "correct" && typeof t.code === "string")?.code ?? r.code;
      if (typeof code === "string") {
        // a Build run is an attempt
        cell.attempts = attempts.length || Math.max(1, Number.isSafeInteger(r.attempts) ? r.attempts : 0);
        onRun(id, null);
        await rerun(cell, runtime, id, v, code, (text) => onRun(id, text));
        if (cell.verified) cell.toSolve = cell.attempts;
        if (cell.regraded && !cell.verified) cell.changed = true; // the student's page showed it solved
      } else cell.note ||= "the file holds no answer or code to check";
    } else if (!answers.length && typeof r.code === "string") cell.attempts = attempts.length
      || (Number.isSafeInteger(r.attempts) ? r.attempts : 0);
  } else {
    // A progress export: the last answer, at the numbers it was given for.
    const v = r.variant ?? 0;
    Object.assign(cell, { variant: v, claimed: (r.clean?.length ?? 0) > 0 || (r.steppedDone?.length ?? 0) > 0,
      revealed: has(r.revealedIn, v), stepped: (r.stepped?.length ?? 0) > 0, carried: (r.carried?.length ?? 0) > 0,
      attempts: r.attempts ?? 0 });
    if ((r.last === undefined || r.last === null) && typeof r.code === "string" && has(r.done, v)) {
      onRun(id, null);
      await rerun(cell, runtime, id, v, r.code, (text) => onRun(id, text));
    } else if (r.last !== undefined && r.last !== null && has(r.done, v)) {
      const verdict = await grade(runtime, { exercise: id, variant: v, answer: r.last });
      if (verdict.error) cell.note = verdict.error.kind === "wrong-op"
        ? "a code exercise: only its recorded code is run again here" : `not re-graded: ${verdict.error.message}`;
      else {
        cell.regraded = true;
        cell.verified = verdict.status === "correct";
      }
    }
    if (cell.verified) cell.toSolve = cell.attempts || null;
  }
  return cell;
}
