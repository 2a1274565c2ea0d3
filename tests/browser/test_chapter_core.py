"""A chapter's page starts its grader with that chapter's part of the grading package.

On a plain start (a first visit over a link where the snapshot is not worth it), the grader takes
the standard library's core compiled (scripts/split_stdlib.py), in two files: the core without the
grading package, and the package. A chapter's page names its own part of the compiled package
(docs/overrides/main.html, the worker's name): only the modules of the package that the chapter's
requests use (scripts/chapter_modules.py), the names of the others listed in it. A request that needs
one of those others (an exercise of another chapter, as the practice and class pages send) still gets
its answer: the first such import fetches the sources' core once and imports from it
(workbook_sandbox/lazy_stdlib.py); later ones fetch nothing. The sandbox starts from the same compiled
core, which the grader's start left in the HTTP cache.
"""

from __future__ import annotations

from conftest import SITE
from helpers import CHAPTERS, wait_runtime
from test_stdlib_on_demand import requests_for

BASE = "python_stdlib.core.compiled.zip"
FULL = "workbook.compiled.zip"
CHAPTER_1 = "workbook.compiled.ch1.zip"
SOURCES = "python_stdlib.core.zip"
LONG = 180_000


def grade(page, exercise: str, answer: str) -> dict:
    return page.evaluate("([e, a]) => workbook.runtime.request({op: 'grade', exercise: e, answer: a})",
                         [exercise, answer])


def test_a_chapter_starts_with_its_own_part_and_imports_the_rest_on_first_use(browser, slow_site):
    context = browser.new_context(service_workers="block")  # the worker's own requests only
    page = context.new_page()
    try:
        base, full, own, sources = (requests_for(page, name) for name in (BASE, FULL, CHAPTER_1, SOURCES))
        page.goto(slow_site.url + CHAPTERS[1])
        wait_runtime(page, timeout=LONG)
        stages = page.evaluate("workbook.runtime.startStages")
        assert stages["snapshot"] == "skipped: a slow link" and stages["stdlib"] == "compiled", stages
        assert (len(base), len(own), full, sources) == (1, 1, [], []), (base, own, full, sources)

        # The chapter's own exercises grade from its part: nothing more is fetched.
        mine = grade(page, "1.1", "1")
        assert mine["ok"] and mine["value"]["status"] in ("correct", "incorrect"), mine
        assert sources == []

        # Another chapter's exercise: its module is not in chapter 1's core; the sources' core is
        # fetched once, and the verdict is the one the whole package gives.
        other = grade(page, "5.1", "1")
        assert other["ok"] and other["value"]["status"] in ("correct", "incorrect"), other
        assert len(sources) == 1, sources
        again = grade(page, "9.2", "1")
        assert again["ok"], again
        assert len(sources) == 1 and full == [], (sources, full)
    finally:
        context.close()


PLAIN = (
    "import math\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (c * x - s * y, s * x + c * y)\n"
)


def test_on_a_plain_start_the_sandbox_starts_compiled_from_the_grader_s_file(browser):
    """The sandbox's Python takes the same rule as the grader's (boot.js): on a link where its snapshot
    is not worth it but the compiled files are, it starts from the grader's compiled core (which holds
    no grading package), and runs code. Served as GitHub Pages serves (max-age=600), the file comes
    over the link once: the sandbox's request for it is answered by the HTTP cache."""
    from helpers import exercise, run_build, set_editor
    from site_server import Link, SiteServer

    with SiteServer(SITE, link=Link("test-8mbps", 8e6, 40), cache_control="max-age=600") as server:
        server.precompress()
        context = browser.new_context(service_workers="block")
        page = context.new_page()
        try:
            asked = requests_for(page, BASE)
            mark = server.mark()
            page.goto(server.url + CHAPTERS[0])
            wait_runtime(page, timeout=LONG)
            ex = exercise(page, "0.5")
            set_editor(page, ex, PLAIN)
            assert run_build(ex, timeout=LONG) == "correct"
            stages = page.evaluate("window.workbook.sandbox.startStages")
            assert stages["from"] == "boot" and stages["stdlib"] == "compiled", stages
            assert len(asked) == 2, asked  # the grader's and the sandbox's
            served = [e for e in server.since(mark) if e["path"].endswith("/" + BASE)]
            assert len(served) == 1, served
        finally:
            context.close()
