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
from workbook import bank
from workbook.kinds.build import Build
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


SOLUTION_CODE = "{{solution_code}}"  # where a Build exercise's derivation shows the bank's model solution


def source_of(block: ExerciseBlock, code: str | None = None) -> dict[str, str]:
    """The block's parts as Markdown; for a Build exercise (``code``: the bank's model solution),
    the derivation's ``{{solution_code}}`` line becomes that code, so the page shows what the tests pass."""
    parts = {part: block.text(part) for part in PARTS}
    if code is not None:
        if parts["solution"].count(SOLUTION_CODE) != 1:
            raise ValueError(f"exercise {block.id}: a Build exercise's derivation shows its model solution "
                             f"once, with a line {SOLUTION_CODE} (filled from the bank)")
        parts["solution"] = parts["solution"].replace(SOLUTION_CODE, f"```python\n{code.rstrip()}\n```")
    return parts


def text_of(block: ExerciseBlock, title: str, convert: Callable[[str], str], code: str | None = None) -> ExerciseText:
    """Convert one block's parts; a placeholder lost in conversion is an error."""
    source = source_of(block, code)
    parts = {part: convert(source[part]) for part in PARTS}
    for part in PARTS:
        asked, kept = placeholders(source[part]), placeholders(parts[part])
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
                ex = bank.get(block.id)
                found[block.id] = text_of(
                    block, block.title, convert, code=ex.solution if isinstance(ex, Build) else None
                )
    return found
