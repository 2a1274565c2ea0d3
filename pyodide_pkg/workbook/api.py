"""The worker's one entry point: a JSON request in, a JSON envelope out.

Requests (``contract.json`` → ``ops``):

* ``{"op": "grade", "exercise": "4.2", "answer": ...}`` for the kinds whose ``op``
  is ``grade`` (Derive, Trace, Debug, Design);
* ``{"op": "run", "exercise": "0.5", "code": "..."}`` for Build (the page starts
  its time limit when the worker says the code starts);
* ``{"op": "figure", "figure": "rotation-2d", "params": {"theta": 30}}`` for a
  figure's next frame (``svg``, ``readouts``, ``flags``);
* ``{"op": "split", "exercise": "0.7", "text": "[[0, -1], [1, 0]]"}``: a pasted
  vector or matrix split into the exercise's entries (Derive, shaped answers);
* ``{"op": "read", "exercise": "6.6", "answer": "L1 cos θ1"}``: how an answer is
  read (a formula's typeset form), before it is checked (Derive);
* ``{"op": "draw", "exercise": "0.1", "variant": 17, "texts": {...}}``: variant
  17's statement, hint, derivation and label, filled into the exercise's
  templates (Derive).

``grade``, ``split`` and ``read`` take an optional ``"variant"`` (default 0).

Every reply is an envelope: ``{"ok": true, "value": VERDICT_OR_FRAME}`` or
``{"ok": false, "error": {"kind": ..., "message": ...}}``.

>>> import json
>>> json.loads(handle('{"op": "grade", "exercise": "0.1", "answer": "3"}'))["value"]["status"]
'correct'
>>> json.loads(handle('{"op": "run", "exercise": "0.1", "code": ""}'))["error"]["kind"]
'wrong-op'
"""

from __future__ import annotations

import json
from typing import Any

from . import bank
from .contract import OPS
from .variants import VariantError, check_seed, fill
from .verdict import GradingError, fail, ok


def _exercise(request: dict[str, Any], kind: str | None = None):
    try:
        seed = check_seed(request.get("variant", 0))
    except ValueError as err:
        raise GradingError("bad-request", f"This page asked for variant {request.get('variant')!r}: {err}.") from None
    try:
        ex = bank.variant(str(request.get("exercise")), seed)
    except KeyError:
        raise GradingError("unknown-exercise", f"This page asked about exercise {request.get('exercise')!r}, "
                           "which the grader does not know.") from None
    if kind is not None:
        if ex.kind != kind:
            raise GradingError("wrong-op", f"Exercise {ex.id} is a {ex.kind} exercise: {request['op']!r} is for {kind} exercises.")
    elif ex.op != request["op"]:
        raise GradingError("wrong-op", f"Exercise {ex.id} is a {ex.kind} exercise: it is graded with "
                           f"{ex.op!r}, not {request['op']!r}.")
    return ex


def _grade(request: dict[str, Any]) -> dict[str, Any]:
    return _exercise(request).check(request.get("answer")).to_dict()


def _run(request: dict[str, Any]) -> dict[str, Any]:
    return _exercise(request).check(str(request.get("code", ""))).to_dict()


def _figure(request: dict[str, Any]) -> dict[str, Any]:
    from . import figures

    try:
        return figures.render(str(request.get("figure")), request.get("params"))
    except figures.FigureError as err:
        raise GradingError("figure", str(err)) from None


def _split(request: dict[str, Any]) -> dict[str, Any]:
    return _exercise(request, "derive").split(request.get("text"))


def _read(request: dict[str, Any]) -> dict[str, Any]:
    return _exercise(request, "derive").read(request.get("answer"))


def _draw(request: dict[str, Any]) -> dict[str, Any]:
    ex = _exercise(request, "derive")
    texts = request.get("texts")
    if not isinstance(texts, dict) or not all(isinstance(texts.get(k, ""), str) for k in TEXTS):
        raise GradingError("bad-request", "A draw needs the exercise's texts (title, prompt, hint, solution).")
    try:
        out = {k: fill(texts.get(k, ""), ex.values) for k in TEXTS}
    except VariantError as err:
        raise GradingError("bad-request", f"Exercise {ex.id}'s page and grader disagree: {err}.") from None
    if out["solution"]:
        out["solution"] += ex.worked_html()
    return {**out, "variant": ex.seed, "label": ex.label_html(), "params": ex.params}


TEXTS = ("title", "prompt", "hint", "solution")
HANDLERS = {"grade": _grade, "run": _run, "figure": _figure, "split": _split, "read": _read, "draw": _draw}
assert set(HANDLERS) == set(OPS), "every op in contract.json has one handler"


def warm_up(ids: list[str] | None = None) -> str:
    """The requests the worker answers before it says "ready" (JSON): for the
    exercises of the page (``ids``; chapter 0's when the page has not said),
    one grade of each checked kind, then for its first Derive exercise a typed
    expression, a draw and a split. The browser compiles WebAssembly functions
    on their first call: this way the learner's first Check does not pay for it.

    >>> [r["op"] for r in json.loads(warm_up(["0.1", "0.3", "0.5"]))]
    ['grade', 'grade', 'grade', 'draw', 'split']
    """
    first: dict[str, Any] = {}
    for ex_id in ids if ids is not None else [ex.id for ex in bank.chapter(0)]:
        try:
            ex = bank.get(str(ex_id))
        except KeyError:
            continue
        if ex.op == "grade":
            first.setdefault(ex.kind, ex)
    requests: list[dict[str, Any]] = [{"op": "grade", "exercise": ex.id, "answer": "1"} for ex in first.values()]
    if "derive" in first:
        derive = first["derive"].id
        requests += [{"op": "grade", "exercise": derive, "answer": "sqrt(2)/2", "variant": 0},
                     {"op": "draw", "exercise": derive, "variant": 1, "texts": {}},
                     {"op": "split", "exercise": derive, "text": "1 2"}]
    return json.dumps(requests)


def dispatch(request: Any) -> dict[str, Any]:
    """The envelope for one decoded request."""
    op = request.get("op") if isinstance(request, dict) else None
    if op not in HANDLERS:
        return fail("bad-request", f"The grader does not know the request {op!r}.")
    try:
        return ok(HANDLERS[op](request))
    except GradingError as err:
        return fail(err.kind, err.message)


def handle(raw: str) -> str:
    """Decode a request, dispatch it, and encode the envelope; never raises."""
    try:
        envelope = dispatch(json.loads(raw))
    except MemoryError:
        envelope = fail("memory", "The grader ran out of memory. The Python runtime was restarted.")
    except Exception as err:  # the page must always get an answer
        envelope = fail("internal", f"The grader failed unexpectedly ({type(err).__name__}). Please report it.")
    return json.dumps(envelope)
