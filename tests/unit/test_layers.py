"""The grading package's layers: every import in ``workbook`` runs down (or across), never up.

Each top-level part of ``pyodide_pkg/workbook`` (a module, or a package with everything in it) sits in
one layer. A part may import a part of its own layer or of a lower one. An import inside a function
counts as much as one at the top of a module: the arrow is there either way (``kinds.build`` once
imported the bank inside ``Build.check``; the bank now registers its cache with ``run_caches``).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[2] / "pyodide_pkg" / "workbook"

LAYERS: tuple[tuple[str, ...], ...] = (  # top first
    ("api", "copying", "version"),  # copying: the teach page's copy-share measure, over the whole bank
    ("bank", "assignment"),
    ("kinds",),
    ("figures", "carried", "build_plain"),
    ("answer_kinds", "steps", "chains", "build_judge"),
    ("expr", "reference", "markup", "math_text", "variants", "registry", "tolerance", "number_format",
     "verdict", "units", "contract", "run_caches", "typed_rounding", "slip_names", "__init__"),
)
RANK = {part: depth for depth, parts in enumerate(LAYERS) for part in parts}


def part_of(module: str) -> str:
    """``workbook.kinds.build`` -> ``kinds``; ``workbook`` -> ``__init__``."""
    names = module.split(".")
    return names[1] if len(names) > 1 else "__init__"


def module_of(path: Path) -> str:
    """``.../workbook/kinds/build.py`` -> ``workbook.kinds.build`` (a package's ``__init__`` -> the package)."""
    return ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts).removesuffix(".__init__")


def imports(text: str, module: str, is_package: bool = False) -> list[tuple[int, str]]:
    """Every ``workbook`` module the source ``text`` of ``module`` imports (line, module), relative imports
    resolved, wherever in the file they are."""
    package = module if is_package else module.rsplit(".", 1)[0]
    found = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names if a.name.split(".")[0] == "workbook"]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                target = ".".join([*base, node.module] if node.module else base)
            else:
                target = node.module or ""
            if target.split(".")[0] != "workbook":
                continue
            # "from .. import bank": the part is the imported name
            found += [(node.lineno, f"{target}.{a.name}") for a in node.names] if target == "workbook" else \
                [(node.lineno, target)]
    return found


FILES = sorted(PACKAGE.rglob("*.py"))


def test_every_part_has_a_layer():
    parts = {part_of(module_of(p)) for p in FILES}
    assert parts <= set(RANK), f"put {sorted(parts - set(RANK))} in a layer of LAYERS"


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(PACKAGE)) for p in FILES])
def test_no_import_runs_up_a_layer(path):
    mine = part_of(module_of(path))
    found = imports(path.read_text(encoding="utf-8"), module_of(path), path.name == "__init__.py")
    upward = [f"line {line}: {target}" for line, target in found if RANK.get(part_of(target), len(LAYERS)) < RANK[mine]]
    assert not upward, f"{path.relative_to(PACKAGE)} ({mine}) imports a layer above it: {upward}"


def test_the_check_sees_an_import_inside_a_function():
    """The check itself: ``from .. import bank`` inside a method of ``kinds.build`` is found, and runs up."""
    found = imports("def check():\n    from .. import bank\n    return bank\n", "workbook.kinds.build")
    assert [t for _, t in found] == ["workbook.bank"] and RANK[part_of(found[0][1])] < RANK["kinds"]
    assert imports("from ...expr import Formula\n", "workbook.answer_kinds.expression", True) == [(1, "workbook.expr")]
