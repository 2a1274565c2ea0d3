"""The standard library beyond the core is fetched on first use, not before ready.

The worker starts with the core (scripts/split_stdlib.py). A Build run that
imports a module of the rest gets it fetched before the run starts; an import
the page cannot see (``__import__``) fetches it synchronously inside Python
(workbook/lazy_stdlib.py). Either way the run passes, and the rest is fetched
once.
"""

from __future__ import annotations

from helpers import exercise, open_chapter, run_build, set_editor

REST = "python_stdlib.rest.zip"
CODE = (
    "import math\n{imp}\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (statistics.fmean([c * x - s * y]), s * x + c * y)\n"
)


def requests_for(page, name: str) -> list[str]:
    seen: list[str] = []
    page.on("request", lambda r: seen.append(r.url) if r.url.endswith(name) else None)
    page.context.on("request", lambda r: seen.append(r.url) if r.url.endswith(name) else None)
    return seen


def test_an_import_of_the_rest_fetches_it_once_before_the_run(page, site_url):
    seen = requests_for(page, REST)
    open_chapter(page, site_url, 0)
    assert seen == [], "the rest of the standard library was fetched before it was needed"
    ex = exercise(page, "0.5")
    set_editor(page, ex, CODE.format(imp="import statistics"))
    assert run_build(ex) == "correct"
    assert len(set(seen)) == 1
    set_editor(page, ex, CODE.format(imp="import statistics, fractions"))
    assert run_build(ex) == "correct"
    assert page.evaluate("workbook.runtime.request({op: 'grade', exercise: '0.1', answer: '3'})")["ok"]


def test_an_import_the_page_cannot_see_still_works(page, site_url):
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, CODE.format(imp="statistics = __import__('statistics')"))
    assert run_build(ex) == "correct"
    assert page.js_errors == []
