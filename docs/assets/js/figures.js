// Interactive figures (role "figure" in the contract). The page computes nothing: it sends
// the control values to the worker ({op: "figure"}) and swaps in the SVG,
// readouts and flags that come back. At most one request per figure is in
// flight; changes made meanwhile are sent, latest values only, when it returns.
// Before the runtime is ready the static first frame stays on screen and the
// request waits in the runtime's queue.

import { ATTR, ROLE, findRole, findRoles } from "./contract.js";

const LIMIT_MS = 10_000;

class FigureView {
  constructor(el, runtime) {
    this.el = el;
    this.runtime = runtime;
    this.name = el.getAttribute(ATTR.figure);
    this.canvas = findRole(el, ROLE.figureCanvas);
    this.status = findRole(el, ROLE.figureStatus);
    this.controls = [...el.querySelectorAll(`[${ATTR.param}]`)];
    this.inFlight = false;
    for (const control of this.controls) {
      if (control.type === "range") {
        control.addEventListener("input", () => this.changed(control));
      } else {
        control.addEventListener("click", () => {
          const on = control.getAttribute("aria-pressed") !== "true";
          control.setAttribute("aria-pressed", String(on));
          this.changed(control);
        });
      }
    }
    this.canvas.addEventListener("pointerdown", (event) => this.startDrag(event));
  }

  params() {
    const out = {};
    for (const control of this.controls) {
      out[control.getAttribute(ATTR.param)] =
        control.type === "range" ? Number(control.value) : control.getAttribute("aria-pressed") === "true" ? 1 : 0;
    }
    return out;
  }

  key() {
    return JSON.stringify(this.params());
  }

  changed(control) {
    if (control.type === "range") {
      const text = control.value + (control.dataset.suffix || "");
      control.setAttribute("aria-valuetext", text);
      const output = findRole(control.parentElement, ROLE.controlValue);
      if (output) output.textContent = text;
    }
    if (!this.inFlight) this.send();
  }

  async send() {
    const key = this.key();
    this.inFlight = true;
    this.el.setAttribute(ATTR.state, "pending");
    const reply = await this.runtime.request(
      { op: "figure", figure: this.name, params: JSON.parse(key) },
      { limitMs: LIMIT_MS },
    );
    this.inFlight = false;
    if (reply.ok) {
      this.apply(reply.value);
      this.status.textContent = "";
      this.el.setAttribute(ATTR.state, "ready");
    } else {
      this.status.textContent = reply.error.message;
      this.el.setAttribute(ATTR.state, "error");
    }
    if (this.key() !== key && (reply.ok || reply.error.kind === "figure")) this.send();
  }

  apply({ svg, readouts, flags }) {
    this.canvas.innerHTML = svg;
    for (const [name, text] of Object.entries(readouts || {})) {
      const out = findRole(this.el, ROLE.readout, `[${ATTR.readout}="${name}"]`);
      if (out) out.textContent = text;
    }
    this.el.setAttribute(ATTR.flags, (flags || []).join(" "));
  }

  // Dragging a handle (data-drag-x / data-drag-y): the SVG's own transform maps
  // the pointer into the figure's coordinates; the sliders then clamp and snap it.
  // Elsewhere on a figure with an orbit (data-orbit names a slider), a sideways drag turns
  // that slider: the picture's width is one full turn, grabbed like the scene itself.
  startDrag(event) {
    const handle = event.target.closest?.("[data-drag-x]");
    const orbit = this.canvas.getAttribute(ATTR.orbit);
    if (!handle && !orbit) return;
    if (event.button > 0) return; // the main button, a touch or a pen only
    event.preventDefault();
    const pointerId = event.pointerId;
    try {
      this.canvas.setPointerCapture(pointerId);
    } catch {
      /* not an active pointer (a synthetic event): the moves still come to the canvas */
    }
    const from = { x: event.clientX, value: Number(this.slider(orbit)?.value) };
    const move = (e) => {
      if (e.pointerId !== pointerId) return;
      if (!handle) return this.turn(orbit, from, e.clientX);
      const frame = this.canvas.querySelector("[data-drag-x]")?.parentNode;
      const ctm = frame?.getScreenCTM();
      if (!ctm) return;
      const q = new DOMPoint(e.clientX, e.clientY).matrixTransform(ctm.inverse());
      this.setSlider(handle.dataset.dragX, q.x);
      this.setSlider(handle.dataset.dragY, q.y);
    };
    const stop = (e) => {
      if (e.pointerId !== pointerId) return;
      this.canvas.removeEventListener("pointermove", move);
      this.canvas.removeEventListener("pointerup", stop);
      this.canvas.removeEventListener("pointercancel", stop);
    };
    this.canvas.addEventListener("pointermove", move);
    this.canvas.addEventListener("pointerup", stop);
    this.canvas.addEventListener("pointercancel", stop);
    move(event);
  }

  slider(param) {
    return this.controls.find((c) => c.getAttribute(ATTR.param) === param && c.type === "range");
  }

  turn(param, from, x) {
    const input = this.slider(param);
    const width = this.canvas.getBoundingClientRect().width;
    if (!input || !width) return;
    const [min, max] = [Number(input.min), Number(input.max)];
    let value = from.value - ((x - from.x) / width) * 360;
    if (max - min === 360) value = ((((value - min) % 360) + 360) % 360) + min; // round and round
    this.setSlider(param, value);
  }

  setSlider(param, value) {
    const input = this.slider(param);
    if (!input) return;
    const before = input.value;
    input.value = String(value); // the browser clamps to [min, max] and snaps to the step
    if (input.value !== before) input.dispatchEvent(new Event("input", { bubbles: true }));
  }
}

/** Wire up every figure under `root` once (pages arrive again with instant navigation). */
export function initFigures(root, runtime) {
  for (const el of findRoles(root, ROLE.figure, `[${ATTR.figure}]`)) {
    if (!el.wbFigure) el.wbFigure = new FigureView(el, runtime);
  }
}
