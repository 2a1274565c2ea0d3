// Mathematics in the page: KaTeX typesets every formula the build wrote (pymdownx
// arithmatex's spans), and the formulas of a verdict, which the grader sends as
// pieces (data.math: plain strings and {tex} objects, workbook/math_text.py).

// KaTeX typesets the page in slices of about 8 ms, yielding in between, so a
// chapter full of formulas never blocks the main thread (no long task). The frame
// after a slice styles and lays out what it typeset, which takes about twice as
// long: with 25 ms slices that frame was itself a long task (46-53 ms on chapter 0);
// chapter 3's formulas are all typeset 0.06 s later than with 25 ms slices.
const SLICE_MS = 8;
const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

export async function renderMath(scope) {
  const katex = window.katex;
  if (!katex) return;
  let sliceStart = performance.now();
  for (const el of scope.querySelectorAll(".arithmatex")) {
    if (el.dataset.rendered) continue;
    if (performance.now() - sliceStart > SLICE_MS) {
      await nextTask();
      sliceStart = performance.now();
      if (el.dataset.rendered || !el.isConnected) continue;
    }
    const tex = el.textContent.trim();
    const display = el.tagName === "DIV";
    const body = display ? tex.replace(/^\\\[|\\\]$/g, "") : tex.replace(/^\\\(|\\\)$/g, "");
    try {
      katex.render(body, el, { displayMode: display, throwOnError: false });
      el.dataset.rendered = "true";
    } catch {
      /* leave the TeX source visible */
    }
  }
}

/** A verdict's message from its pieces, into `p`: text as text, each formula as an inline
 *  formula span the way the build writes them (typeset by renderMath once `p` is placed). */
export function fillMath(p, pieces) {
  for (const piece of pieces) {
    if (typeof piece === "string") p.append(piece);
    else if (piece && typeof piece.tex === "string") {
      const span = document.createElement("span");
      span.className = "arithmatex";
      span.textContent = `\\(${piece.tex}\\)`;
      p.append(span);
    }
  }
}
