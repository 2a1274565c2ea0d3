"""The grader names itself: ``{"op": "version"}`` gives the package's version (pyproject.toml's)
and a hash of its sources that any change to an exercise, key, slip or grader changes, the
same from a source tree as from a zip of the minified sources (the page's standard library,
scripts/split_stdlib.py)."""

from __future__ import annotations

import json
import subprocess
import sys
import tomllib
import zipfile
from pathlib import Path

from workbook import api, version

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from split_stdlib import minify

PKG = Path(version.__file__).resolve().parent
PYPROJECT = PKG.parent / "pyproject.toml"


def _zip_hash(tmp_path: Path, change: str | None = None) -> str:
    archive = tmp_path / f"wb-{bool(change)}.zip"
    with zipfile.ZipFile(archive, "w") as z:
        for p in sorted(PKG.rglob("*")):
            if p.is_file() and "__pycache__" not in p.parts and p.suffix in (".py", ".json"):
                data = p.read_bytes()
                if change and p.name == change:
                    data = data.replace(b"ROTATE", b"ROTATE_FIXED", 1) if b"ROTATE" in data else data + b"\nFIXED = 1\n"
                name = "workbook/" + p.relative_to(PKG).as_posix()
                z.writestr(name, minify(data, name) if p.suffix == ".py" else data)
    code = f"import sys; sys.path.insert(0, {str(archive)!r}); from workbook import version; print(version.bank_hash(), version.__file__)"
    out = subprocess.run([sys.executable, "-S", "-c", code], capture_output=True, text=True, cwd=tmp_path, check=True).stdout.split()
    assert out[1].startswith(str(archive)), out  # read from the zip, not from the tree
    return out[0]


def test_the_version_op_names_the_package_version_and_the_bank_hash():
    reply = json.loads(api.handle(json.dumps({"op": "version"})))
    assert reply == {"ok": True, "value": {"version": version.VERSION, "bank": version.bank_hash()}}
    assert tomllib.loads(PYPROJECT.read_text())["project"]["version"] == version.VERSION
    bank = version.bank_hash()
    assert bank and len(bank) == 12 and int(bank, 16) >= 0


def test_the_bank_hash_is_the_same_from_a_zip_and_changes_with_a_source(tmp_path):
    assert _zip_hash(tmp_path) == version.bank_hash()
    assert _zip_hash(tmp_path, change="ch0_rotations_2d.py") != version.bank_hash()
