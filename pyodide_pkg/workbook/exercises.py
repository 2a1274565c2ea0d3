"""The five kinds of exercise, as plain data.

An exercise holds its key (what counts as right), and whatever the page needs to
draw it (options, code lines, steps). The learner-facing prose (prompt, hint,
derivation) lives in the chapter's Markdown page, placed by id.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

KINDS = ("derive", "trace", "build", "debug", "design")


@dataclass(frozen=True)
class Slip:
    """A known wrong answer with its own message (matched like the key)."""

    value: float
    message: str


@dataclass(frozen=True)
class Derive:
    """Type a number or an expression.

    ``angle`` says the answer is an angle in ``"deg"`` or ``"rad"``, so that a
    value in the other unit can be recognised and named.
    """

    id: str
    title: str
    key: float
    label: str
    unit: str = ""
    angle: str | None = None
    rel_tol: float = 1e-3
    abs_tol: float = 1e-3
    slips: tuple[Slip, ...] = ()
    kind: str = field(default="derive", init=False)


@dataclass(frozen=True)
class Option:
    """One option of a Trace exercise; ``why`` is shown once it is picked."""

    key: str
    text: str
    why: str


@dataclass(frozen=True)
class Trace:
    """Choose one option, then read why."""

    id: str
    title: str
    options: tuple[Option, ...]
    answer: str
    kind: str = field(default="trace", init=False)


@dataclass(frozen=True)
class Build:
    """Write a Python function; tests compare it with ``reference``.

    ``examples`` are the visible cases (argument tuples, usually the workbook's
    own numbers); ``random_args`` draws the hidden cases from a seeded RNG.
    """

    id: str
    title: str
    function: str
    params: tuple[str, ...]
    starter: str
    solution: str
    reference: Callable[..., Any]
    examples: tuple[tuple, ...]
    random_args: Callable[[random.Random], tuple]
    hidden_count: int = 20
    rel_tol: float = 1e-6
    abs_tol: float = 1e-9
    time_limit: float = 5.0
    kind: str = field(default="build", init=False)

    @property
    def signature(self) -> str:
        return f"{self.function}({', '.join(self.params)})"


@dataclass(frozen=True)
class Debug:
    """Click the buggy line of a short program.

    ``notes`` maps every other line number (1-based) to a word on what that
    line does right; ``bug`` explains the bug; ``fixed_line`` is the repair,
    used by the tests to prove the program then agrees with ``reference``.
    """

    id: str
    title: str
    code: str
    bug_line: int
    fixed_line: str
    bug: str
    notes: Mapping[int, str]
    function: str
    reference: Callable[..., Any]
    cases: tuple[tuple, ...]
    kind: str = field(default="debug", init=False)

    @property
    def lines(self) -> list[str]:
        return self.code.rstrip("\n").split("\n")


@dataclass(frozen=True)
class Step:
    key: str
    text: str


@dataclass(frozen=True)
class Design:
    """Put the steps of a pipeline in order.

    ``steps`` are in the solved order; ``shown`` is the order first shown
    (a list of keys), which must never be the solved one.
    """

    id: str
    title: str
    steps: tuple[Step, ...]
    shown: tuple[str, ...]
    kind: str = field(default="design", init=False)

    @property
    def solution(self) -> tuple[str, ...]:
        return tuple(s.key for s in self.steps)


Exercise = Derive | Trace | Build | Debug | Design
