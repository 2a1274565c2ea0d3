"""Drivers: how a Build exercise's function is exercised on one case.

A driver takes the function under test and one case's arguments (as decoded from
JSON: numbers, lists, dicts) and returns what the grader compares. The grader
runs its reference implementation through the same driver, natively, so a
learner's output and the expected one always come from the same procedure.
A Build exercise names its driver in ``Build.harness``.

>>> call(lambda x, y: (y, x), 1, 2)
(2, 1)
>>> driver("call") is call
True
>>> driver("nope")
Traceback (most recent call last):
...
KeyError: "no harness driver 'nope'"
"""

from __future__ import annotations

from typing import Any, Callable


def call(fn: Callable[..., Any], *args: Any) -> Any:
    """One call: the function's own return value."""
    return fn(*args)


DRIVERS: dict[str, Callable[..., Any]] = {"call": call}


def driver(name: str) -> Callable[..., Any]:
    """The driver called ``name`` (KeyError when there is none)."""
    try:
        return DRIVERS[name]
    except (KeyError, TypeError):
        raise KeyError(f"no harness driver {name!r}") from None
