// Using the workbook in a course (the teacher's guide, docs/teaching/): the teacher's page that
// makes assignment links, the learner's assignment page, and the class page.
import { initAssignment } from "./assignment-page.js";
import { initClassPage } from "./class-page.js";
import { initTeach } from "./teach.js";

export function initCourse(shared, siteRoot) {
  initTeach(siteRoot);
  initAssignment(shared, siteRoot);
  initClassPage(shared, siteRoot);
}
