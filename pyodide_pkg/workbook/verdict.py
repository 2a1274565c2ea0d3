"""The one shape every check returns, and the envelope around every reply.

A :class:`Verdict` is what a learner's attempt earned: ``status`` (correct,
incorrect, invalid), a ``message`` for the learner, a ``tag`` naming the kind of
feedback (one of the contract's tags, or ``""``), and ``data`` for extras such as
a Build run's test rows. The worker wraps every reply in an envelope:
``{"ok": true, "value": ...}``, or ``{"ok": false, "error": {"kind", "message"}}``
when no verdict could be given (an unknown exercise, a run out of memory, ...).

>>> Verdict("correct", "Right.").to_dict()
{'status': 'correct', 'message': 'Right.', 'tag': '', 'data': {}}
>>> Verdict("incorrect", "x", tag="nonsense")
Traceback (most recent call last):
...
ValueError: unknown tag 'nonsense' (contract.json lists the tags)
>>> fail("unknown-exercise", "No exercise 99.1.")
{'ok': False, 'error': {'kind': 'unknown-exercise', 'message': 'No exercise 99.1.'}}

A message names a piece of a request by :func:`quote`, which keeps it short
whatever the request held:

>>> quote("abc"), len(quote("9" * 1000)), quote("9" * 1000)[-3:]
("'abc'", 40, '99…')
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any

from workbook_sandbox.values import clip

from .contract import DATA, ERRORS, STATUSES

QUOTE_CAP = 40
MESSAGE_CAP = 1000


@dataclass
class Verdict:
    status: str
    message: str
    tag: str = ""
    data: dict[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"unknown status {self.status!r}")
        if self.tag and self.tag not in DATA["tags"]:
            raise ValueError(f"unknown tag {self.tag!r} (contract.json lists the tags)")

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


class GradingError(Exception):
    """No verdict can be given; ``kind`` is one of the contract's errors."""

    def __init__(self, kind: str, message: str) -> None:
        if kind not in ERRORS:
            raise ValueError(f"unknown error kind {kind!r}")
        super().__init__(message)
        self.kind = kind
        self.message = message


def ok(value: Any) -> dict[str, Any]:
    return {"ok": True, "value": value}


def fail(kind: str, message: str) -> dict[str, Any]:
    return {"ok": False, "error": {"kind": GradingError(kind, message).kind, "message": clip(message, MESSAGE_CAP)}}


def quote(value: Any, limit: int = QUOTE_CAP) -> str:
    """``repr(value)`` cut to ``limit`` characters: how a message names what a request held."""
    try:
        text = repr(value)
    except (ValueError, RecursionError):  # an int too long to print, a structure too deep
        text = f"<{type(value).__name__}>"
    return clip(text, limit)
