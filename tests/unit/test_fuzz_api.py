"""20,000 hostile requests to the worker's entry point: it never raises, always
answers in the envelope shape, never says "internal" for a request it could not
read, and every reply stays small whatever the request held (a 1 MB id gets a
short reply). The generator is seeded: a failure names the request to replay.
"""

import json
import random

import pytest

import many_draws
from workbook import bank
from workbook.api import handle
from workbook.contract import ERRORS, OPS, STATUSES

COUNT = many_draws.count(20_000)  # all of them in make test; a share in make test-unit
SEED = 21
REPLY_CAP = 64_000  # characters; the largest real reply (a figure) is under 9,000
ERROR_CAP = 1_200

IDS = [ex.id for ex in bank.all_exercises()]
BUILD_IDS = [ex.id for ex in bank.all_exercises() if ex.kind == "build"]
HUGE = "9" * 1_000_000
SOLUTION = bank.get("0.5").solution
REPORT = json.dumps({"cases": [{"value": {"type": "tuple", "length": 2, "text": "(0.0, 3.0)",
                                          "items": [{"type": "float", "number": 0.0}, {"type": "float", "number": 3.0}]}}],
                     "load": None, "missing": False, "stdout": "", "stopped": None})
PLAUSIBLE = {"answer": ["3", "0.7071", "45°", [["1", "0"], ["0", "1"]], ["a", "b"], 2], "code": [SOLUTION, "x = 1"],
             "text": ["1 2", "[[1, 0], [0, 1]]"], "texts": [{}, {"prompt": "x"}], "variant": [0, 7, "12"],
             "figure": ["rotation-2d", "pid-response", "nope"], "params": [{}, {"theta": 30}], "outputs": [REPORT, "{}"],
             "step": ["FP", "d", "t12", "nope", "__init__"], "steps": [{}, {"FP": [["1", "0", "0"]] * 3}, {"d": "1 2", "q": "5"}],
             "given": [{}, {"9.2": {"answer": "6", "variant": 0}}, {"3.7": {"answer": [["1"]], "variant": 0}}]}


def _value(rng: random.Random, depth: int = 0):
    """A JSON value of a hostile kind."""
    pick = rng.randrange(16)
    if pick == 0:
        return None
    if pick == 1:
        return rng.choice([True, False])
    if pick == 2:
        return rng.choice([0, -1, 1, 999_999, 1_000_000, 2**63, -(2**70), 10**300])
    if pick == 3:
        return rng.choice([0.5, -0.0, 1e308, -1e-308, 3.141592653589793])
    if pick == 4:
        return rng.choice(["", " ", "3", "sqrt(2)/2", "1e999", "θ₁", "\u0000", "a" * 50_000, "((((((((((", "1/0"])
    if pick == 5:
        return HUGE[: rng.choice([10, 20_000, 20_000, 20_000, 1_000_000])]
    if pick == 6:
        return "".join(chr(rng.randrange(32, 0x2FFF)) for _ in range(rng.randrange(40)))
    if pick == 7 and depth < 4:
        return [_value(rng, depth + 1) for _ in range(rng.randrange(5))]
    if pick == 8 and depth < 4:
        return {rng.choice(["op", "id", "x", "theta", "a" * 300]): _value(rng, depth + 1) for _ in range(rng.randrange(4))}
    if pick == 9:
        return [[rng.choice(["1", "0", "-1", "x", ""]) for _ in range(rng.randrange(4))] for _ in range(rng.randrange(4))]
    if pick == 10:
        return rng.choice(IDS)
    if pick == 11:
        return rng.choice(list(OPS) + ["nope", "", "__class__", "run "])
    if pick == 12:
        return {"prompt": rng.choice(["{{x}}", "", "a" * 60_000]), "hint": _value(rng, depth + 1)}
    if pick == 13:
        return json.dumps({"cases": [{"value": {"type": "tuple", "length": 2, "items": [{"number": 1}, {"number": 2}]}}],
                           "load": rng.choice([None, {"phase": "syntax", "line": -5}, 7]), "stdout": "x" * 9000})
    if pick == 14:
        return "[" * rng.randrange(1, 50_000)
    return rng.randrange(-3, 1_000_001)


def _request(rng: random.Random) -> str:
    """A raw request: mostly an object with an op and fields, sometimes not JSON at all."""
    kind = rng.randrange(20)
    if kind == 0:
        return rng.choice(["", "not json", "{", "[1, 2]", "null", '"x"', "1e999", "{" * 100_000, '{"op": NaN}'])
    if kind == 1:
        return "[" * 30_000 + "]" * 30_000  # deeper than the JSON decoder goes
    op = rng.choice(list(OPS)) if rng.random() < 0.85 else _value(rng)
    request = {"op": op}
    exercise_id = rng.choice(BUILD_IDS if op in ("run", "cases", "judge") and rng.random() < 0.7 else IDS)
    request["exercise"] = exercise_id if rng.random() < 0.8 else _value(rng)
    for field in ("answer", "code", "text", "texts", "variant", "figure", "params", "outputs", "step", "steps", "given"):
        if rng.random() < 0.4:
            request[field] = rng.choice(PLAUSIBLE[field]) if rng.random() < 0.6 else _value(rng)
    if op == "run" and rng.random() < 0.3:
        request["code"] = rng.choice(["def f(:", "import sys\nsys.exit()", "raise SystemExit", "x = 1",
                                      "def rotate_2d(x, y, t):\n    return 10 ** 5000", "exit()"])
    return json.dumps(request)


PARTS = 4  # the requests in four runs of their own, which the test processes share


@pytest.mark.parametrize("part", range(PARTS))
def test_twenty_thousand_hostile_requests(part):
    rng = random.Random(SEED + part)
    seen: dict[str, int] = {}
    for n in range(COUNT // PARTS):
        raw = _request(rng)
        reply = handle(raw)  # must not raise
        where = f"request {n} (seed {SEED + part}): {raw[:200]!r}"
        assert len(reply) <= REPLY_CAP, where
        envelope = json.loads(reply)
        if envelope["ok"]:
            assert set(envelope) == {"ok", "value"}, where
            if isinstance(envelope["value"], dict) and "status" in envelope["value"]:
                assert envelope["value"]["status"] in STATUSES, where
            seen["ok"] = seen.get("ok", 0) + 1
        else:
            error = envelope["error"]
            assert set(envelope) == {"ok", "error"} and error["kind"] in ERRORS, where
            assert error["kind"] != "internal", f"{where}: {error['message']}"
            assert 0 < len(reply) <= ERROR_CAP, where
            seen[error["kind"]] = seen.get(error["kind"], 0) + 1
    # The generator reaches both sides: replies with values, and each error a request can cause.
    # at least one request in 20 well formed enough to be answered (1,000 of the full 20,000)
    assert seen.get("ok", 0) > COUNT // 20 // PARTS and {"bad-request", "unknown-exercise", "wrong-op"} <= set(seen), seen


def test_a_one_megabyte_id_gets_a_short_reply():
    reply = handle(json.dumps({"op": "grade", "exercise": HUGE, "answer": "3"}))
    assert json.loads(reply)["error"]["kind"] == "unknown-exercise" and len(reply) < 300
    reply = handle(json.dumps({"op": "grade", "exercise": "0.1", "variant": HUGE, "answer": "3"}))
    assert json.loads(reply)["error"]["kind"] == "bad-request" and len(reply) < 300
    reply = handle(json.dumps({"op": HUGE}))
    assert json.loads(reply)["error"]["kind"] == "bad-request" and len(reply) < 300
