"""Runs one of the page-side test files in ``tests/js/`` with Node's test runner."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def run_node_test(name: str, env: dict[str, str] | None = None, timeout: float = 120) -> str:
    """Node's report of ``tests/js/<name>`` (with ``env`` added to the environment); fails the
    calling test with that report when Node is missing or a case fails."""
    node = shutil.which("node")
    if node is None:
        pytest.fail("Node is needed for the page-side tests (README.md: Node 20+)")
    run = subprocess.run([node, "--experimental-default-type=module", "--no-warnings", "--test", f"tests/js/{name}"],
                         cwd=ROOT, env={**os.environ, **(env or {})}, capture_output=True, text=True, timeout=timeout)
    assert run.returncode == 0, run.stdout[-6000:] + run.stderr[-2000:]
    return run.stdout
