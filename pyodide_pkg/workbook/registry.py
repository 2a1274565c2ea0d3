"""One way of registering the workbook's parts: a package of modules, each exporting one thing.

=================  ==========================  ==============  =============================
what               where                       exports         its names
=================  ==========================  ==============  =============================
exercise kinds     ``kinds/K.py``              ``EXERCISE``    ``kinds`` in contract.json
answer kinds       ``answer_kinds/A/``         ``ANSWER``      ``answerKinds`` in contract.json
chapters           ``bank/chN_topic.py``       ``EXERCISES``   every ``chN_*`` module found
figures            ``figures/NAME.py``         ``FIGURE``      every module found
run figures        ``figures/runs/NAME.py``    ``RUN``         every module found
=================  ==========================  ==============  =============================

A name's module is the name with ``_`` for ``-`` (figure ``ekf-update`` lives in
``ekf_update.py``), imported on first use; what it exports must call itself by
that name (``kind`` or ``name``). ``check()`` loads every part and says what is
wrong in words; the site's build calls it for each registry (docs/hooks), so a
part that is listed but missing, or found but broken, stops the build.

>>> [name for name in FIGURES.names() if name.startswith(("arm-2", "cap"))][:2]
['arm-2link', 'capstone']
>>> KINDS.get("derive").__name__
'Derive'
>>> FIGURES.get("nope")
Traceback (most recent call last):
...
KeyError: "there is no figure called 'nope'"
"""

from __future__ import annotations

import functools
import importlib
import pkgutil
import sys
from dataclasses import dataclass
from typing import Any

from .contract import ANSWER_KINDS
from .contract import KINDS as KIND_NAMES


@functools.cache
def _found(package: str, helpers: tuple[str, ...], prefix: str) -> tuple[str, ...]:
    """The modules of ``package`` (not its sub-packages or ``helpers``) named with ``prefix``, as names,
    sorted. Looked up once: a package's files do not change while it runs, and in the page every
    lookup lists a folder of the zipped library (a judge of a Build run asked twice)."""
    found = {info.name for info in pkgutil.iter_modules(importlib.import_module(package).__path__) if not info.ispkg}
    found |= _loaded_on_first_use(package)
    return tuple(sorted(name.replace("_", "-") for name in found if name not in helpers and name.startswith(prefix)))


def _loaded_on_first_use(package: str) -> set[str]:
    """The modules (not packages) of ``package`` that a finder on ``sys.meta_path`` says it imports on first
    use (``modules_of``): in the page, the parts of the package a chapter's start leaves out
    (workbook_sandbox/lazy_stdlib.py). None natively."""
    return {name for finder in sys.meta_path for name in getattr(finder, "modules_of", lambda _package: ())(package)}


@dataclass(frozen=True)
class Registry:
    """``package``'s modules, each exporting ``export``; ``listed``: the registered names (None: every
    module found but ``helpers``); ``own``: the attribute that holds the thing's own name ("" for none);
    ``prefix``: only modules whose names start with it (chapters); ``what``: the part, in words."""

    package: str
    export: str
    what: str
    listed: tuple[str, ...] | None = None
    helpers: tuple[str, ...] = ()
    own: str = "name"
    prefix: str = ""

    def names(self) -> list[str]:
        """The registered names: the listed ones in order, or every module found, sorted."""
        return list(self.listed if self.listed is not None else _found(self.package, self.helpers, self.prefix))

    def get(self, name: str) -> Any:
        """The thing registered as ``name`` (a KeyError in words when there is none)."""
        if name not in self.names():
            raise KeyError(f"there is no {self.what} called {name!r}")
        module = importlib.import_module(f"{self.package}.{name.replace('-', '_')}")
        try:
            thing = getattr(module, self.export)
        except AttributeError:
            raise TypeError(f"{module.__name__} registers no {self.what}: it defines no {self.export}") from None
        if self.own and getattr(thing, self.own, name) != name:
            raise TypeError(f"{module.__name__} defines a {self.what} called {getattr(thing, self.own)!r}, not "
                            f"{name!r}")
        return thing

    def check(self) -> dict[str, Any]:
        """Every registered thing, loaded and checked."""
        return {name: self.get(name) for name in self.names()}


KINDS = Registry("workbook.kinds", "EXERCISE", "kind of exercise", listed=KIND_NAMES, own="kind")
ANSWERS = Registry("workbook.answer_kinds", "ANSWER", "answer kind", listed=ANSWER_KINDS, own="kind")
CHAPTER_MODULES = Registry("workbook.bank", "EXERCISES", "chapter module", prefix="ch", helpers=("checks",), own="")
FIGURES = Registry("workbook.figures", "FIGURE", "figure", helpers=("svg", "symptoms"))
RUN_FIGURES = Registry("workbook.figures.runs", "RUN", "run figure", helpers=("marks",))
ALL = (KINDS, ANSWERS, CHAPTER_MODULES, FIGURES, RUN_FIGURES)
