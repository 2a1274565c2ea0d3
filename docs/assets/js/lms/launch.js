// The launcher of a chapter SCO (scripts/scorm/launch.html.j2, one page per SCO of the
// SCORM packages): it holds the launch's one LMS session and shows the workbook's pages
// in its frame, whatever page of the workbook the learner moves to inside it.
//
// - Start: find the LMS's API (api.js), Initialize once, read the learner's id and the
//   mastery score; the id is turned at once into an opaque key (learnerKey: SHA-256 of a
//   fixed salt, the site's path and the id, in this page) and never kept, shown or sent.
//   Then the first page is loaded in the frame.
// - The pages inside (main.js, session.js) find this launch by walking up their parents
//   (findLaunch), key their local record by `learner`, and report through `lms`.
// - End (pagehide of this page, the LMS closing the launch): each open page's last report,
//   exit = suspend and the session's time, Commit, and Terminate/LMSFinish, once.
//
// No API found: no launch is set, and the pages behave as the hosted site.

import { LMS, setRootState } from "../contract.js";
import { LAUNCH, ScormApi, findApi } from "./api.js";
import { VERSIONS } from "./versions.js";

const SALT = "robotics-math-workbook/learner-key/v1";
const SITE_ROOT = "../"; // the launchers sit in the package's launch/ folder

/** The opaque key of learner `id` on the site at `sitePath` (64 hex digits), or "" with no id or no WebCrypto. */
export async function learnerKey(sitePath, id) {
  if (!id || !globalThis.crypto?.subtle) return "";
  const digest = await crypto.subtle.digest("SHA-256", new TextEncoder().encode(`${SALT}\n${sitePath}\n${id}`));
  return Array.from(new Uint8Array(digest), (b) => b.toString(16).padStart(2, "0")).join("");
}

const KEPT_OPEN = "so your answers are kept only while this chapter is open. Export your progress to keep it.";
const NO_ID = `The course's platform did not say who you are, ${KEPT_OPEN}`;
const NO_CRYPTO = "Your work cannot be kept apart from other people's on this computer (the course is not served over "
  + `a secure connection), ${KEPT_OPEN}`;
const NO_SESSION = `The course's platform did not open a session, ${KEPT_OPEN}`;

export class Launch {
  /** `frame`: the iframe the pages are shown in (data-src: the first page; data-ids: the SCO's exercises). */
  constructor(frame, found) {
    this.frame = frame;
    this.ids = (frame.dataset.ids || "").split(" ").filter(Boolean);
    this.version = found.version;
    this.lms = new ScormApi(found);
    this.el = VERSIONS[found.version].element;
    this.state = null; // LMS.open, LMS.failed (no session), LMS.closed (ended)
    this.error = null; // {code, text} when the LMS would not open the session
    this.learner = ""; // the opaque key of the learner's local record ("" : memory only)
    this.memoryOnly = ""; // why the record is kept in memory only, said by the pages
    this.threshold = null; // the LMS's mastery score on 0-1, or null
    this.started = Date.now();
    this.pages = new Set(); // each open page's last report, run at the end
    this.calls = { initialize: 0, finish: 0 };
  }

  setState(state) {
    this.state = state;
    setRootState("lms", state);
  }

  async start() {
    this.calls.initialize += 1;
    if (!this.lms.initialize()) {
      this.error = this.lms.lastError;
      this.memoryOnly = NO_SESSION;
      this.setState(LMS.failed);
      return;
    }
    // Open from here on: a launch that ends even while the key is being made still terminates once.
    window.addEventListener("pagehide", () => this.end());
    this.setState(LMS.open);
    const mastery = this.lms.get(this.el.mastery);
    const scale = VERSIONS[this.version].masteryScale;
    const given = mastery !== "" && Number.isFinite(Number(mastery));
    this.threshold = given ? Math.min(1, Math.max(0, Number(mastery) / scale)) : null;
    const id = this.lms.get(this.el.learner);
    try {
      this.learner = await learnerKey(new URL(SITE_ROOT, location.href).pathname, id);
    } catch {
      this.learner = "";
    }
    if (!this.learner) this.memoryOnly = id ? NO_CRYPTO : NO_ID;
  }

  /** A page inside reports at the end through `last` (a function); returns the function that detaches it. */
  attach(last) {
    this.pages.add(last);
    return () => this.pages.delete(last);
  }

  /** The launch ends: every open page's last report, then exit, time, Commit and Terminate, once. */
  end() {
    if (this.state !== LMS.open) return;
    for (const last of [...this.pages]) {
      try {
        last();
      } catch {
        /* a page already gone: what it sent before stays sent */
      }
    }
    this.pages.clear();
    this.lms.set(this.el.exit, "suspend");
    this.lms.set(this.el.time, VERSIONS[this.version].elapsed(Date.now() - this.started));
    this.lms.commit();
    this.setState(LMS.closed);
    this.calls.finish += 1;
    this.lms.finish();
  }
}

/** Open the launch of this launcher page, then show its first page in the frame. */
export async function openLaunch(frame) {
  const found = findApi(window);
  if (found) {
    const launch = new Launch(frame, found);
    Object.defineProperty(window, LAUNCH, { value: launch, configurable: true });
    await launch.start();
  }
  frame.src = frame.dataset.src;
}
