// The variant an assignment gives a student for an exercise: the same function as
// assigned_variant() in pyodide_pkg/workbook/assignment.py (tests/unit/test_assignment.py
// runs both over many inputs). SHA-256 (WebCrypto) of the salt, the tidied class code,
// student id and exercise id, one per line; the first 8 bytes as a whole number, modulo
// MAX_VARIANT, plus 1. No DOM here: Node runs this file in the test.

export const SALT = "robotics-math-workbook/assignment/1";
export const MAX_VARIANT = 999_999;

/** `text` as the hash reads it: NFC, runs of whitespace as one space, trimmed (`fold`: A-Z as a-z). */
export function tidy(text, { fold = false } = {}) {
  // Python's str.split/\s and JavaScript's \s differ on a few characters: this is the one list both use.
  // eslint-disable-next-line no-control-regex -- U+001C to U+001F are white space to Python's str.split
  const out = String(text).normalize("NFC").replace(/[\t\n\v\f\r \u001c-\u001f\u0085\u00a0\u1680\u2000-\u200a\u2028\u2029\u202f\u205f\u3000]+/gu, " ").replace(/^ +| +$/g, "");
  return fold ? out.replace(/[A-Z]/g, (c) => c.toLowerCase()) : out;
}

/** Promise of the assigned variant (1 to MAX_VARIANT). */
export async function assignedVariant(classCode, student, exerciseId) {
  const text = [SALT, tidy(classCode), tidy(student, { fold: true }), String(exerciseId)].join("\n");
  const digest = new Uint8Array(await crypto.subtle.digest("SHA-256", new TextEncoder().encode(text)));
  let n = 0n;
  for (const byte of digest.slice(0, 8)) n = (n << 8n) | BigInt(byte);
  return 1 + Number(n % BigInt(MAX_VARIANT));
}
