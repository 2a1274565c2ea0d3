"""Issue 48: the 3-D figure (chapter 10's chain of frames) turns by dragging across it, with a
mouse or a finger, and its labels are never selected on the way; its slider (the keyboard's
way to turn it) follows the drag, and the keyboard still turns it."""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from helpers import CHAPTERS, role, wait_runtime
from workbook.contract import ATTR
from workbook.figures import get

FIGURE = get("poses-3d")
VIEW = next(c for c in FIGURE.controls if c.name == FIGURE.orbit)


@pytest.fixture(scope="module")
def browser_context_args(browser_context_args):
    return {**browser_context_args, "viewport": {"width": 360, "height": 740}, "has_touch": True}


def drag(page, canvas, dx: float, pointer: str) -> None:
    """A drag of ``dx`` px sideways across the middle of the canvas, as pointer events of that type."""
    page.evaluate(
        """([el, dx, type]) => {
          const r = el.getBoundingClientRect();
          const y = r.top + r.height / 2, x0 = r.left + r.width / 2 - dx / 2;
          const target = document.elementFromPoint(x0, y);
          if (!el.contains(target)) throw new Error(`the drag starts on ${target?.outerHTML.slice(0, 60)}`);
          const at = (name, x) => target.dispatchEvent(new PointerEvent(name, { bubbles: true, cancelable: true,
            composed: true, pointerId: 7, pointerType: type, isPrimary: true, button: 0, buttons: name === "pointerup" ? 0 : 1,
            clientX: x, clientY: y }));
          at("pointerdown", x0);
          for (let k = 1; k <= 8; k++) at("pointermove", x0 + (dx * k) / 8);
          at("pointerup", x0 + dx);
        }""",
        [canvas.element_handle(), dx, pointer])


def test_the_3d_figure_turns_by_drag_and_touch_and_by_keyboard(page, site_url):
    assert FIGURE.orbit == "view"
    page.goto(site_url + CHAPTERS[10])
    wait_runtime(page)
    fig = page.locator(role("figure", f'[{ATTR.figure}="poses-3d"]'))
    canvas = fig.locator(role("figure-canvas"))
    canvas.evaluate("el => el.scrollIntoView({ block: 'center' })")
    slider = fig.locator(f'input[{ATTR.param}="view"]')
    expect(canvas).to_have_attribute(ATTR.orbit, "view")
    style = canvas.evaluate("el => { const s = getComputedStyle(el); return [s.touchAction, s.userSelect]; }")
    assert style == ["pan-y", "none"], style  # a sideways drag is the figure's, a vertical swipe scrolls
    assert float(slider.input_value()) == VIEW.default

    width = canvas.bounding_box()["width"]
    before = canvas.inner_html()
    drag(page, canvas, width / 4, "mouse")  # a quarter of the width: a quarter turn, grabbed
    expect(slider).to_have_value(f"{VIEW.default - 90:g}")
    expect(slider).to_have_attribute("aria-valuetext", f"{VIEW.default - 90:g}°")
    expect(fig).to_have_attribute(ATTR.state, "ready")
    assert canvas.inner_html() != before, "the picture was not redrawn"
    assert page.evaluate("() => String(getSelection())") == "", "the drag selected the labels"

    drag(page, canvas, -width / 2, "touch")  # back, and past: round and round, within the slider
    expect(slider).to_have_value(f"{VIEW.default + 90:g}")
    drag(page, canvas, -width / 2, "pen")
    want = (VIEW.default + 270 - VIEW.min) % 360 + VIEW.min
    expect(slider).to_have_value(f"{want:g}")

    slider.focus()  # the keyboard's way still turns it
    page.keyboard.press("ArrowRight")
    expect(slider).to_have_value(f"{want + VIEW.step:g}")
    expect(fig.locator(role("control-value")).nth(2)).to_have_text(f"{want + VIEW.step:g}°")
