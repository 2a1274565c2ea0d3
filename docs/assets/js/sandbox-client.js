// A Build run, in three steps: the grader picks the cases, the sandbox runs the
// learner's code on them, the grader judges what came back.
//
//   grader  {op: "cases", exercise, code}    -> {job, plain, limit}
//   sandbox {op: "run", job, code}           -> the report (JSON text), as data
//   grader  {op: "judge", exercise, outputs} -> the verdict
//
// The sandbox (sandbox.js) is one worker per tab, started on a page with a Build
// exercise once the grader is ready and the page is idle (or when the learner
// moves into one, or at the first Run, if that comes first), from a blob: URL, so
// that it inherits the page's Content-Security-Policy. It starts from a memory
// snapshot of its own when that is stored or the link is fast (the grader's
// measure of the link is passed on), and from the grader's compiled WebAssembly
// when the grader has one: the same code, compiled and optimised once for both
// (a second compile took a second of CPU just as the learner reached the code,
// and slowed everything on the page meanwhile). A Run that has to wait for its start says so
// (`onWait`: the exercise shows the start's progress, loading.js).
// It is driven by the same Runtime class as the grader, so time limits work
// the same way (interrupt when cross-origin isolated, else terminate and start
// afresh), the limit starting when the code starts. It is replaced after every
// run whose code was not plain (the grader says so; workbook/build_plain.py),
// after a run that was stopped (interrupted, or out of memory), and whenever it
// fails or stops answering.
import { Runtime } from "./runtime.js";

const ACK_MS = 5_000; // a sandbox that has not acknowledged a request by then is gone
let sandbox = null;

/** The link's speed the grader measured as it started (bytes per ms), if it did (boot.js). */
const linkSpeedOf = (grader) => (typeof grader?.startStages?.link === "number" ? grader.startStages.link : null);

/** The tab's sandbox, started now if it is not running yet (or again, if it could not start);
 *  `module`: the grader's compiled WebAssembly, if it has one. */
export function startSandbox(graderURL, linkSpeed = null, module = null) {
  if (sandbox?.failure) sandbox.worker.terminate();
  if (!sandbox || sandbox.failure) {
    const script = new URL("sandbox.js", graderURL).href;
    // `module`: whether the first message brings the compiled WebAssembly (sandbox.js waits for it).
    const settings = { indexURL: new URL("../vendor/pyodide/", script).href, linkSpeed, module: Boolean(module) };
    const source = `self.WB_SANDBOX = ${JSON.stringify(settings)};\nimportScripts(${JSON.stringify(script)});\n`;
    const url = URL.createObjectURL(new Blob([source], { type: "text/javascript" }));
    const spawn = () => {
      const worker = new Worker(url, { name: "sandbox" });
      if (module) worker.postMessage({ type: "wasm-module", module });
      return worker;
    };
    sandbox = new Runtime(spawn, null, { role: "sandbox", ackMs: ACK_MS });
    if (window.workbook) window.workbook.sandbox = sandbox; // for tests and tools
  }
  return sandbox;
}

async function runBuild(grader, { code, ...request }, options) {
  const cases = await grader.request({ ...request, op: "cases", code });
  if (!cases.ok) return cases;
  const { job, plain, limit } = cases.value;
  const box = startSandbox(grader.workerURL, linkSpeedOf(grader), grader.wasmModule);
  if (!box.ready && !box.failure) options.onWait?.();
  const { interrupts, restarts } = box;
  const ran = await box.request({ op: "run", job, code }, { ...options, limitMs: limit * 1000 || options.limitMs });
  // Replace the sandbox after code that may have left a trace, and after a run it stopped
  // (an interrupt may land in the runner's own code). A terminated one (a time-out past the
  // interrupt's grace, a crash) was replaced already: one replacement per stopped run, not two.
  if (box.restarts === restarts && (!plain || ran.recycle || box.interrupts !== interrupts)) {
    box.recycles = (box.recycles || 0) + 1;
    box.replace();
  }
  if (!ran.ok) return ran; // a time-out, a crash, a package that would not load
  return grader.request({ ...request, op: "judge", outputs: ran.value });
}

/** The grader's runtime, with "run" requests fulfilled through the sandbox. */
export function withSandbox(grader) {
  return {
    request: (request, options = {}) => (request.op === "run" ? runBuild(grader, request, options) : grader.request(request, options)),
    /** Start the sandbox ahead of the first run (a page without a grader has none). */
    prepare: () => grader instanceof Runtime && startSandbox(grader.workerURL, linkSpeedOf(grader), grader.wasmModule),
  };
}
