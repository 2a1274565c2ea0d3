"""The restore remembers what each namespace holds (workbook_sandbox/restore.py, ``_holds``) while
it binds the same objects: a namespace that changed between runs is looked at afresh, so what a
later run changes in it is still put back, and the remembered answer is the one looking afresh gives."""

from __future__ import annotations

import json

from workbook_sandbox import restore
from workbook_sandbox.restore import STDLIB_HOMES, Restore


def _one() -> int:
    return 1


def _two() -> int:
    return 2


class _Probe:
    def value(self) -> int:
        return 1


def test_a_function_bound_between_runs_is_put_back_after_a_later_run():
    with Restore(STDLIB_HOMES):  # the json module's namespace is remembered
        pass
    json._wb_probe = _one  # type: ignore[attr-defined]  # a change between runs, as an import makes
    try:
        with Restore(STDLIB_HOMES):
            _one.__code__ = _two.__code__
        assert _one() == 1
    finally:
        del json._wb_probe  # type: ignore[attr-defined]


def test_a_method_added_to_a_class_between_runs_is_put_back_after_a_later_run():
    _Probe.__module__ = "json"
    json._WbProbe = _Probe  # type: ignore[attr-defined]
    try:
        with Restore(STDLIB_HOMES):
            pass
        def other(self) -> int:
            return 1
        _Probe.other = other  # type: ignore[attr-defined]
        with Restore(STDLIB_HOMES):
            other.__code__ = _two.__code__
            _Probe.value = lambda self: 3  # type: ignore[method-assign]
        assert _Probe().other() == 1 and _Probe().value() == 1  # type: ignore[attr-defined]
    finally:
        del json._WbProbe  # type: ignore[attr-defined]


def test_what_is_remembered_is_what_looking_afresh_finds():
    with Restore(STDLIB_HOMES) as first:
        pass
    remembered = first.functions[0], [c for c, _ in first.classes], [c for c, _ in first.containers]
    restore._HELD.clear()
    with Restore(STDLIB_HOMES) as fresh:
        pass
    assert (fresh.functions[0], [c for c, _ in fresh.classes], [c for c, _ in fresh.containers]) == remembered
    assert len(remembered[0]) > 100 and len(remembered[1]) > 20
