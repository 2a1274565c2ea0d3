// Keyboard access to boxes that scroll sideways: a wide formula, a table of test
// results, a model solution's code or the printed output may not fit the column (at 360 px many do). Such
// a box is only reachable by mouse or touch unless it can take the focus, so each
// one that overflows gets tabindex=0 (the arrow keys then scroll it) and a name;
// one that stops overflowing gives them back. Boxes are re-checked when the page
// changes (instant navigation, a revealed derivation, a test run) or is resized.
//
// A box that scrolls is never cut silently: data-wb-overflow says on which side
// more of it is hidden ("start", "end" or both), kept up to date as it scrolls,
// and the stylesheet draws a fade and an arrow on that side.

const BOXES = [
  [".md-typeset div.arithmatex, .md-typeset .katex-display", "Formula (scrolls sideways)"],
  [".wb-tests", "Test results (scroll sideways)"],
  [".wb-stdout", "Printed output (scrolls)"],
  [".md-typeset pre > code", "Code (scrolls sideways)"],
  [".wb-progress-table-wrap", "Progress table (scrolls sideways)"],
];

function scrolls(box) {
  const style = getComputedStyle(box);
  const x = /auto|scroll/.test(style.overflowX) && box.scrollWidth > box.clientWidth + 1;
  const y = /auto|scroll/.test(style.overflowY) && box.scrollHeight > box.clientHeight + 1;
  return x || y;
}

/** Which sides of a box hide some of its content ("start end", "start", "end" or ""). */
function hiddenSides(box) {
  const left = box.scrollLeft > 1;
  const right = box.scrollLeft + box.clientWidth < box.scrollWidth - 1;
  return [left && "start", right && "end"].filter(Boolean).join(" ");
}

function showCue(box) {
  const sides = hiddenSides(box);
  if (box.dataset.wbOverflow !== sides) box.dataset.wbOverflow = sides;
}

const onScroll = (event) => showCue(event.currentTarget);

function scan() {
  for (const [selector, label] of BOXES) {
    for (const box of /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll(selector))) {
      const mine = box.dataset.wbScrollable === "true";
      if (box.hidden || box.closest("[hidden]")) continue;
      if (scrolls(box)) {
        showCue(box);
        box.addEventListener("scroll", onScroll, { passive: true }); // the same listener is added once
        if (mine || box.hasAttribute("tabindex")) continue;
        Object.assign(box, { tabIndex: 0 });
        box.setAttribute("role", "group");
        box.setAttribute("aria-label", label);
        box.dataset.wbScrollable = "true";
      } else {
        delete box.dataset.wbOverflow;
        if (!mine) continue;
        box.removeAttribute("tabindex");
        box.removeAttribute("role");
        box.removeAttribute("aria-label");
        delete box.dataset.wbScrollable;
      }
    }
  }
}

// Checking a box reads its layout. Done from an idle callback after a short
// pause, the browser has already laid the page out for painting, so the reads
// are cheap; done at once (on every typeset formula) they would force layout
// again and again while the page is still being built.
let queued = false;
function later() {
  if (queued) return;
  queued = true;
  setTimeout(() => {
    const run = () => {
      queued = false;
      scan();
    };
    if (self.requestIdleCallback) requestIdleCallback(run, { timeout: 1000 });
    else run();
  }, 150);
}

/** Check every box now rather than after the pause (tests and tools measure the page as it settles). */
export function checkScrollRegionsNow() {
  scan();
}

export function initScrollRegions() {
  new MutationObserver(later).observe(document.body, { childList: true, subtree: true, attributeFilter: ["hidden"] });
  window.addEventListener("resize", later);
  later();
}
