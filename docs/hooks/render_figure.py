"""Build side: the static HTML of a figure, rendered by the MkDocs hook.

It holds the first frame (the SVG at the default control values), the
controls and the readouts, so the page shows a complete figure before the
Python runtime has started; ``docs/assets/js/figures.js`` then redraws it on
every change.

>>> html = figure_html("rotation-2d")
>>> html.startswith(f'<figure class="wb-figure" {role_attr(ROLE.figure)} {ATTR.figure}="rotation-2d"')
True
>>> f'{role_attr(ROLE.readout)} {ATTR.readout}="image"' in html
True
"""

from __future__ import annotations

from html import escape

from workbook.contract import ATTR, ROLE, role_attr
from workbook.figures import Control, Figure, get


def value_text(value: float, unit: str) -> str:
    """A control's value as the page shows it next to the slider.

    The page writes the slider's own value string followed by the unit, so this
    must match it: ``30°``, ``0.5 m``, ``-1``.

    >>> value_text(30.0, "°"), value_text(0.5, "m"), value_text(-1.0, "")
    ('30°', '0.5 m', '-1')
    """
    return f"{value:g}{unit_suffix(unit)}"


def unit_suffix(unit: str) -> str:
    """Degrees and percent sit on the number; other units get a space."""
    return unit if unit in ("", "°", "%") else " " + unit


def _control(fig: Figure, c: Control) -> str:
    cid = f"fig-{fig.name}-{c.name}"
    if c.kind == "toggle":
        pressed = "true" if c.default else "false"
        return (f'<div class="wb-fig-control wb-fig-toggle"><button type="button" id="{cid}" class="md-button" '
                f'{ATTR.param}="{c.name}" aria-pressed="{pressed}">{escape(c.label)}</button></div>')
    text = value_text(c.default, c.unit)
    return (
        f'<div class="wb-fig-control"><label for="{cid}">{escape(c.label)}</label>'
        f'<output for="{cid}" {role_attr(ROLE.control_value)}>{escape(text)}</output>'
        f'<input type="range" id="{cid}" {ATTR.param}="{c.name}" min="{c.min:g}" max="{c.max:g}" '
        f'step="{c.step:g}" value="{c.default:g}" data-suffix="{escape(unit_suffix(c.unit))}" '
        f'aria-valuetext="{escape(text)}"/></div>'
    )


def figure_html(name: str) -> str:
    """The whole ``<figure>`` element; raises FigureError for an unknown name."""
    fig = get(name)
    frame = fig.render()
    base = f"fig-{fig.name}"
    readouts = "".join(
        f'<div class="wb-fig-readout{" wb-fig-matrix" if r.matrix else ""}{" wb-fig-text" if r.text else ""}">'
        f'<dt>{escape(r.label)}</dt>'
        f'<dd {role_attr(ROLE.readout)} {ATTR.readout}="{r.key}">{escape(frame["readouts"][r.key])}</dd></div>'
        for r in fig.readouts
    )
    controls = "".join(_control(fig, c) for c in fig.controls)
    orbit = f' {ATTR.orbit}="{fig.orbit}"' if fig.orbit else ""
    return (
        f'<figure class="wb-figure" {role_attr(ROLE.figure)} {ATTR.figure}="{fig.name}" id="{base}" '
        f'{ATTR.flags}="{" ".join(frame["flags"])}" aria-labelledby="{base}-caption">'
        f'<div class="wb-fig-canvas" {role_attr(ROLE.figure_canvas)}{orbit}>{frame["svg"]}</div>'
        f'<div class="wb-fig-panel"><div class="wb-fig-controls">{controls}</div>'
        f'<dl class="wb-fig-readouts">{readouts}</dl></div>'
        f'<p class="wb-fig-status" {role_attr(ROLE.figure_status)} role="status"></p>'
        f'<figcaption id="{base}-caption"><strong>{escape(fig.title)}.</strong> {escape(fig.caption)}</figcaption>'
        f"</figure>"
    )
