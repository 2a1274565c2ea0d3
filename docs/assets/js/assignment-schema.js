// The two progress fields an assignment needs (schema 5; CONTRACT.md, "Progress records"):
//   slips     {NAME: count}: the named slips this learner's wrong answers hit (a verdict's
//             data.slip), in any variant; two copies keep, per name, the larger count (a merge
//             repeated or in another order gives the same), the MAX_SLIPS most frequent kept
//   assigned  {CLASS: {variant, attempts: [{answer | code, status, tag, slip, at, steps, given}]}}:
//             the graded answers to the assignment's own numbers, per class code (the hand-in
//             carries them, the class page re-grades them); two copies keep every attempt of
//             either (the newest MAX_ATTEMPTS), the variant of the copy answered last
// Only data checks and merge rules: progress-schema.js lists them among its FIELDS; the
// values an attempt carries are checked as every record's are (record-checks.js).

import { LIMIT } from "./contract.js";
import { FORBIDDEN_KEYS, isAnswer, isGiven, isObject, isShort, isStepAnswers, isVariant,
  keysOk } from "./record-checks.js";

export const MAX_SLIPS = 24;
export const SLIP_NAME_CAP = LIMIT.slipName; // workbook/assignment.py NAME_CAP
export const MAX_ATTEMPTS = 20;
export const MAX_CLASSES = 8;
const TIME_OK = (v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + 86_400_000;

export const isSlips = (v) => keysOk(v, MAX_SLIPS, (k) => k.length >= 1 && k.length <= SLIP_NAME_CAP)
  && Object.values(v).every((n) => Number.isSafeInteger(n) && n >= 1 && n <= 1_000_000);

// An attempt is a graded final answer (`answer`, with the `steps` and `given` its request
// carried) or a graded Build run (`code`: the code that ran, when it fits LIMIT.code): attempt.js.
const ATTEMPT_KEYS = ["answer", "code", "status", "tag", "slip", "at", "steps", "given"];
export const isAttempt = (a) => isObject(a) && Object.keys(a).every((k) => ATTEMPT_KEYS.includes(k))
  && (a.answer === undefined ? a.code === undefined || isShort(a.code, LIMIT.code)
    : a.code === undefined && isAnswer(a.answer))
  && ["correct", "incorrect"].includes(a.status) && TIME_OK(a.at)
  && (a.tag === undefined || isShort(a.tag, 40)) && (a.slip === undefined || isShort(a.slip, SLIP_NAME_CAP))
  && (a.steps === undefined || isStepAnswers(a.steps)) && (a.given === undefined || isGiven(a.given));

export const isAssigned = (v) => keysOk(v, MAX_CLASSES, (k) => k.length >= 1 && k.length <= LIMIT.classCode)
  && Object.values(v).every((a) => keysOk(a, 2, (k) => k === "variant" || k === "attempts") && isVariant(a.variant)
    && Array.isArray(a.attempts) && a.attempts.length <= MAX_ATTEMPTS && a.attempts.every(isAttempt));

const byCount = ([na, a], [nb, b]) => b - a || (na < nb ? -1 : na > nb ? 1 : 0);

/** Two slip counts as one: per name, the larger; the MAX_SLIPS most frequent kept. */
export function mergeSlips(a = {}, b = {}) {
  const out = { ...a };
  for (const [name, n] of Object.entries(b)) out[name] = Math.max(out[name] ?? 0, n);
  return Object.fromEntries(Object.entries(out).sort(byCount).slice(0, MAX_SLIPS));
}

/** `slips` with one more hit of `name` (when full, the least frequent other name is dropped). */
export function countSlip(slips = {}, name) {
  if (typeof name !== "string" || !name || name.length > SLIP_NAME_CAP || FORBIDDEN_KEYS.has(name)) return slips;
  const n = Math.min(1_000_000, (slips[name] ?? 0) + 1);
  const others = Object.entries(slips).filter(([k]) => k !== name).sort(byCount).slice(0, MAX_SLIPS - 1);
  return Object.fromEntries([...others, [name, n]].sort(byCount));
}

const attemptKey = (a) => `${a.at}|${JSON.stringify(a.answer)}|${a.status}`;
const latest = (entry) => Math.max(-1, ...entry.attempts.map((a) => a.at));

/** Two `assigned` fields as one: per class, every attempt of either (newest MAX_ATTEMPTS, oldest first). */
export function mergeAssigned(a = {}, b = {}) {
  const out = {};
  for (const key of new Set([...Object.keys(a), ...Object.keys(b)])) {
    const [x, y] = [a[key], b[key]];
    if (!x || !y) {
      out[key] = x ?? y;
      continue;
    }
    const seen = new Map();
    for (const attempt of [...x.attempts, ...y.attempts]) seen.set(attemptKey(attempt), attempt);
    const attempts = [...seen.values()].sort((p, q) => p.at - q.at || (attemptKey(p) < attemptKey(q) ? -1 : 1))
      .slice(-MAX_ATTEMPTS);
    const newer = latest(y) > latest(x) || (latest(y) === latest(x) && y.variant > x.variant) ? y : x;
    out[key] = { variant: newer.variant, attempts };
  }
  const keys = Object.keys(out).sort((p, q) => latest(out[q]) - latest(out[p]) || (p < q ? -1 : 1))
    .slice(0, MAX_CLASSES);
  return Object.fromEntries(keys.sort().map((k) => [k, out[k]]));
}

/** `assigned` with one more graded attempt for class `key` at `variant` (the oldest dropped when full). */
export function addAttempt(assigned = {}, key, variant, attempt) {
  const mine = assigned[key]?.variant === variant ? assigned[key].attempts : [];
  return mergeAssigned(assigned, { [key]: { variant, attempts: [...mine, attempt].slice(-MAX_ATTEMPTS) } });
}
