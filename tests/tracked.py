"""The files git tracks: what a fresh clone has, the one list the tests that ask "is every
source covered?" or "is nothing generated committed?" read."""

from __future__ import annotations

import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def tracked(*paths: str) -> list[str]:
    """The tracked files under ``paths`` (all of them when none is given), relative to the root."""
    out = subprocess.run(["git", "ls-files", "-z", "--", *paths], cwd=ROOT, capture_output=True, check=True).stdout
    return [n for n in out.decode().split("\0") if n]
