"""No source file over 400 lines: a module that grows past it is split by what it does.

Counted: the project's own code and styles as git tracks them (Python, JavaScript, CSS, templates,
the Makefile and the scripts). Not counted: Markdown pages, data (JSON, locks) and the goldens."""

from __future__ import annotations

from pathlib import Path

from tracked import tracked

ROOT = Path(__file__).resolve().parents[2]
LIMIT = 400
SOURCE = (".py", ".js", ".mjs", ".ts", ".css", ".j2", ".html", ".sh")


def sources() -> list[Path]:
    return [ROOT / n for n in tracked() if n.endswith(SOURCE) or Path(n).name in ("Makefile", "run")]


def test_no_source_file_is_over_400_lines():
    files = [p for p in sources() if p.is_file()]
    assert len(files) > 100, len(files)
    long = {str(p.relative_to(ROOT)): n for p in files
            if (n := len(p.read_text(encoding="utf-8", errors="replace").splitlines())) > LIMIT}
    assert long == {}, f"over {LIMIT} lines: {long}"
