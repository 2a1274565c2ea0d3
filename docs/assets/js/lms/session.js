// A workbook page shown by a SCO's launcher (lms/launch.js) in an LMS: it reports
// through the launch's one SCORM session, whatever chapter the learner has moved to.
//
// - Start (before the first exercise is drawn: main.js calls connectLms first): the
//   progress in cmi.suspend_data (set by this chapter or any other of the workbook's
//   SCOs, on this or another computer) is merged into the local record by the import's
//   field rules: nothing local is replaced.
// - Every check (a graded answer, a Build run, a checked step): the launched chapter's
//   score and status, the checked exercise's objective and interaction (when it is one of
//   the launched chapter's), suspend_data and session_time are set, then Commit.
// - pagehide of this page (a link to another page of the workbook, or the launch ending):
//   the same, once more. The launcher alone Initializes and Terminates.
// - The LMS refuses a call (a full quota, a closed session): a notice says so;
//   the local record is never touched by a failure, and everything is sent again
//   at the next check.
//
// <html data-workbook-lms> (contract: lmsStates) says where this page stands:
// "open" (reporting), "closed" (its last report sent), "failed" (no session to report to).

import { ATTR, LMS, STATE, setRootState } from "../contract.js";
import { clearNotice, exportProgress, showNotice } from "../notice.js";
import { onAttempt } from "../attempt.js";
import { chapterValues, interactionValues, objectiveValues } from "./report.js";
import { decodeSuspend, encodeSuspend } from "./suspend.js";
import { VERSIONS } from "./versions.js";

const NOTICE = "lms";

const says = (error) =>
  (error?.code ? `error ${error.code}${error.text ? `: ${error.text}` : ""}` : error?.text || "no reason given");

/** Report this page's work through `launch` (null: a page an LMS shows without the workbook's launcher). */
export function connectLms(progress, launch) {
  const session = new Session(launch, progress);
  session.start();
  return session;
}

class Session {
  constructor(launch, progress) {
    this.launch = launch;
    this.progress = progress;
    this.lms = launch?.lms ?? null;
    this.version = launch?.version ?? null;
    this.el = this.version ? VERSIONS[this.version].element : null;
    this.ids = launch?.ids ?? []; // the launched chapter's exercises: the SCO's score and objectives
    this.started = Date.now();
    this.state = null;
    // id -> {attempts, steps, since}: what the last change showed, and when the exercise was last checked
    this.seen = new Map();
    this.graded = new Map(); // id -> the exercise's last graded attempt (attempt.js)
    this.resendAll = true;
    this.calls = { commits: 0 };
    this.resumed = { entry: "", records: 0, skipped: 0 };
    this.dropped = null;
  }

  setState(state) {
    this.state = state;
    setRootState("lms", state);
  }

  start() {
    if (!this.launch) {
      this.setState(LMS.failed);
      this.tell("This page was opened by the course without the workbook's launcher, so its results are not sent to "
        + "the course and your answers are kept only while it is open. Open the chapter from the course's list to have "
        + "your work counted.");
      return;
    }
    if (this.launch.state !== LMS.open) {
      this.setState(LMS.failed);
      this.tell(`The course's platform did not open a session for this chapter (${says(this.launch.error)}), so its `
        + "results are not sent to it, and your answers are kept only while it is open. "
        + "Export your progress to keep it.");
      return;
    }
    this.restore();
    this.setState(LMS.open);
    const onPage = [...document.querySelectorAll(`[${ATTR.exercise}]`)].map((el) => el.getAttribute(ATTR.exercise));
    for (const id of new Set([...this.ids, ...onPage])) this.seen.set(id, { ...this.look(id), since: this.started });
    // A check's result is the graded attempt's (attempt.js), heard before the record changes.
    onAttempt(({ id, progress, attempt }) => { if (progress === this.progress) this.graded.set(id, attempt); });
    this.progress.onChange((id) => this.changed(id));
    const detach = this.launch.attach(() => this.last());
    window.addEventListener("pagehide", () => {
      this.last();
      detach();
    });
    this.sync(null);
  }

  /** Merge what the LMS holds into the local record (the import's rules: never replace). */
  restore() {
    this.resumed.entry = this.lms.get(this.el.entry);
    const text = this.lms.get("cmi.suspend_data");
    if (!text) return;
    const { exercises, skipped } = decodeSuspend(text);
    this.resumed.records = Object.keys(exercises).length;
    this.resumed.skipped = skipped;
    if (this.resumed.records) this.progress.merge(exercises);
  }

  look(id) {
    const r = this.progress.get(id);
    return { attempts: r.attempts ?? 0, steps: JSON.stringify([r.stepped ?? [], r.stepWork ?? null]) };
  }

  /** A record changed: a check (attempts, or a checked step) sends it now; anything else waits for the next commit. */
  changed(id) {
    if (this.state !== LMS.open || id === null || this.launch.state !== LMS.open) return;
    const before = this.seen.get(id) ?? { attempts: 0, steps: JSON.stringify([[], null]), since: this.started };
    const now = this.look(id);
    const checked = now.attempts > before.attempts;
    if (!checked && now.steps === before.steps) return;
    const at = Date.now();
    let check = null;
    if (checked) {
      check = { correct: this.graded.get(id)?.status === STATE.correct, latencyMs: at - before.since, at };
    }
    this.seen.set(id, { ...now, since: checked ? at : before.since });
    this.sync(id, check);
  }

  /** Set what changed (everything after a failure or at the start), then Commit. */
  sync(id, check = null, { final = false } = {}) {
    const records = this.progress.all();
    const values = [...chapterValues(this.version, records, this.ids, this.launch.threshold)];
    this.ids.forEach((exercise, i) => {
      if (!this.resendAll && exercise !== id) return;
      const record = records[exercise] || {};
      const earlier = exercise === id ? check : (record.attempts ?? 0) > 0
        ? {
          correct: (record.done ?? []).includes(record.variant ?? 0), latencyMs: null, at: record.updated ?? Date.now(),
        }
        : null;
      values.push(...objectiveValues(this.version, i, exercise, record),
        ...interactionValues(this.version, i, exercise, record, earlier));
    });
    const { text, dropped } = encodeSuspend(records, this.version, this.ids);
    this.dropped = dropped;
    const elapsed = Date.now() - this.launch.started; // the launch's time, not this page's
    values.push(["cmi.suspend_data", text], [this.el.exit, "suspend"],
      [this.el.time, VERSIONS[this.version].elapsed(elapsed)]);
    let ok = values.every(([element, value]) => this.lms.set(element, value));
    if (ok) ok = this.lms.commit();
    if (ok) this.calls.commits += 1;
    this.resendAll = !ok;
    if (ok) clearNotice(NOTICE);
    else if (!final) {
      this.tell(`Your latest work could not be sent to the course's platform (${says(this.lms.lastError)}). `
        + "Nothing is lost: it is kept in this browser, and sent again with your next check.");
    }
    return ok;
  }

  /** This page's last report (its pagehide, or the launch ending first), once. */
  last() {
    if (this.state !== LMS.open || this.launch.state !== LMS.open) return;
    this.sync(null, null, { final: true });
    this.setState(LMS.closed);
  }

  tell(message) {
    showNotice(NOTICE, "Course platform", message,
      [{ text: "Export progress", action: "notice-export", run: () => exportProgress(this.progress) }]);
  }
}
