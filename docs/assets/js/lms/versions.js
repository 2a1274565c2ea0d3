// The one place where SCORM 1.2 and SCORM 2004 differ: what each calls the API and its
// calls, which data-model elements say the same thing, the formats of times and results,
// and how much room suspend_data has. Every other module of lms/ reads this table and
// never tests a version itself.

/** "HHHH:MM:SS.SS" (SCORM 1.2 CMITimespan) of `ms`. */
export function timespan12(ms) {
  const cs = Math.max(0, Math.round(ms / 10));
  const h = Math.floor(cs / 360000);
  const m = Math.floor(cs / 6000) % 60;
  const s = (cs % 6000) / 100;
  return `${String(Math.min(h, 9999)).padStart(4, "0")}:${String(m).padStart(2, "0")}:${s.toFixed(2).padStart(5, "0")}`;
}

/** "PT1H2M3.4S" (SCORM 2004 timeinterval) of `ms`. */
export function duration2004(ms) {
  const cs = Math.max(0, Math.round(ms / 10));
  const h = Math.floor(cs / 360000);
  const m = Math.floor(cs / 6000) % 60;
  const s = (cs % 6000) / 100;
  return `PT${h ? `${h}H` : ""}${m ? `${m}M` : ""}${Number(s.toFixed(2))}S`;
}

const clock12 = (at) => {
  const when = new Date(at);
  return [when.getHours(), when.getMinutes(), when.getSeconds()].map((n) => String(n).padStart(2, "0")).join(":");
};
const stamp2004 = (at) => `${new Date(at).toISOString().slice(0, 22)}Z`;

export const VERSIONS = {
  "1.2": {
    global: "API",
    calls: { init: "LMSInitialize", finish: "LMSFinish", get: "LMSGetValue", set: "LMSSetValue", commit: "LMSCommit",
      error: "LMSGetLastError", errorText: "LMSGetErrorString", diagnostic: "LMSGetDiagnostic" },
    element: { entry: "cmi.core.entry", exit: "cmi.core.exit", time: "cmi.core.session_time",
      mastery: "cmi.student_data.mastery_score", learner: "cmi.core.student_id", score: "cmi.core.score" },
    masteryScale: 100, // mastery_score is on 0-100
    suspendLimit: 4096,
    suspendJson: false, // suspend_data: always the compact form (lms/suspend.js)
    elapsed: timespan12,
    interaction: { type: "fill-in", response: "student_response", responseLength: 255, when: "time", at: clock12,
      correct: "correct", wrong: "wrong", description: false },
    // One lesson_status says both: passed/failed against a mastery score, else passed once complete.
    status: ({ complete, passed, failed }) => [
      ["cmi.core.lesson_status", passed ? "passed" : failed ? "failed" : complete ? "completed" : "incomplete"]],
    objective: (at, status) => [[`${at}.status`, status]],
  },
  "2004": {
    global: "API_1484_11",
    calls: { init: "Initialize", finish: "Terminate", get: "GetValue", set: "SetValue", commit: "Commit",
      error: "GetLastError", errorText: "GetErrorString", diagnostic: "GetDiagnostic" },
    element: { entry: "cmi.entry", exit: "cmi.exit", time: "cmi.session_time",
      mastery: "cmi.scaled_passing_score", learner: "cmi.learner_id", score: "cmi.score" },
    masteryScale: 1, // scaled_passing_score is on 0-1
    suspendLimit: 64000,
    suspendJson: true, // suspend_data: the record as JSON when it fits, else the compact form
    elapsed: duration2004,
    interaction: { type: "long-fill-in", response: "learner_response", responseLength: 4000, when: "timestamp",
      at: stamp2004, correct: "correct", wrong: "incorrect", description: true },
    // Completion and success apart; scaled scores too.
    scaled: true,
    status: ({ complete, passed, failed, share }) => [["cmi.progress_measure", share],
      ["cmi.completion_status", complete ? "completed" : "incomplete"],
      ["cmi.success_status", passed ? "passed" : failed ? "failed" : "unknown"]],
    objective: (at, status) => [[`${at}.success_status`, status === "passed" ? "passed" : "unknown"],
      [`${at}.completion_status`, status === "passed" ? "completed" : status]],
  },
};

/** The versions in the order an API is looked for: 2004 first, as the standard's discovery does. */
export const SEARCH_ORDER = ["2004", "1.2"];
