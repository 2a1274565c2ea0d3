"""The standard library beyond the core is fetched on first use, not before ready.

The grader starts with the core (scripts/split_stdlib.py) and mounts the rest
the first time an import asks for it (workbook_sandbox/lazy_stdlib.py); grading
never does. Build code runs in the sandbox, whose Python is the same core
without the grading package (python_stdlib.sandbox.zip,
scripts/sandbox_files.py) and mounts the same rest the same way: ahead of a run
whose imports need it (outside the run's time limit), or when an import the
page cannot see asks for it. A first Build run that needs none of it fetches
none of it.
"""

from __future__ import annotations

from helpers import exercise, open_chapter, run_build, set_editor

REST = "python_stdlib.rest.zip"
SANDBOX = "python_stdlib.sandbox.zip"
CODE = (
    "import math\n{imp}\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (statistics.fmean([c * x - s * y]), s * x + c * y)\n"
)
PLAIN = (
    "import math\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (c * x - s * y, s * x + c * y)\n"
)


def requests_for(page, name: str, service_worker: bool = True) -> list[str]:
    """The requests for ``name``, each once (a worker's is reported to both the page and the
    context); with ``service_worker=False`` not those of the offline copy."""
    seen: list[str] = []
    noted: list = []  # the requests themselves (kept, so no two are ever the same object)

    def note(r):
        if r.url.endswith(name) and (service_worker or r.service_worker is None) and not any(r is n for n in noted):
            noted.append(r)
            seen.append(r.url)
    page.on("request", note)
    page.context.on("request", note)
    return seen


def test_an_import_of_the_rest_runs_in_the_sandbox_and_the_grader_fetches_nothing(page, site_url):
    seen = requests_for(page, REST, service_worker=False)
    sandbox = requests_for(page, SANDBOX, service_worker=False)
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, PLAIN)
    assert run_build(ex) == "correct"
    assert seen == [], "the rest of the standard library was fetched before it was needed"
    set_editor(page, ex, CODE.format(imp="import statistics"))
    assert run_build(ex) == "correct"
    set_editor(page, ex, CODE.format(imp="import statistics, fractions"))
    assert run_build(ex) == "correct"
    assert page.evaluate("workbook.runtime.request({op: 'grade', exercise: '0.1', answer: '3'})")["ok"]
    # once, by the sandbox: a fetch by the grader would be a second request (the cache's too)
    assert len(seen) == 1 and len(sandbox) == 1


def test_an_import_the_page_cannot_see_still_works(page, site_url):
    seen = requests_for(page, REST, service_worker=False)
    open_chapter(page, site_url, 0)
    ex = exercise(page, "0.5")
    set_editor(page, ex, CODE.format(imp="statistics = __import__('statistics')"))
    assert run_build(ex) == "correct"
    assert len(seen) == 1  # the finder's own fetch, in the run
    assert page.js_errors == []
