"""Widget markup every answer area shares (a leaf: exercise kinds and answer kinds both draw with it)."""

from __future__ import annotations

from .contract import ROLE, role_attr


def check_button() -> str:
    """The Check button that submits an answer area's form."""
    return f'<button type="submit" class="md-button md-button--primary wb-check" {role_attr(ROLE.check)}>Check</button>'


def form(kind: str, inner: str) -> str:
    """An answer area's form, for exercise or answer kind ``kind``."""
    return f'<form class="wb-form wb-{kind}" novalidate>{inner}</form>'
