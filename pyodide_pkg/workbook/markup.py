"""Widget markup every answer area shares (a leaf: exercise kinds and answer kinds both draw with it)."""

from __future__ import annotations

from .contract import ATTR, ROLE, role_attr


def check_button() -> str:
    """The Check button that submits an answer area's form."""
    return f'<button type="submit" class="md-button md-button--primary wb-check" {role_attr(ROLE.check)}>Check</button>'


def form(kind: str, inner: str) -> str:
    """An answer area's form, for exercise or answer kind ``kind``."""
    return f'<form class="wb-form wb-{kind}" novalidate>{inner}</form>'


#: the symbols every answer may need, beyond letters and digits (the phone's keypad row, keypad.js)
KEYPAD = ("−", "+", "×", "/", "^", "(", ")", "√", "π", "°")


def keypad(variables: tuple[str, ...] = (), units: tuple[str, ...] = ()) -> str:
    """The ``data-keys`` attribute of an answer input: the symbols the phone's keypad row offers
    for it, space-separated: :data:`KEYPAD`, the Greek letters of the variables, then the units
    the answer is read in (each once).

    >>> keypad(("theta1", "L1"), ("m", "m", "rad"))
    'data-keys="− + × / ^ ( ) √ π ° θ m rad"'
    """
    from .expr.grammar import GREEK  # the spellings the reader takes
    greek = {name: letter for letter, name in GREEK.items() if letter not in "πϕ"}
    letters = [greek[base] for base in (v.rstrip("0123456789_") for v in variables) if base in greek]
    keys = dict.fromkeys([*KEYPAD, *letters, *(u for u in units if u and " " not in u)])
    return f'{ATTR.keys}="{" ".join(keys)}"'
