"""Accessibility and small screens: an axe-core audit of every page in the light
and dark palettes (no violation of any impact, best-practice rules included, with
hints and solutions open), every exercise kind worked from the keyboard alone with a visible focus,
and every page usable 360 px wide (no sideways scrolling, editors and figures
fit, touch targets at least 24 px).

axe-core comes from node_modules and is injected by the test only; the site
never ships it."""

from __future__ import annotations

import pytest
from playwright.sync_api import Locator, Page, expect

from formula_cues import WIDER_THAN_BOX, check_formulas, formulas_ready
from helpers import (
    CHAPTERS,
    exercise,
    fill_matrix,
    open_all_editors,
    open_chapter,
    role,
    run_build,
    settle,
    wait_runtime,
)
from site_audit import (
    COLOUR_RULES,
    DECISIONS_AUDITED,
    EVERY_PAGE,
    OVERFLOW,
    PAGES,
    SCHEME,
    audit,
    load_axe,
    set_scheme,
)
from workbook import bank
from workbook.number_format import fmt

SPREAD = True  # its tests share nothing: the test processes share them out (conftest.py)
ROTATE_OK = "import math\n\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n    return (c * x - s * y, s * x + c * y)\n"


def open_ready(page: Page, site_url: str, n: int) -> None:
    """Open chapter n and wait (generously: test machines may be busy) for the runtime."""
    open_chapter(page, site_url, n, wait_ready=False)
    wait_runtime(page, timeout=120_000)


SLOW = 120_000  # ms: generous, for a test machine busy with other work (a page's worker boots Python meanwhile)


def settle_page(page: Page) -> None:
    """Wait until the page's script has drawn everything it draws (editors built now)."""
    page.wait_for_function("() => [...document.querySelectorAll('[data-exercise-id]')].every(e => e.dataset.wbReady)", timeout=SLOW)
    open_all_editors(page, timeout=SLOW)
    page.wait_for_function("""() => {
      const exercises = [...document.querySelectorAll('[data-exercise-id]')];
      const builds = exercises.filter(e => e.dataset.kind === 'build');
      return exercises.every(e => e.dataset.wbReady) &&
        builds.every(e => e.querySelector('.cm-editor')) &&
        (!exercises.length || document.querySelector('.wb-chapter-progress')) &&
        [...document.querySelectorAll('[data-wb-progress-panel]')].every(p => p.querySelector('table'));
    }""", timeout=SLOW)


def wait_practise_card(page: Page) -> None:
    """The Practise card's exercise started and showing its new numbers: the prompt is dimmed
    (aria-busy) while they are drawn, and a Derive exercise arrives with the chapter's variant 0."""
    page.wait_for_function("""() => {
      const ex = document.querySelector('.wb-practise-card [data-exercise-id]');
      return !!ex && !!ex.dataset.wbReady && !ex.hasAttribute('aria-busy') &&
        (ex.dataset.kind !== 'derive' || ex.dataset.variant !== '0');
    }""", timeout=SLOW)


def open_all_help(page: Page) -> None:
    """Open every hint, derivation and "Work it in steps" panel. The buttons are pressed from the
    page's own script (an element's click(), the event a press sends), not by moving Playwright's
    mouse to each: the walks only need every panel open, and each scroll to a button costs the
    page a repaint (about 0.3 s of CPU per button, 25 buttons on a chapter). That mouse and
    keyboard work them is test_every_exercise_kind_works_from_the_keyboard's and test_feedback's."""
    page.evaluate("""(sel) => {
      for (const button of document.querySelectorAll(sel)) {
        if (button.getAttribute('aria-expanded') !== 'true') button.click();  // an open panel stays open
      }
    }""", role("hint") + ', ' + role("reveal") + ', ' + role("work-steps-open"))
    for panel in ("solution-panel", "work-steps"):
        page.wait_for_function("sel => [...document.querySelectorAll(sel)].every(s => !s.hidden)", arg=role(panel))


@pytest.mark.parametrize("path", EVERY_PAGE, ids=[p.strip("/") or "home" for p in EVERY_PAGE])
def test_axe_finds_no_violation_on_any_page(page, site_url, path):
    """Every page in both palettes: loaded in one (light for every other page, dark for the rest,
    so both are checked as loaded) with every rule, then switched to the other as the palette
    toggle does, with the rules a palette can change (the page's markup is the same in both).
    On the same visit, at 1280 px: no formula is cut without its cue, and on a chapter as loaded
    no display formula is wider than its box."""
    first = "dark" if EVERY_PAGE.index(path) % 2 else "light"
    page.emulate_media(color_scheme=first)
    page.goto(site_url + path)
    assert page.evaluate("document.body.getAttribute('data-md-color-scheme')") == SCHEME[first]
    settle_page(page)
    found = {}
    if path in CHAPTERS.values():
        formulas_ready(page)
        wide = page.evaluate(WIDER_THAN_BOX)
        if wide:
            found["display formulas wider than their box at 1280 px"] = wide
    if path == "practise/":  # with an exercise on the card
        page.get_by_role("button", name="Practise another").click()
        wait_practise_card(page)
    open_all_help(page)
    formulas_ready(page)
    cut = check_formulas(page)["bad"]
    if cut:
        found["formulas cut without their cue at 1280 px"] = cut
    for scheme, rules in ((first, None), ("light" if first == "dark" else "dark", COLOUR_RULES)):
        if scheme != first:
            set_scheme(page, scheme)
        problems = audit(page, rules)
        if path == "progress/":
            page.get_by_role("button", name="Reset all progress…").click()
            problems += [f"(reset dialog) {p}" for p in audit(page, rules)]
            page.keyboard.press("Escape")
        if problems:
            found[scheme] = problems
    assert found == {}, "\n".join(f"{s}:\n  " + "\n  ".join(v) for s, v in found.items())


def grid(rows) -> list[list[str]]:
    return [[fmt(v) for v in row] for row in rows]


def check_and_settle(page: Page, target: Locator, check_role: str) -> str:
    """Press `target`'s own Check (an exercise's or a step's) and return its state after the reply."""
    target.locator(role(check_role)).first.click()
    page.wait_for_function("el => el.dataset.state !== 'pending'", arg=target.element_handle(), timeout=SLOW)
    return target.get_attribute("data-state")


@pytest.mark.parametrize("width", [1280, 360])
def test_exercise_feedback_states_pass_the_audit(page, site_url, width):
    """After interaction, in both palettes, at 1280 and 360 px, on chapter 3 (it has every kind
    of exercise and checked steps): a wrong answer; a wrong matrix and an answer carried from it
    (with its "Back to exercise" link); an invalid Trace; a wrong step and a step carried from it;
    a Build run's test table; a wrongly chosen Debug line; every hint, derivation and steps panel open."""
    page.set_viewport_size({"width": width, "height": 800})
    open_ready(page, site_url, 3)
    wrong = exercise(page, "3.1")
    wrong.locator(role("answer")).fill(fmt(bank.get("3.1").answer.key + 7))
    assert check_and_settle(page, wrong, "check") == "incorrect"
    F = [list(row) for row in bank.get("3.7").answer.cleaned]
    F[0][2] = -2.0  # a wrong F(1,3), carried into 3.8
    first, later = exercise(page, "3.7"), exercise(page, "3.8")
    fill_matrix(first, grid(F))
    assert check_and_settle(page, first, "check") == "incorrect"
    fill_matrix(later, grid(bank.get("3.8").carried_answer({"F": tuple(map(tuple, F))}).cleaned))
    assert check_and_settle(page, later, "check") == "incorrect"
    expect(later.locator(role("carried-from"))).to_have_count(1)
    trace = exercise(page, "3.6")
    assert check_and_settle(page, trace, "check") == "invalid"  # nothing chosen
    # 3.8 in steps: a wrong step 1 (a named slip) and a step 2 that follows from it
    later.locator(role("work-steps-open")).click()
    steps = bank.get("3.8")
    slip = steps.step_answers["FP"].slips[0].value
    for name, rows in (("FP", slip), ("FPF", steps.carried_steps({"FP": slip})["FPF"].key)):
        li = later.locator(role("work-step", f'[data-step-name="{name}"]'))
        fill_matrix(li, grid(rows))
        assert check_and_settle(page, li, "work-step-check") == "incorrect", name
    build = exercise(page, "3.10")
    run_build(build, timeout=SLOW)  # its verdict, then its run figure
    assert build.locator(role("test-result")).count() > 0
    debug = exercise(page, "3.5")
    line = next(n for n in range(1, 50) if n != bank.get("3.5").bug_line)
    debug.locator("form[data-wb-ready]").wait_for(state="attached")
    debug.locator(role("line", f'[data-line="{line}"]')).click()
    assert check_and_settle(page, debug, "check") == "incorrect"
    assert debug.locator(role("line", f'[data-line="{line}"]')).get_attribute("aria-selected") == "true"
    settle_page(page)
    open_all_help(page)
    load_axe(page)  # and stops colour transitions before the palette changes
    for scheme in ("light", "dark"):  # every rule in one palette; in the other, the rules a palette changes
        set_scheme(page, scheme)
        assert audit(page, None if scheme == "light" else COLOUR_RULES) == [], scheme


def has_visible_focus(page: Page) -> bool:
    """The focused element draws a ring, or (inside the code editor) the editor's frame does."""
    return page.evaluate("""(editor) => {
      const ring = (el) => {
        const s = getComputedStyle(el);
        return (s.outlineStyle !== 'none' && parseFloat(s.outlineWidth) >= 1) || s.boxShadow !== 'none';
      };
      const el = document.activeElement;
      const frame = el.closest(editor);
      return ring(el) || (!!frame && ring(frame));
    }""", role("editor"))


def tab_to(page: Page, selector: str, limit: int = 150) -> None:
    """Press Tab until the focus is on an element matching `selector`."""
    for _ in range(limit):
        page.keyboard.press("Tab")
        if page.evaluate("s => document.activeElement?.matches(s)", selector):
            assert has_visible_focus(page), f"no visible focus on {selector}"
            return
    raise AssertionError(f"Tab never reached {selector}")


def test_every_exercise_kind_works_from_the_keyboard(page, site_url):
    open_ready(page, site_url, 1)
    # Derive: type, Enter.
    exercise(page, "1.1").locator(role("answer")).focus()
    page.keyboard.type("4")
    page.keyboard.press("Enter")
    assert settle(exercise(page, "1.1")) == "correct"
    # Hint and derivation: Tab to the buttons, Enter and Space.
    tab_to(page, ('[data-exercise-id="1.1"] ' + role("hint")))
    page.keyboard.press("Enter")
    expect(exercise(page, "1.1").locator(role("hint-panel"))).to_be_visible()
    tab_to(page, ('[data-exercise-id="1.1"] ' + role("reveal")))
    page.keyboard.press(" ")
    expect(exercise(page, "1.1").locator(role("solution-panel"))).to_be_visible()
    assert exercise(page, "1.1").locator(role("reveal")).get_attribute("aria-expanded") == "true"
    # Trace: Tab into the options, arrows choose, Tab to Check, Enter.
    spec = bank.get("1.4")
    tab_to(page, ('[data-exercise-id="1.4"] ' + role("choice")))
    keys = [o.key for o in spec.options]
    page.keyboard.press(" ")
    for _ in range(keys.index(spec.answer)):
        page.keyboard.press("ArrowDown")
    assert exercise(page, "1.4").locator(role("choice") + f'[value="{spec.answer}"]').is_checked()
    tab_to(page, ('[data-exercise-id="1.4"] ' + role("check")))
    page.keyboard.press("Enter")
    assert settle(exercise(page, "1.4")) == "correct"
    # Design: Tab to the move buttons, Enter moves a step (focus stays on the button).
    design = exercise(page, "1.5")
    solution = list(bank.get("1.5").solution)
    for target, key in enumerate(solution):
        while True:
            order = design.locator(role("step")).evaluate_all("els => els.map(e => e.dataset.step)")
            if order.index(key) == target:
                break
            design.locator(f'[data-step="{key}"] ' + role("move-up")).focus()
            assert has_visible_focus(page)
            page.keyboard.press("Enter")
    assert "is now step" in design.locator(role("feedback")).inner_text()
    tab_to(page, ('[data-exercise-id="1.5"] ' + role("check")))
    page.keyboard.press("Enter")
    assert settle(design) == "correct"

    # Debug: arrows move between lines, Space picks, Enter checks.
    open_ready(page, site_url, 3)
    bug = bank.get("3.5").bug_line
    tab_to(page, ('[data-exercise-id="3.5"] ' + role("line")))
    for _ in range(bug - 1):
        page.keyboard.press("ArrowDown")
    assert has_visible_focus(page)
    page.keyboard.press(" ")
    assert exercise(page, "3.5").locator(f'[data-line="{bug}"]').get_attribute("aria-selected") == "true"
    page.keyboard.press("Enter")
    assert settle(exercise(page, "3.5")) == "correct"

    # Build: type into the editor, Ctrl+Enter runs; Tab leaves the editor after Escape.
    open_ready(page, site_url, 0)
    build = exercise(page, "0.5")
    # Until the editor is built the code is plain text in the tab order; Enter opens the editor.
    # (The page may build the editor on its own once idle, before or just after the focus lands.)
    build.locator(f'{role("code")}, .cm-content').first.focus()
    assert has_visible_focus(page)
    if not build.locator(".cm-content:focus").count():
        page.keyboard.press("Enter")
    build.locator(".cm-content:focus").wait_for()
    page.keyboard.press("Control+a")
    page.keyboard.press("Delete")
    build.evaluate(("(el, code) => el.querySelector('" + role("editor") + "').wbEditor.view.dispatch({changes: {from: 0, insert: code}})"),
                   ROTATE_OK.replace("    ", "\t"))  # typed text is auto-indented; insert as one change
    page.keyboard.press("Control+Enter")
    assert settle(build, timeout=120_000) == "correct"
    page.keyboard.press("Escape")
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.dataset.role") == "run"
    assert has_visible_focus(page)
    page.keyboard.press("Enter")
    assert settle(build, timeout=120_000) == "correct"


def test_progress_controls_work_from_the_keyboard(page, site_url):
    page.goto(site_url + "progress/")
    settle_page(page)
    tab_to(page, '[data-wb-action="reset"]')
    page.keyboard.press("Enter")
    dialog = page.locator("dialog.wb-confirm")
    expect(dialog).to_be_visible()
    assert page.evaluate("document.activeElement.textContent") == "Cancel"
    page.keyboard.press("Escape")
    expect(dialog).to_be_hidden()
    assert page.evaluate("document.activeElement.dataset.wbAction") == "reset"


TARGETS = ("""() => {
  const sel = 'button, input:not([type=radio]):not([type=checkbox]):not([type=file]), select, textarea, .wb-choice,' +
              ' """ + role("line") + """, [role=button], .wb-progress-panel a';
  const small = [];
  for (const el of document.querySelectorAll('.md-content ' + sel.split(',').join(', .md-content '))) {
    const r = el.getBoundingClientRect();
    if (!r.width || !r.height || el.closest('[hidden]')) continue;
    if (el.closest('.wb-progress-table')) continue;  // links in a table of text
    if (r.width < 24 || r.height < 24) small.push(`${el.tagName.toLowerCase()}.${el.className} ${Math.round(r.width)}x${Math.round(r.height)}`);
  }
  return small;
}""")

@pytest.mark.parametrize("path", EVERY_PAGE, ids=[p.strip("/") or "home" for p in EVERY_PAGE])
def test_every_page_fits_360_px(page, site_url, path):
    """Nothing pokes out sideways, every touch target is at least 24 px, and every formula too
    wide for the screen sits in a box that scrolls and shows its cue."""
    page.set_viewport_size({"width": 360, "height": 740})
    page.goto(site_url + path)
    settle_page(page)
    open_all_help(page)
    formulas_ready(page)
    formulas = check_formulas(page)
    found = page.evaluate(OVERFLOW) + page.evaluate(TARGETS) + formulas["bad"]
    assert found == [], "\n  ".join(found)
    if path == CHAPTERS[5]:  # at 360 px every formula fits; at 320 px (WCAG's reflow width) some
        page.set_viewport_size({"width": 320, "height": 740})  # must scroll, and the check sees them cued
        formulas = check_formulas(page)
        assert formulas["bad"] == [] and formulas["cued"] >= 3, formulas
    if path == PAGES[-1]:  # as the walk did once: a page's runtime starts at 360 px too
        wait_runtime(page, timeout=120_000)


def test_the_decision_records_pass_the_audit(page, site_url):
    """The decision records' index and records of each shape: axe (every rule, in the palette each is
    loaded in, in turns) at 1280 px, then nothing poking out sideways and every touch target large
    enough at 360 px."""
    found = {}
    for n, path in enumerate(DECISIONS_AUDITED):
        page.set_viewport_size({"width": 1280, "height": 800})
        page.emulate_media(color_scheme="dark" if n % 2 else "light")
        page.goto(site_url + path)
        problems = audit(page)
        page.set_viewport_size({"width": 360, "height": 740})
        problems += page.evaluate(OVERFLOW) + page.evaluate(TARGETS)
        if problems:
            found[path] = problems
    assert found == {}, "\n".join(f"{s}:\n  " + "\n  ".join(v) for s, v in found.items())

