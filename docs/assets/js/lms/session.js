// A chapter page launched by an LMS as a SCO (dist/robotics-workbook-scorm*.zip):
// one SCORM session from the page's start to its pagehide.
//
// - Start (before the first exercise is drawn: main.js calls connectLms first):
//   Initialize, then the progress in cmi.suspend_data (set by this chapter or any
//   other of the workbook's SCOs, on this or another computer) is merged into the
//   local record by the import's field rules: nothing local is replaced.
// - Every check (a graded answer, a Build run, a checked step): that exercise's
//   objective and interaction, the chapter's score and status, suspend_data and
//   session_time are set, then Commit.
// - pagehide: the same, exit = suspend (the next launch resumes), Commit, then
//   Finish/Terminate, exactly once.
// - The LMS refuses a call (a full quota, a closed session): a notice says so;
//   the local record is never touched by a failure, and everything is sent again
//   at the next check.
//
// <html data-workbook-lms> (contract: lmsStates) says where the session stands:
// "open", "closed" (finished), "failed" (the LMS would not start it).

import { ATTR, LMS, STATE, setRootState } from "../contract.js";
import { clearNotice, exportProgress, showNotice } from "../notice.js";
import { ScormApi, findApi } from "./api.js";
import { onAttempt } from "../attempt.js";
import { chapterValues, duration2004, interactionValues, objectiveValues, timespan12 } from "./report.js";
import { decodeSuspend, encodeSuspend } from "./suspend.js";

const NOTICE = "lms";
const ELEMENT = {
  "1.2": { entry: "cmi.core.entry", exit: "cmi.core.exit", time: "cmi.core.session_time", mastery: "cmi.student_data.mastery_score" },
  "2004": { entry: "cmi.entry", exit: "cmi.exit", time: "cmi.session_time", mastery: "cmi.scaled_passing_score" },
};

const says = (error) => (error?.code ? `error ${error.code}${error.text ? `: ${error.text}` : ""}` : error?.text || "no reason given");

/** Open the SCORM session of this page when an LMS launched it; null (the hosted site) when no API is found. */
export function connectLms(progress) {
  const found = findApi(window);
  if (!found) return null;
  const session = new Session(new ScormApi(found), progress);
  session.start();
  return session;
}

class Session {
  constructor(lms, progress) {
    this.lms = lms;
    this.version = lms.version;
    this.el = ELEMENT[lms.version];
    this.progress = progress;
    // The SCO is its launch page's chapter: its exercises, in page order.
    this.ids = [...document.querySelectorAll(`[${ATTR.exercise}]`)].map((el) => el.getAttribute(ATTR.exercise));
    this.started = Date.now();
    this.state = null;
    this.seen = new Map(); // id -> {attempts, steps, since}: what the last change showed, and when the exercise was last checked
    this.graded = new Map(); // id -> the exercise's last graded attempt (attempt.js)
    this.resendAll = true;
    this.calls = { commits: 0, finishes: 0 };
    this.resumed = { entry: "", records: 0, skipped: 0 };
    this.dropped = null;
  }

  setState(state) {
    this.state = state;
    setRootState("lms", state);
  }

  start() {
    // The session belongs to the page the LMS launched: a page of another chapter, opened by a
    // link inside the same frame, must not report itself as the launched SCO.
    const launched = this.lms.pin(location.pathname);
    if (launched !== location.pathname) {
      this.setState(LMS.failed);
      this.tell("This page is not the chapter the course opened, so its results are not sent to the course from here. Your work is kept in this browser and goes to the platform the next time you open a chapter from the course in this browser.");
      return;
    }
    if (!this.lms.initialize()) {
      this.setState(LMS.failed);
      this.tell(`The course's platform did not open a session for this page (${says(this.lms.lastError)}), so this chapter's results are not sent to it from here. Your work is kept in this browser, and goes to the platform the next time you open the chapter from the course in this browser.`);
      return;
    }
    const mastery = this.lms.get(this.el.mastery);
    const threshold = mastery === "" || !Number.isFinite(Number(mastery)) ? null : Number(mastery) / (this.version === "1.2" ? 100 : 1);
    this.threshold = threshold === null ? null : Math.min(1, Math.max(0, threshold));
    this.restore();
    this.setState(LMS.open);
    for (const id of this.ids) this.seen.set(id, { ...this.look(id), since: this.started });
    // A check's result is the graded attempt's (attempt.js), heard before the record changes.
    onAttempt(({ id, progress, attempt }) => { if (progress === this.progress) this.graded.set(id, attempt); });
    this.progress.onChange((id) => this.changed(id));
    window.addEventListener("pagehide", () => this.finish());
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
    if (this.state !== LMS.open || !this.seen.has(id)) return;
    const before = this.seen.get(id);
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
    const values = [...chapterValues(this.version, records, this.ids, this.threshold)];
    this.ids.forEach((exercise, i) => {
      if (!this.resendAll && exercise !== id) return;
      const record = records[exercise] || {};
      const earlier = exercise === id ? check : (record.attempts ?? 0) > 0
        ? { correct: (record.done ?? []).includes(record.variant ?? 0), latencyMs: null, at: record.updated ?? Date.now() } : null;
      values.push(...objectiveValues(this.version, i, exercise, record), ...interactionValues(this.version, i, exercise, record, earlier));
    });
    const { text, dropped } = encodeSuspend(records, this.version);
    this.dropped = dropped;
    const elapsed = Date.now() - this.started;
    values.push(["cmi.suspend_data", text], [this.el.exit, "suspend"],
      [this.el.time, this.version === "1.2" ? timespan12(elapsed) : duration2004(elapsed)]);
    let ok = values.every(([element, value]) => this.lms.set(element, value));
    if (ok) ok = this.lms.commit();
    if (ok) this.calls.commits += 1;
    this.resendAll = !ok;
    if (ok) clearNotice(NOTICE);
    else if (!final) this.tell(`Your latest work could not be sent to the course's platform (${says(this.lms.lastError)}). Nothing is lost: it is kept in this browser, and sent again with your next check.`);
    return ok;
  }

  /** pagehide: the last commit, then Finish/Terminate, once. */
  finish() {
    if (this.state !== LMS.open) return;
    this.sync(null, null, { final: true });
    this.setState(LMS.closed);
    this.calls.finishes += 1;
    this.lms.finish();
  }

  tell(message) {
    showNotice(NOTICE, "Course platform", message, [{ text: "Export progress", action: "notice-export", run: () => exportProgress(this.progress) }]);
  }
}
