#!/usr/bin/env python3
"""Print the Chromium the tests drive (``--full``: the whole browser, which the bench drives).
Exits 1 when there is none. Used by the Makefile,
tests/browser/conftest.py and scripts/bench (which asks for the full browser, as learners run it).

Headless Chromium comes in two builds of one engine: the full browser run without a window,
and the *headless shell* (``chromium-headless-shell``, what Playwright itself launches for
headless runs), which leaves out the browser's own interface. Pages, workers and service
workers behave the same in both; the shell spends about a third less CPU per page load,
because the full browser also runs its toolbar's WebUI renderer on every navigation. So the
order is: ``$WORKBOOK_CHROMIUM``; a headless shell (Debian's, then Playwright's own from
``playwright install chromium``); a full Chromium (Playwright's, then the system's).
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

SHELLS = ("chromium-headless-shell", "headless_shell")
FULL = ("chromium", "chromium-browser", "google-chrome")


def playwright_browsers() -> Path:
    return Path(os.environ.get("PLAYWRIGHT_BROWSERS_PATH") or Path.home() / ".cache" / "ms-playwright")


def find_browser(shell: bool = True) -> str | None:
    """The executable to launch: a headless shell if there is one (unless ``shell`` is false),
    else a full Chromium; None when there is neither."""
    override = os.environ.get("WORKBOOK_CHROMIUM")
    if override:
        return override
    if shell:
        on_path = next((found for name in SHELLS if (found := shutil.which(name))), None)
        if on_path:
            return on_path
        own = sorted(playwright_browsers().glob("chromium_headless_shell-*/chrome-*/*headless_shell"))
        if own:
            return str(own[-1])
    try:
        from playwright.sync_api import sync_playwright

        with sync_playwright() as p:
            path = p.chromium.executable_path
        if path and Path(path).exists():
            return path
    except Exception:
        pass
    return next((found for name in FULL if (found := shutil.which(name))), None)


if __name__ == "__main__":
    if sys.argv[1:] == ["--shell"]:  # exit 0 when a headless shell is there (or one is named)
        if os.environ.get("WORKBOOK_CHROMIUM"):
            sys.exit(0)
        path = find_browser()
        sys.exit(0 if path and Path(path).name in SHELLS else 1)
    path = find_browser(shell=sys.argv[1:] != ["--full"])  # --full: the whole browser (make bench)
    if not path:
        sys.exit(1)
    print(path)
