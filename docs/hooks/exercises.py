"""MkDocs hook: place each exercise's widget and each figure where its page names it.

``blocks.parse`` reads the ``:::`` blocks of a page (strictly: anything it does
not understand fails the build). For each exercise block the hook renders the
prompt, hint and solution with the site's own Markdown extensions, and
``render_exercise`` builds the widget around the HTML its kind draws. The build
fails on an unknown, duplicate or missing exercise id, an unknown kind (one not
in the contract, or without its page module ``docs/assets/js/kinds/K.js``), an
answer kind without its package (``workbook/answer_kinds/A/`` and
``docs/assets/js/answer-kinds/A.js``), an unknown figure, and a ``{{name}}``
placeholder that the exercise's generator does not fill (``exercise_text.py``).
It also writes ``assets/exercises.json`` (the chapters and the ids on each, each
exercise's title, which ones draw variants and which join the review queue: for the
progress pages and the Practise page; and, for the teach page, why an exercise has the same
right answer for every student, ``sameAnswer``) and exposes the contract to the theme
templates as ``config.extra.contract``.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

import markdown
from mkdocs.exceptions import PluginError
from mkdocs.utils import get_relative_url

from blocks import BlockError, ExerciseBlock, FigureBlock, parse
from exercise_text import text_of
from render_exercise import PageTools, chapter_list_html, dom_id, exercise_html, exercise_index_html
from render_figure import figure_html
from workbook import bank, copying, figures, registry
from workbook.contract import ANSWER_KINDS, DATA, KINDS, REVIEW_KINDS
from workbook.kinds.build import Build
from workbook.variants import VariantError, fill

SLOT = '<div data-wb-slot="{id}"></div>'
CHAPTER_LIST = "<div data-wb-chapter-list></div>"  # the home page's list of chapters, filled from the menu
MANIFEST = "assets/exercises.json"
JS = Path(__file__).resolve().parent.parent / "assets" / "js"


@dataclass
class BuildState:
    """Everything one build learns, page by page (a new one at every on_config)."""

    md: markdown.Markdown
    placed: dict[str, str] = field(default_factory=dict)  # exercise id -> page
    slots: dict[str, dict[str, str]] = field(default_factory=dict)  # page -> slot html -> widget html
    ids: dict[str, list[str]] = field(default_factory=dict)  # page -> exercise ids in order
    titles: dict[str, str] = field(default_factory=dict)  # exercise id -> title as printed (variant 0)
    pages: dict[str, tuple[str, str]] = field(default_factory=dict)  # page -> (url, title)
    nav: list[str] = field(default_factory=list)

    def convert(self, text: str) -> str:
        return self.md.reset().convert(text.strip()) if text.strip() else ""

    def inline(self, text: str) -> str:
        html = self.convert(text)
        m = re.fullmatch(r"<p>(.*)</p>", html, re.S)
        return m.group(1) if m else html


_state: BuildState | None = None


def _built() -> BuildState:
    """The build's state, which on_config makes before MkDocs calls any page hook."""
    if _state is None:
        raise PluginError("exercises hook: a page hook ran before on_config")
    return _state


def _check_kinds() -> None:
    for ex in bank.all_exercises():
        if ex.kind not in KINDS:
            raise PluginError(f"exercise {ex.id} has kind {ex.kind!r}, which contract.json does not list")
    for folder, names in (("kinds", KINDS), ("answer-kinds", ANSWER_KINDS)):
        for name in names:
            if not (JS / folder / f"{name}.js").is_file():
                raise PluginError(f"{name!r} has no page module docs/assets/js/{folder}/{name}.js")
    for parts in registry.ALL:  # every kind, answer kind, chapter module, figure and run figure loads, under its name
        try:
            parts.check()
        except (KeyError, TypeError, ImportError) as err:
            raise PluginError(f"the grading package's {parts.what}s: {err}") from None


def on_config(config, **kwargs):
    global _state
    _check_kinds()
    _state = BuildState(markdown.Markdown(extensions=config.markdown_extensions, extension_configs=config.mdx_configs))
    config.extra["contract"] = DATA
    return config


def _exercise(state: BuildState, block: ExerciseBlock, path: str) -> tuple[str, str]:
    """The Markdown that replaces the block, and the widget that fills its slot."""
    try:
        ex = bank.get(block.id)
    except KeyError:
        raise PluginError(f"{path}: unknown exercise id {block.id!r} (no such exercise in the grading "
                          "package)") from None
    if block.id in state.placed:
        raise PluginError(f"{path}: exercise {block.id} is placed twice (also in {state.placed[block.id]})")
    state.placed[block.id] = path
    try:
        text = text_of(block, block.title, state.convert, code=ex.solution if isinstance(ex, Build) else None)
    except ValueError as err:
        raise PluginError(f"{path}: {err}") from None
    values = getattr(ex, "values", {})
    try:
        shown = text.filled(values)  # variant 0: the workbook's own numbers
        title = fill(block.title, values, html=False) or ex.title
    except VariantError as err:
        raise PluginError(f"{path}: exercise {block.id}: {err}") from None
    templates = text.as_dict() if getattr(ex, "vary", None) is not None else None
    unfilled = [name for name in text.names() if name not in values]
    if templates is None and unfilled:
        raise PluginError(f"{path}: exercise {block.id} has placeholders {unfilled} but no generator (vary=...) or "
                          "values")
    widget = exercise_html(ex, shown.prompt, shown.hint, shown.solution, PageTools(inline=state.inline), templates)
    state.titles[block.id] = title
    slot = SLOT.format(id=block.id)
    return f"### {block.id} · {title} {{ #{dom_id(block.id)}-title }}\n\n{slot}\n", widget


def _figure(block: FigureBlock, path: str, seen: set[str]) -> tuple[str, str]:
    if block.name not in figures.names():
        raise PluginError(f"{path}: unknown figure {block.name!r} (known: {', '.join(figures.names())})")
    if block.name in seen:
        raise PluginError(f"{path}: figure {block.name!r} is placed twice on this page")
    seen.add(block.name)
    slot = f'<div data-wb-slot="figure:{block.name}"></div>'
    return f"\n{slot}\n", figure_html(block.name)


def on_page_markdown(text, page, config, files, **kwargs):
    state, path = _built(), page.file.src_uri
    try:
        found = parse(text, path)
    except BlockError as err:
        raise PluginError(str(err)) from None
    lines = text.split("\n")
    slots: dict[str, str] = {}
    ids: list[str] = []
    figures_seen: set[str] = set()
    for block in reversed(found):
        if isinstance(block, ExerciseBlock):
            markdown_text, widget = _exercise(state, block, path)
            lines[block.start : block.end + 1] = [markdown_text]
            ids.insert(0, block.id)
        else:
            markdown_text, widget = _figure(block, path, figures_seen)
            lines[block.line : block.line + 1] = [markdown_text]
        slots[markdown_text.strip().splitlines()[-1]] = widget
    state.slots[path], state.ids[path] = slots, ids
    return "\n".join(lines)


def on_page_content(html, page, config, files, **kwargs):
    for slot, widget in _built().slots.get(page.file.src_uri, {}).items():
        if slot not in html:
            raise PluginError(f"{page.file.src_uri}: the slot {slot} was lost in rendering")
        html = html.replace(slot, widget)
    ids = _built().ids.get(page.file.src_uri)
    for i in ids or []:
        # The exercise is a region named by its title: the heading's text without its permalink's "¶".
        heading = re.compile(rf'(<h\d id="{dom_id(i)}-title">)(.*?)(<a class="headerlink"|</h\d>)', re.S)
        html, found = heading.subn(rf'\1<span id="{dom_id(i)}-name">\2</span>\3', html, count=1)
        if not found:
            raise PluginError(f"{page.file.src_uri}: exercise {i} has no heading to name it")
    if ids:
        # The page's exercises listed under its title: the target of the "Skip to exercises" link (a11y.py).
        index = exercise_index_html([(i, _built().titles[i]) for i in ids])
        html = html.replace("</h1>", "</h1>" + index, 1) if "</h1>" in html else index + html
    return html


def on_nav(nav, config, files, **kwargs):
    _built().nav[:] = [page.file.src_uri for page in nav.pages]
    return nav


CHAPTER_PACKAGE = "workbook.compiled.ch{}.zip"  # scripts/split_stdlib.py writes one per chapter


def chapter_package(ids: list[str] | None, config) -> str | None:
    """The part of the compiled grading package a page's grader mounts on a plain start: its chapter's when
    all its exercises are one chapter's (and the build wrote it), else None (the whole package)."""
    chapters = {i.split(".")[0] for i in ids or []}
    if len(chapters) != 1:
        return None
    name = CHAPTER_PACKAGE.format(chapters.pop())
    return name if (Path(config["docs_dir"]) / "assets/vendor/pyodide" / name).is_file() else None


def on_page_context(context, page, config, nav, **kwargs):
    _built().pages[page.file.src_uri] = (page.url, page.title or "")
    context["wb_grader_package"] = chapter_package(_built().ids.get(page.file.src_uri), config)
    if page.content and CHAPTER_LIST in page.content:
        # Every page has been read by now: the chapters' own titles (their H1s) are known.
        chapters = [(get_relative_url(p.url, page.url), p.title) for p in nav.pages if _built().ids.get(p.file.src_uri)]
        page.content = page.content.replace(CHAPTER_LIST, chapter_list_html(chapters))
    return context


def on_post_build(config, **kwargs):
    missing = [ex.id for ex in bank.all_exercises() if ex.id not in _built().placed]
    if missing:
        raise PluginError(f"exercises with no page: {', '.join(missing)} (place each with '::: exercise ID')")
    order = {src: i for i, src in enumerate(_built().nav)}
    chapters = [
        {"url": _built().pages[src][0], "title": _built().pages[src][1], "ids": ids}
        for src, ids in sorted(_built().ids.items(), key=lambda item: (order.get(item[0], len(order)), item[0]))
        if ids and src in _built().pages
    ]
    out = Path(config.site_dir) / MANIFEST
    out.parent.mkdir(parents=True, exist_ok=True)
    everything = bank.all_exercises()
    variants = [ex.id for ex in everything if getattr(ex, "vary", None) is not None]
    reviewed = [ex.id for ex in everything if ex.kind in REVIEW_KINDS]
    titles = {ex.id: ex.title for ex in everything}
    same = {ex.id: why for ex in everything if (why := copying.same_answer(ex))}
    out.write_text(json.dumps({"version": 2, "chapters": chapters, "variants": variants, "reviewed": reviewed,
                               "titles": titles, "sameAnswer": same},
                              ensure_ascii=False, separators=(",", ":")))
