"""A message with mathematics in it, as the page typesets it.

Trace options and Design steps are written like the chapter: words, with TeX
between ``$`` signs. The verdict's ``message`` keeps that source; its
``data["math"]`` holds the same text cut into pieces, plain strings and
``{"tex": ...}`` formulas, which the page places as text and as KaTeX (it never
looks for ``$`` itself). Text without ``$`` needs no pieces.

>>> pieces("Right: $R^{-1} = R^\\\\top$, always.")
['Right: ', {'tex': 'R^{-1} = R^\\\\top'}, ', always.']
>>> math_data("No formula here."), math_data("$K = 1$")
({}, {'math': [{'tex': 'K = 1'}]})
>>> pieces("it costs $5")
Traceback (most recent call last):
...
ValueError: an odd number of $ (1) in 'it costs $5': every formula needs its closing $
"""

from __future__ import annotations

from typing import Any


def pieces(text: str) -> list[Any]:
    """``text`` as plain strings and ``{"tex": ...}`` formulas, in order (empty strings left out)."""
    parts = text.split("$")
    if len(parts) % 2 == 0:
        raise ValueError(f"an odd number of $ ({len(parts) - 1}) in {text!r}: every formula needs its closing $")
    out: list[Any] = []
    for i, part in enumerate(parts):
        if i % 2:
            if not part.strip():
                raise ValueError(f"an empty formula ($$) in {text!r}")
            out.append({"tex": part})
        elif part:
            out.append(part)
    return out


def math_data(text: str) -> dict[str, Any]:
    """The verdict ``data`` that lets the page typeset ``text``: ``{"math": pieces}``, or ``{}`` without TeX."""
    return {"math": pieces(text)} if "$" in text else {}
