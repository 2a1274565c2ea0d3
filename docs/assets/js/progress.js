// Learner progress in localStorage: namespaced per site, versioned, never lost.
//
// One record per exercise: {solved, revealed, solvedAfterReveal, hinted,
// attempts, last, code, draftOrder, updated} and, since version 2, the variant
// on screen and what was done with each variant, with the review schedule:
// {variant, done, clean, missed, revealedIn, box, due, reviewed} and, since
// version 3, `carried`, and since version 4 the checked steps: `stepped`,
// `steppedDone` and `stepWork` (review.js
// says what they mean; progress-schema.js checks them and merges two copies).
//
// Never lost:
// - Every write merges: it reads what storage holds now, merges this tab's
//   records into it (progress-schema.js) and writes the result at once; then
//   it does so again inside a Web Lock, so that tabs take turns repairing what
//   a concurrent write dropped. Because a tab's view of localStorage may lag
//   another tab's write (and where Web Locks are missing), every tab also
//   merges each change another tab makes (the storage event) and writes back
//   whatever it knows that the other did not: the copies converge.
// - Storage that cannot be written (full, or blocked) never hides what it
//   holds: the saved records are shown, the page says that new answers are
//   not saved, and everything stays exportable from memory.
// - A saved value that cannot be read (not JSON, a newer version, a field of
//   the wrong type) is copied under a backup key before anything is written;
//   if even that copy fails, nothing is written at all until it succeeds, and
//   the page offers the unreadable text as a download.

import { mergeData, mergeRecord, salvageRecord, same, canonical, isObject, EXPORT_FORMAT,
  SCHEMA_VERSION } from "./progress-schema.js";
import { migrateRecord } from "./review.js";

export { MAX_IMPORT_BYTES, parseImport, SCHEMA_VERSION, EXPORT_FORMAT } from "./progress-schema.js";

const FULL = "Your browser's storage for this site is full, so new answers are not saved. Free some space (or export "
  + "your progress to keep it), then answer again.";

/** localStorage, or null where the browser refuses it (private mode, disabled). */
function openStorage() {
  try {
    const s = window.localStorage;
    s.getItem("__workbook_probe__");
    return s;
  } catch {
    return null;
  }
}

const mapRecords = (exercises, fn) => Object.fromEntries(Object.entries(exercises).map(([id, r]) => [id, fn(r)]));
const MIGRATIONS = {
  // 1 -> 2: variants and the review queue; a solved mark becomes variant 0 solved.
  1: (data) => ({ ...data, version: 2, exercises: mapRecords(data.exercises, (r) => migrateRecord(r)) }),
  // 2 -> 3: adds `carried` (the variants answered right only given a wrong earlier value); records keep the rest.
  2: (data) => ({ ...data, version: 3 }),
  // 3 -> 4: adds the checked steps (`stepped`, `steppedDone`, `stepWork`); records keep the rest.
  3: (data) => ({ ...data, version: 4 }),
  // 4 -> 5: adds the assignment fields (`slips`, `assigned`: assignment-schema.js); records keep the rest.
  4: (data) => ({ ...data, version: 5 }),
};

class Unreadable extends Error {}

/** Stored text -> {data, setAside}: the readable records, and what had to be left out. Throws Unreadable. */
function parseStored(raw) {
  let data;
  try {
    data = JSON.parse(raw);
  } catch {
    throw new Unreadable("it is not valid JSON");
  }
  if (!isObject(data) || !isObject(data.exercises)) throw new Unreadable("it is not a progress record");
  if ((data.version ?? 0) > SCHEMA_VERSION) throw new Unreadable(`it was written by a newer version of the workbook `
    + `(${data.version})`);
  while ((data.version ?? 0) < SCHEMA_VERSION) {
    const step = MIGRATIONS[data.version ?? 0];
    if (!step) throw new Unreadable(`no migration from version ${data.version}`);
    data = step(data);
  }
  const exercises = {};
  const setAside = {};
  for (const [id, raw] of Object.entries(data.exercises)) {
    const { record, bad } = salvageRecord(raw);
    if (record) exercises[id] = record;
    if (bad !== null) setAside[id] = bad;
  }
  const reset = Number.isFinite(data.reset) ? data.reset : 0;
  return { data: { version: SCHEMA_VERSION, ...(reset ? { reset } : {}), exercises }, setAside };
}

const emptyData = () => ({ version: SCHEMA_VERSION, exercises: {} });

export class Progress {
  /**
   * @param {string} siteRoot the site's base address: each site keeps its own record
   * @param {{learner?: string, memoryOnly?: string}} [options] `learner`: an opaque key (a hash, never a name or an id)
   *   that gives one learner of a shared browser a record of their own (the LMS's learner, the assignment's student)
   *   `memoryOnly`: when set, the record is kept in memory only (nothing read or written in
   *   storage), and this text tells the learner why (an LMS that gives no learner id: lms/learner.js)
   */
  constructor(siteRoot, { learner = "", memoryOnly = "" } = {}) {
    const scope = new URL(siteRoot).pathname.replace(/\/+$/, "") || "/";
    this.key = learner ? `robotics-workbook:${scope}:learner:${learner}:progress`
      : `robotics-workbook:${scope}:progress`;
    this.memoryOnly = memoryOnly;
    this.store = memoryOnly ? null : openStorage();
    this.listeners = new Set();
    this.problems = []; // {kind, message, download?}: what the page must tell the learner
    this.pending = null; // a backup that must be written before anything else
    this.queued = false;
    this.data = this.load();
    if (!this.store) return;
    this.probe();
    // Another tab saved: merge it in, and write back what this tab knows that it did not.
    window.addEventListener("storage", (event) => {
      if (event.key !== this.key || event.storageArea !== this.store || event.newValue === null) return;
      let theirs;
      try {
        theirs = parseStored(event.newValue).data;
      } catch {
        return; // unreadable here (e.g. a newer version in another tab): leave it to that tab
      }
      this.absorb(theirs);
      if (!same(theirs, this.data)) this.persist();
    });
  }

  load() {
    if (!this.store && this.memoryOnly) {
      this.report("memory", this.memoryOnly);
      return emptyData();
    }
    if (!this.store) {
      this.report("unavailable", "This browser does not let the workbook store anything, so your answers last only "
        + "until you close this page. Export your progress to keep it.");
      return emptyData();
    }
    const raw = this.store.getItem(this.key);
    if (raw === null) return emptyData();
    try {
      const { data, setAside } = parseStored(raw);
      const ids = Object.keys(setAside);
      if (ids.length) {
        const what = ids.slice(0, 6).map((id) => (isObject(setAside[id])
          ? `${id} (${Object.keys(setAside[id]).join(", ")})` : id)).join("; ");
        this.keepAside(raw, `Part of your saved progress could not be read (exercise ${what}); the rest is shown as `
          + `usual.`);
      }
      return data;
    } catch (err) {
      if (!(err instanceof Unreadable)) throw err;
      this.keepAside(raw, `Your saved progress could not be read (${err.message}), so this page starts from an empty `
        + `record.`);
      return emptyData();
    }
  }

  /** Storage already full when the page opens: say so now, not after the first answer is lost. */
  probe() {
    const key = `${this.key}:probe`;
    try {
      this.store.setItem(key, "x".repeat(1024)); // about what one answer adds
      this.store.removeItem(key);
    } catch {
      this.failed("full");
    }
  }

  /** Copy `raw` under a backup key before anything is written; say where it is, or that nothing will be written until
   * it is. */
  keepAside(raw, why) {
    const backup = `${this.key}:backup:${Date.now()}`;
    this.pending = { key: backup, raw };
    this.keptRaw = raw;
    const download = { name: "robotics-math-workbook-unreadable-progress.json", text: raw };
    if (this.writeBackup()) {
      this.report("set-aside", `${why} The saved text is kept unchanged under “${backup}” in this browser's storage.`,
        download);
    } else {
      this.report("blocked", `${why} There is no room to keep a copy of it, so nothing will be saved until there is: `
        + `download it, or free some space.`, download);
    }
  }

  writeBackup() {
    if (!this.pending) return true;
    try {
      this.store.setItem(this.pending.key, this.pending.raw);
      this.pending = null;
      return true;
    } catch {
      return false;
    }
  }

  report(kind, message, download = null) {
    const problem = { kind, message, download };
    this.problems.push(problem);
    document.dispatchEvent(new CustomEvent("workbook:progress-problem", { detail: problem }));
  }

  get(id) {
    return this.data.exercises[id] || {};
  }

  /** Every record, keyed by exercise id (a copy). */
  all() {
    return structuredClone(this.data.exercises);
  }

  update(id, patch) {
    const next = { ...this.get(id), ...patch, updated: this.stamp(id) };
    for (const [k, v] of Object.entries(next)) if (v === undefined) delete next[k];
    this.data.exercises[id] = next;
    this.persist();
    this.notify(id, next);
    return next;
  }

  /**
   * The time a write of `id` is stamped with: now, or just after what is already stored when
   * that is later (a record stamped by a clock that ran ahead, in another tab or an imported
   * file) or after the last erase. A later write on this device always counts as the newer.
   */
  stamp(id) {
    return Math.max(Date.now(), (this.get(id).updated ?? 0) + 1, (this.data.reset ?? 0) + 1);
  }

  notify(id, record) {
    for (const fn of this.listeners) fn(id, record);
  }

  /** Take in another copy of the store (another tab's); tell the page if anything changed. */
  absorb(theirs) {
    const merged = mergeData(theirs, this.data);
    if (same(merged, this.data)) return false;
    this.data = merged;
    this.notify(null, null);
    return true;
  }

  /**
   * Write now (read, merge, write), then once more inside the Web Lock that
   * every tab of this site shares: that second pass reads again and writes back
   * anything a concurrent write from another tab dropped.
   */
  persist() {
    this.flush();
    if (!this.store || this.queued || !navigator.locks?.request) return;
    this.queued = true;
    const again = () => {
      this.queued = false;
      this.flush();
    };
    navigator.locks.request(this.key, again).catch(again);
  }

  /** Read what is stored, merge, write: the one place that writes the record. */
  flush() {
    if (!this.store) return false;
    if (!this.writeBackup()) return this.failed("blocked");
    const raw = this.store.getItem(this.key);
    let stored = emptyData();
    if (raw !== null && raw !== this.keptRaw) {
      try {
        stored = parseStored(raw).data;
      } catch {
        // Changed since load into something unreadable (another tab, a newer version): keep it first.
        this.keepAside(raw, "Another copy of your saved progress could not be read.");
        if (this.pending) return this.failed("blocked");
      }
    }
    this.absorb(stored);
    if (raw !== null && same(stored, this.data)) return this.saved();
    try {
      this.store.setItem(this.key, canonical(this.data));
      return this.saved();
    } catch {
      return this.failed("full");
    }
  }

  saved() {
    if (this.unsaved) {
      this.unsaved = false;
      this.problems = this.problems.filter((p) => p.kind !== "full" && p.kind !== "blocked");
      document.dispatchEvent(new CustomEvent("workbook:progress-saved"));
    }
    return true;
  }

  failed(kind) {
    if (!this.unsaved) { // said once; the next answer tries again
      this.unsaved = true;
      if (kind === "full") this.report("full", FULL);
    }
    return false;
  }

  /** The export file's content (an object; JSON.stringify it). */
  exportData() {
    return { format: EXPORT_FORMAT, version: SCHEMA_VERSION, exported: new Date().toISOString(),
      exercises: this.all() };
  }

  /**
   * Merge clean records (from parseImport) into these, field by field
   * (progress-schema.js). Returns the ids added, changed and already up to date.
   */
  merge(records) {
    const summary = { added: [], merged: [], unchanged: [] };
    for (const [id, record] of Object.entries(records)) {
      const mine = this.data.exercises[id];
      const next = mergeRecord(mine, record);
      if (!mine) summary.added.push(id);
      else if (same(mine, next)) {
        summary.unchanged.push(id);
        continue;
      } else summary.merged.push(id);
      this.data.exercises[id] = next;
    }
    if (summary.added.length || summary.merged.length) {
      this.persist();
      this.notify(null, null);
    }
    return summary;
  }

  /** Forget every exercise's record (answers, code, solved marks), in every tab. */
  reset() {
    // Stamped after every record this tab knows of, however far ahead its clock ran, so that
    // the erase drops them all here, in storage and in every other tab's copy.
    this.flush();
    const latest = Math.max(0, ...Object.values(this.data.exercises).map((r) => r.updated ?? 0));
    this.data = { version: SCHEMA_VERSION, reset: Math.max(Date.now(), latest + 1, (this.data.reset ?? 0) + 1),
      exercises: {} };
    this.persist();
    this.notify(null, null);
  }

  onChange(fn) {
    this.listeners.add(fn);
  }
}
