"""Put back, when a run ends, what a learner's code changed in the interpreter.

:class:`Restore` is a context manager. On entry it notes

* every loaded module's namespace (which object each name is bound to) and the
  module table ``sys.modules`` itself;
* for the modules of ``homes`` (package names): the attributes of the classes
  they define, the contents of their module-level dicts, lists and sets, and
  the code and defaults of their functions;
* the fields (``__dict__``) of ``objects``, and the code of the functions they hold;
* the recursion limit, the trace and profile hooks (``sys.settrace``, ``sys.setprofile``) and the
  import machinery's lists (``sys.meta_path``, ``sys.path``, ``sys.path_hooks``).

On exit it puts all of that back (names a run added to a module are removed),
the builtins and this module's own names first, with nothing but dict methods
(the rest of the restore looks them up),
reseeds :mod:`random`, and, when NumPy is loaded, resets its error handling,
print options and global generator. Modules a run imported stay loaded (NumPy
is slow to load); their state is reset only where it existed before the run. An
entry a run put in ``sys.modules`` that is no module imported under that name
(an object planted there) is removed, so a later import finds the real one.

What it cannot see (a change inside an object no module names, memory written
through ``js``...) is why the page replaces the sandbox after any run whose code
was not plain (``workbook.build_plain``).

>>> import math
>>> with Restore():
...     math.cos = abs
...     math.extra = 1
>>> math.cos(0.0), hasattr(math, "extra")
(1.0, False)
>>> with Restore():
...     sys.modules["json.planted"] = types.ModuleType("json.planted")
...     sys.settrace(lambda *a: None)
>>> "json.planted" in sys.modules, sys.gettrace() is None
(False, True)
"""

from __future__ import annotations

import builtins
import random
import sys
import types
from collections.abc import Iterable, Mapping
from operator import attrgetter, is_
from typing import Any, cast

_FIRST = (vars(builtins), globals())  # what the restore itself looks names up in
# Packages whose classes, containers and functions are watched besides every module's names.
# The modules plain code may import (workbook.build_plain) are watched too, NumPy among them: a
# run that writes into one of their module-level dicts (``numpy.sctypeDict['float64'] = ...``)
# is undone. They are imported before the run's snapshot (runner.preimport), so that a run that
# imports one for the first time is undone as well.
PLAIN_HOMES = ("numpy", "cmath", "itertools", "statistics", "fractions", "collections", "typing")
STDLIB_HOMES = ("random", "math", "copy", "json", "io", "contextlib", "traceback", "dataclasses", "functools",
                "workbook_sandbox") + PLAIN_HOMES
_MISSING = object()
_NUMPY_PRINT_DEFAULTS = dict(edgeitems=3, infstr="inf", linewidth=75, nanstr="nan", precision=8, suppress=False,
                             threshold=1000, formatter=None, sign="-", floatmode="maxprec", legacy=False)


def _in_homes(name: str, homes: tuple[str, ...]) -> bool:
    return name.split(".")[0] in homes


def _functions_of(value: Any) -> list[types.FunctionType]:
    """The plain functions behind ``value`` (a function, a static or class method, a property)."""
    if isinstance(value, types.FunctionType):
        return [value]
    if isinstance(value, (staticmethod, classmethod)):
        return _functions_of(value.__func__)
    if isinstance(value, property):
        return [f for part in (value.fget, value.fset, value.fdel) for f in _functions_of(part)]
    return []


# A type whose attributes cannot be set or deleted (a C type such as NumPy's ndarray): nothing a
# run can change through setattr, and nothing this restore could put back, so it is not noted.
_IMMUTABLE = 1 << 8  # Py_TPFLAGS_IMMUTABLETYPE
_HOLDS_CODE = (types.FunctionType, staticmethod, classmethod, property)  # what _functions_of looks into


def _function_state(fn: types.FunctionType) -> tuple:
    """What a run could swap in a function: its code and its defaults."""
    return fn.__code__, fn.__defaults__, fn.__kwdefaults__


_STATE_OF = (attrgetter("__code__"), attrgetter("__defaults__"), attrgetter("__kwdefaults__"))


def _function_states(functions: tuple[types.FunctionType, ...]) -> tuple[tuple, ...]:
    """The functions' codes, defaults and keyword defaults, each in the functions' order."""
    return tuple(tuple(map(get, functions)) for get in _STATE_OF)


class Restore:
    def __init__(self, homes: Iterable[str] = STDLIB_HOMES, objects: Iterable[object] = ()) -> None:
        self.homes = tuple(homes)
        self.objects = list(objects)
        self.held = False  # whether the notes still describe the interpreter (see _notes_hold)
        self.table: dict[str, Any] = {}

    def _notes_hold(self) -> bool:
        """Whether noting again would give the notes this restore already has: it noted before and
        the interpreter binds, by identity, exactly what they say (no module loaded or dropped since,
        every noted namespace, class, container, function, hook and import list as noted). Checking
        costs about half of noting (no copies are made); one restore serves a sandbox's runs, and
        whatever ran between them (Pyodide loading a package, a snapshot's own set-up) is seen."""
        if not self.held or not _same_binding(sys.modules, self.table):
            return False
        return (all(_same_binding(space, saved) for space, saved in self.first)
                and all(_unchanged(space, kept) for space, kept in self.spaces + self.fields)
                and all(_same_binding(vars(cls), saved) for cls, saved in self.classes)
                and all(_same_items(container, saved) for container, saved in self.containers)
                and self._functions_unchanged()
                and all(_same_items(lst, items) for lst, items in self.imports)
                and (sys.gettrace(), sys.getprofile()) == self.hooks and sys.getrecursionlimit() == self.recursion
                and _numpy_state() == self.numpy)

    def _functions_unchanged(self) -> bool:
        """Whether every noted function still has the code and defaults noted (by identity)."""
        functions, states = self.functions
        return all(all(map(is_, now, then)) for now, then in zip(_function_states(functions), states))

    def __enter__(self) -> Restore:
        if self._notes_hold():
            return self
        self.first = [(space, dict(space)) for space in _FIRST]
        self.table = dict(sys.modules)
        self.spaces = [(mod.__dict__, _snapshot(mod.__dict__)) for mod in self.table.values()
                       if isinstance(getattr(mod, "__dict__", None), dict)]
        watched = [(name, mod) for name, mod in self.table.items()
                   if mod is not None and _in_homes(name, self.homes) and hasattr(mod, "__dict__")]
        self.classes = [(cls, dict(vars(cls))) for name, mod in watched for cls in list(vars(mod).values())
                        if isinstance(cls, type) and cls.__module__ == name and not cls.__flags__ & _IMMUTABLE]
        # Each container once, however many modules name it (every module names the builtins' dict).
        containers = {id(c): c for _, mod in watched for c in list(vars(mod).values()) if type(c) in (dict, list, set)}
        self.containers = [(c, _copy(c)) for c in containers.values()]
        self.fields = [(vars(obj), _snapshot(vars(obj))) for obj in self.objects if hasattr(obj, "__dict__")]
        holders = [vars(mod) for _, mod in watched] + [saved for _, saved in self.classes] \
            + [vars(obj) for obj in self.objects if hasattr(obj, "__dict__")]
        functions = {id(fn): fn for space in holders for value in list(space.values())
                     if isinstance(value, _HOLDS_CODE) for fn in _functions_of(value)}
        found = tuple(functions.values())
        self.functions = found, _function_states(found)
        self.recursion = sys.getrecursionlimit()
        self.hooks = sys.gettrace(), sys.getprofile()
        self.imports: list[tuple[list[Any], list[Any]]] = [
            (lst, list(lst)) for lst in (cast(list, sys.meta_path), cast(list, sys.path), cast(list, sys.path_hooks))]
        self.numpy = _numpy_state()
        return self

    def __exit__(self, *exc: object) -> None:
        self.held = False
        for space, saved in self.first:
            space.clear()
            space.update(saved)
        sys.settrace(self.hooks[0])
        sys.setprofile(self.hooks[1])
        for name, mod in self.table.items():
            if sys.modules.get(name, _MISSING) is not mod:
                sys.modules[name] = mod
        for name in [name for name in list(sys.modules) if name not in self.table]:
            if not _imported_as(sys.modules.get(name), name):
                sys.modules.pop(name, None)
        for lst, items in self.imports:
            if not _same_items(lst, items):
                lst[:] = items
        for where, kept in self.spaces + self.fields:
            _put_back(where, kept)
        for cls, saved in self.classes:
            if _same_binding(vars(cls), saved):
                continue
            for name in set(vars(cls)) - set(saved):
                _quietly(delattr, cls, name)
            for name, value in saved.items():
                if vars(cls).get(name, _MISSING) is not value:
                    _quietly(setattr, cls, name, value)
        for container, saved in self.containers:
            if not _same_items(container, saved):
                container.clear()
                (container.update if not isinstance(container, list) else container.extend)(saved)
        if not self._functions_unchanged():
            functions, states = self.functions
            for fn, code, defaults, kwdefaults in zip(functions, *states):
                if not all(map(is_, _function_state(fn), (code, defaults, kwdefaults))):
                    _quietly(setattr, fn, "__code__", code)
                    _quietly(setattr, fn, "__defaults__", defaults)
                    _quietly(setattr, fn, "__kwdefaults__", kwdefaults)
        sys.setrecursionlimit(self.recursion)
        random.seed()
        _reset_numpy(self.numpy)
        self.held = True


def _imported_as(mod: Any, name: str) -> bool:
    """Whether ``mod`` is a module the import system loaded as ``name`` (not an object planted there)."""
    spec = getattr(mod, "__spec__", None) if isinstance(mod, types.ModuleType) else None
    return spec is not None and getattr(spec, "name", None) == name


def _copy(container: Any) -> Any:
    return type(container)(container)


def _snapshot(space: dict) -> tuple[tuple, tuple]:
    return tuple(space), tuple(space.values())


def _unchanged(space: dict, snapshot: tuple[tuple, tuple]) -> bool:
    """Whether ``space`` binds the same names to the same objects, in the same order (by identity:
    an object's ``==`` is not to be trusted, nor called)."""
    keys, values = snapshot
    return len(space) == len(keys) and all(map(is_, space, keys)) and all(map(is_, space.values(), values))


def _same_binding(space: Mapping, saved: Mapping) -> bool:
    """Whether ``space`` binds the names of ``saved`` to the same objects, in the same order (by
    identity, as :func:`_unchanged`, against a saved copy instead of a snapshot)."""
    return len(space) == len(saved) and all(map(is_, space, saved)) and all(map(is_, space.values(), saved.values()))


def _same_items(container: Any, saved: Any) -> bool:
    if isinstance(container, dict):
        return _same_binding(container, saved)
    if isinstance(container, list):
        return len(container) == len(saved) and all(map(is_, container, saved))
    return container == saved


def _put_back(space: dict, snapshot: tuple[tuple, tuple]) -> None:
    """Make ``space`` bind exactly what ``snapshot`` held, without ever emptying it."""
    if _unchanged(space, snapshot):
        return
    saved = dict(zip(*snapshot))
    for name in [k for k in space if k not in saved]:
        del space[name]
    for name, value in saved.items():
        if space.get(name, _MISSING) is not value:
            space[name] = value


def _quietly(action, *args) -> None:
    try:
        action(*args)
    except (AttributeError, TypeError, ValueError):
        pass


def _numpy_state() -> tuple | None:
    np = sys.modules.get("numpy")
    if np is None:
        return None
    try:
        return np.geterr(), np.get_printoptions()
    except Exception:
        return None


def _reset_numpy(saved: tuple | None) -> None:
    """NumPy's error handling and print options as before the run (or its defaults, when the run
    loaded it); its global generator reseeded."""
    np = sys.modules.get("numpy")
    if np is None:
        return
    try:
        err, printing = saved or ({"divide": "warn", "over": "warn", "under": "ignore", "invalid": "warn"},
                                  _NUMPY_PRINT_DEFAULTS)
        np.seterr(**err)
        np.set_printoptions(**printing)
        np.random.seed()
    except Exception:
        pass  # a NumPy the run broke: the page replaces the sandbox after a run that was not plain
