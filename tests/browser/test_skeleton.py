"""The walking skeleton, end to end in Chromium: one exercise of each kind,
right and wrong, invalid input, a runaway loop stopped, instant navigation,
and a solved exercise still solved after a reload.

The four tests that grade one exercise of each kind share the module's one tab (``tour``, in the
order chapter 0, 3, 0, 1: one grader, by instant navigation); each answers its own exercise, and
no other test reads what they leave."""

from __future__ import annotations

import re
from pathlib import Path

from playwright.sync_api import expect

from helpers import (
    answer_debug,
    answer_derive,
    answer_trace,
    arrange_design,
    before_the_widget,
    check,
    editor_code,
    exercise,
    feedback,
    graded,
    open_chapter,
    role,
    run_build,
    set_editor,
    settle,
    wait_runtime,
)
from workbook import bank

SITE = Path(__file__).resolve().parents[2] / "site"
ROTATE_OK = "import math\n\ndef rotate_2d(x, y, theta):\n    c, s = math.cos(theta), math.sin(theta)\n    return (c * x - s * y, s * x + c * y)\n"


def test_html_contract_before_python_is_ready(page, site_url):
    page.goto(site_url + "chapters/00-rotations-2d/")
    # Rendered at build time: visible before the runtime is ready.
    assert page.locator("[data-exercise-id]").count() == len(bank.chapter(0))
    assert page.locator('[data-exercise-id="0.3"] ' + role("choice")).count() >= 3
    assert exercise(page, "0.1").get_attribute("data-kind") == "derive"
    assert exercise(page, "0.1").get_attribute("data-state") == "unanswered"
    assert page.evaluate("document.documentElement.dataset.workbookRuntime") in ("loading", "ready")
    # No answer key in plain HTML: the derivation is not readable text.
    assert "y' = 3" not in page.content()
    wait_runtime(page)


def test_derive_right_wrong_and_invalid(tour):
    page = tour(0)
    ex = exercise(page, "0.1")
    assert answer_derive(ex, "3") == "correct"
    assert answer_derive(ex, "2") == "incorrect"
    assert answer_derive(ex, "2,5") == "invalid"
    assert "2.5" in feedback(ex)
    assert answer_derive(ex, "") == "invalid"
    assert answer_derive(ex, "sqrt(9)") == "correct"


def test_debug_right_and_wrong_line(tour):
    page = tour(3)
    ex = exercise(page, "3.5")
    spec = bank.get("3.5")
    other = next(iter(spec.notes))
    assert answer_debug(ex, other) == "incorrect"
    assert f"Line {other} is fine" in feedback(ex)
    # One line selected at a time.
    assert ex.locator(role("line") + '.is-selected').count() == 1
    assert answer_debug(ex, spec.bug_line) == "correct"
    assert ex.locator(role("line") + '[aria-selected="true"]').count() == 1


def test_trace_right_and_wrong_with_reasons(tour):
    page = tour(0)
    ex = exercise(page, "0.3")
    spec = bank.get("0.3")
    wrong = next(o for o in spec.options if o.key != spec.answer)
    assert answer_trace(ex, wrong.key) == "incorrect"
    assert wrong.why.split("$")[0][:30] in feedback(ex)
    assert answer_trace(ex, spec.answer) == "correct"


def test_design_starts_unsolved_and_can_be_ordered(tour):
    page = tour(1)
    ex = exercise(page, "1.5")
    spec = bank.get("1.5")
    shown = ex.locator(role("step")).evaluate_all("els => els.map(e => e.dataset.step)")
    assert tuple(shown) != spec.solution
    assert check(ex) == "incorrect"
    assert "steps are in place" in feedback(ex)
    arrange_design(ex, list(spec.solution))
    assert check(ex) == "correct"


def test_runtime_starts_from_the_memory_snapshot(page, site_url):
    open_chapter(page, site_url, 0)
    assert page.evaluate("workbook.runtime.startedFrom") == "snapshot"
    # A first visit: Pyodide fetches and compiles its WebAssembly itself (see test_offline for later visits).
    assert page.evaluate("workbook.runtime.startStages.wasm") == "compiled by Pyodide"
    # The snapshot's zip importer knows the core's sources: a snapshot start never takes the compiled core.
    assert page.evaluate("workbook.runtime.startStages.stdlib") == "sources"
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    # The snapshot's random generator is reseeded at every start: no two starts draw alike.
    draws = []
    for _ in range(2):
        ex = exercise(page, "0.5")
        set_editor(page, ex, "import random\nprint('draw', random.random())\n" + ROTATE_OK)
        assert run_build(ex) == "correct"
        draws.append(re.search(r"draw (\S+)", ex.locator(role("stdout")).inner_text()).group(1))
        page.reload()
        wait_runtime(page)
    assert draws[0] != draws[1]


def test_runtime_boots_without_a_usable_snapshot(page, site_url):
    """A missing or damaged snapshot costs time, not the exercises."""
    page.context.route("**/workbook.snapshot.gz", lambda route: route.fulfill(status=200, body=b"not a snapshot"))
    messages = []
    page.on("console", lambda msg: messages.append(msg.text))
    open_chapter(page, site_url, 0, wait_ready=False)
    wait_runtime(page, timeout=120_000)
    assert page.evaluate("workbook.runtime.startedFrom") == "boot"
    assert any("booted without the snapshot" in m for m in messages)
    assert page.evaluate("workbook.runtime.startStages.stdlib") == "sources"  # the snapshot was chosen, then failed
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    set_editor(page, exercise(page, "0.5"), ROTATE_OK)
    assert run_build(exercise(page, "0.5")) == "correct"


def test_editor_is_built_when_the_exercise_comes_into_view(page, site_url):
    page.set_viewport_size({"width": 1000, "height": 700})
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    page.wait_for_timeout(1500)  # idle time after start-up: still nothing to build off screen
    assert ex.locator(".cm-editor").count() == 0
    assert "def rotate_2d" in ex.locator(role("code")).text_content()  # not scrolled to: not rendered yet
    ex.locator(role("editor")).scroll_into_view_if_needed()
    ex.locator(".cm-editor").wait_for()
    assert ex.locator(role("code")).count() == 0
    assert "def rotate_2d" in editor_code(ex)


def test_run_works_before_the_editor_is_built(page, site_url):
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    assert ex.locator(".cm-editor").count() == 0
    ex.evaluate("el => el.querySelector('" + role("run") + "').click()")  # no scrolling: the editor is not built yet
    assert settle(ex) == "incorrect"  # the starter code, graded
    assert ex.locator(role("test-result")).count() >= 1
    assert ex.locator(".cm-editor").count() == 1


def test_build_wrong_then_right(page, site_url):
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    assert run_build(ex) == "incorrect"  # the starter stub
    assert ex.locator(role("test-result") + '[data-passed="false"]').count() >= 1
    set_editor(page, ex, ROTATE_OK)
    assert run_build(ex) == "correct"
    rows = ex.locator(role("test-result"))
    assert rows.count() == len(bank.get("0.5").examples) + 1
    assert ex.locator(role("test-result") + '[data-passed="false"]').count() == 0


def test_infinite_loop_is_stopped_and_the_page_keeps_grading(page, site_url):
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, "def rotate_2d(x, y, theta):\n    while True:\n        pass\n")
    ex.locator(role("run")).click()
    # While the worker is stuck, the page itself stays responsive.
    assert page.evaluate("1 + 1") == 2
    derive = exercise(page, "0.1")
    derive.locator(role("answer")).fill("3")
    derive.locator(role("check")).click()  # queued: answered by the new worker
    page.wait_for_function("el => el.dataset.state === 'error'", arg=ex.element_handle(), timeout=60_000)
    assert re.search(r"stopped after 5 s", feedback(ex), re.I)
    page.wait_for_function("el => el.dataset.state === 'correct'", arg=derive.element_handle(), timeout=60_000)
    # Same page, same editor: the code is kept; a correct solution now passes.
    assert "while True" in editor_code(ex)
    set_editor(page, ex, ROTATE_OK)
    assert run_build(ex) == "correct"


def test_instant_navigation_keeps_grading(page, site_url):
    open_chapter(page, site_url, 0)
    page.evaluate("window.__sameDocument = true")
    page.locator("nav.md-nav a[href$='03-ekf-predict/']").first.click()
    page.wait_for_url(re.compile(r"03-ekf-predict/$"))
    exercise(page, "3.5").wait_for()
    assert page.evaluate("window.__sameDocument === true"), "expected an instant (same-document) navigation"
    wait_runtime(page)
    assert answer_debug(exercise(page, "3.5"), bank.get("3.5").bug_line) == "correct"
    assert answer_derive(exercise(page, "3.1"), "1") == "correct"


def test_solved_exercise_stays_solved_after_reload(page, site_url):
    open_chapter(page, site_url, 0)
    assert answer_derive(exercise(page, "0.1"), "3") == "correct"
    page.reload()
    assert exercise(page, "0.1").get_attribute("data-state") == "correct"
    # The answer is put back once the exercise's answer-kind module has loaded (a dynamic import).
    expect(exercise(page, "0.1").locator(role("answer"))).to_have_value("3")
    wait_runtime(page)


def test_opened_from_a_file_explains_how_to_serve(browser):
    page = browser.new_page()
    page.goto((SITE / "chapters" / "00-rotations-2d" / "index.html").as_uri())
    page.wait_for_function("() => document.documentElement.dataset.workbookRuntime === 'failed'")
    assert "python3 -m http.server" in feedback(exercise(page, "0.1"))
    page.close()


def test_a_check_pressed_before_the_widget_is_ready_is_held_not_lost(page, site_url):
    """Enter in an answer field before the exercise's script has loaded: no reload, and the answer is checked."""
    ex = exercise(page, "0.1")

    def type_and_press_enter():
        ex.locator(role("answer")).fill("3")
        ex.locator(role("answer")).press("Enter")
        page.wait_for_function("() => true")  # the page is still the same document
        assert "?" not in page.url

    before_the_widget(page, "derive", lambda: page.goto(site_url + "chapters/00-rotations-2d/"), type_and_press_enter)
    assert graded(page, ex) == "correct"
