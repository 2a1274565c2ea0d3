// Wires each exercise element (see the page contract) to the runtime and the
// progress store. Everything here is plain DOM; the grading happens in Python.

import { renderTests, setPending, showMessage, showResult } from "./feedback.js";

function decodeBase64(text) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  return new TextDecoder().decode(bytes);
}

async function grade(ctx, answer, limitMs) {
  const { el, id, runtime, progress } = ctx;
  setPending(el);
  const result = await runtime.request({ op: "grade", exercise: id, answer }, { limitMs });
  showResult(el, result);
  recordAttempt(ctx, result, { last: answer });
  return result;
}

// A graded attempt (not an invalid input or a runtime error) counts; the first
// correct one marks the exercise solved, noting whether the solution was revealed first.
function recordAttempt({ id, progress }, result, extra = {}) {
  if (result.status !== "correct" && result.status !== "incorrect") return;
  const before = progress.get(id);
  const patch = { ...extra, attempts: (before.attempts || 0) + 1 };
  if (result.status === "correct" && !before.solved) {
    patch.solved = true;
    patch.solvedAfterReveal = Boolean(before.revealed);
  }
  progress.update(id, patch);
}

// ---- Derive ---------------------------------------------------------------
function initDerive(ctx) {
  const form = ctx.el.querySelector("form");
  const input = ctx.el.querySelector('[data-role="answer"]');
  const saved = ctx.progress.get(ctx.id);
  if (typeof saved.last === "string") input.value = saved.last;
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    grade(ctx, input.value);
  });
}

// ---- Trace ----------------------------------------------------------------
function initTrace(ctx) {
  const form = ctx.el.querySelector("form");
  const saved = ctx.progress.get(ctx.id);
  const choices = [...ctx.el.querySelectorAll('[data-role="choice"]')];
  for (const c of choices) if (c.value === saved.last) c.checked = true;
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    const picked = choices.find((c) => c.checked);
    if (!picked) {
      setPending(ctx.el);
      showResult(ctx.el, { status: "invalid", message: "Choose one of the options first." });
      return;
    }
    grade(ctx, picked.value);
  });
}

// ---- Debug ----------------------------------------------------------------
function initDebug(ctx) {
  const form = ctx.el.querySelector("form");
  const lines = [...ctx.el.querySelectorAll('[data-role="line"]')];
  const select = (line, focus) => {
    for (const l of lines) {
      const on = l === line;
      l.classList.toggle("is-selected", on);
      l.setAttribute("aria-selected", String(on));
      l.tabIndex = on ? 0 : -1;
    }
    if (focus) line.focus();
  };
  const saved = ctx.progress.get(ctx.id);
  const restored = lines.find((l) => Number(l.dataset.line) === Number(saved.last));
  if (restored) select(restored, false);
  for (const line of lines) {
    line.addEventListener("click", () => select(line, false));
    line.addEventListener("keydown", (event) => {
      const i = lines.indexOf(line);
      const moves = { ArrowDown: i + 1, ArrowUp: i - 1, Home: 0, End: lines.length - 1 };
      if (event.key in moves) {
        event.preventDefault();
        const target = lines[Math.max(0, Math.min(lines.length - 1, moves[event.key]))];
        target.tabIndex = 0;
        line.tabIndex = -1;
        target.focus();
      } else if (event.key === " " || event.key === "Enter") {
        event.preventDefault();
        select(line, false);
        if (event.key === "Enter") form.requestSubmit();
      }
    });
  }
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    const picked = lines.find((l) => l.classList.contains("is-selected"));
    if (!picked) {
      setPending(ctx.el);
      showResult(ctx.el, { status: "invalid", message: "Click the line you think holds the bug, then check." });
      return;
    }
    grade(ctx, Number(picked.dataset.line));
  });
}

// ---- Design ---------------------------------------------------------------
function initDesign(ctx) {
  const form = ctx.el.querySelector("form");
  const list = ctx.el.querySelector(".wb-steps");
  const steps = () => [...list.querySelectorAll('[data-role="step"]')];
  const order = () => steps().map((s) => s.dataset.step);
  const saved = ctx.progress.get(ctx.id);
  const savedOrder = saved.draftOrder || saved.last;
  if (Array.isArray(savedOrder)) {
    const byKey = new Map(steps().map((s) => [s.dataset.step, s]));
    if (savedOrder.length === byKey.size && savedOrder.every((k) => byKey.has(k))) {
      for (const k of savedOrder) list.append(byKey.get(k));
    }
  }
  const announce = (step) => {
    const pos = steps().indexOf(step) + 1;
    showMessage(ctx.el, `“${step.querySelector(".wb-step-text").textContent}” is now step ${pos} of ${steps().length}.`);
  };
  const move = (step, delta) => {
    const all = steps();
    const i = all.indexOf(step);
    const j = i + delta;
    if (j < 0 || j >= all.length) return;
    if (delta < 0) list.insertBefore(step, all[j]);
    else list.insertBefore(all[j], step);
    ctx.progress.update(ctx.id, { draftOrder: order() });
    announce(step);
  };
  list.addEventListener("click", (event) => {
    const button = event.target.closest("[data-role=move-up],[data-role=move-down]");
    if (!button) return;
    const step = button.closest('[data-role="step"]');
    move(step, button.dataset.role === "move-up" ? -1 : 1);
    button.focus();
  });
  // Drag and drop (HTML5); the buttons above are the keyboard and touch path.
  let dragged = null;
  list.addEventListener("dragstart", (event) => {
    dragged = event.target.closest('[data-role="step"]');
    if (!dragged) return;
    dragged.classList.add("is-dragging");
    event.dataTransfer.effectAllowed = "move";
    event.dataTransfer.setData("text/plain", dragged.dataset.step);
  });
  list.addEventListener("dragover", (event) => {
    if (!dragged) return;
    event.preventDefault();
    const over = event.target.closest('[data-role="step"]');
    if (!over || over === dragged) return;
    const rect = over.getBoundingClientRect();
    const after = event.clientY > rect.top + rect.height / 2;
    list.insertBefore(dragged, after ? over.nextSibling : over);
  });
  list.addEventListener("dragend", () => {
    if (!dragged) return;
    dragged.classList.remove("is-dragging");
    announce(dragged);
    dragged = null;
  });
  form.addEventListener("submit", (event) => {
    event.preventDefault();
    grade(ctx, order());
  });
}

// ---- Build ----------------------------------------------------------------
// The page shows the code (starter or saved) as plain text at first. CodeMirror
// is loaded and built only when the exercise comes near the viewport and the
// browser is idle after the Python runtime has started, or at once when the
// learner clicks, focuses or runs it: so opening a chapter never waits for, or
// stutters on, an editor nobody is looking at yet.
const runtimeSettled = new Promise((resolve) => {
  const done = () => document.documentElement.dataset.workbookRuntime !== "loading";
  if (done()) return resolve();
  const onChange = () => done() && (document.removeEventListener("workbook:runtime", onChange), resolve());
  document.addEventListener("workbook:runtime", onChange);
  setTimeout(resolve, 8000); // a slow start should not keep the editor away for long
});
const whenIdle = () => new Promise((resolve) => (self.requestIdleCallback ? requestIdleCallback(resolve, { timeout: 1500 }) : setTimeout(resolve, 50)));

function initBuild(ctx) {
  const { el, id, runtime, progress } = ctx;
  const host = el.querySelector('[data-role="editor"]');
  const plain = host.querySelector(".wb-starter");
  const starter = plain.textContent;
  const limitMs = Number(host.dataset.timeLimit || 5) * 1000;
  const saved = progress.get(id);
  let code = typeof saved.code === "string" ? saved.code : starter;
  // A <pre> hides one final newline; the editor shows it as an empty last line.
  plain.querySelector("code").textContent = code.endsWith("\n") ? code + "\n" : code;
  plain.tabIndex = 0;
  plain.setAttribute("aria-label", "Python code (press Enter or click to edit)");
  let editor = null;
  let timer = null;
  let opening = null;

  function openEditor() {
    opening ||= import("./editor.js").then(({ createEditor }) => {
      const hadFocus = document.activeElement === plain;
      editor = createEditor(host, code, {
        onChange(text) {
          code = text;
          clearTimeout(timer);
          timer = setTimeout(() => progress.update(id, { code }), 400);
        },
        onRun: () => run(),
      });
      plain.remove();
      host.wbEditor = editor; // for tests and tools: getCode(), setCode(), markLine()
      if (hadFocus) editor.view.focus();
      return editor;
    });
    return opening;
  }
  host.wbOpenEditor = openEditor; // builds the editor now (tests and tools); resolves to it

  const nearView = new IntersectionObserver((entries) => {
    if (!entries.some((entry) => entry.isIntersecting)) return;
    nearView.disconnect();
    runtimeSettled.then(whenIdle).then(openEditor);
  }, { rootMargin: "400px 0px" });
  nearView.observe(host);
  const openNow = () => {
    nearView.disconnect();
    openEditor().then((ed) => ed.view.focus());
  };
  plain.addEventListener("click", openNow);
  plain.addEventListener("keydown", (event) => {
    if (event.key === "Enter" || event.key === " ") {
      event.preventDefault();
      openNow();
    }
  });

  const runButton = el.querySelector('[data-role="run"]');
  async function run() {
    setPending(el);
    runButton.disabled = true;
    const ed = editor || (await openEditor());
    code = ed.getCode();
    clearTimeout(timer);
    progress.update(id, { code });
    ed.markLine(null);
    const result = await runtime.request(
      { op: "run", exercise: id, code },
      { limitMs, onProgress: (text) => showMessage(el, text) },
    );
    runButton.disabled = false;
    showResult(el, result);
    renderTests(el, result);
    const line = result.data?.error?.line;
    if (line) ed.markLine(line);
    recordAttempt(ctx, result);
  }
  runButton.addEventListener("click", run);
  el.querySelector('[data-role="reset"]').addEventListener("click", async () => {
    if (window.confirm("Replace your code with the starter code? Your current code will be lost.")) {
      (editor || (await openEditor())).setCode(starter);
      progress.update(id, { code: starter });
    }
  });
}

// ---- Hints and reveals -------------------------------------------------------
function initHelp(ctx) {
  const { el, id, progress } = ctx;
  const hintButton = el.querySelector('[data-role="hint"]');
  const revealButton = el.querySelector('[data-role="reveal"]');
  const toggle = (button, panel, showLabel, hideLabel) => {
    const open = panel.hidden;
    panel.hidden = !open;
    button.setAttribute("aria-expanded", String(open));
    button.textContent = open ? hideLabel : showLabel;
    return open;
  };
  if (hintButton) {
    const panel = el.querySelector(".wb-hint");
    hintButton.addEventListener("click", () => {
      if (toggle(hintButton, panel, "Show hint", "Hide hint")) progress.update(id, { hinted: true });
    });
  }
  if (revealButton) {
    const panel = el.querySelector(".wb-solution");
    const showLabel = revealButton.textContent;
    const hideLabel = showLabel.replace("Show", "Hide");
    revealButton.addEventListener("click", () => {
      if (!panel.dataset.rendered) {
        panel.innerHTML = `<p class="admonition-title">${panel.dataset.title}</p>${decodeBase64(panel.dataset.content)}`;
        panel.dataset.rendered = "true";
        ctx.renderMath?.(panel);
      }
      if (toggle(revealButton, panel, showLabel, hideLabel)) {
        const before = progress.get(id);
        if (!before.revealed) progress.update(id, { revealed: true });
      }
    });
  }
}

const INIT = { derive: initDerive, trace: initTrace, debug: initDebug, design: initDesign, build: initBuild };

export function initExercise(el, shared) {
  if (el.dataset.wbReady) return;
  el.dataset.wbReady = "true";
  const ctx = { ...shared, el, id: el.dataset.exerciseId };
  const saved = ctx.progress.get(ctx.id);
  if (saved.solved) {
    el.dataset.state = "correct";
    showMessage(el, saved.solvedAfterReveal ? "Solved earlier (after revealing the solution)." : "Solved earlier.");
  }
  initHelp(ctx);
  const init = INIT[el.dataset.kind];
  Promise.resolve(init?.(ctx)).catch((err) => {
    el.dataset.state = "error";
    showMessage(el, `This exercise could not start: ${err.message}`);
  });
}
