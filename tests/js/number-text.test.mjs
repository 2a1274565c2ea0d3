// groupDigits (docs/assets/js/number-text.js) writes whole numbers as en-US's toLocaleString does,
// without loading the browser's locale data. Run by tests/unit/test_number_text.py.

import { test } from "node:test";
import assert from "node:assert/strict";
import { groupDigits } from "../../docs/assets/js/number-text.js";

test("every size of whole number reads as toLocaleString('en-US') writes it", () => {
  const numbers = [0, 7, 10, 99, 100, 999, 1000, 1001, 9999, 10000, 65536, 100000, 999999, 1000000, 32000000,
    123456789, Number.MAX_SAFE_INTEGER];
  for (let n = 1; n < 1e15; n = n * 7 + 3) numbers.push(n);
  for (const n of numbers) assert.equal(groupDigits(n), n.toLocaleString("en-US"), String(n));
});
