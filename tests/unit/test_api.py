"""The worker's entry point never raises and always answers in the one envelope shape."""

import json

from workbook.api import HANDLERS, handle
from workbook.contract import ERRORS, OPS, STATUSES


def call(request):
    out = json.loads(handle(json.dumps(request) if not isinstance(request, str) else request))
    if out["ok"]:
        assert set(out) == {"ok", "value"}
    else:
        assert set(out) == {"ok", "error"} and set(out["error"]) == {"kind", "message"}
        assert out["error"]["kind"] in ERRORS and out["error"]["message"]
    return out


def test_every_op_of_the_contract_has_one_handler():
    assert set(HANDLERS) == set(OPS)


def test_grade_and_run_answer_with_a_verdict():
    for request, status in (
        ({"op": "grade", "exercise": "0.1", "answer": "3"}, "correct"),
        ({"op": "grade", "exercise": "0.3", "answer": "a"}, "incorrect"),
        ({"op": "grade", "exercise": "0.1", "answer": ""}, "invalid"),
        ({"op": "run", "exercise": "0.5", "code": "def rotate_2d(x, y, t):\n    return x, y\n"}, "incorrect"),
    ):
        value = call(request)["value"]
        assert set(value) == {"status", "message", "tag", "data"} and value["status"] in STATUSES
        assert value["status"] == status


def test_bad_requests_get_an_error_envelope():
    cases = [
        ({"op": "grade", "exercise": "99.1", "answer": "3"}, "unknown-exercise"),
        ({"op": "grade", "exercise": None}, "unknown-exercise"),
        ({"op": "nope"}, "bad-request"),
        ({"op": "ping"}, "bad-request"),
        ({"op": "run", "exercise": "0.1", "code": ""}, "wrong-op"),
        ({"op": "grade", "exercise": "0.5", "answer": "def f(): pass"}, "wrong-op"),  # Build runs only through "run"
        ("not json", "bad-request"),  # issue 21: malformed is a bad request, not "internal"
        ("[1, 2]", "bad-request"),
    ]
    for request, kind in cases:
        assert call(request)["error"]["kind"] == kind, request


def test_an_answer_over_the_cap_is_an_invalid_verdict_the_page_shows():
    """Issue 26: 10,001 characters typed or pasted came back as a request error, which the page cannot
    show as the exercise's feedback."""
    from workbook import bank
    from workbook.api import ANSWER_CAP
    long = "1" * (ANSWER_CAP + 1)
    derive = {ex.answer_kind: ex.id for ex in bank.all_exercises() if ex.kind == "derive"}
    for kind, ex_id in derive.items():
        answer = long if kind != "matrix" else [[long] * len(row) for row in bank.get(ex_id).answer.key]
        for sent in (answer, long):
            value = call({"op": "grade", "exercise": ex_id, "answer": sent})["value"]
            assert value["status"] == "invalid" and "too long" in value["message"], (kind, value)
        read = call({"op": "read", "exercise": ex_id, "answer": long})["value"]
        assert "too long" in read["message"]
        stepped = next(ex for ex in bank.all_exercises() if ex.kind == "derive" and ex.steps)
        value = call({"op": "grade", "exercise": stepped.id, "answer": long, "step": stepped.steps[0].name})["value"]
        assert value["status"] == "invalid" and "too long" in value["message"]
    earlier = call({"op": "grade", "exercise": "7.2", "answer": "1", "given": {"7.1": {"answer": long, "variant": 0}}})
    assert earlier["error"]["kind"] == "bad-request" and "earlier answer" in earlier["error"]["message"]
