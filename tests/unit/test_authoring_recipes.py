"""AUTHORING.md's "Adding a chapter" and "Adding a Build exercise", followed in a copy of the repository.

Each test copies what the build reads (mkdocs.yml, docs/, the two packages, the page contract, the
licences and scripts/notices.py) into
a temporary directory and applies every step of the recipe that has code, exactly as AUTHORING.md
writes it: "Create `PATH`:", "In `PATH`, after the line starting `TEXT`, add:" and "At the end
of `PATH`, add:", each followed by its code block. Then it builds: every registered part loads
(``workbook.registry``), the new exercise grades, the contract's table of Build functions is the
bank's, and ``mkdocs build --strict`` writes the site with the new exercise on its page and the
page in the menu. A step AUTHORING.md leaves out, or gets wrong, fails one of these. (The steps
without code, the golden files and the tests' lists, are checked by the suite itself.)
"""

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from markdown_table import table_after

ROOT = Path(__file__).resolve().parents[2]
GUIDE = (ROOT / "AUTHORING.md").read_text(encoding="utf-8")  # the author's guide (README.md links to it)
STEP = re.compile(
    r"(?:Create\s+`(?P<create>[^`]+)`"
    r"|In\s+`(?P<into>[^`]+)`,\s+after\s+the\s+line\s+starting\s+`(?P<anchor>[^`]+)`,\s+add"
    r"|At\s+the\s+end\s+of\s+`(?P<end>[^`]+)`,\s+add):\n\n"
    r"(?P<indent> *)```[a-z]*\n(?P<body>.*?)\n(?P=indent)```",
    re.S,
)
# Run in a fresh interpreter on the copy: every registry loads, then what the exercise is and does.
PROBE = """
import json, sys
from workbook import bank, registry
for parts in registry.ALL:
    parts.check()
ex = bank.get(sys.argv[1])
out = {"kind": ex.kind, "builds": {e.id: e.signature for e in bank.all_exercises() if e.kind == "build"},
       "chapter": [e.id for e in bank.chapter(int(ex.id.split(".")[0]))]}
if ex.kind == "build":
    out["solution"], out["starter"] = ex.check(ex.solution).status, ex.check(ex.starter).status
else:
    out["key"] = ex.check(str(ex.answer.key)).status
print(json.dumps(out))
"""


def recipe(title: str) -> list[re.Match]:
    """The steps with code of AUTHORING.md's section ``title``, in order."""
    start = GUIDE.index(f"\n## {title}\n")
    end = GUIDE.find("\n## ", start + 1)
    return list(STEP.finditer(GUIDE[start:end if end > 0 else None]))


def _body(step: re.Match) -> str:
    indent = len(step["indent"])
    return "\n".join(line[indent:] for line in step["body"].split("\n")) + "\n"


def follow(title: str, root: Path) -> list[str]:
    """Apply the recipe's steps to the copy at ``root``; the files they touched."""
    touched = []
    for step in recipe(title):
        path = root / (step["create"] or step["into"] or step["end"])
        body = _body(step)
        if step["create"]:
            assert not path.exists(), f"AUTHORING.md: {path.relative_to(root)} is there already"
            path.write_text(body, encoding="utf-8")
        elif step["end"]:
            path.write_text(path.read_text(encoding="utf-8") + body, encoding="utf-8")
        else:
            lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
            at = [i for i, line in enumerate(lines) if line.lstrip().startswith(step["anchor"])]
            assert len(at) == 1, f"AUTHORING.md: {step['anchor']!r} starts {len(at)} lines of {path.relative_to(root)}"
            lines.insert(at[0] + 1, body)
            path.write_text("".join(lines), encoding="utf-8")
        touched.append(str(path.relative_to(root)))
    return touched


def copy_repo(root: Path) -> None:
    junk = shutil.ignore_patterns("__pycache__", "*.pyc")
    shutil.copy2(ROOT / "mkdocs.yml", root / "mkdocs.yml")
    shutil.copy2(ROOT / "CONTRACT.md", root / "CONTRACT.md")
    shutil.copytree(ROOT / "contract", root / "contract")  # its parts, one per audience
    shutil.copytree(ROOT / "docs", root / "docs", ignore=junk)
    # The notices page's hook (docs/hooks/notices_page.py) runs scripts/notices.py over the licences
    # and what the build used (node_modules: linked, not copied).
    (root / "scripts").mkdir()
    for name in ("scripts/notices.py", "LICENSE", "LICENSE-text.md"):
        shutil.copy2(ROOT / name, root / name)
    (root / "node_modules").symlink_to(ROOT / "node_modules", target_is_directory=True)
    for package in ("workbook", "workbook_sandbox"):
        shutil.copytree(ROOT / "pyodide_pkg" / package, root / "pyodide_pkg" / package, ignore=junk)


def build(root: Path, exercise: str) -> dict:
    """The probe's findings on ``exercise`` in the copy, after ``mkdocs build --strict`` into root/site."""
    env = {**os.environ, "PYTHONPATH": str(root / "pyodide_pkg"), "NO_MKDOCS_2_WARNING": "1"}
    probe = subprocess.run([sys.executable, "-c", PROBE, exercise], cwd=root, env=env, capture_output=True, text=True)
    assert probe.returncode == 0, probe.stderr[-3000:]
    mkdocs = Path(sys.executable).with_name("mkdocs")
    built = subprocess.run([str(mkdocs), "build", "--strict", "--quiet", "-d", str(root / "site")], cwd=root, env=env,
                           capture_output=True, text=True)
    assert built.returncode == 0, built.stderr[-3000:]
    return json.loads(probe.stdout)


def contract_builds(root: Path) -> dict[str, str]:
    """The page contract's table of Build functions in the copy (contract/pages.md): id -> signature."""
    text = (root / "contract" / "pages.md").read_text(encoding="utf-8")
    rows = table_after(text, "The Build exercises' functions")
    return {row[0]: row[1].strip("`") for row in rows}


needs_site = pytest.mark.skipif(not (ROOT / "docs" / "assets" / "dist").is_dir(),
                                reason="the page bundle is built by `make site` (make test builds it first)")


@needs_site
def test_adding_a_chapter_as_authoring_says_builds(tmp_path):
    copy_repo(tmp_path)
    touched = follow("Adding a chapter", tmp_path)
    assert touched == ["pyodide_pkg/workbook/reference/odometry.py", "pyodide_pkg/workbook/bank/ch14_odometry.py",
                       "docs/chapters/14-odometry.md", "mkdocs.yml"]
    found = build(tmp_path, "14.1")
    assert found["kind"] == "derive" and found["chapter"] == ["14.1"] and found["key"] == "correct"
    page = (tmp_path / "site" / "chapters" / "14-odometry" / "index.html").read_text(encoding="utf-8")
    assert 'data-exercise-id="14.1"' in page
    home = (tmp_path / "site" / "index.html").read_text(encoding="utf-8")
    assert 'href="chapters/14-odometry/"' in home, "the chapter is not in the menu"
    chapters = json.loads((tmp_path / "site" / "assets" / "exercises.json").read_text(encoding="utf-8"))["chapters"]
    urls = [c["url"] for c in chapters]  # the new chapter sits where the recipe put it, after chapter 13
    at = urls.index("chapters/14-odometry/")
    assert chapters[at]["ids"] == ["14.1"] and urls[at - 1] == "chapters/13-aligning-point-sets/"


@needs_site
def test_adding_a_build_exercise_as_authoring_says_builds(tmp_path):
    copy_repo(tmp_path)
    touched = follow("Adding a Build exercise", tmp_path)
    assert touched == ["pyodide_pkg/workbook/reference/rotation2d.py", "pyodide_pkg/workbook/bank/ch0_code.py",
                       "docs/chapters/00-rotations-2d.md", "contract/pages.md"]
    found = build(tmp_path, "0.9")
    assert found["kind"] == "build" and found["chapter"][-1] == "0.9"
    assert (found["solution"], found["starter"]) == ("correct", "incorrect")
    assert contract_builds(tmp_path) == found["builds"], "the contract's table of Build functions is not the bank's"
    page = (tmp_path / "site" / "chapters" / "00-rotations-2d" / "index.html").read_text(encoding="utf-8")
    assert 'data-exercise-id="0.9"' in page
