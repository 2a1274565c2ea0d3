"""The SCORM packages in a real SCORM runtime: scorm-again (npm) plays the LMS.

``scorm_host/host.html`` loads scorm-again's SCORM 1.2 and 2004 runtimes, sets
``window.API`` or ``window.API_1484_11``, and launches a chapter SCO of the package
(built by scripts/scorm_package.py from site/ into a temporary folder, unzipped,
served on the same origin) in its frame: the SCO's launcher (launch/ch00.html), which
holds the session and shows the chapter in a frame of its own. What the runtime stores
is what the next launch gets (``host.js``: the learner's id, suspend_data, status,
score, objectives, entry=resume).
"""

from __future__ import annotations

import hashlib
import zipfile
from pathlib import Path

import pytest

import scorm_package
from helpers import record_leaving
from site_server import SiteServer
from workbook import bank

ROOT = Path(__file__).resolve().parents[2]
SITE = ROOT / "site"
HOST = Path(__file__).resolve().parent / "scorm_host"
SCORM_AGAIN = ROOT / "node_modules" / "scorm-again" / "dist"
LAUNCHER = "launch/ch00.html"
LEARNER_ID = {"1.2": "cmi.core.student_id", "2004": "cmi.learner_id"}
SALT = "robotics-math-workbook/learner-key/v1"  # docs/assets/js/lms/launch.js
PREFIX = {"1.2": "/p12/", "2004": "/p2004/"}
LMS_ATTR = "data-workbook-lms"
CH0 = [ex.id for ex in bank.chapter(0)]


@pytest.fixture(scope="module")
def lms_server(tmp_path_factory):
    if not (SITE / "index.html").exists():
        pytest.fail("site/ is not built: run `make site` (make test does)")
    if not (SCORM_AGAIN / "scorm12.min.js").exists():
        pytest.fail("scorm-again is not installed: run `npm ci` (make test does)")
    tmp = tmp_path_factory.mktemp("scorm")
    mounts = {"/host/": HOST, "/scorm-again/": SCORM_AGAIN}
    for version, path in zip(("1.2", "2004"), scorm_package.build(SITE, tmp / "dist")):
        folder = tmp / path.stem
        with zipfile.ZipFile(path) as zf:
            zf.extractall(folder)
        mounts[PREFIX[version]] = folder
    with SiteServer(SITE, mounts=mounts) as server:
        yield server


@pytest.fixture
def lms(context, lms_server):
    return open_lms(context, lms_server)


def open_lms(context, server):
    leaving = record_leaving(context, server.url)
    page = context.new_page()
    page.set_default_timeout(30_000)
    page.js_errors = []
    page.on("pageerror", lambda err: page.js_errors.append(str(err)))
    page.goto(server.origin + "/host/host.html")
    page.leaving = leaving
    return page


def progress_key(version, learner):
    """The local record's key of `learner` in the package at PREFIX[version] (what launch.js and progress.js make)."""
    site = PREFIX[version]
    digest = hashlib.sha256(f"{SALT}\n{site}\n{learner}".encode()).hexdigest()
    return f"robotics-workbook:{site.rstrip('/')}:learner:{digest}:progress"


def launch(page, version, stored=None, refuse=None, learner="learner-a"):
    """Start the runtime with `stored` CMI data (and `learner`'s id, unless None) and launch chapter 0's SCO;
    the frame of the page the launcher shows, once that page has met the session."""
    stored = dict(stored or {})
    if learner is not None:
        stored.setdefault(LEARNER_ID[version], learner)
    page.evaluate("(a) => window.lms.start(a)", {"version": version, "href": PREFIX[version] + LAUNCHER,
                                                 "stored": stored, "refuse": refuse})
    launcher = page.wait_for_selector("#sco").content_frame()
    frame = launcher.wait_for_selector("iframe[data-workbook-sco]").content_frame()
    frame.wait_for_function("(a) => document.documentElement.getAttribute(a)", arg=LMS_ATTR, timeout=60_000)
    return frame


def ready(frame):
    frame.wait_for_function("() => document.documentElement.dataset.workbookRuntime === 'ready'", timeout=120_000)


def ex(frame, ex_id):
    return frame.locator(f'[data-exercise-id="{ex_id}"]')


def check(frame, ex_id) -> str:
    el = ex(frame, ex_id)
    el.locator('[data-role="check"]').click()
    frame.wait_for_function("el => !['pending', 'unanswered'].includes(el.dataset.state)", arg=el.element_handle(), timeout=60_000)
    return el.get_attribute("data-state")


def answer(frame, ex_id, text) -> str:
    ex(frame, ex_id).locator('[data-role="answer"]').fill(text)
    return check(frame, ex_id)


def choose(frame, ex_id, key) -> str:
    el = ex(frame, ex_id)
    el.locator("form[data-wb-ready]").wait_for(state="attached")
    el.locator(f'[data-role="choice"][value="{key}"]').check()
    return check(frame, ex_id)


def calls(page) -> dict:
    return page.evaluate("() => ({ ...window.lms.calls })")


def value(page, element) -> str:
    return page.evaluate("(e) => window.lms.value(e)", element)


def finish(page):
    page.evaluate("() => window.lms.close()")
    page.wait_for_function("() => window.lms.calls.finish > 0")


def no_trouble(page):
    assert page.js_errors == [], page.js_errors
    assert page.leaving == [], page.leaving


ELEMENTS = {
    "1.2": {"raw": "cmi.core.score.raw", "max": "cmi.core.score.max", "status": "cmi.core.lesson_status",
            "response": "student_response", "wrong": "wrong", "time": "cmi.core.session_time", "exit": "cmi.core.exit"},
    "2004": {"raw": "cmi.score.raw", "max": "cmi.score.max", "status": "cmi.completion_status",
             "response": "learner_response", "wrong": "incorrect", "time": "cmi.session_time", "exit": "cmi.exit"},
}


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_launch_report_and_resume_on_another_computer(browser, lms, lms_server, version):
    e = ELEMENTS[version]
    frame = launch(lms, version)
    assert frame.evaluate("(a) => document.documentElement.getAttribute(a)", LMS_ATTR) == "open"
    ready(frame)
    assert frame.evaluate("() => navigator.serviceWorker.getRegistrations().then((r) => r.length)") == 0
    start = calls(lms)
    assert start["init"] == 1 and start["commit"] == 1  # the chapter's state, sent once at the start

    assert answer(frame, "0.1", "3") == "correct"
    assert choose(frame, "0.3", bank.get("0.3").answer) == "correct"
    assert answer(frame, "0.6", "7") == "incorrect"
    assert calls(lms)["commit"] == start["commit"] + 3  # a commit after every check
    assert value(lms, e["raw"]) == f"{100 * 2 / len(CH0):g}" and value(lms, e["max"]) == "100"
    assert value(lms, e["status"]) == "incomplete"
    at = {i: CH0.index(i) for i in ("0.1", "0.3", "0.6")}
    assert value(lms, f"cmi.interactions.{at['0.1']}.id") == "exercise-0.1"
    assert value(lms, f"cmi.interactions.{at['0.1']}.result") == "correct"
    assert value(lms, f"cmi.interactions.{at['0.1']}.{e['response']}") == "3"
    assert value(lms, f"cmi.interactions.{at['0.6']}.result") == e["wrong"]
    assert value(lms, f"cmi.interactions.{at['0.6']}.{e['response']}") == "7"
    assert value(lms, f"cmi.interactions.{at['0.6']}.latency")
    assert value(lms, f"cmi.objectives.{at['0.3']}.id") == "exercise-0.3"
    assert value(lms, f"cmi.objectives.{at['0.3']}.score.raw") == "1"  # one clean variant of the three of mastery
    # One objective and one interaction per exercise, in the chapter's order, and no more.
    for kind in ("objectives", "interactions"):
        assert [value(lms, f"cmi.{kind}.{i}.id") for i in range(len(CH0) + 1)] == [f"exercise-{i}" for i in CH0] + [""]
    assert value(lms, e["exit"]) == "suspend"
    assert value(lms, e["time"])

    finish(lms)
    assert calls(lms)["finish"] == 1
    stored = lms.evaluate("() => window.lms.stored()")
    no_trouble(lms)
    assert stored["cmi.suspend_data"].startswith("wb1:" if version == "1.2" else "wbj:")

    # Another computer: nothing in its local storage; the LMS's data alone brings the work back,
    # before any exercise is drawn (the solved mark is on the page before the grader is ready).
    other = browser.new_context()
    try:
        page2 = open_lms(other, lms_server)
        frame2 = launch(page2, version, stored=stored)
        # An exercise's form is ready once its kind has started and put its last answer back (kinds/*.js);
        # the exercise's own data-wb-ready is set before that, as it starts (a wait on it lost a race under load).
        for shown in ("0.1", "0.3", "0.6"):
            ex(frame2, shown).locator("form[data-wb-ready]").wait_for(state="attached")
        assert ex(frame2, "0.1").get_attribute("data-state") == "correct"
        assert ex(frame2, "0.6").locator('[data-role="answer"]').input_value() == "7"
        assert ex(frame2, "0.3").locator(f'[data-role="choice"][value="{bank.get("0.3").answer}"]').is_checked()
        kept = frame2.evaluate("() => window.workbook.progress.all()")
        assert kept["0.1"]["solved"] and kept["0.6"]["attempts"] == 1 and kept["0.6"]["last"] == "7"
        ready(frame2)
        assert value(page2, e["raw"]) == f"{100 * 2 / len(CH0):g}"
        finish(page2)
        assert calls(page2)["finish"] == 1
        no_trouble(page2)
    finally:
        other.close()


def test_a_full_workbook_of_records_fits_scorm12_suspend_data(browser, lms, lms_server):
    """Every exercise solved three times, in the review queue, with a long last answer: more than
    1.2's 4,096 characters hold (131 records at their widest take 4,722), so the launched chapter's
    records travel whole and the others' as far as they fit, oldest dropped first."""
    ids = [e.id for e in bank.all_exercises()]
    lms.evaluate("""([key, ids]) => {
        const now = Date.now();
        const exercises = Object.fromEntries(ids.map((id, i) => {
            const v = 999999 - i, updated = now - (ids.length - i) * 3600000;
            return [id, { solved: true, hinted: true, attempts: 120, variant: v, done: [v - 2, v - 1, v], clean: [v - 2, v - 1, v],
              box: 5, due: updated + 21 * 86400000, reviewed: updated, updated, last: `answer ${i} `.padEnd(60, "x") }];
        }));
        localStorage.setItem(key, JSON.stringify({ version: 4, exercises }));
    }""", [progress_key("1.2", "learner-a"), ids])
    frame = launch(lms, "1.2")
    data = value(lms, "cmi.suspend_data")
    assert data.startswith("wb1:") and 3000 < len(data) <= 4096, len(data)
    assert frame.locator('[data-wb-notice="lms"]').count() == 0  # the LMS took it
    assert value(lms, "cmi.core.score.raw") == "100" and value(lms, "cmi.core.lesson_status") == "passed"
    finish(lms)
    stored = lms.evaluate("() => window.lms.stored()")
    no_trouble(lms)

    other = browser.new_context()
    try:
        page2 = open_lms(other, lms_server)
        frame2 = launch(page2, "1.2", stored=stored)
        back = frame2.evaluate("() => window.workbook.progress.all()")
        own = [i for i in ids if i.split(".")[0] == "0"]
        others = [i for i in ids if i not in own]  # oldest first, as made above
        missing = [i for i in ids if i not in back]
        assert set(own) <= set(back), "the launched chapter's records travel whole"
        assert missing == others[:len(missing)], f"only other chapters' records are dropped, oldest first: {missing}"
        assert len(back) > len(ids) // 2, len(back)
        assert all(len(r["clean"]) == 3 and r["box"] == 5 for r in back.values())  # mastered, in the top box: all of them
        # The answers travel too, as room allows: the launched chapter's (chapter 0's SCO) first, its newest kept.
        kept = [i for i in ids if "last" in back.get(i, {})]
        assert kept and all(i.split(".")[0] == "0" for i in kept), kept
        assert kept == own[len(own) - len(kept):], kept
        assert back[kept[-1]]["last"].startswith(f"answer {ids.index(kept[-1])} ")
        finish(page2)
        no_trouble(page2)
    finally:
        other.close()


@pytest.mark.parametrize(("version", "code"), [("1.2", 405), ("2004", 351)])
def test_an_lms_that_refuses_to_store_gets_a_notice_and_nothing_is_lost(lms, version, code):
    frame = launch(lms, version, refuse={"code": code, "from": 1})
    notice = frame.locator('[data-wb-notice="lms"]')
    notice.wait_for()
    assert f"error {code}" in notice.inner_text() and "Nothing is lost" in notice.inner_text()
    ready(frame)
    assert answer(frame, "0.1", "3") == "correct"
    assert calls(lms)["refused"] > 1  # tried again after the check
    assert f"error {code}" in notice.inner_text()
    kept = frame.evaluate("(k) => JSON.parse(localStorage.getItem(k)).exercises['0.1']", progress_key(version, "learner-a"))
    assert kept["solved"] and kept["last"] == "3"
    finish(lms)
    assert calls(lms)["finish"] == 1
    no_trouble(lms)


def test_a_session_the_lms_will_not_open_is_said_and_the_page_works(lms):
    """Initialize refused (a closed session, e.g. a second page opened in the same frame): a notice, and the chapter works from local storage."""
    lms.evaluate("""() => {
        const start = window.lms.start.bind(window.lms);
        window.lms.start = (a) => { start(a); window.API.LMSInitialize = () => { window.API.lastErrorCode = "101"; return "false"; }; };
    }""")
    frame = launch(lms, "1.2")
    assert frame.evaluate("(a) => document.documentElement.getAttribute(a)", LMS_ATTR) == "failed"
    assert "did not open a session" in frame.locator('[data-wb-notice="lms"]').inner_text()
    ready(frame)
    assert answer(frame, "0.1", "3") == "correct"
    assert calls(lms)["commit"] == 0
    no_trouble(lms)
