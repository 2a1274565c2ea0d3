"""Build side: an exercise's statement, hint and derivation as HTML templates.

The chapter's Markdown may hold ``{{name}}`` placeholders where a variant's
numbers go (``workbook/variants.py``). Each part is converted once, with the
site's own Markdown extensions and the placeholders left in; the page prints
the template filled with variant 0's values, and the worker fills the same
template for any other variant. ``load_all`` does this for every chapter, for
tests and scripts that need the texts without a whole MkDocs build.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path

from blocks import ExerciseBlock, parse
from workbook.variants import fill, placeholders

PARTS = ("prompt", "hint", "solution")


@dataclass(frozen=True)
class ExerciseText:
    """The HTML templates of one exercise (a part may be empty)."""

    title: str
    prompt: str
    hint: str
    solution: str

    def names(self) -> list[str]:
        return list(dict.fromkeys(n for part in (self.title, *self.parts()) for n in placeholders(part)))

    def parts(self) -> tuple[str, str, str]:
        return self.prompt, self.hint, self.solution

    def filled(self, values: dict[str, str]) -> ExerciseText:
        return ExerciseText(**{k: fill(v, values) for k, v in asdict(self).items()})

    def as_dict(self) -> dict[str, str]:
        return asdict(self)


def text_of(block: ExerciseBlock, title: str, convert: Callable[[str], str]) -> ExerciseText:
    """Convert one block's parts; a placeholder lost in conversion is an error."""
    parts = {part: convert(block.text(part)) for part in PARTS}
    for part in PARTS:
        asked, kept = placeholders(block.text(part)), placeholders(parts[part])
        if sorted(asked) != sorted(kept):
            lost = sorted(set(asked) - set(kept))
            raise ValueError(f"exercise {block.id}: the {part}'s placeholder(s) {lost} did not survive Markdown")
    return ExerciseText(title=title, **parts)


def load_all(root: Path) -> dict[str, ExerciseText]:
    """Every exercise's templates, converted as ``mkdocs build`` converts them."""
    import markdown
    from mkdocs.config import load_config

    config = load_config(str(root / "mkdocs.yml"))
    md = markdown.Markdown(extensions=config.markdown_extensions, extension_configs=config.mdx_configs)

    def convert(text: str) -> str:
        return md.reset().convert(text.strip()) if text.strip() else ""

    found: dict[str, ExerciseText] = {}
    for path in sorted((root / "docs").rglob("*.md")):
        for block in parse(path.read_text(encoding="utf-8"), str(path)):
            if isinstance(block, ExerciseBlock):
                found[block.id] = text_of(block, block.title, convert)
    return found
