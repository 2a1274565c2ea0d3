"""Each answer kind takes only the options it honours; a Derive exercise holds one; mistakes fail the build."""

import ast
import dataclasses
import inspect

import pytest

from workbook import bank
from workbook.answer_kinds import classes
from workbook.answer_kinds.expression import formula
from workbook.answer_kinds.matrix import matrix
from workbook.answer_kinds.number import number
from workbook.kinds import derive
from workbook.kinds.derive import Derive
from workbook.variants import Param, VariantError, Vary


def test_every_registered_kind_is_a_package_with_its_parts():
    for name, cls in classes().items():
        package = cls.__module__
        for part in ("read", "mark", "show"):
            __import__(f"{package}.{part}")
        assert cls.kind == name


@pytest.mark.parametrize("spec,option", [
    (matrix(key=((1.0,),), periodic=True), "periodic"),
    (matrix(key=((1.0,),), angle="deg"), "angle"),
    (formula(key=lambda x: x, variables=("x",), domain={"x": (0, 1)}, rel_tol=0.1), "rel_tol"),
    (formula(key=lambda x: x, variables=("x",), domain={"x": (0, 1)}, either_sign="?"), "either_sign"),
    (number(key=1.0, names=("x",)), "names"),
])
def test_an_option_a_kind_does_not_have_fails_with_the_exercise_id(spec, option):
    with pytest.raises(ValueError, match=rf"exercise 9\.99: .*no option '{option}'"):
        Derive(id="9.99", title="t", spec=spec)


def test_a_name_make_returns_that_nothing_takes_fails_with_the_exercise_id():
    misspelt = Vary(lambda p: {"key": p["x"], "slip": ()}, Param("x", 1, 1, 5, 1))
    with pytest.raises(ValueError, match=r"exercise 9\.98: .*no option 'slip'"):
        Derive(id="9.98", title="t", spec=number(), vary=misspelt)


def test_the_worked_placeholder_belongs_to_the_answer_kind():
    takes_it = Vary(lambda p: {"key": p["x"], "values": {"worked": "7"}}, Param("x", 1, 1, 5, 1))
    with pytest.raises(VariantError, match="worked"):
        Derive(id="9.97", title="t", spec=number(), vary=takes_it)
    ex = Derive(id="9.96", title="t", spec=number(), vary=Vary(lambda p: {"key": p["x"] / 3}, Param("x", 1, 1, 5, 1)))
    assert ex.values["worked"] == ex.worked_text() == "0.3333"


def test_options_are_checked_for_sense():
    with pytest.raises(ValueError, match="periodic needs angle"):
        Derive(id="9.95", title="t", spec=number(key=1.0, periodic=True))
    with pytest.raises(ValueError, match="one unit per entry"):
        Derive(id="9.94", title="t", spec=matrix(key=((1.0,), (2.0,)), units=("m",)))
    with pytest.raises(ValueError, match="names are for a vector"):
        Derive(id="9.93", title="t", spec=matrix(key=((1.0, 2.0), (3.0, 4.0)), names=("a", "b", "c", "d")))


def test_a_derive_exercise_is_built_complete_and_never_changed():
    """Derive's fields are what the bank wrote: the draw is computed once and read through read-only views,
    and a variant is another exercise (dataclasses.replace), never the same one changed (issue 47)."""
    tree = ast.parse(inspect.getsource(derive))
    calls = [n for n in ast.walk(tree) if isinstance(n, ast.Attribute) and n.attr == "__setattr__"]
    assert not calls, "kinds/derive.py changes a frozen dataclass through object.__setattr__"
    ex = bank.get("2.1")
    other = ex.variant(5)
    assert other is not ex and ex.seed == 0 and other.seed == 5 and other.title != ex.title
    assert {f.name: getattr(other, f.name) for f in dataclasses.fields(other) if f.name not in ("seed", "title")} == \
        {f.name: getattr(ex, f.name) for f in dataclasses.fields(ex) if f.name not in ("seed", "title")}
    for name in ("values", "params", "step_answers"):
        copy = getattr(ex, name)
        copy["x"] = 1  # the caller's own copy: the exercise does not change
        assert "x" not in getattr(ex, name)
        with pytest.raises(TypeError):
            getattr(ex.drawn, "steps" if name == "step_answers" else name)["x"] = 1  # the draw is read-only
    assert other.variant(0) == ex and other.variant(0).values == ex.values
