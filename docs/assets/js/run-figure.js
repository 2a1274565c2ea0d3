// A Build exercise's run figure (role "run-figure"): after a run, the grader draws
// the learner's function beside the reference (the run-figure op, asked for once
// the verdict is shown: one frame per case, SVG and words computed in Python).
// This module only places a frame and steps through them: the range input (arrow
// keys), Previous and Next.
import { ROLE, findRole } from "./contract.js";

export function runFigure(el) {
  const box = findRole(el, ROLE.runFigure);
  if (!box) return { wanted: false, busy() {}, show() {} };
  const part = (role) => findRole(box, role);
  const [canvas, readout, description, range, previous, next, caseLabel] = [
    ROLE.runCanvas, ROLE.readout, ROLE.runDescription, ROLE.runCase, ROLE.runPrevious, ROLE.runNext, ROLE.runCaseLabel,
  ].map(part);
  let figure = null;

  function showFrame(index) {
    const frames = figure.frames;
    const i = Math.max(0, Math.min(frames.length - 1, index));
    const frame = frames[i];
    canvas.innerHTML = frame.svg;
    canvas.setAttribute("aria-label", `${figure.title}: ${frame.label}`);
    description.textContent = frame.description;
    caseLabel.textContent = frames.length > 1 ? `${frame.readout} (${i + 1} of ${frames.length})` : frame.readout;
    range.value = String(i);
    range.setAttribute("aria-valuetext", `${frame.label}, ${i + 1} of ${frames.length}`);
    previous.disabled = i === 0;
    next.disabled = i === frames.length - 1;
  }

  range.addEventListener("input", () => figure && showFrame(Number(range.value)));
  previous.addEventListener("click", () => figure && showFrame(Number(range.value) - 1));
  next.addEventListener("click", () => figure && showFrame(Number(range.value) + 1));

  return {
    wanted: true,
    /** A run has started: the figure on screen is the last run's until the new one comes. */
    busy() {
      box.setAttribute("aria-busy", "true");
    },
    /** Show the figure of a run-figure reply ({figure}), or hide it when the run drew none (or
     *  `reply` is null). */
    show(reply) {
      figure = (reply?.ok && reply.value.figure) || null;
      box.removeAttribute("aria-busy");
      box.hidden = !figure?.frames?.length;
      if (box.hidden) return;
      range.max = String(figure.frames.length - 1);
      for (const control of [range, previous, next]) control.hidden = figure.frames.length < 2;
      range.parentElement.hidden = figure.frames.length < 2;
      const title = document.getElementById(box.getAttribute("aria-labelledby"));
      if (title) title.textContent = figure.title;
      readout.textContent = figure.readout;
      showFrame(figure.start || 0);
    },
  };
}
