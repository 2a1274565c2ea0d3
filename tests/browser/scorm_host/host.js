// A test LMS: scorm-again's real SCORM 1.2 or 2004 runtime in this window, the SCO in the
// frame (tests/browser/test_scorm*.py). What it keeps between sessions is what an LMS keeps:
// who the learner is and the course's mastery score, suspend_data, the status and score, the
// objectives (and 2004's interactions), and entry = "resume" after a session that exited with "suspend".

const KEPT = {
  "1.2": /^cmi\.(suspend_data|core\.(student_id|student_name|lesson_status|score\.(raw|min|max))|student_data\.mastery_score|objectives\.\d+\.(id|status|score\.(raw|min|max)))$/,
  "2004": /^cmi\.(suspend_data|learner_id|learner_name|scaled_passing_score|completion_status|success_status|progress_measure|score\.(raw|min|max|scaled)|objectives\.\d+\..+|interactions\.\d+\..+)$/,
};
const NAMES = {
  "1.2": { global: "API", init: "LMSInitialize", finish: "LMSFinish", commit: "LMSCommit", set: "LMSSetValue", exit: "cmi.core.exit", entry: "cmi.core.entry" },
  "2004": { global: "API_1484_11", init: "Initialize", finish: "Terminate", commit: "Commit", set: "SetValue", exit: "cmi.exit", entry: "cmi.entry" },
};

// What an LMS sets for a graded launch (Moodle does): credit, normal mode. scorm-again's 1.2 runtime applies
// the mastery score at LMSFinish only then (raw against mastery_score: passed or failed).
const LAUNCH = {
  "1.2": { "cmi.core.credit": "credit", "cmi.core.lesson_mode": "normal" },
  "2004": { "cmi.credit": "credit", "cmi.mode": "normal" },
};

function flatten(value, prefix, out) {
  if (value && typeof value === "object") {
    for (const [k, v] of Object.entries(value)) flatten(v, prefix ? `${prefix}.${k}` : k, out);
  } else if (value !== "" && value !== null && value !== undefined) {
    out[prefix] = String(value);
  }
  return out;
}

window.lms = {
  /** Launch `href` in the frame with a fresh runtime holding `stored` (from a previous stored()); `refuse`: {code, from}. */
  start({ version, href, stored = null, refuse = null }) {
    const names = NAMES[version];
    const Api = version === "1.2" ? window.Scorm12API : window.Scorm2004API;
    const api = new Api({ logLevel: 5, autocommit: false });
    api.loadFromFlattenedJSON({ ...LAUNCH[version], ...(stored || {}) });
    const calls = { init: 0, finish: 0, commit: 0, set: 0, refused: 0 };
    for (const op of ["init", "finish", "commit", "set"]) {
      const real = api[names[op]].bind(api);
      api[names[op]] = (...args) => {
        calls[op] += 1;
        // An LMS that refuses to store (a full quota): every SetValue from the `from`-th on fails with `code`.
        if (op === "set" && refuse && calls.set >= refuse.from) {
          calls.refused += 1;
          api.lastErrorCode = String(refuse.code);
          return "false";
        }
        return real(...args);
      };
    }
    delete window.API;
    delete window.API_1484_11;
    window[names.global] = api;
    this.api = api;
    this.version = version;
    this.calls = calls;
    document.getElementById("sco").src = href;
  },

  /** What the LMS keeps of this session for the next one (flattened CMI). */
  stored() {
    const names = NAMES[this.version];
    const all = flatten(this.api.renderCMIToJSONObject().cmi, "cmi", {});
    const kept = Object.fromEntries(Object.entries(all).filter(([k]) => KEPT[this.version].test(k)));
    if (all[names.exit] === "suspend") kept[names.entry] = "resume";
    return kept;
  },

  value(element) {
    return this.api.cmi ? flatten(this.api.renderCMIToJSONObject().cmi, "cmi", {})[element] ?? "" : "";
  },

  /** The learner leaves: the frame's page goes away (pagehide). */
  close() {
    document.getElementById("sco").src = "about:blank";
  },
};
