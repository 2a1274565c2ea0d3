// The SCORM run-time API, found the standard way and called through one small
// adapter for both versions (SCORM 1.2's `API`, SCORM 2004's `API_1484_11`).
//
// Discovery follows the ADL algorithm: look at this window, then walk up
// window.parent (at most MAX_HOPS frames), then do the same from the top
// window's opener. A frame of another origin cannot be read: the walk stops
// there. No API found: the page is not in an LMS and behaves as the hosted site.
//
// Why not a wrapper library: the npm SCO-side wrappers are single releases of
// old code (pipwerks-scorm-api-wrapper depends on a git URL that `npm ci`
// cannot fetch from the registry alone; @gamestdio/scorm is one TypeScript 2
// release); the part this page needs is the walk and eight calls, here.

import { SEARCH_ORDER, VERSIONS } from "./versions.js";

const MAX_HOPS = 500;
/** The property of the launcher's window (lms/launch.js) that holds the launch's one session. */
export const LAUNCH = "__workbookLaunch";

/** The API object in `win` ({version, api}), or null; a window of another origin reads as none. */
function apiIn(win) {
  try {
    for (const version of SEARCH_ORDER) {
      const api = win[VERSIONS[version].global];
      if (api && typeof api[VERSIONS[version].calls.init] === "function") return { version, api };
    }
  } catch {
    /* another origin: not ours to read */
  }
  return null;
}

function launchIn(win) {
  try {
    const launch = win[LAUNCH];
    return launch && typeof launch === "object" ? launch : null;
  } catch {
    return null;
  }
}

/** `look(win)` for `win` and each parent up (at most MAX_HOPS), until one answers; null if none does. */
function walkUp(win, look) {
  for (let hops = 0; win && hops <= MAX_HOPS; hops += 1) {
    const found = look(win);
    if (found) return found;
    let parent;
    try {
      parent = win.parent;
    } catch {
      return null;
    }
    if (!parent || parent === win) return null;
    win = parent;
  }
  return null;
}

/** The LMS's API seen from `win` ({version, api}), or null outside an LMS. */
export function findApi(win = window) {
  const found = walkUp(win, apiIn);
  if (found) return found;
  try {
    const opener = win.top?.opener;
    return opener ? walkUp(opener, apiIn) : null;
  } catch {
    return null;
  }
}

/** The launch (lms/launch.js) holding this page's LMS session, from the nearest launcher page above `win`; null if
 *  none. */
export function findLaunch(win = window) {
  return walkUp(win.parent === win ? null : win.parent, launchIn);
}

/** One SCORM session over a found API: every call says whether it worked, failures keep their error. */
export class ScormApi {
  constructor({ version, api }) {
    this.version = version;
    this.api = api;
    this.names = VERSIONS[version].calls;
    this.lastError = null; // {code, text, element} of the last call that failed
  }

  call(op, ...args) {
    let result;
    try {
      result = this.api[this.names[op]](...args);
    } catch (err) {
      const text = `the platform's ${this.names[op]} failed (${err?.message || err})`;
      this.lastError = { code: "", text, element: args[0] };
      return null;
    }
    return result;
  }

  ok(result, element = "") {
    if (String(result) === "true") return true;
    let code = "";
    let text = "";
    try {
      code = String(this.api[this.names.error]() ?? "");
      text = String(this.api[this.names.errorText](code) ?? "");
    } catch {
      /* an API that cannot even say its error */
    }
    if (result !== null || !this.lastError) this.lastError = { code, text, element };
    return false;
  }

  initialize() {
    return this.ok(this.call("init", ""));
  }

  finish() {
    return this.ok(this.call("finish", ""));
  }

  commit() {
    return this.ok(this.call("commit", ""));
  }

  /** The value of `element` ("" when unset or unreadable). */
  get(element) {
    const value = this.call("get", element);
    return value === null || value === undefined ? "" : String(value);
  }

  set(element, value) {
    return this.ok(this.call("set", element, String(value)), element);
  }
}
