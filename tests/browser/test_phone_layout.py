"""Code listings on a phone (a 360 px wide viewport).

In Python the indentation is part of the program, so a listing must keep its
columns: on every chapter page, for every Debug program, every Build exercise's
plain code (shown before the editor is built) and every CodeMirror editor:

- the first character of every line starts at the same x;
- a line indented by N spaces has its first non-space character exactly N
  character widths to the right of that (measured with a Range over the
  character, not with the line's box);
- every line stays on one visual line: a listing with a line longer than its
  box scrolls sideways (scrollWidth > clientWidth), as one block, instead of
  wrapping;

and no page is wider than the viewport.
"""

from __future__ import annotations

import pytest

from helpers import CHAPTERS, exercise, open_editor, role, run_build, set_editor, wait_runtime
from workbook import bank
from workbook.contract import ATTR, KINDS, ROLE, role_attr

WIDTH = 360
TOL = 0.5  # px: Chromium places glyphs on a 1/64 px grid; a column off by one is ~9 px
EDITOR_CHUNK = "**/assets/dist/chunks/editor-*.js"


def kind(name: str) -> str:
    assert name in KINDS
    return f'[{ATTR.kind}="{name}"]'


@pytest.fixture(scope="module")
def browser_context_args(browser_context_args):
    # No service worker: the test holds back the editor's chunk (below) to see the
    # plain code first, and a service worker would answer that request itself.
    return {**browser_context_args, "viewport": {"width": WIDTH, "height": 740}, "service_workers": "block"}


# Measures the listings of one kind on the page. For each line: where its first
# character starts (origin), where its first non-space character starts, where
# its last character ends, the vertical extent of all its text (one line, or
# more if it wrapped), and the height of one character. Each listing is
# measured scrolled fully left and fully right.
MEASURE = """async ({which, exercise, line, editor}) => {
  await document.fonts.ready;
  const at = (root, index) => {
    const walk = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
    for (let n = walk.nextNode(); n; n = walk.nextNode()) {
      if (index < n.length) return [n, index];
      index -= n.length;
    }
    throw new Error(`no character ${index} in ${root.textContent.length}`);
  };
  const range = (root, from, to) => {
    const r = document.createRange();
    const [a, ai] = at(root, from), [b, bi] = at(root, to - 1);
    r.setStart(a, ai);
    r.setEnd(b, bi + 1);
    return r;
  };
  const lineAt = (root, start, text, box) => {
    const row = { text, indent: text.length - text.trimStart().length };
    if (!text.trim()) return row;
    const first = range(root, start, start + 1).getBoundingClientRect();
    const rects = [...range(root, start, start + text.length).getClientRects()].filter((r) => r.width || r.height);
    Object.assign(row, {
      origin: first.left,
      charHeight: first.height,
      textLeft: range(root, start + row.indent, start + row.indent + 1).getBoundingClientRect().left,
      right: range(root, start + text.length - 1, start + text.length).getBoundingClientRect().right,
      top: Math.min(...rects.map((r) => r.top)),
      bottom: Math.max(...rects.map((r) => r.bottom)),
    });
    if (box) {
      const b = box.getBoundingClientRect();
      Object.assign(row, { boxLeft: b.left, boxHeight: b.height });
    }
    return row;
  };
  const listings = [];
  for (const ex of document.querySelectorAll(exercise)) {
    let scroller, lines;
    if (which === "debug") {
      const els = [...ex.querySelectorAll(line)];
      if (!els.length) continue;
      scroller = els[0].parentElement;
      lines = () => els.map((el) => { const code = el.querySelector("code"); return lineAt(code, 0, code.textContent, code); });
    } else if (which === "plain") {
      const pre = ex.querySelector(`${editor} > pre`);
      if (!pre) continue;
      scroller = pre;
      lines = () => {
        const out = [];
        let start = 0;
        for (const text of pre.textContent.split("\\n")) {
          out.push(lineAt(pre, start, text, null));
          start += text.length + 1;
        }
        return out;
      };
    } else {
      scroller = ex.querySelector(`${editor} .cm-scroller`);
      if (!scroller) continue;
      lines = () => [...scroller.querySelectorAll(".cm-line")].map((el) => lineAt(el, 0, el.textContent, el));
    }
    const box = scroller.getBoundingClientRect();
    scroller.scrollLeft = 0;
    const left = lines();
    scroller.scrollLeft = scroller.scrollWidth;
    const scrolledBy = scroller.scrollLeft;
    const right = lines();
    scroller.scrollLeft = 0;
    listings.push({
      id: ex.getAttribute("data-exercise-id"), which,
      scrollWidth: scroller.scrollWidth, clientWidth: scroller.clientWidth,
      visibleRight: box.left + scroller.clientLeft + scroller.clientWidth,
      scrolledBy, lines: left, scrolled: right,
    });
  }
  return listings;
}"""

PAGE_WIDTH = """() => ({
  view: document.documentElement.clientWidth,
  html: document.documentElement.scrollWidth,
  body: document.body.scrollWidth,
})"""


def measure(page, which: str) -> list[dict]:
    ex = f"[{ATTR.exercise}]" + kind("build" if which != "debug" else "debug")
    return page.evaluate(MEASURE, {"which": which, "exercise": ex, "line": f"[{role_attr(ROLE.line)}]",
                                   "editor": f"[{role_attr(ROLE.editor)}]"})


def check_listing(where: str, listing: dict) -> bool:
    """Assert the listing keeps its columns and does not wrap; return whether it has
    a line longer than its box (so that it must scroll)."""
    name = f"{where} {listing['id']} ({listing['which']})"
    rows = [r for r in listing["lines"] if r["text"].strip()]
    assert rows, f"{name}: no lines found"
    for r in rows:
        assert r["bottom"] - r["top"] < 1.5 * r["charHeight"], f"{name}: the line {r['text']!r} wraps"
        if "boxHeight" in r:
            assert r["boxHeight"] < 1.5 * r["charHeight"], f"{name}: the box of {r['text']!r} is taller than a line"
    origins = [r["origin"] for r in rows]
    assert max(origins) - min(origins) <= TOL, (
        f"{name}: lines start at different x: " + ", ".join(f"{r['origin']:.1f} {r['text'][:20]!r}" for r in rows)
    )
    if "boxLeft" in rows[0]:
        lefts = [r["boxLeft"] for r in rows]
        assert max(lefts) - min(lefts) <= TOL, f"{name}: the lines' boxes start at different x: {lefts}"
    longest = max(rows, key=lambda r: len(r["text"]))
    char = (longest["right"] - longest["origin"]) / len(longest["text"])
    assert char > 4, f"{name}: implausible character width {char:.2f} px"
    for r in rows:
        want = r["origin"] + r["indent"] * char
        assert abs(r["textLeft"] - want) <= TOL, (
            f"{name}: {r['text']!r} is indented by {r['indent']} spaces but starts "
            f"{(r['textLeft'] - r['origin']) / char:.2f} character widths in"
        )
    # Scrolled fully right, every line has moved by the same amount: one block.
    moved = [s["origin"] - r["origin"] for r, s in zip(listing["lines"], listing["scrolled"]) if r["text"].strip()]
    assert max(moved) - min(moved) <= TOL, f"{name}: lines scroll separately: {moved}"
    assert abs(moved[0] + listing["scrolledBy"]) <= TOL, f"{name}: scrolled {listing['scrolledBy']} px, lines moved {moved[0]}"
    long = any(r["origin"] + len(r["text"]) * char > listing["visibleRight"] + TOL for r in rows)
    if long:
        assert listing["scrollWidth"] > listing["clientWidth"], f"{name}: a line is longer than the box but it does not scroll"
    return long


def test_listings_keep_their_columns_at_360_px(page, site_url):
    held = []

    def hold(route):  # keep the plain code on the page until it is measured
        held.append(route)

    page.route(EDITOR_CHUNK, hold)
    seen = {"debug": 0, "plain": 0, "editor": 0}
    long = {"debug": 0, "plain": 0, "editor": 0}
    wide = {}
    for _n, path in CHAPTERS.items():
        page.goto(site_url + path)
        builds = page.locator(f"[{ATTR.exercise}]" + kind("build"))
        for which in ("debug", "plain"):
            for listing in measure(page, which):
                seen[which] += 1
                long[which] += check_listing(path, listing)
        assert len(measure(page, "plain")) == builds.count(), f"{path}: a Build exercise's plain code is missing"
        while held:
            held.pop().continue_()
        page.unroute(EDITOR_CHUNK, hold)
        for i in range(builds.count()):
            open_editor(builds.nth(i))
        for listing in measure(page, "editor"):
            seen["editor"] += 1
            long["editor"] += check_listing(path, listing)
        page.route(EDITOR_CHUNK, hold)
        wait_runtime(page, timeout=120_000)  # the figures are drawn: the page is complete
        size = page.evaluate(PAGE_WIDTH)
        if max(size["html"], size["body"]) > size["view"]:
            wide[path] = size
    assert wide == {}, f"pages wider than the {WIDTH} px viewport: {wide}"
    # The checks above ran on real listings, long ones included.
    assert seen["debug"] >= 2 and seen["plain"] == seen["editor"] >= 4, seen
    assert all(long.values()), f"no listing with a line longer than its box at {WIDTH} px: {long}"


# After a Build run: where each row's cells are against the table's box, and whether the box
# must scroll; the editor's help line: where its text lies against what the exercise shows
# (the exercise clips what lies under its borders).
FITS = """(ex) => {
  const px = (v) => parseFloat(v) || 0;
  const s = getComputedStyle(ex), box = ex.getBoundingClientRect();
  const shown = [box.left + px(s.borderLeftWidth), box.right - px(s.borderRightWidth)];
  const tests = ex.querySelector('[data-role="tests"]');
  const t = tests?.getBoundingClientRect();
  const cells = tests ? [...tests.querySelectorAll('tr > *')].map((c) => {
    const r = c.getBoundingClientRect();
    return [c.textContent.trim().slice(0, 30), r.left, r.right];
  }) : [];
  const described = ex.querySelector('[data-role="editor"] [aria-describedby]');  // the editor's help line
  const hint = described && document.getElementById(described.getAttribute('aria-describedby'));
  const range = document.createRange();
  if (hint) range.selectNodeContents(hint);
  const text = hint ? [...range.getClientRects()].map((r) => [r.left, r.right]) : [];
  return { shown, view: document.documentElement.clientWidth, cells, text,
           box: t && [t.left, t.right], scroll: tests && [tests.scrollWidth, tests.clientWidth] };
}"""


def test_a_build_runs_table_and_the_editors_help_line_fit_at_360_px(tour):
    """Issue 48: after a Build run at 360 px the pass/fail column was past the screen's edge
    (x = 329-369 on 4.5) with no visible scrollbar, and the editor's help line was clipped on both
    sides by the exercise's borders. Every Build exercise, its solution run (and a failing run)."""
    runs = 0
    for n in CHAPTERS:
        builds = [ex for ex in bank.chapter(n) if ex.kind == "build"]
        if not builds:
            continue
        page = tour(n)
        for k, ex in enumerate(builds):
            el = exercise(page, ex.id)
            for code in (ex.solution, ex.starter) if k == 0 else (ex.solution,):
                set_editor(page, el, code)
                run_build(el, timeout=120_000)
                got = el.evaluate(FITS)
                left, right = got["shown"]
                assert got["text"], f"{ex.id}: no help line under the editor"
                for a, b in got["text"]:
                    assert left - TOL <= a and b <= right + TOL, f"{ex.id}: help line text at x={a:.0f}-{b:.0f}, shown {left:.0f}-{right:.0f}"
                if not got["cells"]:
                    continue  # a plain program's run: its output, no table
                for text, _left, b in got["cells"]:
                    assert b <= min(got["box"][1], got["view"]) + TOL, (
                        f"{ex.id}: the cell {text!r} ends at x={b:.0f}, past the table's box ({got['box'][1]:.0f})")
                assert got["scroll"][0] <= got["scroll"][1], f"{ex.id}: the test table scrolls sideways {got['scroll']}"
                runs += 1
    assert runs >= 14, runs  # tables checked, a failing run's among them


# Every display formula's box, and the nearest box around it that scrolls sideways and must.
DISPLAY_SCROLLS = """async () => {
  await document.fonts.ready;
  const out = [];
  const shown = [...document.querySelectorAll('.katex-display')].filter((d) => d.checkVisibility());
  for (const d of shown) {
    for (let el = d; el && el !== document.body; el = el.parentElement) {
      if (/auto|scroll/.test(getComputedStyle(el).overflowX) && el.scrollWidth > el.clientWidth + 1) {
        out.push([el.scrollWidth, el.clientWidth, d.querySelector('annotation')?.textContent.trim().slice(0, 80)]);
        break;
      }
    }
  }
  return [shown.length, out];
}"""


def test_no_display_formula_scrolls_at_360_px(tour):
    """Issue 48: 14 display formulas of the chapters (27 before the first fixes: measured with this
    script) scrolled sideways at 360 px; each now breaks at a natural operator (aligned and
    gathered forms in the Markdown), the hints' formulas included."""
    formulas = 0
    wide = {}
    for n, path in CHAPTERS.items():
        page = tour(n)
        # KaTeX typesets the page in slices (math.js): wait for every display formula
        page.wait_for_function("() => { const all = [...document.querySelectorAll('div.arithmatex')];"
                               " return all.length > 0 && all.every((el) => el.dataset.rendered); }")
        hints = page.locator(role("hint"))
        for i in range(hints.count()):
            if hints.nth(i).is_visible():
                hints.nth(i).click()
        count, scrolls = page.evaluate(DISPLAY_SCROLLS)
        formulas += count
        if scrolls:
            wide[path] = scrolls
    assert wide == {}, f"display formulas that scroll at {WIDTH} px: {wide}"
    assert formulas >= 50, formulas


def test_no_revealed_derivation_scrolls_at_360_px(page, site_url):
    """Every chapter with every derivation revealed (variant 0, as a page first draws it): each
    display formula of the worked answers breaks at a relation or between two statements instead
    of scrolling sideways. Before: 68 of 170 scrolled."""
    formulas = 0
    wide = {}
    for _n, path in CHAPTERS.items():
        page.goto(site_url + path)
        page.evaluate("(sel) => { for (const b of document.querySelectorAll(sel)) b.click(); }", role("reveal"))
        page.wait_for_function("sel => [...document.querySelectorAll(sel)].every(s => !s.hidden)",
                               arg=role("solution-panel"))
        page.wait_for_function("() => { const all = [...document.querySelectorAll('div.arithmatex')];"
                               " return all.length > 0 && all.every((el) => el.dataset.rendered); }")
        count, scrolls = page.evaluate(DISPLAY_SCROLLS)
        formulas += count
        if scrolls:
            wide[path] = scrolls
    assert wide == {}, f"revealed display formulas that scroll at {WIDTH} px: {wide}"
    assert formulas >= 150, formulas
