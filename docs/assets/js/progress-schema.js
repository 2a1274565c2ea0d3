// The progress record's fields: what each may hold (checked on import and on
// load) and how two copies of it combine (imports, other tabs, other devices).
//
// Merge, never replace (CONTRACT.md, "Progress records"): two records of one
// exercise become one that keeps what each knows. Each field names its rule:
//   union   lists: every item of either (a variant answered on a phone and one
//           on a laptop are both answered); capped to the newest KEEP items
//   any     booleans: true if either is (hinted, revealed, solved)
//   max     counters and times (attempts, updated)
//   latest  what is on screen (the last answer, the code, the variant, a draft
//           order): the value of the record updated last, if it has one
//   review  the Leitner schedule (box, due, reviewed) moves as one: from the
//           record reviewed last
// A new field needs one line in FIELDS with its check and its rule; a new list
// of variants merges as a union without new code.

import { LIMIT } from "./contract.js";
import { KEEP, TOP_BOX, migrateRecord } from "./review.js";
import { isAssigned, isSlips, mergeAssigned, mergeSlips } from "./assignment-schema.js";
import { groupDigits } from "./number-text.js";
import { FORBIDDEN_KEYS, STEP_NAME, isAnswer, isKeyList, isObject, isShort, isVariant } from "./record-checks.js";

export const SCHEMA_VERSION = 5;
export const EXPORT_FORMAT = "robotics-math-workbook-progress";
// No browser keeps more than 10 MB of local storage for a site, so the largest
// export this page can write (escaped JSON included) stays below this.
export const MAX_IMPORT_BYTES = 32_000_000;

const DAY_MS = 86_400_000;
const MAX_VARIANT = LIMIT.variant;
const isBool = (v) => typeof v === "boolean";
const isText = (v) => typeof v === "string";
const isVariantList = (v) => Array.isArray(v) && v.length <= KEEP && v.every(isVariant);
const notFuture = (v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + DAY_MS;
const STATUSES = ["correct", "incorrect", "invalid"];
// A carried step's link: back to the learner's own earlier step, or to an earlier exercise.
const isCarriedLink = (v) => isObject(v) && Object.keys(v).every((k) => ["step", "from", "variant", "link"].includes(k))
  && isShort(v.link, 200) && (v.step === undefined || STEP_NAME.test(v.step))
  && (v.from === undefined || isShort(v.from, 20))
  && (v.variant === undefined || isVariant(v.variant));
const isStepVerdict = (v) => isObject(v)
  && Object.keys(v).every((k) => ["answer", "status", "tag", "message", "carried"].includes(k))
  && isAnswer(v.answer) && (v.status === undefined || STATUSES.includes(v.status))
  && (v.tag === undefined || isShort(v.tag, 40))
  && (v.message === undefined || isShort(v.message, 2000)) && (v.carried === undefined || isCarriedLink(v.carried));
/** The checked steps on screen: {variant, steps: {NAME: {answer, status, tag, message, carried}}} (null: cleared by new
 * numbers). */
const isStepWork = (v) => v === null || (isObject(v) && Object.keys(v).every((k) => k === "variant" || k === "steps")
  && isVariant(v.variant) && isObject(v.steps) && Object.keys(v.steps).length <= LIMIT.steps
  && Object.entries(v.steps).every(([name, step]) => STEP_NAME.test(name) && !FORBIDDEN_KEYS.has(name)
    && isStepVerdict(step)));
const VARIANTS = { check: isVariantList,
  says: `a list of at most ${KEEP} variant numbers (0 to ${groupDigits(MAX_VARIANT)})`, merge: "union" };
const TIME = "a time (milliseconds since 1970) not in the future";

export const FIELDS = {
  solved: { check: isBool, says: "true or false", merge: "any" },
  revealed: { check: isBool, says: "true or false", merge: "any" },
  // Solved only after revealing: true only if no copy solved it before revealing.
  solvedAfterReveal: { check: isBool, says: "true or false", merge: "afterReveal" },
  hinted: { check: isBool, says: "true or false", merge: "any" },
  attempts: { check: (v) => Number.isSafeInteger(v) && v >= 0, says: "a whole number, 0 or more", merge: "max" },
  // null: cleared on purpose (new numbers drawn), which a stale copy must not undo.
  last: { check: (v) => v === null || isAnswer(v),
    says: "an answer (text, number, list of step keys or grid of entries)", merge: "latest" },
  draftOrder: { check: isKeyList, says: "a list of step keys", merge: "latest" },
  code: { check: isText, says: "text", merge: "latest" },
  updated: { check: notFuture, says: TIME, merge: "max" },
  variant: { check: isVariant, says: `a variant number from 0 to ${groupDigits(MAX_VARIANT)}`, merge: "latest" },
  done: VARIANTS,
  clean: VARIANTS,
  missed: VARIANTS,
  revealedIn: VARIANTS,
  carried: VARIANTS, // since version 3: answers right given the learner's own wrong earlier value (or step)
  // Since version 4: checked steps (CONTRACT.md, "Checked steps").
  stepped: VARIANTS, // the variants worked with steps (a step checked)
  steppedDone: VARIANTS, // the variants solved after working with steps, the derivation not revealed first
  stepWork: { check: isStepWork,
    says: "the steps on screen ({variant, steps: {name: {answer, status, tag, message, carried}}}) or null",
    merge: "latest" },
  // Since version 5: assignments (assignment-schema.js; CONTRACT.md, "Progress records").
  slips: { check: isSlips, says: "the named slips hit, {name: count} (at most 24)", merge: "slips" },
  assigned: { check: isAssigned, says: "an assignment's graded answers, {class: {variant, attempts}}",
    merge: "assigned" },
  box: { check: (v) => Number.isInteger(v) && v >= 1 && v <= TOP_BOX, says: `a review box from 1 to ${TOP_BOX}`,
    merge: "review" },
  due: { check: (v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + 366 * DAY_MS,
    says: "a time (milliseconds since 1970) within a year", merge: "review" },
  reviewed: { check: notFuture, says: TIME, merge: "review" },
};

export { isObject };

export class ImportError extends Error {}

export function checkKeys(obj, where) {
  for (const key of Object.keys(obj)) {
    if (FORBIDDEN_KEYS.has(key)) throw new ImportError(`${where} contains the forbidden key “${key}”.`);
  }
}

/** A checked copy of one record; ImportError on the first field that is wrong. */
export function cleanRecord(id, raw) {
  if (!isObject(raw)) throw new ImportError(`The entry for exercise ${id} is not an object.`);
  checkKeys(raw, `The entry for exercise ${id}`);
  const record = {};
  for (const [field, value] of Object.entries(raw)) {
    const rule = FIELDS[field];
    if (!rule) throw new ImportError(`The entry for exercise ${id} has an unknown field “${field.slice(0, 40)}”.`);
    if (!rule.check(value)) throw new ImportError(`In exercise ${id}, “${field}” must be ${rule.says}.`);
    record[field] = value;
  }
  return record;
}

/**
 * What can be read of a saved record: {record, bad}, where `bad` holds the
 * fields that fail their check (set aside, never shown to the widgets), or
 * {record: null, bad: raw} for a record that is not an object at all.
 */
export function salvageRecord(raw) {
  if (!isObject(raw)) return { record: null, bad: raw };
  const record = {};
  const bad = {};
  for (const [field, value] of Object.entries(raw)) {
    if (FORBIDDEN_KEYS.has(field)) continue;
    if (FIELDS[field]?.check(value)) record[field] = value;
    else bad[field] = value;
  }
  return { record, bad: Object.keys(bad).length ? bad : null };
}

// ---- Merging -------------------------------------------------------------------
/** A canonical text of any JSON value: object keys sorted, so equal data reads equal. */
export function canonical(value) {
  if (Array.isArray(value)) return `[${value.map(canonical).join(",")}]`;
  if (isObject(value)) {
    return `{${Object.keys(value).sort().filter((k) => value[k] !== undefined)
      .map((k) => `${JSON.stringify(k)}:${canonical(value[k])}`).join(",")}}`;
  }
  return JSON.stringify(value) ?? "null";
}

const itemKey = (v) => (typeof v === "number" ? `n${v}` : canonical(v));
/** Every item of `older` then those of `newer` it lacks; the newest KEEP kept. */
function union(older = [], newer = []) {
  const seen = new Set(older.map(itemKey));
  return [...older, ...newer.filter((v) => !seen.has(itemKey(v)))].slice(-KEEP);
}

const RULES = {
  union: (older, newer, field) => union(older[field], newer[field]),
  any: (older, newer, field) => Boolean(older[field] || newer[field]),
  max: (older, newer, field) => Math.max(older[field] ?? 0, newer[field] ?? 0),
  latest: (older, newer, field) => (field in newer ? newer[field] : older[field]),
  review: (older, newer, field) => {
    const when = (r) => r.reviewed ?? r.due ?? -1;
    const from = when(newer) >= when(older) && newer.box !== undefined ? newer : older.box !== undefined
      ? older : newer;
    return from[field];
  },
  slips: (older, newer, field) => mergeSlips(older[field], newer[field]),
  assigned: (older, newer, field) => mergeAssigned(older[field], newer[field]),
  afterReveal: (older, newer) => [older, newer].filter((r) => r.solved).every((r) => r.solvedAfterReveal === true),
};

/** Which of two records counts as the newer: the later `updated`; a tie is settled by their text, the same way in every
 * tab. */
function order(a, b) {
  const ta = a.updated ?? 0;
  const tb = b.updated ?? 0;
  if (ta !== tb) return ta < tb ? [a, b] : [b, a];
  return canonical(a) <= canonical(b) ? [a, b] : [b, a];
}

/** One record holding what `a` and `b` each know (either may be missing). */
export function mergeRecord(a, b) {
  if (!a) return b && { ...b };
  if (!b) return { ...a };
  const [older, newer] = order(a, b);
  const out = {};
  for (const field of new Set([...Object.keys(older), ...Object.keys(newer)])) {
    const value = RULES[FIELDS[field]?.merge ?? "latest"](older, newer, field);
    if (value !== undefined) out[field] = value;
  }
  if (!out.solved) delete out.solvedAfterReveal;
  return out;
}

/**
 * Two whole stores as one. `reset` (a time) marks an erase: a copy from before
 * the latest erase keeps only the records changed after it. Same erase (or
 * none): every exercise's records are merged.
 */
export function mergeData(a, b) {
  const reset = Math.max(a.reset ?? 0, b.reset ?? 0);
  const keep = (data) => ((data.reset ?? 0) === reset ? data.exercises
    : Object.fromEntries(Object.entries(data.exercises).filter(([, r]) => (r.updated ?? 0) > reset)));
  const ea = keep(a);
  const eb = keep(b);
  const exercises = {};
  for (const id of new Set([...Object.keys(ea), ...Object.keys(eb)])) exercises[id] = mergeRecord(ea[id], eb[id]);
  return { version: SCHEMA_VERSION, ...(reset ? { reset } : {}), exercises };
}

/** Whether two stores hold the same (lists compared as sets). */
export function same(a, b) {
  return canonical(sorted(a)) === canonical(sorted(b));
}

function sorted(value) {
  if (Array.isArray(value)) {
    return value.every((v) => typeof v === "number") ? [...value].sort((x, y) => x - y) : value.map(sorted);
  }
  if (isObject(value)) return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, sorted(v)]));
  return value;
}

// ---- Import files --------------------------------------------------------------
/**
 * Check the text of a progress file. Returns {ok: true, exercises} with clean
 * records, or {ok: false, reason} saying what is wrong. `knownIds` (a Set) lists
 * the site's exercises; ids outside it are refused.
 */
export function parseImport(text, knownIds) {
  try {
    if (typeof text !== "string") throw new ImportError("The file could not be read as text.");
    if (text.length > MAX_IMPORT_BYTES) throw new ImportError(`The file is too large (over ${groupDigits(
      MAX_IMPORT_BYTES)} characters); a progress file is much smaller.`);
    let data;
    try {
      data = JSON.parse(text);
    } catch {
      throw new ImportError("The file is not valid JSON.");
    }
    if (!isObject(data)) throw new ImportError("The file does not hold a progress record (expected a JSON object).");
    checkKeys(data, "The file");
    if (data.format !== EXPORT_FORMAT) throw new ImportError(
      "The file is not a Robotics Math Workbook progress export (its “format” is missing or different).");
    if (!Number.isInteger(data.version) || data.version < 1) throw new ImportError("The file has no valid “version”.");
    if (data.version > SCHEMA_VERSION) throw new ImportError(`The file was written by a newer version of the workbook `
      + `(version ${data.version}); update this page first.`);
    for (const key of Object.keys(data)) {
      if (!["format", "version", "exported", "site", "exercises"].includes(key)) {
        throw new ImportError(`The file has an unexpected entry “${key.slice(0, 40)}”.`);
      }
    }
    if (!isObject(data.exercises)) throw new ImportError("The file has no “exercises” object.");
    checkKeys(data.exercises, "The exercise list");
    const exercises = {};
    for (const [id, raw] of Object.entries(data.exercises)) {
      if (knownIds && !knownIds.has(id)) {
        throw new ImportError(`The file mentions exercise “${id.slice(0, 20)}”, which this workbook does not have.`);
      }
      const record = cleanRecord(id, raw);
      // a version-1 file: same migration as on load (2 -> 3 -> 4 -> 5 add fields only)
      exercises[id] = data.version < 2 ? migrateRecord(record) : record;
    }
    return { ok: true, exercises };
  } catch (err) {
    if (err instanceof ImportError) return { ok: false, reason: err.message };
    return { ok: false, reason: "The file could not be checked." };
  }
}
