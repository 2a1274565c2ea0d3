"""Issue 48, input made for thumbs: on a phone (touch emulation, 360 x 740) every answer box
brings up the right keyboard (inputmode, enterkeyhint), and a row of the symbols its answer
needs sits above the keyboard and inserts at the caret without taking the focus. Every answer
of the workbook (each Derive exercise and each of its checked steps, at the printed numbers)
can be typed with the keypad's keys and the keyboard's letters and digits only; a few are
typed so, tap by tap, and checked. In a matrix, Enter ("next") moves entry by entry."""

from __future__ import annotations

import re

import pytest
from playwright.sync_api import expect

from helpers import CHAPTERS, entry, exercise, role, settle, wait_runtime
from workbook import bank
from workbook.contract import ATTR

# What a phone keyboard's letter page has, besides the letters: digits (its top row or a long
# press), the space, the point and the comma.
LETTER_PAGE = re.compile(r"[A-Za-z0-9 .,]")
DIGITS = re.compile(r"[0-9]")
# The ASCII symbols of the worked answers, as the keypad spells them.
AS_KEYPAD = {"-": "−", "*": "×"}
INPUTS = f'{role("answer")}, {role("entry")}'


@pytest.fixture(scope="module")
def browser_context_args(browser_context_args):
    return {**browser_context_args, "viewport": {"width": 360, "height": 740}, "has_touch": True,
            "is_mobile": True, "device_scale_factor": 2}


def strokes(text: str, keys: list[str], numeric: bool = False) -> list[tuple[str, str]]:
    """``text`` as ("key", symbol) taps on the keypad and ("type", character) presses of the
    letter page; raises AssertionError for a character neither has."""
    out: list[tuple[str, str]] = []
    i = 0
    while i < len(text):
        longest = max((k for k in keys if text.startswith(k, i)), key=len, default=None)
        ch = text[i]
        if longest and len(longest) > 1:
            out.append(("key", longest))
            i += len(longest)
        elif AS_KEYPAD.get(ch, ch) in keys:
            out.append(("key", AS_KEYPAD.get(ch, ch)))
            i += 1
        else:
            allowed = DIGITS if numeric else LETTER_PAGE
            assert allowed.fullmatch(ch), f"{text!r}: {ch!r} is neither on the keypad {keys} nor on the keyboard"
            out.append(("type", ch))
            i += 1
    return out


def answers(ex) -> list[tuple[str | None, object]]:
    """(step name or None, answer kind) of every answer box of a Derive exercise."""
    return [(None, ex.answer), *((name, a) for name, a in getattr(ex, "step_answers", {}).items())]


def cells(answer) -> list[tuple[tuple[int, int] | None, str]]:
    typed = answer.typed(answer.key)
    if isinstance(typed, list):
        return [((i, j), text) for i, row in enumerate(typed, 1) for j, text in enumerate(row, 1)]
    return [(None, typed)]


def open_steps(ex_el) -> None:
    """Open the exercise's checked steps (they wait in a <template> until the panel first opens)."""
    if ex_el.locator(role("work-step")).count():
        return
    opener = ex_el.locator(role("work-steps-open"))
    opener.wait_for()
    ex_el.page.wait_for_function("el => el.closest('[data-exercise-id]').querySelector('form[data-wb-ready]')",
                                 arg=opener.element_handle())
    opener.click()
    ex_el.locator(role("work-step")).first.wait_for(state="attached")


# Every answer box of an exercise, read at once: {"step|row|col": [keys, inputmode]}, step "" for
# the exercise's own answer, row and col "" for a single box.
BOXES = """(ex, [inputs, step, stepName, row, col, keys]) => Object.fromEntries(
  [...ex.querySelectorAll(inputs)].map((b) => [
    [b.closest(step)?.getAttribute(stepName) ?? "", b.getAttribute(row) ?? "", b.getAttribute(col) ?? ""].join("|"),
    [b.getAttribute(keys), b.getAttribute("inputmode")]]))"""


def boxes(ex_el) -> dict[str, list[str]]:
    return ex_el.evaluate(BOXES, [INPUTS, role("work-step"), ATTR.stepName, ATTR.row, ATTR.col, ATTR.keys])


def where(step: str | None, at: tuple[int, int] | None) -> str:
    return "|".join([step or "", *(map(str, at) if at else ("", ""))])


def test_every_answer_of_the_workbook_can_be_typed_with_the_keypad_and_letters(tour):
    seen = 0
    for n, path in CHAPTERS.items():
        page = tour(n)
        missing = page.locator(INPUTS).evaluate_all(
            "els => els.filter(e => !e.getAttribute('inputmode') || !e.getAttribute('enterkeyhint')"
            " || !e.dataset.keys).map(e => e.outerHTML.slice(0, 100))")
        assert missing == [], f"{path}: answer boxes without inputmode, enterkeyhint or keys: {missing}"
        for ex in bank.chapter(n):
            if ex.kind != "derive":
                continue
            el = exercise(page, ex.id)
            if getattr(ex, "step_answers", None):
                open_steps(el)
            found = boxes(el)
            for step, answer in answers(ex):
                for at, text in cells(answer):
                    assert where(step, at) in found, f"{ex.id}: no answer box {where(step, at)!r} in {sorted(found)}"
                    keys, mode = found[where(step, at)]
                    strokes(text, keys.split(), mode == "numeric")
                    seen += 1
    assert seen > 150, seen


def tap_in(page, target, text: str) -> None:
    """Type ``text`` into the focused ``target`` as a thumb would: symbols from the keypad row,
    the rest from the keyboard's letter page; the focus never leaves the box."""
    keypad = page.locator(role("keypad"))
    expect(keypad).to_be_visible()
    for how, what in strokes(text, keypad.get_attribute(ATTR.keys).split()):
        if how == "key":
            keypad.locator(role("keypad-key", f'[data-key="{what}"]')).tap()
        else:
            page.keyboard.type(what)
        expect(target).to_be_focused()


def test_a_formula_a_number_and_a_matrix_typed_tap_by_tap_are_right(page, site_url):
    page.goto(site_url + CHAPTERS[6])
    wait_runtime(page)
    assert page.evaluate("() => matchMedia('(pointer: coarse)').matches")
    keypad = page.locator(role("keypad"))
    expect(keypad).to_be_hidden()

    # A formula: θ from the row (the variables' Greek letters), ×, parentheses and + too.
    formula = exercise(page, "6.6")
    answer = formula.locator(role("answer"))
    expect(answer).to_have_attribute("inputmode", "text")
    expect(answer).to_have_attribute("enterkeyhint", "go")
    answer.tap()
    expect(keypad).to_have_attribute("role", "toolbar")
    expect(keypad).to_have_accessible_name(re.compile("symbols", re.I))
    key = keypad.locator(role("keypad-key", '[data-key="θ"]'))
    expect(key).to_have_attribute("tabindex", "-1")
    box_top = keypad.bounding_box()
    assert box_top and box_top["y"] + box_top["height"] <= 740 and box_top["width"] <= 360
    text = bank.get("6.6").answer.answer_text.replace("theta", "θ")
    tap_in(page, answer, text)
    expect(answer).to_have_value(text.replace("-", "−").replace("*", "×"))
    expect(keypad.locator('[aria-live="polite"]')).to_contain_text("closing parenthesis inserted")
    page.keyboard.press("Enter")
    assert settle(formula) == "correct"

    # A number in degrees (90°): ° from the row, inserted at the caret (not at the end).
    assert bank.get("6.3").answer.typed(bank.get("6.3").answer.key) == "90°"
    number = exercise(page, "6.3")
    answer = number.locator(role("answer"))
    answer.tap()
    page.keyboard.type("90")
    page.keyboard.press("ArrowLeft")
    keypad.locator(role("keypad-key", '[data-key="°"]')).tap()
    expect(answer).to_have_value("9°0")
    page.keyboard.press("End")
    page.keyboard.press("Backspace")
    page.keyboard.press("Backspace")
    page.keyboard.type("0")
    keypad.locator(role("keypad-key", '[data-key="°"]')).tap()
    expect(answer).to_have_value("90°")
    page.keyboard.press("Enter")
    assert settle(number) == "correct", number.locator(role("feedback")).inner_text()

    # Leaving the answers hides the row.
    page.locator("h1").first.tap()
    expect(keypad).to_be_hidden()


def test_in_a_matrix_next_moves_entry_by_entry_and_the_last_checks(page, site_url):
    ex = next(e for e in bank.all_exercises() if e.kind == "derive" and e.answer.kind == "matrix"
              and any("-" in t for _, t in cells(e.answer)) and e.answer.shape[0] * e.answer.shape[1] >= 3)
    n = int(ex.id.split(".")[0])
    page.goto(site_url + CHAPTERS[n])
    wait_runtime(page)
    el = exercise(page, ex.id)
    grid = cells(ex.answer)
    r, c = ex.answer.shape
    entry(el, 1, 1).tap()
    for (i, j), text in grid:
        target = entry(el, i, j)
        expect(target).to_be_focused()
        expect(target).to_have_attribute("enterkeyhint", "go" if (i, j) == (r, c) else "next")
        tap_in(page, target, text)
        page.keyboard.press("Enter")
    assert settle(el) == "correct", ex.id
