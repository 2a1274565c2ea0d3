"""Values as the sandbox reports them and as a test row shows them.

:func:`show` is the short text of a value (floats to six decimals, lists and
tuples item by item, cut at :data:`TEXT_CAP` characters); :func:`encode` turns
whatever a learner's function returned into plain JSON that the grader can
check without running anything: the type's name, that text, the number it
stands for, or its length and items. Nothing here trusts the value: a
``__repr__`` or ``__len__`` that raises, an int too long to print, a sequence of
a billion items, all give a short answer.

>>> show((3, 0, 1.5707963267948966)), show([2.0, "x"]), len(show("y" * 100))
('(3, 0, 1.570796)', "[2.0, 'x']", 80)
>>> encode((1, 2.5))["items"]
[{'type': 'int', 'number': 1, 'text': '1'}, {'type': 'float', 'number': 2.5, 'text': '2.5'}]
>>> big = encode(10 ** 400)
>>> big["number"], big["text"]
(None, 'an int of 401 digits')
"""

from __future__ import annotations

import itertools
import math
from typing import Any

TEXT_CAP = 80
ITEMS_CAP = 64  # items of a returned sequence reported (its length always is)
DEPTH_CAP = 3
BIG_INT_BITS = 1000  # beyond any float, and maybe beyond what str() prints


def clip(text: str, cap: int) -> str:
    """``text`` cut to ``cap`` characters, marked with an ellipsis when cut."""
    return text if len(text) <= cap else text[: cap - 1] + "…"


def _repr(value: Any) -> str:
    try:
        return clip(repr(value), TEXT_CAP)
    except (KeyboardInterrupt, MemoryError):
        raise
    except BaseException:  # a learner's __repr__ that raises or exits
        return f"<{clip(type(value).__name__, 40)} that cannot be shown>"


def _big_int(value: int) -> str:
    bits = value.bit_length()
    digits = str(len(str(value))) if bits < 10_000 else f"about {int(bits * 0.30103)}"  # str() refuses longer ints
    return f"an int of {digits} digits"


def _float(value: float) -> str:
    return repr(round(value, 6)) if math.isfinite(value) else repr(value)


def _text(value: Any, depth: int) -> str:
    if isinstance(value, bool):
        return repr(value)
    if isinstance(value, int):
        return _big_int(value) if value.bit_length() > BIG_INT_BITS else repr(int(value))
    if isinstance(value, float):
        return _float(float(value))
    if type(value) in (list, tuple) and depth < DEPTH_CAP:
        parts = [_text(item, depth + 1) for item in value[:ITEMS_CAP]] + (["…"] if len(value) > ITEMS_CAP else [])
        inner = ", ".join(parts)
        return f"({inner})" if isinstance(value, tuple) else f"[{inner}]"
    return _repr(value)


def show(value: Any) -> str:
    """A value as a test row shows it."""
    return clip(_text(value, 0), TEXT_CAP)


def _length(value: Any) -> int | None:
    """The length of a sequence the grader may compare item by item, else None."""
    if isinstance(value, (str, bytes, bytearray, dict)) or not hasattr(value, "__iter__"):
        return None
    try:
        length = len(value)
    except Exception:  # a 0-d NumPy array, an iterator, a __len__ that raises
        return None
    return length if isinstance(length, int) else None


def _items(value: Any) -> list | None:
    try:
        return list(itertools.islice(iter(value), ITEMS_CAP))
    except Exception:  # an __iter__ that raises
        return None


def encode(value: Any, depth: int = 0) -> dict[str, Any]:
    """What a learner's function returned, as plain JSON (see the module's docstring)."""
    kind = clip(type(value).__name__, 40)
    if isinstance(value, (bool, int)):
        number: float | None = int(value) if value.bit_length() <= BIG_INT_BITS else None
        return {"type": kind, "number": number, "text": show(value)}
    if isinstance(value, float):
        return {"type": kind, "number": float(value), "text": show(value)}
    length = _length(value) if depth < DEPTH_CAP else None
    items = _items(value) if length is not None else None
    if items is not None:
        return {"type": kind, "length": length, "text": show(value) if type(value) in (list, tuple) else _repr(value),
                "items": [encode(item, depth + 1) for item in items]}
    if hasattr(value, "__float__") and not isinstance(value, (str, bytes, complex)):  # NumPy's scalars, Fraction...
        try:
            number = float(value)
        except (TypeError, ValueError, OverflowError):
            number = None
        return {"type": kind, "number": number, "text": _float(number) if number is not None else _repr(value)}
    return {"type": kind, "number": None, "text": _repr(value)}
