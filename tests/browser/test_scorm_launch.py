"""One learner, one record, one session, grades an LMS reads right: the SCORM packages'
launchers (launch/chNN.html, docs/assets/js/lms/launch.js) in scorm-again as the LMS.

- Two learners of one browser profile (a shared lab computer) each keep their own record:
  learner B's first launch shows none of A's solves, reports none of A's score and sends
  none of A's answers; the hosted site's record (no learner key) is never read.
- No learner id from the LMS: the record is kept in memory only, and the page says so.
- A fully solved chapter under a mastery score of 80 ends passed (raw 100 of 100).
- One session per launch: a check, a link to another chapter, back, another check: the
  LMS's score rises in the same session; Initialize and Terminate are each called once.
"""

from __future__ import annotations

import json

import pytest

import test_scorm
from test_scorm import CH0, PREFIX, answer, calls, choose, ex, finish, launch, no_trouble, progress_key, ready, value
from workbook import bank

# test_scorm.py's fixtures: the packages built from site/ and unzipped (once for this module), the test LMS page.
lms_server = test_scorm.lms_server
lms = test_scorm.lms

RAW = {"1.2": "cmi.core.score.raw", "2004": "cmi.score.raw"}
RESPONSE = {"1.2": "student_response", "2004": "learner_response"}
MASTERY = {"1.2": ("cmi.student_data.mastery_score", "80"), "2004": ("cmi.scaled_passing_score", "0.8")}
STATUS = {"1.2": "cmi.core.lesson_status", "2004": "cmi.success_status"}


def shown_solved(frame) -> int:
    for i in ("0.1", "0.2", "0.3", "0.6"):
        ex(frame, i).locator("form[data-wb-ready]").wait_for(state="attached")
    return frame.evaluate("() => document.querySelectorAll('[data-exercise-id][data-state=correct]').length")


def responses(page, version) -> list[str]:
    return [r for r in (value(page, f"cmi.interactions.{i}.{RESPONSE[version]}") for i in range(len(CH0))) if r]


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_two_learners_on_one_browser_each_keep_their_own_record(lms, version):
    # Someone used the hosted site's copy at this address before: an LMS page never reads that record.
    lms.evaluate("([k]) => localStorage.setItem(k, JSON.stringify({ version: 5, exercises: { '0.2': { solved: true, "
                 "attempts: 1, done: [0], variant: 0, last: 'site', updated: Date.now() } } }))",
                 [f"robotics-workbook:{PREFIX[version].rstrip('/')}:progress"])
    frame = launch(lms, version, learner="alice-0042")
    ready(frame)
    assert shown_solved(frame) == 0  # not the hosted site's 0.2
    assert answer(frame, "0.1", "3") == "correct"
    assert choose(frame, "0.3", bank.get("0.3").answer) == "correct"
    assert answer(frame, "0.6", "7") == "incorrect"
    a_raw = value(lms, RAW[version])
    assert a_raw == f"{100 * 2 / len(CH0):g}"
    finish(lms)
    a_stored = lms.evaluate("() => window.lms.stored()")
    a_text = a_stored["cmi.suspend_data"]

    # Learner B, the same browser profile, a first launch (the LMS holds nothing for B).
    frame = launch(lms, version, learner="bob-0043")
    ready(frame)
    before = {"solved": shown_solved(frame), "raw": value(lms, RAW[version]), "answers": responses(lms, version)}
    assert before == {"solved": 0, "raw": "0", "answers": []}, before
    assert frame.evaluate("() => Object.keys(window.workbook.progress.all()).length") == 0
    assert value(lms, "cmi.suspend_data") == {"1.2": "wb1:AAA", "2004": "wbj:{}"}[version] != a_text  # an empty record
    finish(lms)

    # A again, on this computer: A's own record is back (from this browser and the LMS alike).
    frame = launch(lms, version, stored=a_stored, learner=None)
    ready(frame)
    assert shown_solved(frame) == 2 and value(lms, RAW[version]) == a_raw
    finish(lms)

    # The LMS's learner ids are never stored in this browser: only their keys, hashed.
    store = lms.evaluate("() => JSON.stringify(Object.entries(localStorage))")
    assert "alice-0042" not in store and "bob-0043" not in store
    assert progress_key(version, "alice-0042").split(":")[3] in store
    no_trouble(lms)


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_no_learner_id_keeps_the_record_in_memory_and_says_so(lms, version):
    frame = launch(lms, version, learner=None)
    notice = frame.locator('[data-wb-notice="progress-memory"]')
    notice.wait_for()
    assert "did not say who you are" in notice.inner_text()
    ready(frame)
    assert answer(frame, "0.1", "3") == "correct"
    assert value(lms, RAW[version]) == f"{100 / len(CH0):g}"  # still reported to the LMS
    assert lms.evaluate("() => Object.keys(localStorage).filter((k) => k.includes(':progress'))") == []
    finish(lms)
    no_trouble(lms)


@pytest.mark.parametrize("version", ["1.2", "2004"])
@pytest.mark.parametrize(("solved", "status"), [(len(CH0), "passed"), (1, "failed")])
def test_under_a_mastery_score_of_80_a_solved_chapter_passes_and_less_fails(lms, version, solved, status):
    now = lms.evaluate("() => Date.now()")
    records = {i: {"solved": True, "attempts": 1, "done": [0], "clean": [0], "variant": 0, "updated": now - 1000} for i in CH0[:solved]}
    element, mastery = MASTERY[version]
    frame = launch(lms, version, stored={element: mastery, "cmi.suspend_data": "wbj:" + json.dumps(records)})
    ready(frame)
    finish(lms)  # the LMS's own rule runs at LMSFinish/Terminate too (scorm-again compares raw or scaled with mastery)
    assert value(lms, RAW[version]) == f"{100 * solved / len(CH0):g}"
    assert value(lms, STATUS[version]) == status
    if version == "2004":
        assert value(lms, "cmi.score.scaled") == f"{solved / len(CH0):g}"
    no_trouble(lms)


@pytest.mark.parametrize("version", ["1.2", "2004"])
def test_a_link_to_another_chapter_and_back_keeps_reporting_in_the_same_session(lms, version):
    frame = launch(lms, version)
    ready(frame)
    assert answer(frame, "0.1", "3") == "correct"
    first = value(lms, RAW[version])
    assert first == f"{100 / len(CH0):g}"
    chapter0 = frame.url
    frame.goto(chapter0.replace("00-rotations-2d", "01-transforms"))
    frame.wait_for_function("() => document.documentElement.dataset.workbookLms === 'open'")
    ready(frame)
    frame.goto(chapter0)
    frame.wait_for_function("() => document.documentElement.dataset.workbookLms === 'open'")
    ready(frame)
    assert ex(frame, "0.1").get_attribute("data-state") == "correct"  # the learner's own record, kept
    assert choose(frame, "0.3", bank.get("0.3").answer) == "correct"
    assert value(lms, RAW[version]) == f"{100 * 2 / len(CH0):g}"  # rose, in the same launch
    assert calls(lms)["init"] == 1 and calls(lms)["finish"] == 0
    assert frame.locator('[data-wb-notice="lms"]').count() == 0
    finish(lms)
    assert calls(lms)["init"] == 1 and calls(lms)["finish"] == 1
    no_trouble(lms)


def test_a_page_an_lms_opens_without_the_launcher_keeps_nothing_and_says_so(lms):
    """An LMS frame showing a chapter page directly (an old package's launch href): no session, memory only."""
    lms.evaluate("(a) => window.lms.start(a)", {"version": "1.2", "href": PREFIX["1.2"] + "chapters/00-rotations-2d/index.html",
                                                "stored": {"cmi.core.student_id": "carol"}, "refuse": None})
    frame = lms.wait_for_selector("#sco").content_frame()
    frame.wait_for_function("() => document.documentElement.dataset.workbookLms === 'failed'")
    assert "without the workbook's launcher" in frame.locator('[data-wb-notice="lms"]').inner_text()
    ready(frame)
    assert answer(frame, "0.1", "3") == "correct"
    assert calls(lms)["init"] == 0 and calls(lms)["set"] == 0
    assert lms.evaluate("() => Object.keys(localStorage).filter((k) => k.includes(':progress'))") == []
    no_trouble(lms)


def test_packaged_pages_name_no_build_host(lms, lms_server):
    for version, prefix in PREFIX.items():
        for path in ("chapters/00-rotations-2d/index.html", "index.html", "launch/ch00.html"):
            text = lms.request.get(lms_server.origin + prefix + path).text()
            assert "<title>" in text and 'rel="canonical"' not in text, (version, path)
