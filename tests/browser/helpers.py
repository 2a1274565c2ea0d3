"""Small helpers over the page contract (CONTRACT.md; names from workbook/contract.json)."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from urllib.parse import urlsplit

from playwright.sync_api import Locator, Page

from workbook.contract import ATTR, ROLE
from workbook.number_format import fmt


def role(name: str, extra: str = "") -> str:
    """A CSS selector for the contract role ``name`` (raises for a role the contract lacks)."""
    if name.replace("-", "_") not in vars(ROLE):
        raise KeyError(f"no role {name!r} in the contract")
    return f'[{ATTR.role}="{name}"]{extra}'

# every chapter page, by its number, from the pages themselves (docs/chapters/NN-slug.md)
CHAPTERS = {int(page.name[:2]): f"chapters/{page.stem}/"
            for page in sorted((Path(__file__).resolve().parents[2] / "docs" / "chapters").glob("[0-9][0-9]-*.md"))}


def open_chapter(page: Page, site_url: str, n: int, wait_ready: bool = True) -> None:
    page.goto(site_url + CHAPTERS[n])
    if wait_ready:
        wait_runtime(page)


def go_instantly(page: Page, site_url: str, n: int) -> None:
    """Open chapter ``n`` from the page the tab is on by mkdocs-material's instant navigation (a
    same-document swap, as a learner's click on a link makes): the grader the tab booted keeps
    running, so a test that visits many chapters boots Python once. Returns when every exercise
    of the new page has started and the grader is ready."""
    url = site_url + CHAPTERS[n]
    page.evaluate("() => { window.__sameDocument = true; }")
    page.evaluate("u => { const a = document.createElement('a'); a.href = u; document.body.append(a); a.click(); a.remove(); }",
                  url)
    page.wait_for_url(url)
    page.wait_for_function(
        "p => { const els = [...document.querySelectorAll('[data-exercise-id]')];"
        " return els.length > 0 && els.every(e => e.dataset.exerciseId.startsWith(p) && e.dataset.wbReady); }",
        arg=f"{n}.")
    assert page.evaluate("() => window.__sameDocument === true"), "expected an instant (same-document) navigation"
    wait_runtime(page)


def check_while_loading(page: Page, site_url: str) -> Locator:
    """Open chapter 0 and press Check on 0.1 (answered 3) while the grader is still loading;
    returns the exercise."""
    page.goto(site_url + CHAPTERS[0], wait_until="commit")
    ex = exercise(page, "0.1")
    ex.locator(role("answer")).fill("3", timeout=180_000)  # a slow link: the page takes a while
    assert page.evaluate("a => document.documentElement.getAttribute(a)", ATTR.runtime) == "loading"
    ex.locator(role("check")).click()
    return ex


def wait_runtime(page: Page, state: str = "ready", timeout: float = 120_000) -> None:
    # Generous: on a 2-core machine busy with other work, booting Python can take over a minute.
    page.wait_for_function(
        "s => document.documentElement.dataset.workbookRuntime === s", arg=state, timeout=timeout
    )


def exercise(page: Page, ex_id: str) -> Locator:
    return page.locator(f'[data-exercise-id="{ex_id}"]')


def settle(ex: Locator, timeout: float = 30_000) -> str:
    """Wait until the exercise is no longer pending; return its state."""
    ex.page.wait_for_function(
        "el => el.dataset.state !== 'pending'", arg=ex.element_handle(), timeout=timeout
    )
    return ex.get_attribute("data-state")


def check(ex: Locator, timeout: float = 30_000) -> str:
    ex.locator('[data-role="check"]').click()
    return settle(ex, timeout)


def answer_derive(ex: Locator, text: str) -> str:
    ex.locator('[data-role="answer"]').fill(text)
    return check(ex)


def widget_ready(ex: Locator) -> None:
    """Wait until the exercise's widget has started (its form is marked ready): a click before that selects nothing."""
    ex.locator("form[data-wb-ready]").wait_for(state="attached")


def before_the_widget(page: Page, chunk: str, go: Callable[[], object], act: Callable[[], object]) -> None:
    """Open a page (``go``) with the widget's script (``chunk``, its bundle chunk) held back, do
    what the learner does meanwhile (``act``), then let the script load."""
    held = []
    pattern = f"**/chunks/{chunk}-*.js"
    page.route(pattern, lambda route: held.append(route))
    go()
    act()
    # The page asks for the chunk when its script gets to it, which may come after `act` on a fast run: the
    # learner's work is done by then either way (the chunk is held until now), so wait for the request.
    for _ in range(600):
        if held:
            break
        page.wait_for_timeout(50)  # Playwright's route handlers run while it waits
    assert held, f"the {chunk} widget's script was not held back"
    for route in held:
        route.continue_()
    page.unroute(pattern)


def graded(page: Page, el: Locator) -> str:
    """The exercise's state once a held Check has been graded."""
    page.wait_for_function("el => ['correct', 'incorrect', 'invalid'].includes(el.dataset.state)",
                           arg=el.element_handle(), timeout=120_000)
    return el.get_attribute(ATTR.state)


def answer_trace(ex: Locator, key: str) -> str:
    widget_ready(ex)
    ex.locator(f'[data-role="choice"][value="{key}"]').check()
    return check(ex)


def answer_debug(ex: Locator, line: int) -> str:
    widget_ready(ex)
    ex.locator(f'[data-role="line"][data-line="{line}"]').click()
    return check(ex)


def arrange_design(ex: Locator, order: list[str]) -> None:
    """Reorder the steps with the move-up buttons (the keyboard path)."""
    widget_ready(ex)
    for target, key in enumerate(order):
        while True:
            keys = ex.locator('[data-role="step"]').evaluate_all("els => els.map(e => e.dataset.step)")
            pos = keys.index(key)
            if pos == target:
                break
            ex.locator(f'[data-role="step"][data-step="{key}"] [data-role="move-up"]').click()


# A Build exercise's editor host gets wbOpenEditor when its widget starts (kinds/build.js). That is
# later than the exercise's own data-wb-ready, which is set when the widget's module starts loading.
EDITORS_STARTED = """() => [...document.querySelectorAll('[data-role=editor]')]
  .every((host) => typeof host.wbOpenEditor === 'function')"""
EDITOR_STARTED = "el => typeof el.querySelector('[data-role=editor]')?.wbOpenEditor === 'function'"


def editor_started(ex: Locator, timeout: float = 60_000) -> None:
    """Wait until the exercise's Build widget has started (its editor can be opened)."""
    ex.page.wait_for_function(EDITOR_STARTED, arg=ex.element_handle(), timeout=timeout)


def open_all_editors(page: Page, timeout: float = 60_000) -> None:
    """Build every editor on the page now, once every Build widget has started."""
    page.wait_for_function(EDITORS_STARTED, timeout=timeout)
    page.evaluate("() => Promise.all([...document.querySelectorAll('[data-role=editor]')].map((h) => h.wbOpenEditor())).then(() => null)")


def open_editor(ex: Locator) -> None:
    """Build the exercise's CodeMirror editor now (the page builds it lazily)."""
    editor_started(ex)
    ex.evaluate("el => el.querySelector('[data-role=editor]').wbOpenEditor().then(() => null)")  # not the editor: serialising it back costs ~0.3 s
    ex.locator(".cm-editor").wait_for()


def set_editor(page: Page, ex: Locator, code: str) -> None:
    """The exercise's code, typed into the editor it opens (in one step: the editor set is the one
    that was opened, whatever the page did between two of Playwright's calls)."""
    editor_started(ex)
    ex.evaluate("(el, code) => el.querySelector('[data-role=editor]').wbOpenEditor().then((ed) => { ed.setCode(code); })",
                code)


def editor_code(ex: Locator) -> str:
    editor_started(ex)
    return ex.evaluate("el => el.querySelector('[data-role=editor]').wbOpenEditor().then((ed) => ed.getCode())")


def run_build(ex: Locator, timeout: float = 60_000) -> str:
    """Run a Build exercise; its verdict, once its run figure (if it has one) is the new run's too: the
    figure comes after the verdict, and is marked busy (aria-busy) until then."""
    ex.locator('[data-role="run"]').click()
    state = settle(ex, timeout)
    ex.page.wait_for_function("el => !el.querySelector('[data-role=\"run-figure\"][aria-busy=\"true\"]')",
                              arg=ex.element_handle(), timeout=timeout)
    return state


def feedback(ex: Locator) -> str:
    """The verdict as the learner reads it: on screen (an exercise off screen is not rendered,
    ``content-visibility: auto``, and has no rendered text until it comes near the viewport)."""
    box = ex.locator('[data-role="feedback"]')
    box.scroll_into_view_if_needed()
    # Scrolled to, it is rendered from the next frame on: wait for that (a box that is not shown at
    # all, an empty verdict, is read as it is).
    box.page.wait_for_function("el => !el.checkVisibility() || el.checkVisibility({ contentVisibilityAuto: true })",
                               arg=box.element_handle())
    return box.inner_text()


def fill_matrix(ex: Locator, rows: list[list[str]]) -> None:
    """Type each entry of a vector or matrix answer."""
    for i, row in enumerate(rows, start=1):
        for j, text in enumerate(row, start=1):
            ex.locator(f'[data-role="entry"][data-row="{i}"][data-col="{j}"]').fill(text)


def entry(ex: Locator, row: int, col: int) -> Locator:
    """The input of entry (row, col), 1-based, of a vector or matrix answer."""
    return ex.locator(role("entry", f'[{ATTR.row}="{row}"][{ATTR.col}="{col}"]'))


def entry_values(ex: Locator) -> list[list[str]]:
    """What the grid's entries hold, row by row."""
    cells = ex.locator(role("entry")).evaluate_all(
        "(els, a) => els.map(e => [Number(e.getAttribute(a.row)), Number(e.getAttribute(a.col)), e.value])",
        {"row": ATTR.row, "col": ATTR.col})
    rows = max(r for r, _, _ in cells)
    cols = max(c for _, c, _ in cells)
    grid = [[""] * cols for _ in range(rows)]
    for r, c, v in cells:
        grid[r - 1][c - 1] = v
    return grid


def marked_entries(ex: Locator) -> set[tuple[int, int]]:
    """The (row, col) of every entry marked aria-invalid="true"."""
    cells = ex.locator(role("entry", '[aria-invalid="true"]')).evaluate_all(
        "(els, a) => els.map(e => [Number(e.getAttribute(a.row)), Number(e.getAttribute(a.col))])",
        {"row": ATTR.row, "col": ATTR.col})
    return {(r, c) for r, c in cells}


def focused_entry(page: Page) -> tuple[int, int] | None:
    """(row, col) of the entry that has the keyboard focus, or None."""
    got = page.evaluate(
        "a => { const e = document.activeElement; return e && e.getAttribute(a.role) === a.entry"
        " ? [Number(e.getAttribute(a.row)), Number(e.getAttribute(a.col))] : null; }",
        {"role": ATTR.role, "entry": ROLE.entry, "row": ATTR.row, "col": ATTR.col})
    return tuple(got) if got else None


def paste(target: Locator, text: str) -> None:
    """Paste ``text`` into an input as the clipboard would: a ClipboardEvent carrying a DataTransfer.

    A synthetic paste inserts nothing by itself, so it waits until the widget listens: the
    exercise's form is marked ready once its kind's script has started (exercise.js)."""
    target.page.wait_for_function("el => el.closest('form')?.dataset.wbReady === 'true'", arg=target.element_handle())
    target.focus()
    target.evaluate(
        "(el, text) => { const data = new DataTransfer(); data.setData('text/plain', text);"
        " el.dispatchEvent(new ClipboardEvent('paste', {clipboardData: data, bubbles: true, cancelable: true})); }",
        text)


def formula_reading(ex: Locator) -> Locator:
    """Where a formula answer shows how it was read: the first element the answer input is described by."""
    first = ex.locator(role("answer")).get_attribute("aria-describedby").split()[0]
    return ex.page.locator(f"#{first}")


def reveal(ex: Locator) -> Locator:
    """Open the derivation; return its panel."""
    ex.locator(role("reveal")).click()
    panel = ex.locator(role("solution-panel"))
    panel.wait_for(state="visible")
    return panel


def solve(page: Page, ex) -> str:
    """Answer exercise ``ex`` (from the bank) correctly in the page; return the state it ends in."""
    el = exercise(page, ex.id)
    el.scroll_into_view_if_needed()
    if ex.kind == "derive":
        if ex.answer_kind == "matrix":
            fill_matrix(el, [[fmt(v) for v in row] for row in ex.answer.cleaned])
            return check(el)
        return answer_derive(el, ex.worked_text())
    if ex.kind == "trace":
        return answer_trace(el, ex.answer)
    if ex.kind == "debug":
        return answer_debug(el, ex.bug_line)
    if ex.kind == "design":
        arrange_design(el, list(ex.solution))
        return check(el)
    set_editor(page, el, ex.solution)
    return run_build(el)


def record_leaving(context, url: str) -> list[str]:
    """Record every request of ``context`` that leaves ``url``'s origin (the browser itself cannot
    resolve any other host: conftest's launch arguments). Unlike :func:`keep_to_origin` this leaves
    the browser's HTTP cache on, as a learner's browser has it."""
    origin = "{0.scheme}://{0.netloc}".format(urlsplit(url))
    leaving: list[str] = []

    def seen(request):
        if not request.url.startswith((origin, "data:", "blob:")):
            leaving.append(request.url)

    context.on("request", seen)
    return leaving


def keep_to_origin(context, url: str) -> list[str]:
    """Abort every request of ``context`` that leaves ``url``'s origin; the list records them.
    Routing every request turns the browser's HTTP cache off: the offline tests want exactly that
    (what is stored for offline use must come from the site's own copy, not from that cache)."""
    origin = "{0.scheme}://{0.netloc}".format(urlsplit(url))
    blocked: list[str] = []

    def guard(route):
        if route.request.url.startswith((origin, "data:", "blob:")):
            route.continue_()
        else:
            blocked.append(route.request.url)
            route.abort()

    context.route("**/*", guard)
    return blocked


def network_is_off(page: Page) -> bool:
    """Whether the page's network is really gone: a request outside the service
    worker's scope (the site sits under a sub-path) fails. ``navigator.onLine``
    does not say: recent Chromium leaves it true under Playwright's offline mode."""
    return page.evaluate(
        "() => fetch('/?offline-probe=' + Math.random(), {cache: 'no-store'}).then(() => false, () => true)")
