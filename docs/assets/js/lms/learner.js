// Whose record a page inside an LMS keeps: the learner's own, keyed by the opaque key the
// launcher made of the LMS's learner id (lms/launch.js); never the hosted site's record
// (no key), which another person of a shared computer may have filled. With no key (the
// LMS gave no id, or no session), the record is kept in memory only, and the page says so.

import { Progress } from "../progress.js";

const NO_LAUNCHER = "This page was opened by the course without the workbook's launcher, so your answers are kept "
  + "only while it is open. Export your progress to keep it.";

/** The progress record of a page an LMS shows: `launch` from findLaunch (null without a launcher). */
export function learnerProgress(siteRoot, launch) {
  if (launch?.learner) return new Progress(siteRoot, { learner: launch.learner });
  return new Progress(siteRoot, { memoryOnly: launch?.memoryOnly || NO_LAUNCHER });
}
