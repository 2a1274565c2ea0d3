// Learner progress in localStorage: namespaced per site, versioned, never lost.
//
// One record per exercise: {solved, revealed, solvedAfterReveal, attempts,
// last, code, updated}. A value that cannot be read is set aside under a
// backup key, never silently wiped; a full quota is reported, not swallowed.

export const SCHEMA_VERSION = 1;

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

const MIGRATIONS = {
  // 0 -> 1 would go here: (data) => ({ ...data, version: 1 })
};

export class Progress {
  constructor(siteRoot) {
    const scope = new URL(siteRoot).pathname.replace(/\/+$/, "") || "/";
    this.key = `robotics-workbook:${scope}:progress`;
    this.store = storage();
    this.listeners = new Set();
    this.data = this.load();
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

  update(id, patch) {
    const next = { ...this.get(id), ...patch, updated: Date.now() };
    this.data.exercises[id] = next;
    this.save();
    for (const fn of this.listeners) fn(id, next);
    return next;
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

  onChange(fn) {
    this.listeners.add(fn);
  }
}
