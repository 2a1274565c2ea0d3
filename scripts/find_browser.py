#!/usr/bin/env python3
"""Print the Chromium the tests should drive: Playwright's own if it is
installed (``playwright install chromium``), else Debian's /usr/bin/chromium.
Exits 1 when there is none. Used by the Makefile and tests/browser/conftest.py.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path


def find_browser() -> str | None:
    override = os.environ.get("WORKBOOK_CHROMIUM")
    if override:
        return override
    try:
        from playwright.sync_api import sync_playwright

        with sync_playwright() as p:
            path = p.chromium.executable_path
        if path and Path(path).exists():
            return path
    except Exception:
        pass
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    return None


if __name__ == "__main__":
    path = find_browser()
    if not path:
        sys.exit(1)
    print(path)
