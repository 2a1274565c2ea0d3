// The variant an assignment gives a student for an exercise: the same function as
// assigned_variant() in pyodide_pkg/workbook/assignment.py (tests/unit/test_assignment.py
// runs both over many inputs). SHA-256 (WebCrypto) of the salt, the tidied class code,
// the folded student id and the exercise id, one per line; the first 8 bytes as a whole
// number, modulo LIMIT.variant, plus 1. The folded id also names the learner's own record
// in this browser (learnerKey) and tags their hand-in's file name (studentTag), as a hash:
// never the id itself. No DOM here: Node runs this file in the test.

import { LIMIT } from "./contract.js";

export const SALT = "robotics-math-workbook/assignment/1";
const LEARNER_SALT = "robotics-math-workbook/learner/1";
export const MAX_VARIANT = LIMIT.variant;

/** `text` as the hash reads it: NFC, runs of whitespace as one space, trimmed. */
export function tidy(text) {
  // Python's str.split/\s and JavaScript's \s differ on a few characters: this is the one list both use.
  return String(text).normalize("NFC")
    // eslint-disable-next-line no-control-regex -- U+001C to U+001F are white space to Python's str.split
    .replace(/[\t\n\v\f\r \u001c-\u001f\u0085\u00a0\u1680\u2000-\u200a\u2028\u2029\u202f\u205f\u3000]+/gu, " ")
    .replace(/^ +| +$/g, "");
}

// Python's str.casefold and its Unicode version's unassigned code points, from the table
// scripts/casefold_table.py writes at build time (make: build/casefold.json), loaded the
// first time an id is folded.
let folding = null;
function foldTable() {
  folding ??= import("../../../build/casefold.json", { with: { type: "json" } }).then(({ default: table }) => {
    const map = new Map();
    for (const [first, count, step, delta] of table.runs) {
      for (let i = 0; i < count; i++) map.set(first + i * step, String.fromCodePoint(first + i * step + delta));
    }
    for (const [cp, text] of table.multi) map.set(cp, text);
    const gaps = []; // [first, end) of each unassigned run, in order
    let end = 0;
    for (const [gap, count] of table.unassigned) {
      gaps.push([end + gap, end + gap + count]);
      end += gap + count;
    }
    return { map, gaps };
  });
  return folding;
}

function unassigned(gaps, cp) {
  let [lo, hi] = [0, gaps.length];
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (gaps[mid][1] <= cp) lo = mid + 1;
    else hi = mid;
  }
  return lo < gaps.length && gaps[lo][0] <= cp;
}

// NFKC as Python's Unicode version does it: a code point that version has not assigned is a
// starter that nothing composes with, left as it is; a browser that knows a newer version may
// decompose it, so the text is normalised around it, a piece at a time.
function nfkc(text, gaps) {
  let out = "";
  let piece = "";
  for (const ch of text) {
    if (!unassigned(gaps, ch.codePointAt(0))) piece += ch;
    else {
      out += piece.normalize("NFKC") + ch;
      piece = "";
    }
  }
  return out + piece.normalize("NFKC");
}

/** Promise of a student id as the hash reads it: NFKC, full case folding, NFKC again, tidied (Python's fold()). */
export async function fold(text) {
  const { map, gaps } = await foldTable();
  let out = "";
  for (const ch of nfkc(String(text), gaps)) out += map.get(ch.codePointAt(0)) ?? ch;
  return tidy(nfkc(out, gaps));
}

const digest = async (text) => new Uint8Array(await crypto.subtle.digest("SHA-256", new TextEncoder().encode(text)));
const hex = (bytes) => [...bytes].map((b) => b.toString(16).padStart(2, "0")).join("");

/** Promise of the assigned variant (1 to MAX_VARIANT). */
export async function assignedVariant(classCode, student, exerciseId) {
  const bytes = await digest([SALT, tidy(classCode), await fold(student), String(exerciseId)].join("\n"));
  let n = 0n;
  for (const byte of bytes.slice(0, 8)) n = (n << 8n) | BigInt(byte);
  return 1 + Number(n % BigInt(MAX_VARIANT));
}

/** Promise of the key of a student's own record in this browser (progress.js `learner`): 16 hex digits. */
export async function learnerKey(student) {
  return hex((await digest(`${LEARNER_SALT}\n${await fold(student)}`)).slice(0, 8));
}

/** Promise of the short tag a hand-in's file name carries (the first 8 digits of learnerKey). */
export async function studentTag(student) {
  return (await learnerKey(student)).slice(0, 8);
}
