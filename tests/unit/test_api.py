"""The worker's entry point never raises and always answers in the one result shape."""

import json

from workbook.api import handle


def call(request):
    out = json.loads(handle(json.dumps(request) if not isinstance(request, str) else request))
    assert set(out) == {"status", "message", "tag", "data"}
    return out


def test_grade_and_run():
    assert call({"op": "grade", "exercise": "0.1", "answer": "3"})["status"] == "correct"
    assert call({"op": "grade", "exercise": "0.3", "answer": "a"})["status"] == "incorrect"
    assert call({"op": "run", "exercise": "0.5", "code": "def rotate_2d(x, y, t):\n    return x, y\n"})["status"] == "incorrect"


def test_bad_requests_get_an_error_result():
    assert call({"op": "grade", "exercise": "99.1", "answer": "3"})["status"] == "error"
    assert call({"op": "grade", "exercise": None})["status"] == "error"
    assert call({"op": "nope"})["status"] == "error"
    assert call({"op": "run", "exercise": "0.1", "code": ""})["status"] == "error"
    assert call("not json")["status"] == "error"
    assert call("[1, 2]")["status"] == "error"
