// suspend_data's encodings (docs/assets/js/lms/suspend.js) at their limits, in Node.
// Run by tests/unit/test_scorm_suspend.py: node --experimental-default-type=module --test
// with WORKBOOK_IDS, every exercise id of the workbook (from the grading package).

import { test } from "node:test";
import assert from "node:assert/strict";
import {
  COMPACT, LIMIT_12, LIMIT_2004, compactCoverage, decodeSuspend, encodeCompact, encodeSuspend,
} from "../../docs/assets/js/lms/suspend.js";
import { FIELDS, cleanRecord, mergeRecord } from "../../docs/assets/js/progress-schema.js";
import { MASTERED, isMastered, isSolved } from "../../docs/assets/js/review.js";
import { chapterValues, duration2004, interactionValues, timespan12 } from "../../docs/assets/js/lms/report.js";

const IDS = JSON.parse(process.env.WORKBOOK_IDS);
const NOW = Date.now();
const DAY = 86_400_000;

/** A record as full as a learner can make it: every essential field at its widest. */
function fullRecord(i, { answer = null, ids = IDS } = {}) {
  const updated = NOW - (ids.length - i) * 3_600_000 - 123; // one per hour, oldest first
  const v = 999_999 - i;
  const box = 5;
  const due = updated + 21 * DAY;
  return cleanRecord(ids[i], {
    solved: true, solvedAfterReveal: false, hinted: true, revealed: true, attempts: 9999, variant: v,
    done: [0, v - 3, v - 2, v - 1, v], clean: [v - 3, v - 2, v - 1, v], steppedDone: [v - 5], missed: [5],
    revealedIn: [7], stepped: [v - 5], box, due, reviewed: due - 21 * DAY, updated,
    ...(answer === null ? {} : { last: answer }),
  });
}

const essential = (r) => ({
  solved: isSolved(r), mastered: isMastered(r), clean: (r.clean ?? []).slice(-MASTERED), variant: r.variant ?? 0,
  attempts: r.attempts, box: r.box, hinted: Boolean(r.hinted), revealed: Boolean(r.revealed),
});

const chapterOf = (id) => id.split(".")[0];

function checkKept(exercises, records, ids) {
  for (const id of ids) {
    const back = exercises[id];
    assert.ok(back, `${id} kept`);
    assert.deepEqual(essential(back), essential(records[id]), id);
    assert.ok(Math.abs(back.due - records[id].due) < 60_000, `${id}: due within the minute`);
    assert.ok(back.updated <= records[id].updated && records[id].updated - back.updated < 1000,
      `${id}: updated to the second, never later`);
  }
}

// The workbook as it is, and one with a made-up chapter 99 of 40 more exercises (past 1.2's limit at their widest).
const BOOKS = [IDS, [...IDS, ...Array.from({ length: 40 }, (_, i) => `99.${i + 1}`)]];

for (const book of BOOKS) test(`every chapter's records of ${book.length}, each at its widest, travel whole in ` +
  "its own SCO's 4,096 characters, the others' as far as they fit", () => {
  const chapters = [...new Set(book.map(chapterOf))];
  assert.ok(chapters.length > 1);
  const records = Object.fromEntries(book.map((id, i) => [id, fullRecord(i, { ids: book })]));
  const whole = encodeCompact(records, Infinity).text.length;
  for (const chapter of chapters) {
    const own = book.filter((id) => chapterOf(id) === chapter);
    const { text, dropped } = encodeSuspend(records, "1.2", own);
    assert.ok(text.length <= LIMIT_12, `${chapter}: ${text.length} characters`);
    assert.deepEqual(dropped.answers, []);
    const { exercises, skipped } = decodeSuspend(text);
    assert.equal(skipped, 0);
    checkKept(exercises, records, own);
    // What is left out is others' only, the oldest of them, and no more than must be.
    const others = book.filter((id) => chapterOf(id) !== chapter); // oldest first
    assert.deepEqual(dropped.records, others.slice(0, dropped.records.length), chapter);
    checkKept(exercises, records, others.slice(dropped.records.length));
    if (dropped.records.length) {
      const oneMore = Object.fromEntries(Object.entries(records)
        .filter(([id]) => !dropped.records.slice(0, -1).includes(id)));
      assert.ok(encodeCompact(oneMore, Infinity).text.length > LIMIT_12, `${chapter}: dropped one more than needed`);
    } else {
      assert.ok(whole <= LIMIT_12);
    }
  }
  console.log(`# ${book.length} widest records: ${whole} characters (SCORM 1.2 holds ${LIMIT_12})`);
});

test("over the limit, last answers are dropped first, oldest record first, and nothing else", () => {
  // Short answers: with 100 exercises at their widest, room is left for some of their answers only.
  const long = "x".repeat(8);
  const ids = IDS.slice(0, 100); // records that fit whole at their widest, without their answers
  const widest = Object.fromEntries(ids.map((id, i) => [id, fullRecord(i)]));
  assert.ok(encodeCompact(widest, Infinity).text.length <= LIMIT_12);
  const records = Object.fromEntries(ids.map((id, i) => [id, fullRecord(i, { answer: `${long} ${i}` })]));
  const { text, dropped } = encodeSuspend(records, "1.2");
  assert.ok(text.length <= LIMIT_12, `${text.length} characters`);
  assert.ok(dropped.answers.length > 0 && dropped.answers.length < ids.length,
    `${dropped.answers.length} answers dropped`);
  assert.deepEqual(dropped.records, []);
  // Oldest first: the dropped ones are exactly the first N by time.
  assert.deepEqual(dropped.answers, ids.slice(0, dropped.answers.length));
  const { exercises } = decodeSuspend(text);
  for (const [i, id] of ids.entries()) {
    if (i < dropped.answers.length) assert.equal(exercises[id].last, undefined, id);
    else assert.equal(exercises[id].last, `${long} ${i}`, id);
  }
  // Just one answer fewer would not have fitted: the limit is used, not wasted.
  const kept = new Set(ids.slice(dropped.answers.length - 1));
  const oneMore = Object.fromEntries(ids.map((id) =>
    [id, kept.has(id) ? records[id] : { ...records[id], last: undefined }]));
  for (const r of Object.values(oneMore)) if (r.last === undefined) delete r.last;
  assert.ok(encodeCompact(oneMore, Infinity).text.length > LIMIT_12);
});

test("answers of every shape come back as they were: text, numbers, step keys, grids, non-ASCII", () => {
  const answers = ["θ = 0.62 rad, x = −5.87", 3.25, ["b", "a", "c"], [["1", "0"], ["0", "cos(π/2)"]], "", 0];
  const records = Object.fromEntries(answers.map((a, i) => [IDS[i], { ...fullRecord(i), last: a }]));
  const { exercises } = decodeSuspend(encodeSuspend(records, "1.2").text);
  answers.forEach((a, i) => assert.deepEqual(exercises[IDS[i]].last, a));
});

test("a decoded record merges with the local one by the import's rules: nothing local is lost", () => {
  const local = { ...fullRecord(3), code: "def f(): pass", missed: [5, 6], last: "mine" };
  const older = { [IDS[3]]: { ...local, updated: local.updated - 5000, last: "older" } };
  const lms = decodeSuspend(encodeSuspend(older, "1.2").text).exercises[IDS[3]];
  const merged = mergeRecord(local, lms);
  assert.equal(merged.code, "def f(): pass");
  assert.deepEqual(merged.missed, [5, 6]);
  assert.equal(merged.last, "mine", "the local answer is newer");
  // And the other way round: the LMS's copy is newer, so its answer and variant win; the local lists stay.
  const theirs = { [IDS[3]]: { ...local, updated: local.updated + 5000, last: "theirs", variant: 42 } };
  const newer = decodeSuspend(encodeSuspend(theirs, "1.2").text).exercises[IDS[3]];
  const merged2 = mergeRecord(local, newer);
  assert.equal(merged2.last, "theirs");
  assert.equal(merged2.variant, 42);
  assert.deepEqual(merged2.missed, [5, 6]);
});

test("SCORM 2004 carries every field as it is, and drops checked steps, then code, before the compact form", () => {
  const records = Object.fromEntries(IDS.map((id, i) => [id, { ...fullRecord(i), code: "print(1)\n", last: `a${i}` }]));
  const full = encodeSuspend(records, "2004");
  assert.ok(full.text.startsWith("wbj:"));
  assert.deepEqual(full.dropped, { fields: [] });
  assert.deepEqual(decodeSuspend(full.text).exercises, records);

  const steps = { variant: 1, steps: { FP: { answer: "y".repeat(1500), status: "incorrect", message: "m" } } };
  const big = Object.fromEntries(IDS.map((id) => [id, { ...records[id], stepWork: steps }]));
  const noSteps = encodeSuspend(big, "2004");
  assert.ok(noSteps.text.length <= LIMIT_2004);
  assert.deepEqual(noSteps.dropped, { fields: ["stepWork"] });
  assert.equal(decodeSuspend(noSteps.text).exercises[IDS[0]].code, "print(1)\n");

  const code = "z".repeat(1000);
  const coded = Object.fromEntries(IDS.map((id) => [id, { ...big[id], code }]));
  const noCode = encodeSuspend(coded, "2004");
  assert.ok(noCode.text.startsWith("wbj:") && noCode.text.length <= LIMIT_2004);
  assert.deepEqual(noCode.dropped, { fields: ["stepWork", "code"] });
  assert.equal(decodeSuspend(noCode.text).exercises[IDS[0]].last, "a0");

  const answer = "w".repeat(900);
  const huge = Object.fromEntries(IDS.map((id) => [id, { ...coded[id], last: answer }]));
  const compact = encodeSuspend(huge, "2004");
  assert.ok(compact.text.startsWith("wb1:") && compact.text.length <= LIMIT_2004, `${compact.text.length}`);
  assert.ok(compact.dropped.answers.length > 0 && compact.dropped.answers.length < IDS.length);
  assert.deepEqual(compact.dropped.records, []);
  assert.equal(decodeSuspend(compact.text).exercises[IDS.at(-1)].last, answer);
});

test("text the LMS hands back is never trusted: garbage, cut text and forged fields are left out", () => {
  assert.deepEqual(decodeSuspend("").exercises, {});
  assert.equal(decodeSuspend("hello").skipped, 1);
  assert.equal(decodeSuspend("wb1:!!!!").skipped, 1);
  assert.equal(decodeSuspend('wbj:{"0.1":{"box":9}}').skipped, 1);
  assert.equal(decodeSuspend('wbj:{"__proto__":{"solved":true}}').skipped, 1);
  const records = Object.fromEntries(IDS.slice(0, 10).map((id, i) => [id, fullRecord(i)]));
  const { text } = encodeSuspend(records, "1.2");
  const cut = decodeSuspend(text.slice(0, Math.floor(text.length / 2)));
  assert.ok(Object.keys(cut.exercises).length >= 3 && Object.keys(cut.exercises).length < 10);
  assert.equal(cut.skipped, 1);
});

test("the chapter's score is the share solved on 0-100; under a mastery score, passed at or above it " +
  "and failed below", () => {
  const ids = IDS.slice(0, 4);
  const records = { [ids[0]]: fullRecord(0), [ids[1]]: { attempts: 2, missed: [0] } };
  const get = (pairs) => Object.fromEntries(pairs);
  const v12 = get(chapterValues("1.2", records, ids, null));
  assert.equal(v12["cmi.core.score.raw"], 25);
  assert.equal(v12["cmi.core.score.min"], 0);
  assert.equal(v12["cmi.core.score.max"], 100);
  assert.equal(v12["cmi.core.lesson_status"], "incomplete"); // no mastery score: never failed
  assert.equal(get(chapterValues("1.2", records, ids, 0.25))["cmi.core.lesson_status"], "passed"); // at it
  assert.equal(get(chapterValues("1.2", records, ids, 0.8))["cmi.core.lesson_status"], "failed"); // below it
  const all = Object.fromEntries(ids.map((id, i) => [id, fullRecord(i)]));
  assert.equal(get(chapterValues("1.2", all, ids, 0.8))["cmi.core.lesson_status"], "passed");
  assert.equal(get(chapterValues("1.2", all, ids, null))["cmi.core.score.raw"], 100);
  const v2004 = get(chapterValues("2004", all, ids, null));
  assert.equal(v2004["cmi.completion_status"], "completed");
  assert.equal(v2004["cmi.success_status"], "passed");
  assert.equal(v2004["cmi.score.scaled"], 1);
  assert.equal(v2004["cmi.score.raw"], 100);
  assert.equal(v2004["cmi.score.max"], 100);
  assert.equal(get(chapterValues("2004", {}, ids, null))["cmi.success_status"], "unknown");
  const some = get(chapterValues("2004", records, ids, 0.8));
  assert.equal(some["cmi.success_status"], "failed");
  assert.equal(some["cmi.completion_status"], "incomplete");
  assert.equal(some["cmi.score.scaled"], 0.25);
  assert.equal(get(chapterValues("2004", all, ids, 0.8))["cmi.success_status"], "passed");
  // Three of eight: a share that is not a whole percentage stays exact to two places.
  const eight = IDS.slice(0, 8);
  const three = Object.fromEntries(eight.slice(0, 3).map((id, i) => [id, fullRecord(i)]));
  assert.equal(get(chapterValues("1.2", three, eight, null))["cmi.core.score.raw"], 37.5);
});

test("every field of the record schema is carried by the compact form, rebuilt, or dropped on purpose", () => {
  assert.deepEqual(compactCoverage(), { unlisted: [], unknown: [] });
  // A new field of the schema that nobody listed is found (the test fails until it is listed).
  assert.deepEqual(compactCoverage({ ...FIELDS, newField: FIELDS.attempts }).unlisted, ["newField"]);
  assert.deepEqual(compactCoverage({ solved: FIELDS.solved }).unknown.includes("attempts"), true);
  // What is carried comes back as it was (the newest items of the variant lists).
  const record = fullRecord(0, { answer: [["1", "2"], ["3", "4"]] });
  const back = decodeSuspend(encodeCompact({ [IDS[0]]: record }).text).exercises[IDS[0]];
  for (const field of COMPACT.flags) assert.equal(Boolean(back[field]), Boolean(record[field]), field);
  for (const field of ["variant", "attempts", "box", "last"]) assert.deepEqual(back[field], record[field], field);
  assert.equal(back.updated, Math.floor(record.updated / 1000) * 1000); // to the second
  assert.equal(back.due, Math.floor(record.due / 60_000) * 60_000); // to the minute
  assert.deepEqual(back.clean, record.clean.slice(-MASTERED));
  assert.ok(Number.isFinite(back.reviewed));
  for (const field of Object.keys(COMPACT.dropped)) assert.ok(!(field in back), field);
});

test("times in each version's format", () => {
  assert.equal(timespan12(0), "0000:00:00.00");
  assert.equal(timespan12(3_723_450), "0001:02:03.45");
  assert.equal(duration2004(0), "PT0S");
  assert.equal(duration2004(3_723_450), "PT1H2M3.45S");
  assert.equal(duration2004(60_000), "PT1M0S");
  // 2004's timestamp: UTC, said so, to the hundredth of a second (the most SCORM's time type holds).
  const at = Date.UTC(2026, 10, 27, 5, 52, 1, 239);
  const v = Object.fromEntries(
    interactionValues("2004", 3, "0.4", { last: "1" }, { correct: true, latencyMs: 90_500, at }));
  assert.equal(v["cmi.interactions.3.timestamp"], "2026-11-27T05:52:01.23Z");
  assert.equal(v["cmi.interactions.3.latency"], "PT1M30.5S");
  assert.equal(v["cmi.interactions.3.learner_response"], "1");
  const none = Object.fromEntries(
    interactionValues("1.2", 3, "0.4", { last: "1" }, { correct: false, latencyMs: null, at }));
  assert.equal(none["cmi.interactions.3.result"], "wrong");
  assert.ok(!("cmi.interactions.3.latency" in none), "no latency for a check of an earlier session");
});
