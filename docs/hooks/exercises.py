"""MkDocs hook: place each exercise's widget where its chapter page names it.

A chapter page writes an exercise as a block::

    ::: exercise 0.1 | Rotate a point by 90°
    The prompt, in Markdown.

    ::: hint
    Optional hint.
    :::

    ::: solution
    The derivation or explanation.
    :::
    :::

The hook renders the prompt, hint and solution with the site's own Markdown
extensions, asks the grading package (``workbook.render``) for the widget's
HTML, and fails the build on an unknown, duplicate or missing exercise id.

A line ``::: figure NAME`` (alone on its line, outside exercise blocks) places
an interactive figure: its first frame, controls and readouts come from
``workbook.figures.html``; an unknown name fails the build.
"""

from __future__ import annotations

import json
import logging
import re
from pathlib import Path

import markdown
from mkdocs.exceptions import PluginError

from workbook import bank, figures
from workbook.figures.html import figure_html
from workbook.render import dom_id, exercise_html

log = logging.getLogger("mkdocs.hooks.exercises")

OPEN = re.compile(r"^::: exercise\s+(?P<id>\S+)\s*(?:\|\s*(?P<title>.*?))?\s*$")
SECTION = re.compile(r"^::: (?P<name>hint|solution)\s*$")
CLOSE = re.compile(r"^:::\s*$")
SLOT = '<div data-wb-slot="{id}"></div>'
FIGURE = re.compile(r"^::: figure\s+(?P<name>\S+)\s*$")
FIGURE_SLOT = '<div data-wb-figure-slot="{name}"></div>'

_md: markdown.Markdown | None = None
_placed: dict[str, str] = {}  # exercise id -> page that holds it
_slots: dict[str, dict[str, str]] = {}  # page -> exercise id -> html
_figure_slots: dict[str, dict[str, str]] = {}  # page -> figure name -> html
_pages: dict[str, tuple[str, str]] = {}  # page -> (url, title), for the progress manifest
_nav_order: list[str] = []  # pages in navigation order
MANIFEST = "assets/exercises.json"  # which exercise ids each chapter holds (read by progress-ui.js)


def _convert(text: str) -> str:
    assert _md is not None
    return _md.reset().convert(text.strip())


def _inline(text: str) -> str:
    html = _convert(text)
    m = re.fullmatch(r"<p>(.*)</p>", html, re.S)
    return m.group(1) if m else html


def on_config(config, **kwargs):
    global _md
    _md = markdown.Markdown(extensions=config.markdown_extensions, extension_configs=config.mdx_configs)
    _placed.clear()
    _slots.clear()
    _figure_slots.clear()
    _pages.clear()
    return config


def _parse_blocks(text: str, page_path: str):
    """Yield (start, end, id, title, prompt, hint, solution) for each block, in order."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = OPEN.match(lines[i])
        if not m:
            i += 1
            continue
        start, parts, current, depth = i, {"prompt": [], "hint": [], "solution": []}, "prompt", 0
        i += 1
        while True:
            if i >= len(lines):
                raise PluginError(f"{page_path}: exercise {m['id']} is not closed with ':::'")
            line = lines[i]
            if SECTION.match(line) and current == "prompt" and depth == 0:
                current = SECTION.match(line)["name"]
            elif CLOSE.match(line) and current != "prompt" and depth == 0:
                current = "prompt"
            elif CLOSE.match(line) and current == "prompt" and depth == 0:
                break
            else:
                if line.lstrip().startswith("```"):
                    depth = 1 - depth
                parts[current].append(line)
            i += 1
        yield start, i, m["id"], (m["title"] or "").strip(), *("\n".join(parts[k]) for k in ("prompt", "hint", "solution"))
        i += 1


def on_page_markdown(text, page, config, files, **kwargs):
    path = page.file.src_uri
    out_lines = text.split("\n")
    replacements = []
    slots: dict[str, str] = {}
    for start, end, ex_id, title, prompt, hint, solution in _parse_blocks(text, path):
        try:
            ex = bank.get(ex_id)
        except KeyError:
            raise PluginError(f"{path}: unknown exercise id {ex_id!r} (no such exercise in the grading package)") from None
        if ex_id in _placed and _placed[ex_id] != path or ex_id in slots:
            raise PluginError(f"{path}: exercise {ex_id} is placed twice (also in {_placed.get(ex_id, path)})")
        _placed[ex_id] = path
        title = title or ex.title
        slots[ex_id] = exercise_html(ex, _convert(prompt), _convert(hint) if hint.strip() else "",
                                     _convert(solution) if solution.strip() else "", _inline)
        block = f"### {ex_id} · {title} {{ #{dom_id(ex_id)}-title }}\n\n{SLOT.format(id=ex_id)}\n"
        replacements.append((start, end, block))
    for start, end, block in reversed(replacements):
        out_lines[start : end + 1] = [block]
    _slots[path] = slots
    return "\n".join(_place_figures(out_lines, path))


def _place_figures(lines: list[str], path: str) -> list[str]:
    """Swap each ``::: figure NAME`` line for a slot and remember its HTML."""
    placed = _figure_slots.setdefault(path, {})
    placed.clear()
    out = []
    for line in lines:
        m = FIGURE.match(line)
        if m:
            name = m["name"]
            if name not in figures.names():
                raise PluginError(f"{path}: unknown figure {name!r} (known: {', '.join(figures.names())})")
            if name in placed:
                raise PluginError(f"{path}: figure {name!r} is placed twice on this page")
            placed[name] = figure_html(name)
            line = "\n" + FIGURE_SLOT.format(name=name) + "\n"
        out.append(line)
    return out


def on_page_content(html, page, config, files, **kwargs):
    slots = _slots.get(page.file.src_uri, {})
    for ex_id, widget in slots.items():
        slot = SLOT.format(id=ex_id)
        if slot not in html:
            raise PluginError(f"{page.file.src_uri}: the widget slot of exercise {ex_id} was lost in rendering")
        html = html.replace(slot, widget)
    for name, figure in _figure_slots.get(page.file.src_uri, {}).items():
        slot = FIGURE_SLOT.format(name=name)
        if slot not in html:
            raise PluginError(f"{page.file.src_uri}: the slot of figure {name!r} was lost in rendering")
        html = html.replace(slot, figure)
    return html


def on_post_build(config, **kwargs):
    missing = [ex.id for ex in bank.all_exercises() if ex.id not in _placed]
    if missing:
        raise PluginError(f"exercises with no page: {', '.join(missing)} (place each with '::: exercise ID')")
    _write_manifest(config)


def on_nav(nav, config, files, **kwargs):
    _nav_order[:] = [page.file.src_uri for page in nav.pages]
    return nav


def on_page_context(context, page, config, nav, **kwargs):
    _pages[page.file.src_uri] = (page.url, page.title or "")
    return context


def _write_manifest(config) -> None:
    """site/assets/exercises.json: the chapters in navigation order and the ids on each."""
    order = {src: i for i, src in enumerate(_nav_order)}
    chapters = [
        {"url": _pages[src][0], "title": _pages[src][1], "ids": list(ids)}
        for src, ids in sorted(_slots.items(), key=lambda item: (order.get(item[0], len(order)), item[0]))
        if ids and src in _pages
    ]
    out = Path(config.site_dir) / MANIFEST
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"version": 1, "chapters": chapters}, ensure_ascii=False, separators=(",", ":")))
