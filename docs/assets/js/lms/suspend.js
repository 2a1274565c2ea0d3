// The progress record in SCORM's suspend_data: what travels with the learner from
// one computer to another through the LMS.
//
// Two encodings, each a prefix and a body:
// - "wbj:" + the records as JSON (every field the local record holds): SCORM 2004
//   (64,000 characters) when it fits;
// - "wb1:" + base64url of a compact binary form of each record's essential state:
//   solved (the newest MASTERED clean variants, else one solved with steps, else one
//   solved after a reveal), the flags (solved, solved after reveal, hinted,
//   revealed), attempts, the variant on screen, the review box and due time, the
//   time it was updated, and the last answer (the answer of the variant on screen).
//   Every exercise's essential state fits in SCORM 1.2's 4,096 characters.
//
// When it would not fit, what is dropped first:
//   2004: the checked steps on screen (`stepWork`), then Build code, then the
//         compact form (as for 1.2);
//   1.2:  last answers, of the exercise updated longest ago first; then whole records,
//         oldest first. The launched chapter's own (`first`) go last in each round: a SCO's
//         suspend_data is its own, so every chapter's records travel whole in their own
//         SCO's copy, and the others' as far as they fit (at their widest, 112 records take
//         4,036 characters, so a few more chapters pass the limit; one chapter's need under 500).
// What is dropped is only left out of the LMS's copy: this browser keeps it.
//
// Decoding never trusts the text: every record passes the progress schema's
// checks (cleanRecord) or is left out.
//
// The compact form answers for every field of the one record schema (progress-schema.js
// FIELDS): each is carried, rebuilt from carried ones, or dropped on purpose (COMPACT);
// tests/js/suspend.test.mjs fails when a field of the schema is none of these.

import { MASTERED, INTERVAL_MS, TOP_BOX } from "../review.js";
import { FIELDS, canonical, cleanRecord, isObject } from "../progress-schema.js";
import { VERSIONS } from "./versions.js";

export const LIMIT_12 = VERSIONS["1.2"].suspendLimit;
export const LIMIT_2004 = VERSIONS["2004"].suspendLimit;

/** What the compact form does with each field of the record schema. */
export const COMPACT = {
  // Written as one bit each, in this order (append only: the order is the format).
  flags: ["solved", "solvedAfterReveal", "hinted", "revealed"],
  // Written as they are (the variant lists: their newest items that say the state).
  carried: ["clean", "steppedDone", "done", "variant", "attempts", "updated", "box", "due", "last"],
  rebuilt: { reviewed: "from the review box and the due time" },
  dropped: {
    missed: "the variants answered wrong: history, not state",
    revealedIn: "the variants whose worked answer was shown: history (revealed and solvedAfterReveal say the state)",
    carried: "the variants right only given a wrong earlier value: history",
    stepped: "the variants worked with steps: history (steppedDone says what was solved that way)",
    stepWork: "the checked steps on screen: too large for 4,096 characters",
    code: "Build code: too large for 4,096 characters",
    draftOrder: "a draft order of steps not yet checked",
    slips: "the named slips hit: the assignment page's, not the LMS's",
    assigned: "an assignment's graded answers: the assignment page's, not the LMS's",
  },
};

/** The schema's fields that COMPACT does not answer for, and COMPACT's names that are not in the schema. */
export function compactCoverage(schema = FIELDS) {
  const listed = [
    ...COMPACT.flags, ...COMPACT.carried, ...Object.keys(COMPACT.rebuilt), ...Object.keys(COMPACT.dropped)];
  return {
    unlisted: Object.keys(schema).filter((f) => !listed.includes(f)),
    unknown: listed.filter((f) => !(f in schema)),
  };
}
const JSON_PREFIX = "wbj:";
const COMPACT_PREFIX = "wb1:";
const ID = /^(\d{1,3})\.(\d{1,3})$/;
const MINUTE = 60_000;

// ---- bytes ----------------------------------------------------------------------
class Writer {
  constructor() {
    this.bytes = [];
  }
  uint(n) { // unsigned varint, 7 bits a byte
    let v = Math.max(0, Math.floor(n));
    while (v >= 128) {
      this.bytes.push((v % 128) | 128);
      v = Math.floor(v / 128);
    }
    this.bytes.push(v);
  }
  int(n) { // zigzag: small negatives stay small
    this.uint(n < 0 ? -2 * n - 1 : 2 * n);
  }
  list(values) {
    this.uint(values.length);
    values.forEach((v) => this.uint(v));
  }
  text(s) {
    const b = new TextEncoder().encode(s);
    this.uint(b.length);
    this.bytes.push(...b);
  }
}

class Reader {
  constructor(bytes) {
    this.bytes = bytes;
    this.at = 0;
  }
  byte() {
    if (this.at >= this.bytes.length) throw new Error("short");
    return this.bytes[this.at++];
  }
  uint() {
    let v = 0;
    for (let scale = 1; ; scale *= 128) {
      const b = this.byte();
      v += (b & 127) * scale;
      if (b < 128) return v;
      if (scale > 2 ** 42) throw new Error("too long");
    }
  }
  int() {
    const z = this.uint();
    return z % 2 ? -(z + 1) / 2 : z / 2;
  }
  list() {
    const n = this.uint();
    if (n > 100) throw new Error("list");
    return Array.from({ length: n }, () => this.uint());
  }
  text() {
    const n = this.uint();
    if (this.at + n > this.bytes.length) throw new Error("short");
    const s = new TextDecoder().decode(new Uint8Array(this.bytes.slice(this.at, this.at + n)));
    this.at += n;
    return s;
  }
}

const toBase64Url = (bytes) => {
  let bin = "";
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
};
const fromBase64Url = (text) => {
  const bin = atob(text.replace(/-/g, "+").replace(/_/g, "/"));
  return Array.from(bin, (c) => c.charCodeAt(0));
};

// ---- the compact form -----------------------------------------------------------
// The record's flags, then two of the layout's own (a review schedule follows, a last answer follows).
const FLAG = Object.fromEntries([...COMPACT.flags, "review", "last"].map((name, i) => [name, 2 ** i]));
const newest = (list, n) => (Array.isArray(list) ? list.slice(-n) : []);

/** One record's essential state, as bytes; `withLast` keeps its last answer. */
function writeRecord(w, id, r, base, withLast) {
  const [, chapter, number] = ID.exec(id);
  w.uint(Number(chapter));
  w.uint(Number(number));
  const review = Number.isInteger(r.box) && Number.isFinite(r.due);
  const last = withLast && r.last !== undefined && r.last !== null ? JSON.stringify(r.last) : null;
  let flags = 0;
  for (const name of COMPACT.flags) if (r[name]) flags |= FLAG[name];
  if (review) flags |= FLAG.review;
  if (last !== null) flags |= FLAG.last;
  w.uint(flags);
  // Solved as few variants as say it: the clean ones (mastery), else one with steps, else one after a reveal.
  const clean = newest(r.clean, MASTERED);
  const stepped = clean.length ? [] : newest(r.steppedDone, 1);
  const done = clean.length || stepped.length ? [] : newest(r.done, 1);
  w.list(clean);
  w.list(stepped);
  w.list(done);
  w.uint(r.variant ?? 0);
  w.uint(r.attempts ?? 0);
  w.uint(Number.isFinite(r.updated) ? Math.floor(r.updated / 1000) - base + 1 : 0);
  if (review) {
    w.uint(r.box);
    w.int(Math.floor(r.due / MINUTE) - Math.floor(base / 60));
  }
  if (last !== null) w.text(last);
}

function readRecord(rd, base) {
  const id = `${rd.uint()}.${rd.uint()}`;
  const flags = rd.uint();
  const clean = rd.list();
  const steppedDone = rd.list();
  const doneOnly = rd.list();
  const r = {};
  for (const name of COMPACT.flags) if (flags & FLAG[name]) r[name] = true;
  if (clean.length) r.clean = clean;
  if (steppedDone.length) r.steppedDone = steppedDone;
  const done = [...new Set([...doneOnly, ...steppedDone, ...clean])];
  if (done.length) r.done = done;
  r.variant = rd.uint();
  r.attempts = rd.uint();
  const updated = rd.uint();
  if (updated) r.updated = (updated - 1 + base) * 1000;
  if (flags & FLAG.review) {
    const box = rd.uint();
    r.box = box;
    r.due = (rd.int() + Math.floor(base / 60)) * MINUTE;
    if (box >= 1 && box <= TOP_BOX) r.reviewed = Math.min(r.due - INTERVAL_MS[box], r.updated ?? Infinity);
  }
  if (flags & FLAG.last) r.last = JSON.parse(rd.text());
  return [id, r];
}

function compact(entries, withLast) {
  const times = entries.map(([, r]) => r.updated).filter(Number.isFinite);
  const base = times.length ? Math.floor(Math.min(...times) / 1000) : 0;
  const w = new Writer();
  w.uint(base);
  w.uint(entries.length);
  for (const [id, r] of entries) writeRecord(w, id, r, base, withLast.has(id));
  return COMPACT_PREFIX + toBase64Url(w.bytes);
}

/**
 * The compact text of `exercises` ({id: record}) within `limit` characters; `first`: the launched chapter's ids.
 * What does not fit is dropped in this order, each step only as far as needed, the record updated longest ago
 * first: other chapters' last answers, then other chapters' records (their own SCOs carry them), then the
 * launched chapter's last answers, and its records only if the chapter alone does not fit.
 * Returns {text, dropped: {answers: [ids], records: [ids]}}.
 */
export function encodeCompact(exercises, limit = LIMIT_12, first = []) {
  const entries = Object.entries(exercises).filter(([id, r]) => ID.test(id) && isObject(r));
  const own = new Set(first);
  const oldest = (list) => [...list].sort(([, x], [, y]) => (x.updated ?? 0) - (y.updated ?? 0));
  const others = oldest(entries.filter(([id]) => !own.has(id)));
  const mine = oldest(entries.filter(([id]) => own.has(id)));
  const withLast = new Set(entries.filter(([, r]) => r.last !== undefined && r.last !== null).map(([id]) => id));
  const dropped = { answers: [], records: [] };
  let kept = entries;
  let text = compact(kept, withLast);
  const answers = (list) => {
    for (const [id] of list) {
      if (text.length <= limit) return;
      if (!withLast.delete(id)) continue;
      dropped.answers.push(id);
      text = compact(kept, withLast);
    }
  };
  const records = (list) => {
    for (const [id] of list) {
      if (text.length <= limit) return;
      dropped.records.push(id);
      kept = kept.filter(([k]) => k !== id);
      text = compact(kept, withLast);
    }
  };
  answers(others);
  records(others);
  answers(mine);
  records(mine);
  return { text, dropped };
}

/** suspend_data for SCORM `version` ("1.2" or "2004"): {text, dropped}; `first`: the launched chapter's ids. */
export function encodeSuspend(exercises, version, first = []) {
  const { suspendLimit, suspendJson } = VERSIONS[version];
  if (!suspendJson) return encodeCompact(exercises, suspendLimit, first);
  const fields = [];
  let records = exercises;
  for (const field of [null, "stepWork", "code"]) {
    if (field) {
      fields.push(field);
      records = Object.fromEntries(Object.entries(records).map(([id, r]) => {
        const rest = { ...r };
        delete rest[field];
        return [id, rest];
      }));
    }
    const text = JSON_PREFIX + canonical(records);
    if (text.length <= suspendLimit) return { text, dropped: { fields } };
  }
  return encodeCompact(exercises, suspendLimit, first);
}

/** The records in a suspend_data text: {exercises, skipped}, where `skipped` counts records that failed their
 *  checks. */
export function decodeSuspend(text) {
  const exercises = {};
  let skipped = 0;
  const keep = (id, raw) => {
    try {
      if (!ID.test(id)) throw new Error("id");
      exercises[id] = cleanRecord(id, raw);
    } catch {
      skipped += 1;
    }
  };
  if (typeof text !== "string" || !text) return { exercises, skipped };
  try {
    if (text.startsWith(JSON_PREFIX)) {
      const data = JSON.parse(text.slice(JSON_PREFIX.length));
      if (!isObject(data)) return { exercises, skipped: 1 };
      for (const [id, raw] of Object.entries(data)) keep(id, raw);
    } else if (text.startsWith(COMPACT_PREFIX)) {
      const rd = new Reader(fromBase64Url(text.slice(COMPACT_PREFIX.length)));
      const base = rd.uint();
      const count = rd.uint();
      for (let i = 0; i < count; i += 1) {
        const [id, r] = readRecord(rd, base);
        keep(id, r);
      }
    } else {
      skipped = 1;
    }
  } catch {
    skipped += 1; // a cut or garbled text: what was read before it is kept
  }
  return { exercises, skipped };
}
