"""Build: write a Python function; tests compare it with the reference implementation.

A run has three steps, and the learner's code takes part in one of them only:

1. :meth:`Build.job`: the grader picks the cases (the examples, then hidden cases
   drawn from a seeded generator) and names the harness driver that exercises
   the function (``workbook_sandbox.harness``).
2. ``workbook_sandbox.runner.run(job, code)`` runs the learner's code on them and
   reports what came back, as plain JSON. In the page this happens in the
   sandbox, a Web Worker of its own that holds no grading package
   (``docs/assets/js/sandbox.js``); natively, in this process.
3. :meth:`Build.judge`: the grader runs its reference through the same driver,
   now that the learner's code has finished, and ``workbook.build_judge`` reads
   the report, compares and writes the verdict. The report is data: it can at most claim outputs
   for the learner's own function.

:meth:`Build.check` does all three in process (tests, the golden transcript).
There, what the code changes in the grader's modules, classes, functions and
exercises is put back before the grader judges (``workbook_sandbox.restore``),
and the cache of variants is emptied. Time limits are the page's.
"""

from __future__ import annotations

import copy
import json
import random
import sys
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from typing import Any, ClassVar

from workbook_sandbox import harness, runner
from workbook_sandbox.restore import STDLIB_HOMES, Restore
from workbook_sandbox.values import show

from .. import build_judge, run_caches
from ..build_judge import Case, read_report
from ..contract import ROLE
from ..figures import runs
from ..variants import check_seed
from ..verdict import Verdict
from .base import Exercise, Page, escape, role_attr

STDOUT_CAP = runner.STDOUT_CAP


@dataclass(frozen=True)
class Build(Exercise):
    """``examples`` are the visible cases (argument tuples, usually the workbook's
    own numbers); ``edge_cases`` are hidden cases that every run tries (a zero time step, an unreachable
    target, an angle past ±π), then ``random_args`` draws the other hidden cases from a seeded RNG;
    ``harness`` names the driver that exercises the function on a case
    (``workbook_sandbox.harness``: ``"call"`` calls it once). ``run_figure`` names
    the picture drawn after a run, the learner's function beside the reference
    (``workbook.figures.runs``); its frames go in the verdict's ``data["figure"]``.
    ``values`` fill the ``{{name}}`` placeholders of its chapter text (numbers its
    solution prints, computed from the reference when the bank loads).
    """

    function: str = ""
    params: tuple[str, ...] = ()
    starter: str = ""
    solution: str = ""
    reference: Callable[..., Any] | None = None
    examples: tuple[tuple, ...] = ()
    random_args: Callable[[random.Random], tuple] | None = None
    edge_cases: tuple[tuple, ...] = ()
    describe: Callable[..., str] | None = None  # how a case is named in a test row (default: the call)
    # what is wrong with a value that disagrees, in words: diagnose(args, got, want) -> a sentence, or ""
    diagnose: Callable[[tuple, Any, Any], str] | None = None
    hidden_count: int = 20
    rel_tol: float = 1e-6
    abs_tol: float = 1e-9
    time_limit: float = 5.0
    harness: str = "call"
    run_figure: str = ""
    angles: tuple[str, ...] = ()  # index paths of outputs compared as angles (π and −π agree): "[2]", "[*][2]"
    seed: int = 0  # which hidden cases: 0 the exercise's own, any other a fresh draw (a review, new cases)
    # the chapter's {{name}}s (from the reference)
    values: Mapping[str, str] = field(default_factory=dict, compare=False, repr=False)
    kind: ClassVar[str] = "build"
    op: ClassVar[str] = "run"
    reveal_label: ClassVar[str] = "Show solution"

    @property
    def signature(self) -> str:
        return f"{self.function}({', '.join(self.params)})"

    def variant(self, seed: object) -> Build:
        """This exercise with seed ``seed``'s hidden cases (the examples stay): the page's ``variant``."""
        seed = check_seed(seed)
        return self if seed == self.seed else replace(self, seed=seed)

    def hidden_cases(self) -> list[tuple]:
        """The edge cases, then random ones: the same for the same seed (the seed 0 ones are the exercise's own)."""
        rng = random.Random(f"hidden:{self.id}" + (f":{self.seed}" if self.seed else ""))
        # random_args may be None in the dataclass; every Build in the bank (all 12) gives it.
        return [*self.edge_cases, *(self.random_args(rng) for _ in range(self.hidden_count))]  # type: ignore[misc]

    def arguments(self) -> list[list]:
        """Every case's arguments, examples first, as the sandbox receives them (through JSON)."""
        return json.loads(json.dumps([list(args) for args in (*self.examples, *self.hidden_cases())]))

    def job(self) -> str:
        """What the sandbox needs to run the learner's code (JSON): the function's name, the driver, the cases."""
        job: dict[str, Any] = {"function": self.function, "harness": self.harness, "cases": self.arguments()}
        figure = runs.trace_job(self)
        if figure is not None:
            job["figure"] = figure
        return json.dumps(job)

    def cases(self, arguments: list[list]) -> list[Case]:
        """The grader's cases: how each is shown and what the reference gives (run through the same driver)."""
        drive = harness.driver(self.harness)
        out = []
        for i, args in enumerate(arguments):
            want = _numbers(drive(self.reference, *copy.deepcopy(args)))
            name = self.describe(*args) if self.describe else f"{self.function}({', '.join(show(a) for a in args)})"
            out.append(Case("example" if i < len(self.examples) else "hidden", name, want, self._diagnose(args, want)))
        return out

    def _diagnose(self, args: list, want: Any) -> Callable[[Any], str] | None:
        """The case's diagnosis (:attr:`diagnose` bound to its arguments and the reference's value)."""
        if self.diagnose is None:
            return None
        diagnose = self.diagnose
        return lambda got: diagnose(tuple(args), got, want)

    def judge(self, report: Any, figure: bool = True) -> Verdict:
        """The verdict on a run, from the sandbox's report (JSON text or a dict), with the run figure in
        its data; without it when ``figure`` is false (the page shows the verdict first, then asks for
        the figure: :meth:`drawn`)."""
        arguments = self.arguments()
        read = self._read(report, arguments)
        cases = self.cases(arguments)
        verdict = build_judge.judge(read, cases, self.signature, len(self.examples), self.rel_tol, self.abs_tol,
                                    self.angles)
        drawn = self._draw(read, cases, arguments) if figure else None
        if drawn is not None:
            verdict.data["figure"] = drawn
        return verdict

    def drawn(self, report: Any) -> dict[str, Any] | None:
        """The run figure of the sandbox's report, as :meth:`judge` puts it in a verdict (None when the
        run draws none: the exercise has no run figure, or the code did not load)."""
        arguments = self.arguments()
        read = self._read(report, arguments)
        return self._draw(read, self.cases(arguments), arguments)

    def _read(self, report: Any, arguments: list[list]) -> Any:
        figure = runs.trace_job(self)
        return read_report(report, len(arguments), len(figure["cases"]) if figure else 0)

    def _draw(self, read: Any, cases: list[Case], arguments: list[list]) -> dict[str, Any] | None:
        if not (self.run_figure and read.load is None and not read.missing):
            return None
        try:
            return runs.draw_run(self, read, cases, arguments)
        except Exception:  # a fault of the drawing must never cost the learner the verdict
            return None  # (tests/unit/test_run_figures.py looks for the figure on every odd output)

    def check(self, code: object) -> Verdict:
        """The whole run in this process: job, the learner's code, judgement."""
        report = runner.run_json(self.job(), str(code), Restore(STDLIB_HOMES + ("workbook",), _grader_objects()))
        run_caches.empty_all()  # a run may have reached a cached variant through gc (the bank registers it)
        return self.judge(report)

    def widget(self, base: str, page: Page) -> str:
        return (
            f'<div class="wb-build">'
            f'<p class="wb-label" id="{base}-editor-label">Your code: define <code>{escape(self.signature)}</code>. '
            f"<kbd>Ctrl</kbd>+<kbd>Enter</kbd> runs the tests.</p>"
            f'<div class="wb-editor" {role_attr(ROLE.editor)} data-time-limit="{self.time_limit:g}" '
            f'aria-labelledby="{base}-editor-label">'
            f'<pre class="wb-starter" {role_attr(ROLE.code)}><code>{escape(self.starter)}</code></pre></div>'
            f'<div class="wb-build-actions">'
            f'<button type="button" class="md-button md-button--primary" {role_attr(ROLE.run)}>Run tests</button>'
            f'<button type="button" class="md-button" {role_attr(ROLE.reset)}>Reset to starter</button></div>'
            f'<div class="wb-tests" {role_attr(ROLE.tests)} hidden></div>'
            f'<pre class="wb-stdout" {role_attr(ROLE.stdout)} hidden></pre>'
            f"{self._run_figure(base)}</div>"
        )

    def _run_figure(self, base: str) -> str:
        """The run figure's place, hidden until a run draws it (``docs/assets/js/run-figure.js``)."""
        if not self.run_figure:
            return ""
        return (
            f'<figure class="wb-figure wb-run-figure" {role_attr(ROLE.run_figure)} '
            f'data-figure="{escape(self.run_figure)}" '
            f'aria-labelledby="{base}-run-title" hidden>'
            f'<figcaption class="wb-run-title" id="{base}-run-title">Your function, drawn</figcaption>'
            f'<p class="wb-run-readout" {role_attr(ROLE.readout)} aria-live="polite"></p>'
            f'<div class="wb-fig-canvas" {role_attr(ROLE.run_canvas)} role="img" '
            f'aria-describedby="{base}-run-desc"></div>'
            f'<p class="wb-run-description" id="{base}-run-desc" {role_attr(ROLE.run_description)}></p>'
            f'<div class="wb-run-steps">'
            f'<button type="button" class="md-button" {role_attr(ROLE.run_previous)}>Previous case</button>'
            f'<label class="wb-run-case"><span id="{base}-run-case">Case</span> '
            f'<input type="range" min="0" max="0" step="1" value="0" {role_attr(ROLE.run_case)} '
            f'aria-labelledby="{base}-run-case"></label>'
            f'<button type="button" class="md-button" {role_attr(ROLE.run_next)}>Next case</button>'
            f'<output class="wb-run-case-label" {role_attr(ROLE.run_case_label)}></output></div>'
            f"</figure>"
        )


EXERCISE = Build


def _numbers(value: Any) -> Any:
    """The reference's output as floats, keeping its nesting (tuples become lists); None (a refusal,
    such as an unreachable target) and booleans (a yes/no test) stay as they are."""
    if value is None or isinstance(value, bool):
        return value
    if isinstance(value, (list, tuple)) or (hasattr(value, "__iter__") and not isinstance(value, (str, dict))):
        return [_numbers(v) for v in value]
    return float(value)


def _grader_objects() -> list[object]:
    """The exercises loaded so far (their fields hold keys and references), for a run in this process."""
    out: list[object] = []
    for name, mod in list(sys.modules.items()):
        if name.startswith("workbook.bank.ch"):
            out += [ex for ex in getattr(mod, "EXERCISES", ()) if hasattr(ex, "__dict__")]
    return out
