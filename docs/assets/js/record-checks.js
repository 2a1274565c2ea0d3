// The checks of a progress record's values that more than one field shares: an answer, a
// variant, a step's name, the earlier answers (`given`) and steps a graded answer carried.
// One schema: progress-schema.js (every field) and assignment-schema.js (an assignment's
// attempts) both check with these, and every bound is the grader's own (contract.json
// `limits`), so a record holds exactly what a request may carry. No DOM: Node runs it.

import { LIMIT } from "./contract.js";

export const FORBIDDEN_KEYS = new Set(["__proto__", "constructor", "prototype"]);
export const isObject = (v) => v !== null && typeof v === "object" && !Array.isArray(v);
export const isShort = (v, n) => typeof v === "string" && v.length <= n;
export const isVariant = (v) => Number.isSafeInteger(v) && v >= 0 && v <= LIMIT.variant;
/** An object of at most `max` keys, each passing `key` and none that could reach a prototype. */
export const keysOk = (v, max, key) => isObject(v) && Object.keys(v).length <= max
  && Object.keys(v).every((k) => !FORBIDDEN_KEYS.has(k) && key(k));

export const STEP_NAME = /^[A-Za-z_][A-Za-z0-9_]{0,39}$/;
const EXERCISE_ID = /^\d{1,2}\.\d{1,2}$/;
const GRID = 12; // rows and columns of a matrix answer
const isCell = (v) => isShort(v, LIMIT.answer) || Number.isFinite(v);
/** A list of step keys (a Trace answer, a draft order). */
export const isKeyList = (v) => Array.isArray(v) && v.length <= 50 && v.every((k) => isShort(k, 200));
// A vector or matrix answer is saved as its grid of entries, row by row.
const isGrid = (v) => Array.isArray(v) && v.length >= 1 && v.length <= GRID
  && v.every((row) => Array.isArray(row) && row.length <= GRID && row.every(isCell));
/** One answer as a request carries it: a text, a number, a list of step keys or a grid of entries. */
export const isAnswer = (v) => isCell(v) || isKeyList(v) || isGrid(v);
/** The step answers one graded answer carried: {NAME: answer}, at most LIMIT.steps. */
export const isStepAnswers = (v) => keysOk(v, LIMIT.steps, (k) => STEP_NAME.test(k))
  && Object.values(v).every(isAnswer);
/** The earlier answers one graded answer carried: {ID: {answer, variant}}, at most LIMIT.given. */
export const isGiven = (v) => keysOk(v, LIMIT.given, (k) => EXERCISE_ID.test(k))
  && Object.values(v).every((g) => keysOk(g, 2, (k) => k === "answer" || k === "variant") && isAnswer(g.answer)
  && isVariant(g.variant));
