// Learner progress in localStorage: namespaced per site, versioned, never lost.
//
// One record per exercise: {solved, revealed, solvedAfterReveal, hinted,
// attempts, last, code, draftOrder, updated} and, since version 2, the variant
// on screen and what was done with each variant, with the review schedule:
// {variant, done, clean, missed, revealedIn, box, due, reviewed} (review.js
// says what they mean). Version-1 records are migrated on load and on import. A value that cannot be read is set
// aside under a backup key, never silently wiped; a full quota is reported, not
// swallowed (the record stays in memory and can still be exported).
//
// Export/import: a JSON file {format, version, exported, exercises}. An import is
// checked field by field against FIELDS below (add a new record field there) and
// merged per exercise, the newer `updated` winning; anything unexpected refuses
// the whole file and changes nothing.

import { migrateRecord, TOP_BOX } from "./review.js";

export const SCHEMA_VERSION = 2;
export const EXPORT_FORMAT = "robotics-math-workbook-progress";
export const MAX_IMPORT_BYTES = 1_000_000;

function storage() {
  try {
    const s = window.localStorage;
    const probe = "__workbook_probe__";
    s.setItem(probe, "1");
    s.removeItem(probe);
    return s;
  } catch {
    return null; // private mode or storage disabled: keep progress in memory
  }
}

const mapRecords = (exercises, fn) => Object.fromEntries(Object.entries(exercises).map(([id, r]) => [id, fn(r)]));
const MIGRATIONS = {
  // 1 -> 2: variants and the review queue; a solved mark becomes variant 0 solved.
  1: (data) => ({ ...data, version: 2, exercises: mapRecords(data.exercises, (r) => migrateRecord(r)) }),
};

// ---- The record schema (used to validate imports) ---------------------------
const DAY_MS = 86_400_000;
const isBool = (v) => typeof v === "boolean";
const isKeyList = (v) => Array.isArray(v) && v.length <= 50 && v.every((k) => typeof k === "string" && k.length <= 200);
// A vector or matrix answer is saved as its grid of entry texts, row by row.
const isGrid = (v) => Array.isArray(v) && v.length >= 1 && v.length <= 12
  && v.every((row) => Array.isArray(row) && row.length <= 12 && row.every((s) => typeof s === "string" && s.length <= 200));
const MAX_VARIANT = 999_999;
const isVariant = (v) => Number.isSafeInteger(v) && v >= 0 && v <= MAX_VARIANT;
const isVariantList = (v) => Array.isArray(v) && v.length <= 100 && v.every(isVariant);
const VARIANTS = [isVariantList, "a list of at most 100 variant numbers (0 to 999,999)"];
const FIELDS = {
  solved: [isBool, "true or false"],
  revealed: [isBool, "true or false"],
  solvedAfterReveal: [isBool, "true or false"],
  hinted: [isBool, "true or false"],
  attempts: [(v) => Number.isSafeInteger(v) && v >= 0 && v <= 1_000_000, "a whole number from 0 to 1,000,000"],
  last: [(v) => (typeof v === "string" && v.length <= 2000) || Number.isFinite(v) || isKeyList(v) || isGrid(v), "a short answer (text, number, list of step keys or grid of entries)"],
  draftOrder: [isKeyList, "a list of step keys"],
  code: [(v) => typeof v === "string" && v.length <= 100_000, "text of at most 100,000 characters"],
  updated: [(v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + DAY_MS, "a time (milliseconds since 1970) not in the future"],
  variant: [isVariant, "a variant number from 0 to 999,999"],
  done: VARIANTS,
  clean: VARIANTS,
  missed: VARIANTS,
  revealedIn: VARIANTS,
  box: [(v) => Number.isInteger(v) && v >= 1 && v <= TOP_BOX, `a review box from 1 to ${TOP_BOX}`],
  due: [(v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + 366 * DAY_MS, "a time (milliseconds since 1970) within a year"],
  reviewed: [(v) => Number.isFinite(v) && v >= 0 && v <= Date.now() + DAY_MS, "a time (milliseconds since 1970) not in the future"],
};
const FORBIDDEN_KEYS = new Set(["__proto__", "constructor", "prototype"]);
const isObject = (v) => v !== null && typeof v === "object" && !Array.isArray(v);

class ImportError extends Error {}

function checkKeys(obj, where) {
  for (const key of Object.keys(obj)) {
    if (FORBIDDEN_KEYS.has(key)) throw new ImportError(`${where} contains the forbidden key “${key}”.`);
  }
}

function cleanRecord(id, raw) {
  if (!isObject(raw)) throw new ImportError(`The entry for exercise ${id} is not an object.`);
  checkKeys(raw, `The entry for exercise ${id}`);
  const record = {};
  for (const [field, value] of Object.entries(raw)) {
    const rule = FIELDS[field];
    if (!rule) throw new ImportError(`The entry for exercise ${id} has an unknown field “${field.slice(0, 40)}”.`);
    if (!rule[0](value)) throw new ImportError(`In exercise ${id}, “${field}” must be ${rule[1]}.`);
    record[field] = value;
  }
  return record;
}

/**
 * Check the text of a progress file. Returns {ok: true, exercises} with clean
 * records, or {ok: false, reason} saying what is wrong. `knownIds` (a Set) lists
 * the site's exercises; ids outside it are refused.
 */
export function parseImport(text, knownIds) {
  try {
    if (typeof text !== "string") throw new ImportError("The file could not be read as text.");
    if (text.length > MAX_IMPORT_BYTES) throw new ImportError(`The file is too large (over ${MAX_IMPORT_BYTES.toLocaleString("en")} characters); a progress file is much smaller.`);
    let data;
    try {
      data = JSON.parse(text);
    } catch {
      throw new ImportError("The file is not valid JSON.");
    }
    if (!isObject(data)) throw new ImportError("The file does not hold a progress record (expected a JSON object).");
    checkKeys(data, "The file");
    if (data.format !== EXPORT_FORMAT) throw new ImportError("The file is not a Robotics Math Workbook progress export (its “format” is missing or different).");
    if (!Number.isInteger(data.version) || data.version < 1) throw new ImportError("The file has no valid “version”.");
    if (data.version > SCHEMA_VERSION) throw new ImportError(`The file was written by a newer version of the workbook (version ${data.version}); update this page first.`);
    for (const key of Object.keys(data)) {
      if (!["format", "version", "exported", "site", "exercises"].includes(key)) throw new ImportError(`The file has an unexpected entry “${key.slice(0, 40)}”.`);
    }
    if (!isObject(data.exercises)) throw new ImportError("The file has no “exercises” object.");
    checkKeys(data.exercises, "The exercise list");
    const exercises = {};
    for (const [id, raw] of Object.entries(data.exercises)) {
      if (knownIds && !knownIds.has(id)) throw new ImportError(`The file mentions exercise “${id.slice(0, 20)}”, which this workbook does not have.`);
      const record = cleanRecord(id, raw);
      exercises[id] = data.version < 2 ? migrateRecord(record) : record; // a version-1 file: same migration as on load
    }
    return { ok: true, exercises };
  } catch (err) {
    if (err instanceof ImportError) return { ok: false, reason: err.message };
    return { ok: false, reason: "The file could not be checked." };
  }
}

export class Progress {
  constructor(siteRoot) {
    const scope = new URL(siteRoot).pathname.replace(/\/+$/, "") || "/";
    this.key = `robotics-workbook:${scope}:progress`;
    this.store = storage();
    this.listeners = new Set();
    this.data = this.load();
    // Another tab saved progress: take it over, so both tabs agree.
    window.addEventListener("storage", (event) => {
      if (event.key !== this.key || event.storageArea !== this.store) return;
      this.data = this.load();
      this.notify(null, null);
    });
  }

  load() {
    const empty = { version: SCHEMA_VERSION, exercises: {} };
    if (!this.store) return empty;
    const raw = this.store.getItem(this.key);
    if (raw === null) return empty;
    try {
      let data = JSON.parse(raw);
      if (!data || typeof data !== "object" || typeof data.exercises !== "object") throw new Error("not a progress record");
      while ((data.version ?? 0) < SCHEMA_VERSION) {
        const step = MIGRATIONS[data.version ?? 0];
        if (!step) throw new Error(`no migration from version ${data.version}`);
        data = step(data);
      }
      if (data.version > SCHEMA_VERSION) throw new Error(`written by a newer version (${data.version})`);
      return data;
    } catch (err) {
      const backup = `${this.key}:backup:${Date.now()}`;
      try {
        this.store.setItem(backup, raw);
      } catch {
        /* nothing more we can keep */
      }
      this.notice = `Saved progress could not be read (${err.message}); it was kept aside as “${backup}” and a fresh record started.`;
      return empty;
    }
  }

  get(id) {
    return this.data.exercises[id] || {};
  }

  /** Every record, keyed by exercise id (a copy). */
  all() {
    return structuredClone(this.data.exercises);
  }

  update(id, patch) {
    const next = { ...this.get(id), ...patch, updated: Date.now() };
    this.data.exercises[id] = next;
    this.save();
    this.notify(id, next);
    return next;
  }

  notify(id, record) {
    for (const fn of this.listeners) fn(id, record);
  }

  save() {
    if (!this.store) return true;
    try {
      this.store.setItem(this.key, JSON.stringify(this.data));
      this.saveError = null;
      return true;
    } catch (err) {
      this.saveError = "Your browser's storage is full, so this progress is not saved yet. Free some space (or export your progress) to keep it.";
      document.dispatchEvent(new CustomEvent("workbook:storage-error", { detail: this.saveError }));
      return false;
    }
  }

  /** The export file's content (an object; JSON.stringify it). */
  exportData() {
    return { format: EXPORT_FORMAT, version: SCHEMA_VERSION, exported: new Date().toISOString(), exercises: this.all() };
  }

  /**
   * Merge clean records (from parseImport): per exercise, the record with the
   * newer `updated` wins; a tie keeps the one here. Returns the ids added,
   * replaced and kept.
   */
  merge(records) {
    const summary = { added: [], replaced: [], kept: [] };
    const next = { ...this.data.exercises };
    for (const [id, record] of Object.entries(records)) {
      const mine = next[id];
      if (!mine) summary.added.push(id);
      else if ((record.updated ?? 0) > (mine.updated ?? 0)) summary.replaced.push(id);
      else {
        summary.kept.push(id);
        continue;
      }
      next[id] = structuredClone(record);
    }
    if (summary.added.length || summary.replaced.length) {
      this.data.exercises = next;
      this.save();
      this.notify(null, null);
    }
    return summary;
  }

  /** Forget every exercise's record (answers, code, solved marks). */
  reset() {
    this.data.exercises = {};
    this.save();
    this.notify(null, null);
  }

  onChange(fn) {
    this.listeners.add(fn);
  }
}
