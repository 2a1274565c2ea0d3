"""The README fits on a page, and every link of it and of the guides leads somewhere.

README.md is page one (at most 120 lines); the guides it sends people to (AUTHORING.md,
DEVELOPING.md, the page contract's index and parts, the teacher's guide on the site) link to
files and to sections of them. Each relative link must name a file of the repository, and
its `#anchor` a heading of that file: GitHub's anchors for the files read on GitHub, the
site's (MkDocs' table of contents) for the pages under docs/. Links in code are not links.
"""

from __future__ import annotations

import os
import re
import unicodedata
from pathlib import Path
from urllib.parse import unquote

import pytest

ROOT = Path(__file__).resolve().parents[2]
README_LINES = 120
GUIDES = sorted({
    ROOT / "README.md", ROOT / "AUTHORING.md", ROOT / "DEVELOPING.md", ROOT / "CONTRACT.md",
    *(ROOT / "contract").glob("*.md"), *(ROOT / "docs" / "teaching").glob("*.md"),
    *(ROOT / "docs" / "decisions").glob("*.md"), ROOT / "docs" / "performance.md",
})
FENCE = re.compile(r"^( *)(```|~~~).*?^\1\2[ \t]*$", re.M | re.S)
CODE_SPAN = re.compile(r"(`+).+?\1", re.S)
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^#{1,6}[ \t]+(.+?)[ \t#]*$", re.M)


def _prose(text: str) -> str:
    """The text without its code blocks and code spans (whose brackets are not links)."""
    return CODE_SPAN.sub("", FENCE.sub("", text))


def links(path: Path) -> list[str]:
    return LINK.findall(_prose(path.read_text(encoding="utf-8")))


def _heading_text(heading: str) -> str:
    heading = re.sub(r"\s*\{[^}]*\}\s*$", "", heading)  # an attribute list ({#id .class})
    heading = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link: its text
    return re.sub(r"[`*]", "", heading)


def github_slug(heading: str) -> str:
    """The anchor GitHub gives a heading: lower case, punctuation dropped, each space a hyphen."""
    text = _heading_text(heading).strip().lower()
    kept = "".join(ch for ch in text if ch in " -_" or unicodedata.category(ch)[0] in "LN")
    return kept.replace(" ", "-")


def site_slug(heading: str) -> str:
    """The anchor MkDocs' table of contents gives a heading (Python-Markdown's slugify)."""
    text = unicodedata.normalize("NFKD", _heading_text(heading)).encode("ascii", "ignore").decode()
    text = re.sub(r"[^\w\s-]", "", text).strip().lower()
    return re.sub(r"[-\s]+", "-", text)


def anchors(path: Path) -> set[str]:
    """The anchors of a Markdown file, as the place that shows it makes them."""
    text = FENCE.sub("", path.read_text(encoding="utf-8"))
    on_site = (ROOT / "docs") in path.parents
    slug = site_slug if on_site else github_slug
    found: set[str] = set()
    for heading in HEADING.findall(text):
        explicit = re.search(r"\{[^}]*#([\w-]+)[^}]*\}\s*$", heading)
        base = explicit.group(1) if explicit else slug(heading)
        name, n = base, 1
        while name in found:  # a repeated heading gets -1, -2, ... (GitHub) or _1, _2 (MkDocs)
            name = f"{base}{'_' if on_site else '-'}{n}"
            n += 1
        found.add(name)
    return found


def broken(path: Path) -> list[str]:
    """The links of ``path`` that lead nowhere, each with why."""
    out = []
    for target in links(path):
        if re.match(r"[a-z][a-z0-9+.-]*:", target):  # https:, mailto: (not checked: no network)
            continue
        file_part, _, anchor = unquote(target).partition("#")
        dest = (path.parent / file_part).resolve() if file_part else path
        if not dest.exists():
            out.append(f"{target}: no such file")
            continue
        if dest.is_dir():
            out.append(f"{target}: a folder (link to its index page instead)")
            continue
        if anchor and anchor not in anchors(dest):
            out.append(f"{target}: {os.path.relpath(dest, path.parent)} has no heading with the anchor #{anchor}")
    return out


def test_readme_fits_on_a_page():
    lines = (ROOT / "README.md").read_text(encoding="utf-8").count("\n")
    assert lines <= README_LINES, f"README.md has {lines} lines: page one keeps to {README_LINES}; move the rest to a guide"


def test_readme_sends_each_role_to_its_guide():
    said = links(ROOT / "README.md")
    for guide in ("docs/teaching/index.md", "AUTHORING.md", "DEVELOPING.md", "CONTRACT.md"):
        assert any(t.split("#")[0] == guide for t in said), f"README.md does not link to {guide}"
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "make serve" in readme and "make test" in readme and "PORT=" in readme


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_link_resolves(path):
    assert links(path) or path.name != "README.md"
    assert not broken(path), f"{path.relative_to(ROOT)}: " + "; ".join(broken(path))


def test_the_link_checker_sees_a_broken_link(tmp_path):
    # The checker itself: a missing file and a missing anchor are found, code is skipped.
    (tmp_path / "a.md").write_text("# Title here\n\n## Second: part (two)\n", encoding="utf-8")
    page = tmp_path / "b.md"
    page.write_text("[ok](a.md#second-part-two) [gone](c.md) [bad](a.md#third) `[code](x.md)`\n"
                    "```\n[fenced](y.md)\n```\n", encoding="utf-8")
    found = broken(page)
    assert found == ["c.md: no such file", "a.md#third: a.md has no heading with the anchor #third"]
