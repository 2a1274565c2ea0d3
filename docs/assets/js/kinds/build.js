// Build: the learner's code and a Run button. The code runs in the sandbox, a
// worker of its own (sandbox-client.js); the grader picks the tests and judges.
//
// The page shows the code (starter or saved) as plain text at first. CodeMirror
// is loaded and built only when the exercise comes near the viewport and the
// browser is idle after the Python runtime has started, or at once when the
// learner clicks, focuses or runs it: opening a chapter never waits for, or
// stutters on, an editor nobody is looking at yet.
import { ROLE, ownRole } from "../contract.js";
import { renderTests, setPending, showMessage } from "../feedback.js";
import { runFigure } from "../run-figure.js";
import { withSandbox } from "../sandbox-client.js";
import { showSandboxStart } from "../loading.js";
import { delay, idle, runtimeReady, runtimeSettled } from "../wait.js";

const EDITOR_WAITS_MS = 8000; // a slow start of the grader should not keep the editor away for long
const IDLE_MS = 1500;
// The sandbox's start takes a core for about a second (several on a phone). Started while the learner
// is checking answers, it made those Checks 5-10 times slower until it was done (3.8's round trip:
// 2-3 ms, 20-45 ms meanwhile): so, unless the learner asks for it, it waits until the grader has had
// nothing to do for this long.
const GRADER_QUIET_MS = 3000;
// The editor, once the grader has settled (or a while has passed) and the browser is idle.
const editorMayOpen = () => Promise.race([runtimeSettled(), delay(EDITOR_WAITS_MS)]).then(() => idle(IDLE_MS));
// The sandbox, once the grader is ready (its start must not compete with the grader's) and quiet (nor
// with the learner's Checks), and the browser is idle.
const sandboxMayStart = (grader) => runtimeReady()
  .then(() => (typeof grader.quietFor === "function" ? grader.quietFor(GRADER_QUIET_MS) : undefined))
  .then(() => idle(IDLE_MS));

/** The plain code first, the editor when it is wanted; `code()` is always the latest text. */
function lazyEditor(ctx, host, onRun) {
  const plain = ownRole(host, ROLE.code);
  const starter = plain.textContent;
  const saved = ctx.progress.get(ctx.id);
  let code = typeof saved.code === "string" ? saved.code : starter;
  // A <pre> hides one final newline; the editor shows it as an empty last line.
  plain.querySelector("code").textContent = code.endsWith("\n") ? code + "\n" : code;
  plain.tabIndex = 0;
  plain.setAttribute("aria-label", "Python code (press Enter or click to edit)");
  let editor = null;
  let opening = null;
  let timer = null;
  const save = () => {
    clearTimeout(timer);
    ctx.progress.update(ctx.id, { code });
  };
  const open = () => {
    opening ||= import("../editor.js").then(({ createEditor }) => {
      const hadFocus = document.activeElement === plain;
      editor = createEditor(host, code, {
        onChange(text) {
          code = text;
          clearTimeout(timer);
          timer = setTimeout(save, 400);
        },
        onRun,
      });
      plain.remove();
      host.wbEditor = editor; // for tests and tools: getCode(), setCode(), markLine()
      if (hadFocus) editor.view.focus();
      return editor;
    });
    return opening;
  };
  host.wbOpenEditor = open; // builds the editor now (tests and tools); resolves to it
  const nearView = new IntersectionObserver((entries) => {
    if (!entries.some((entry) => entry.isIntersecting)) return;
    nearView.disconnect();
    editorMayOpen().then(open);
  }, { rootMargin: "400px 0px" });
  nearView.observe(host);
  const openNow = () => {
    nearView.disconnect();
    open().then((ed) => ed.view.focus());
  };
  plain.addEventListener("click", openNow);
  plain.addEventListener("keydown", (event) => {
    if (event.key === "Enter" || event.key === " ") {
      event.preventDefault();
      openNow();
    }
  });
  return {
    starter,
    open,
    async latest() {
      const ed = editor || (await open());
      code = ed.getCode();
      save();
      return ed;
    },
  };
}

export function init(ctx) {
  // This exercise's runs go through the sandbox (`via` below); ctx.runtime stays the grader's, which the page shares.
  const sandboxed = withSandbox(ctx.runtime);
  // The sandbox is a second Python (about 21 MB): it starts once a Build exercise is within a
  // screen and a half of the viewport, the grader is ready and has been quiet for a while, and
  // the browser is idle, so that it is ready by the time the learner reaches the code (from its
  // snapshot it takes about a second; sandbox-client.js); at once if the learner moves into a
  // Build exercise or runs one. A page read elsewhere never pays for it. A Run that still has
  // to wait for it shows its start, as a Check shows the grader's.
  const prepare = () => sandboxed.prepare();
  const nearSandbox = new IntersectionObserver((entries) => {
    if (!entries.some((entry) => entry.isIntersecting)) return;
    nearSandbox.disconnect();
    sandboxMayStart(ctx.runtime).then(prepare);
  }, { rootMargin: "150% 0px" });
  nearSandbox.observe(ctx.el);
  ctx.el.addEventListener("focusin", prepare, { once: true });
  const host = ownRole(ctx.el, ROLE.editor);
  const runButton = ownRole(ctx.el, ROLE.run);
  const limitMs = Number(host.dataset.timeLimit || 5) * 1000;
  const editor = lazyEditor(ctx, host, () => run());
  const figure = runFigure(ctx.el);
  let runs = 0; // a figure that comes after a later run started is not shown

  async function run() {
    const thisRun = ++runs;
    setPending(ctx.el); // at once: building the editor first may take a moment
    figure.busy();
    runButton.disabled = true;
    const ed = await editor.latest();
    ed.markLine(null);
    const reply = await ctx.submit("run", { code: ed.getCode() }, {
      via: sandboxed, limitMs,
      onProgress: (text) => showMessage(ctx.el, text),
      onWait: () => showSandboxStart(ctx.el),
    });
    runButton.disabled = false;
    renderTests(ctx.el, reply);
    const line = reply.ok && reply.value.data?.error?.line;
    if (line) ed.markLine(line);
    // The verdict first; then the run's figure (sandbox-client.js), drawn by the grader meanwhile.
    const drawn = figure.wanted && reply.ok
      ? await sandboxed.request({ op: "run-figure", exercise: ctx.id, variant: ctx.variant })
      : null;
    if (thisRun === runs) figure.show(drawn);
  }
  runButton.addEventListener("click", run);
  ownRole(ctx.el, ROLE.reset).addEventListener("click", async () => {
    if (window.confirm("Replace your code with the starter code? Your current code will be lost.")) {
      (await editor.open()).setCode(editor.starter);
      ctx.progress.update(ctx.id, { code: editor.starter });
    }
  });
}
