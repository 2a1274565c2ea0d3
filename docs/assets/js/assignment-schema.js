// The two progress fields an assignment needs (schema 5; CONTRACT.md, "Progress records"):
//   slips     {NAME: count}: the named slips this learner's wrong answers hit (a verdict's
//             data.slip), in any variant; two copies keep, per name, the larger count (a merge
//             repeated or in another order gives the same), the MAX_SLIPS most frequent kept
//   assigned  {CLASS: {variant, attempts: [{answer, status, tag, slip, at, steps, given}]}}:
//             the graded answers to the assignment's own numbers, per class code (the hand-in
//             carries them, the class page re-grades them); two copies keep every attempt of
//             either (the newest MAX_ATTEMPTS), the variant of the copy answered last
// Only data checks and merge rules: progress-schema.js lists them among its FIELDS.

export const MAX_SLIPS = 24;
export const SLIP_NAME_CAP = 80; // workbook/assignment.py NAME_CAP
export const MAX_ATTEMPTS = 20;
export const MAX_CLASSES = 8;
export const CLASS_CAP = 200;
const MAX_VARIANT = 999_999;
const FORBIDDEN = new Set(["__proto__", "constructor", "prototype"]);
const isObject = (v) => v !== null && typeof v === "object" && !Array.isArray(v);
const isText = (v, n) => typeof v === "string" && v.length <= n;
const isVariant = (v) => Number.isSafeInteger(v) && v >= 0 && v <= MAX_VARIANT;
const isCell = (v) => isText(v, 10_000) || Number.isFinite(v);
const isGrid = (v) => Array.isArray(v) && v.length <= 12 && v.every((row) => Array.isArray(row) && row.length <= 12 && row.every(isCell));
const isAnswer = (v) => isCell(v) || (Array.isArray(v) && v.length <= 50 && v.every((k) => isText(k, 200))) || isGrid(v);
const keysOk = (v, max, key) => isObject(v) && Object.keys(v).length <= max && Object.keys(v).every((k) => !FORBIDDEN.has(k) && key(k));
const STEP_NAME = /^[A-Za-z_][A-Za-z0-9_]{0,39}$/;
const EXERCISE_ID = /^\d{1,2}\.\d{1,2}$/;
const TIME_OK = (v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + 86_400_000;

export const isSlips = (v) => keysOk(v, MAX_SLIPS, (k) => k.length >= 1 && k.length <= SLIP_NAME_CAP)
  && Object.values(v).every((n) => Number.isSafeInteger(n) && n >= 1 && n <= 1_000_000);

const ATTEMPT_KEYS = ["answer", "status", "tag", "slip", "at", "steps", "given"];
export const isAttempt = (a) => isObject(a) && Object.keys(a).every((k) => ATTEMPT_KEYS.includes(k))
  && isAnswer(a.answer) && ["correct", "incorrect"].includes(a.status) && TIME_OK(a.at)
  && (a.tag === undefined || isText(a.tag, 40)) && (a.slip === undefined || isText(a.slip, SLIP_NAME_CAP))
  && (a.steps === undefined || (keysOk(a.steps, 12, (k) => STEP_NAME.test(k)) && Object.values(a.steps).every(isAnswer)))
  && (a.given === undefined || (keysOk(a.given, 4, (k) => EXERCISE_ID.test(k))
    && Object.values(a.given).every((g) => keysOk(g, 2, (k) => k === "answer" || k === "variant") && isAnswer(g.answer) && isVariant(g.variant))));

export const isAssigned = (v) => keysOk(v, MAX_CLASSES, (k) => k.length >= 1 && k.length <= CLASS_CAP)
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
  if (typeof name !== "string" || !name || name.length > SLIP_NAME_CAP || FORBIDDEN.has(name)) return slips;
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
    const attempts = [...seen.values()].sort((p, q) => p.at - q.at || (attemptKey(p) < attemptKey(q) ? -1 : 1)).slice(-MAX_ATTEMPTS);
    const newer = latest(y) > latest(x) || (latest(y) === latest(x) && y.variant > x.variant) ? y : x;
    out[key] = { variant: newer.variant, attempts };
  }
  const keys = Object.keys(out).sort((p, q) => latest(out[q]) - latest(out[p]) || (p < q ? -1 : 1)).slice(0, MAX_CLASSES);
  return Object.fromEntries(keys.sort().map((k) => [k, out[k]]));
}

/** `assigned` with one more graded attempt for class `key` at `variant` (the oldest dropped when full). */
export function addAttempt(assigned = {}, key, variant, attempt) {
  const mine = assigned[key]?.variant === variant ? assigned[key].attempts : [];
  return mergeAssigned(assigned, { [key]: { variant, attempts: [...mine, attempt].slice(-MAX_ATTEMPTS) } });
}
