"""Run every docstring example in the grading package: the library teaches and tests at once."""

import doctest
import importlib
import inspect
import pkgutil

import pytest

import workbook
import workbook_sandbox

MODULES = sorted(
    info.name for package in (workbook, workbook_sandbox)
    for info in pkgutil.walk_packages(package.__path__, prefix=package.__name__ + ".")
)


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0, f"{result.failed} doctest(s) failed in {name}"


def test_reference_functions_carry_examples():
    """Each public reference function shows a worked example."""
    missing = []
    for info in pkgutil.iter_modules(importlib.import_module("workbook.reference").__path__):
        module = importlib.import_module(f"workbook.reference.{info.name}")
        for name, obj in vars(module).items():
            public = inspect.isfunction(obj) and not name.startswith("_")
            if public and getattr(obj, "__module__", "") == module.__name__ and ">>>" not in (obj.__doc__ or ""):
                missing.append(f"{module.__name__}.{name}")
    assert missing == []
