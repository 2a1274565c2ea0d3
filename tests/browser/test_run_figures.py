"""Run figures in the page: after a run of 6.5, 8.4 and 5.10 the Build widget draws the learner's
function beside the reference (role run-figure); the keyboard steps through the cases; the
picture is named and described for screen readers; a wrong run shows its largest error.

The tests share the module's one tab (``tour``: one grader and one sandbox for them all); each
sets its own exercise's code before it runs, and no test reads another's records."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from helpers import exercise, role, run_build, set_editor
from workbook import bank


def figure(ex):
    return ex.locator(role("run-figure"))


def run_shown(tour, chapter: int, ex_id: str, code: str, state: str):
    """Run ``code`` in exercise ``ex_id`` of chapter ``chapter``: its page, exercise and run figure, shown."""
    page = tour(chapter)
    ex = exercise(page, ex_id)
    set_editor(page, ex, code)
    assert run_build(ex) == state
    fig = figure(ex)
    expect(fig).to_be_visible()
    return page, ex, fig


@pytest.mark.parametrize("chapter, ex_id", [(6, "6.5"), (8, "8.4"), (5, "5.10")])
def test_a_correct_run_draws_the_learners_function(tour, chapter, ex_id):
    page = tour(chapter)
    ex = exercise(page, ex_id)
    fig = figure(ex)
    expect(fig).to_be_hidden()
    set_editor(page, ex, bank.get(ex_id).solution)
    assert run_build(ex) == "correct"
    expect(fig).to_be_visible()
    canvas = fig.locator(role("run-canvas"))
    expect(canvas.locator("svg")).to_be_visible()
    assert canvas.locator("svg .wb-fig-a").count() > 0  # the learner's own trace is drawn
    expect(fig.locator(role("readout"))).to_have_text(re.compile(r"^Largest error 0( m)?: yours agrees"))
    # named and described for assistive technology
    assert canvas.get_attribute("role") == "img"
    assert canvas.get_attribute("aria-label")
    described = fig.locator("#" + canvas.get_attribute("aria-describedby"))
    expect(described).to_have_text(re.compile(r"\w+"))
    assert fig.get_attribute("aria-labelledby")


def test_the_keyboard_steps_through_the_cases(tour):
    page = tour(6)
    ex = exercise(page, "6.5")
    set_editor(page, ex, bank.get("6.5").solution)
    assert run_build(ex) == "correct"
    fig = figure(ex)
    label = fig.locator(role("run-case-label"))
    expect(label).to_have_text(re.compile(r"^test 1: "))
    first = fig.locator(role("run-canvas")).get_attribute("aria-label")
    fig.locator(role("run-case")).focus()
    page.keyboard.press("ArrowRight")
    expect(label).to_have_text(re.compile(r"^test 2: "))
    assert fig.locator(role("run-canvas")).get_attribute("aria-label") != first
    fig.locator(role("run-next")).focus()
    page.keyboard.press("Enter")
    expect(label).to_have_text(re.compile(r"^test 3: "))
    fig.locator(role("run-previous")).focus()
    page.keyboard.press("Enter")
    expect(label).to_have_text(re.compile(r"^test 2: "))
    assert fig.locator(role("run-case")).get_attribute("aria-valuetext").startswith("test 2")


def test_a_wrong_run_shows_its_largest_error(tour):
    _, _, fig = run_shown(tour, 8, "8.4", bank.get("8.4").starter, "incorrect")
    expect(fig.locator(role("readout"))).to_have_text(re.compile(r"^Largest error 0\.\d+ at run \d"))
    expect(fig.locator(role("run-case-label"))).to_have_text(re.compile(r"error 0\.\d+"))


def test_the_verdict_is_shown_before_the_figure_is_drawn(tour):
    """The figure is asked for once the verdict is on screen (run-figure): held back here, the verdict
    and its test rows are shown, and the last run's figure stays marked busy until the new one comes."""
    page, ex, fig = run_shown(tour, 6, "6.5", bank.get("6.5").solution, "correct")
    page.evaluate("""() => {
      const grader = window.workbook.runtime, request = grader.request.bind(grader);
      window.__heldFigure = null;
      grader.request = (msg, options) => msg.op !== "run-figure" ? request(msg, options)
        : new Promise((resolve) => { window.__heldFigure = () => resolve(request(msg, options)); });
    }""")
    set_editor(page, ex, bank.get("6.5").starter)
    ex.locator(role("run")).click()
    page.wait_for_function("() => window.__heldFigure !== null")
    assert ex.get_attribute("data-state") == "incorrect"
    assert ex.locator(role("test-result")).count() > 0
    assert fig.get_attribute("aria-busy") == "true"
    expect(fig.locator(role("readout"))).to_have_text(re.compile(r"^Largest error 0( m)?: yours agrees"))  # the last run's
    page.evaluate("() => window.__heldFigure()")
    expect(fig).not_to_have_attribute("aria-busy", "true")
    expect(fig.locator(role("readout"))).to_have_text(re.compile(r"^Largest error \d[\d.]*( m)? at "))  # the new run's
