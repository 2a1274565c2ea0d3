"""The worker's one entry point: a JSON request in, a JSON envelope out.

Requests (``contract.json`` → ``ops``):

* ``{"op": "grade", "exercise": "4.2", "answer": ...}`` for the kinds whose ``op``
  is ``grade`` (Derive, Trace, Debug, Design);
* ``{"op": "run", "exercise": "0.5", "code": "..."}`` for Build, natively (in the
  page the grader refuses it: learner code runs in the sandbox worker, and the
  page asks for ``cases``, runs the code there, then asks for ``judge``);
* ``{"op": "cases", "exercise": "0.5", "code": "..."}``: what the sandbox needs
  for a Build run (``job``), and whether the code is ``plain`` (else the page
  replaces the sandbox after the run);
* ``{"op": "judge", "exercise": "0.5", "outputs": "..."}``: the verdict on the
  sandbox's report;
* ``{"op": "figure", "figure": "rotation-2d", "params": {"theta": 30}}`` for a
  figure's next frame (``svg``, ``readouts``, ``flags``);
* ``{"op": "split", "exercise": "0.7", "text": "[[0, -1], [1, 0]]"}``: a pasted
  vector or matrix split into the exercise's entries (Derive, shaped answers);
* ``{"op": "read", "exercise": "6.6", "answer": "L1 cos θ1"}``: how an answer is
  read (a formula's typeset form), before it is checked (Derive);
* ``{"op": "draw", "exercise": "0.1", "variant": 17, "texts": {...}}``: variant
  17's statement, hint, derivation and label, filled into the exercise's
  templates (Derive);
* ``{"op": "version"}``: the grader's version and a hash of its bank
  (:mod:`workbook.version`).

``grade``, ``split``, ``read``, ``cases`` and ``judge`` take an optional
``"variant"`` (default 0); ``grade`` of a Derive exercise an optional ``"given"``:
the learner's last answers to the exercises it builds on (:mod:`workbook.chains`),
and, for an exercise with checked steps, an optional ``"step"`` (the step this
answer is for) and ``"steps"`` (the learner's answers to the steps so far,
:mod:`workbook.steps`).

Every reply is an envelope: ``{"ok": true, "value": VERDICT_OR_FRAME}`` or
``{"ok": false, "error": {"kind": ..., "message": ...}}``. A request that is not
JSON, not an object, too large, or whose fields have the wrong types is a
``bad-request``; a message quotes at most a short prefix of what a request held.

>>> import json
>>> json.loads(handle('{"op": "grade", "exercise": "0.1", "answer": "3"}'))["value"]["status"]
'correct'
>>> json.loads(handle('{"op": "run", "exercise": "0.1", "code": ""}'))["error"]["kind"]
'wrong-op'
"""

from __future__ import annotations

import json
import sys
from typing import Any

from . import bank, chains, steps, version
from .build_plain import plain
from .contract import LIMIT, OPS
from .slip_names import slip_name
from .variants import VariantError, check_seed, fill
from .verdict import GradingError, Verdict, fail, ok, quote

REQUEST_CAP = 2_000_000  # characters of a request (a Build program may be long)
ANSWER_CAP = LIMIT.answer  # characters of an answer's text
TEXTS_CAP = 50_000  # characters of a draw's templates
# The type of each field a request may carry (None stands for a field left out); a figure's
# params are the figure's to check (an error of kind "figure").
FIELDS: dict[str, type] = {"exercise": str, "code": str, "text": str, "figure": str, "outputs": str, "texts": dict,
                           "given": dict, "step": str, "steps": dict, "figureLater": bool}


def _exercise(request: dict[str, Any], kind: str | None = None):
    try:
        seed = check_seed(request.get("variant", 0))
    except ValueError as err:
        raise GradingError("bad-request", f"This page asked for variant {quote(request.get('variant'))}: "
                                          f"{err}.") from None
    try:
        ex = bank.variant(str(request.get("exercise")), seed)
    except KeyError:
        raise GradingError("unknown-exercise", f"This page asked about exercise {quote(request.get('exercise'))}, "
                           "which the grader does not know.") from None
    if kind is not None:
        if ex.kind != kind:
            raise GradingError("wrong-op", f"Exercise {ex.id} is a {ex.kind} exercise: {request['op']!r} is for {kind} "
                                           "exercises.")
    elif ex.op != request["op"]:
        raise GradingError("wrong-op", f"Exercise {ex.id} is a {ex.kind} exercise: it is graded with "
                           f"{ex.op!r}, not {request['op']!r}.")
    return ex


def _grade(request: dict[str, Any]) -> dict[str, Any]:
    ex = _exercise(request)
    if ex.kind != "derive":
        if request.get("step") is not None or request.get("steps"):
            raise GradingError("bad-request", f"Exercise {ex.id} is a {ex.kind} exercise: it has no steps.")
        return ex.check(request.get("answer")).to_dict()
    out = ex.grade(request.get("answer"), given=request.get("given"), steps=request.get("steps"),
                   step=request.get("step"), lookup=bank.variant).to_dict()
    if out["status"] == "incorrect" and (name := slip_name(out["tag"], out["message"])):
        out["data"]["slip"] = name  # the named slip, the same in every variant (the class page counts them)
    return out


def _run(request: dict[str, Any]) -> dict[str, Any]:
    ex = _exercise(request)
    if sys.platform == "emscripten":  # the page: learner code runs in the sandbox worker only
        raise GradingError("bad-request", f"Exercise {ex.id}'s code runs in the page's sandbox, never in the grader: "
                           "ask for its cases, run it there, then ask for the judgement.")
    return ex.check(request.get("code") or "").to_dict()


def _cases(request: dict[str, Any]) -> dict[str, Any]:
    ex = _exercise(request, "build")
    return {"job": ex.job(), "plain": plain(request.get("code") or ""), "limit": ex.time_limit}


def _outputs(request: dict[str, Any], what: str) -> tuple[Any, str]:
    """The Build exercise of a request and the sandbox's report it carries."""
    ex = _exercise(request, "build")
    if not isinstance(request.get("outputs"), str):
        raise GradingError("bad-request", f"{what} of exercise {ex.id} needs the sandbox's report.")
    return ex, request["outputs"]


def _judge(request: dict[str, Any]) -> dict[str, Any]:
    ex, outputs = _outputs(request, "A judgement")
    return ex.judge(outputs, figure=not request.get("figureLater")).to_dict()


def _run_figure(request: dict[str, Any]) -> dict[str, Any]:
    ex, outputs = _outputs(request, "The run figure")
    return {"figure": ex.drawn(outputs)}


def _figure(request: dict[str, Any]) -> dict[str, Any]:
    from . import figures

    try:
        return figures.render(str(request.get("figure")), request.get("params"))
    except figures.FigureError as err:
        raise GradingError("figure", str(err)) from None


def _part(request: dict[str, Any]):
    """The answer a split or read is for: the exercise's own, or one of its steps' (``step``)."""
    ex = _exercise(request, "derive")
    return ex if request.get("step") is None else ex.step_kind(request["step"])


def _split(request: dict[str, Any]) -> dict[str, Any]:
    return _part(request).split(request.get("text"))


def _read(request: dict[str, Any]) -> dict[str, Any]:
    return _part(request).read(request.get("answer"))


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
HANDLERS = {"grade": _grade, "run": _run, "figure": _figure, "split": _split, "read": _read, "draw": _draw,
            "cases": _cases, "judge": _judge, "run-figure": _run_figure, "version": lambda _request: version.describe()}
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


def _well_formed(request: dict[str, Any]) -> None:
    """Raise GradingError("bad-request") unless every field has its type and size."""
    for name, kind in FIELDS.items():
        value = request.get(name)
        if value is not None and not isinstance(value, kind):
            raise GradingError("bad-request", f"This request's {name!r} is a {type(value).__name__}, "
                               f"not a {getattr(kind, '__name__', 'value')}.")
    _check_answer(request.get("answer"))
    _check_given(request.get("given") or {})
    steps.check_sent(request.get("steps") or {})
    for answer in (request.get("steps") or {}).values():
        _check_answer(answer)
    texts = request.get("texts") or {}
    if sum(len(v) for v in texts.values() if isinstance(v, str)) > TEXTS_CAP:
        raise GradingError("bad-request", "This draw's texts are too long.")


def _check_given(sent: dict[str, Any]) -> None:
    """``given``: at most a few earlier answers, ``{ID: {"answer": ..., "variant": N}}``."""
    if len(sent) > chains.MAX_GIVEN:
        raise GradingError("bad-request", f"This request carries {len(sent)} earlier answers; at most "
                                          f"{chains.MAX_GIVEN}.")
    for source, earlier in sent.items():
        if not isinstance(earlier, dict) or set(earlier) - {"answer", "variant"}:
            raise GradingError("bad-request", f"This request's earlier answer to {quote(source)} is not "
                               "{answer, variant}.")
        try:
            check_seed(earlier.get("variant", 0))
        except ValueError as err:
            raise GradingError("bad-request", f"This request's earlier answer to {quote(source)}: {err}.") from None
        try:
            _check_answer(earlier.get("answer"))
        except TooLong as err:  # the earlier exercise's answer, not the one being checked
            raise GradingError("bad-request", f"This request's earlier answer to {quote(source)}: "
                                              f"{err.message}") from None


class TooLong(GradingError):
    """An answer's text is over :data:`ANSWER_CAP`: a learner can type or paste that, so a grade or a read
    answers with the learner's verdict (``invalid``), not a request error."""

    def __init__(self, length: int):
        super().__init__("bad-request", f"This answer is too long to read ({length:,} characters; at most "
                         f"{ANSWER_CAP:,}): type the value asked for, one number or expression per box.")


def _check_answer(answer: Any, depth: int = 0) -> None:
    """An answer is text, a number, or a list (of lists) of them, as the page's widgets send."""
    if answer is None or isinstance(answer, (int, float)):
        return
    if isinstance(answer, str):
        if len(answer) > ANSWER_CAP:
            raise TooLong(len(answer))
        return
    if isinstance(answer, list) and depth < 2 and len(answer) <= 1000:
        for item in answer:
            _check_answer(item, depth + 1)
        return
    raise GradingError("bad-request", f"This request's answer is not one a widget sends: {quote(answer)}.")


def dispatch(request: Any) -> dict[str, Any]:
    """The envelope for one decoded request."""
    op = request.get("op") if isinstance(request, dict) else None
    if not isinstance(op, str) or op not in HANDLERS:
        return fail("bad-request", f"The grader does not know the request {quote(op)}.")
    try:
        _well_formed(request)
        return ok(HANDLERS[op](request))
    except TooLong as err:
        if op == "grade":
            return ok(Verdict("invalid", err.message).to_dict())
        return ok({"message": err.message}) if op == "read" else fail(err.kind, err.message)
    except GradingError as err:
        return fail(err.kind, err.message)


def handle(raw: str) -> str:
    """Decode a request, dispatch it, and encode the envelope; never raises."""
    try:
        if not isinstance(raw, (str, bytes)) or len(raw) > REQUEST_CAP:
            envelope = fail("bad-request", "This request is not text, or too large to read.")
        else:
            try:
                request = json.loads(raw)
            except (ValueError, RecursionError):
                envelope = fail("bad-request", "This request is not JSON.")
            else:
                envelope = dispatch(request)
        return json.dumps(envelope)
    except MemoryError:
        envelope = fail("memory", "The grader ran out of memory. The Python runtime was restarted.")
    except KeyboardInterrupt:  # the page's interrupt at a time limit: it answers with a timeout itself
        envelope = fail("timeout", "The grader was stopped at the time limit.")
    except BaseException as err:  # the page must always get an answer
        envelope = fail("internal", f"The grader failed unexpectedly ({type(err).__name__}). Please report it.")
    return json.dumps(envelope)
