// The launcher page's script (assets/dist/lms-launch.js, scripts/scorm/launch.html.j2).
import { openLaunch } from "./launch.js";

const frame = document.querySelector("iframe[data-workbook-sco]");
if (frame) openLaunch(frame);
