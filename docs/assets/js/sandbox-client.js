// A Build run, in three steps: the grader picks the cases, the sandbox runs the
// learner's code on them, the grader judges what came back; then, once the
// verdict is shown, the grader draws the run figure of the same report. From an
// exercise's second run on, the first two go side by side (its job is known).
//
//   grader  {op: "cases", exercise, code}                 -> {job, plain, limit}
//   sandbox {op: "run", job, code}                        -> the report (JSON text), as data
//   grader  {op: "judge", exercise, outputs, figureLater} -> the verdict
//   grader  {op: "run-figure", exercise, outputs}         -> {figure} (asked for by kinds/build.js)
//
// The sandbox (sandbox.js) is one worker per tab, started on a page with a Build
// exercise once the grader is ready and has been quiet for a while and the page is
// idle (kinds/build.js), or when the learner moves into one, or at the first Run, if
// that comes first; from a blob: URL, so
// that it inherits the page's Content-Security-Policy. It starts from a memory
// snapshot of its own when that is stored or the link is fast (the grader's
// measure of the link is passed on), and from the grader's compiled WebAssembly
// when the grader has one: the same code, compiled and optimised once for both
// (a compile of its own competed with the grader and the page just as the learner
// reached the code). A Run that has to wait for its start says so (`onWait`: the
// exercise shows the start's progress, loading.js).
// It is driven by the same Runtime class as the grader, so time limits work
// the same way (interrupt when cross-origin isolated, else terminate and start
// afresh), the limit starting when the code starts. It is replaced after every
// run whose code was not plain (the grader says so; workbook/build_plain.py),
// after a run that was stopped (interrupted, or out of memory), and whenever it
// fails or stops answering.
import { Runtime } from "./runtime.js";

const ACK_MS = 5_000; // a sandbox that has not acknowledged a request by then is gone
let sandbox = null;
const reports = new Map(); // exercise -> {variant, outputs}: the report of its last run, for its run figure

/** The link's speed the grader measured as it started (bytes per ms), if it did (boot.js). */
const linkSpeedOf = (grader) => (typeof grader?.startStages?.link === "number" ? grader.startStages.link : null);

/** The tab's sandbox, started now if it is not running yet (or again, if it could not start);
 *  `module`: the grader's compiled WebAssembly, if it has one; `forRun`: a run the learner asked for
 *  waits for this start (the sandbox then skips its warm-up: sandbox.js). */
export function startSandbox(graderURL, linkSpeed = null, module = null, forRun = false) {
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
    if (forRun) sandbox.worker.postMessage({ type: "run-waiting" }); // the first start only, not a replacement's
    if (window.workbook) window.workbook.sandbox = sandbox; // for tests and tools
  }
  return sandbox;
}

// An exercise's job for a variant never changes (its hidden cases are seeded): after the first run of
// one, the next starts in the sandbox at once, while the grader says whether the code is plain.
const jobs = new Map(); // "exercise variant" -> {job, limit}

async function runBuild(grader, { code, ...request }, options) {
  const asked = grader.request({ ...request, op: "cases", code });
  // Started (if it is not yet) before the first job is known: its start goes on while the grader picks the cases.
  startSandbox(grader.workerURL, linkSpeedOf(grader), grader.wasmModule, true);
  const key = `${request.exercise} ${request.variant}`;
  if (!jobs.has(key)) {
    const cases = await asked;
    if (!cases.ok) return cases;
    jobs.set(key, { job: cases.value.job, limit: cases.value.limit });
  }
  const { job, limit } = jobs.get(key);
  const box = startSandbox(grader.workerURL, linkSpeedOf(grader), grader.wasmModule); // the same, unless it failed
  if (!box.ready && !box.failure) options.onWait?.();
  const { interrupts, restarts } = box;
  const ran = await box.request({ op: "run", job, code }, { ...options, limitMs: limit * 1000 || options.limitMs });
  const cases = await asked; // whether the code is plain; a refusal of the code is the reply
  // Replace the sandbox after code that may have left a trace (or that the grader did not look at),
  // and after a run it stopped (an interrupt may land in the runner's own code). A terminated one (a
  // time-out past the interrupt's grace, a crash) was replaced already: one replacement per stopped run.
  const plain = cases.ok && cases.value.plain;
  if (box.restarts === restarts && (!plain || ran.recycle || box.interrupts !== interrupts)) {
    box.recycles = (box.recycles || 0) + 1;
    box.replace();
  }
  if (!cases.ok) return cases;
  if (!ran.ok) return ran; // a time-out, a crash, a package that would not load
  reports.set(request.exercise, { variant: request.variant, outputs: ran.value });
  return grader.request({ ...request, op: "judge", outputs: ran.value, figureLater: true });
}

/** The run figure of the exercise's last run ({figure: null} when there is none to draw). */
function runFigure(grader, request, options) {
  const last = reports.get(request.exercise);
  if (!last || last.variant !== request.variant) return Promise.resolve({ ok: true, value: { figure: null } });
  return grader.request({ ...request, outputs: last.outputs }, options);
}

/** The grader's runtime, with "run" requests fulfilled through the sandbox. */
export function withSandbox(grader) {
  return {
    request(request, options = {}) {
      if (request.op === "run") return runBuild(grader, request, options);
      if (request.op === "run-figure") return runFigure(grader, request, options);
      return grader.request(request, options);
    },
    /** Start the sandbox ahead of the first run (a page without a grader has none). */
    prepare: () => grader instanceof Runtime && startSandbox(grader.workerURL, linkSpeedOf(grader), grader.wasmModule),
  };
}
