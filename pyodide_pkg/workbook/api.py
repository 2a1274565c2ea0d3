"""The one entry point the page's worker calls: a JSON request in, JSON out.

Requests: ``{"op": "grade", "exercise": "4.2", "answer": ...}`` for Derive, Trace,
Debug and Design; ``{"op": "run", "exercise": "0.5", "code": "..."}`` for Build;
``{"op": "figure", "figure": "rotation-2d", "params": {"theta": 30}}`` for a
figure's next frame (``data`` holds its ``svg``, ``readouts`` and ``flags``).
"""

from __future__ import annotations

import json
from typing import Any

from . import bank
from .result import Result


def dispatch(request: dict[str, Any]) -> Result:
    op = request.get("op")
    if op == "ping":
        return Result("correct", "pong")
    if op == "figure":
        return _figure(request)
    if op not in ("grade", "run"):
        return Result("error", f"Unknown request {op!r}.")
    try:
        ex = bank.get(str(request.get("exercise")))
    except KeyError:
        return Result("error", f"This page asked about exercise {request.get('exercise')!r}, which the grader does not know.")
    if op == "run":
        if ex.kind != "build":
            return Result("error", f"Exercise {ex.id} has no tests to run.")
        from .runner import run_build

        return run_build(ex, str(request.get("code", "")))
    from .checkers import check

    return check(ex, request.get("answer"))


def _figure(request: dict[str, Any]) -> Result:
    from . import figures

    try:
        frame = figures.render(str(request.get("figure")), request.get("params"))
    except figures.FigureError as err:
        return Result("error", str(err), tag="figure")
    return Result("correct", "", data=frame)


def handle(raw: str) -> str:
    """Decode a request, dispatch it, and encode the result; never raises."""
    try:
        request = json.loads(raw)
        result = dispatch(request if isinstance(request, dict) else {})
    except Exception as err:  # the page must always get an answer
        result = Result("error", f"The grader failed unexpectedly ({type(err).__name__}). Please report it.")
    return json.dumps(result.to_dict())
