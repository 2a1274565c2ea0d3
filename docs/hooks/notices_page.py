"""MkDocs hook: the page of licences and third-party notices (``notices/``), written at build time.

``scripts/notices.py`` reads every component the site ships from the files the build used (the
locks, the vendored runtime, node_modules, the bundles' source maps, the theme) and writes the
page's Markdown; this hook adds it to the site as a generated page, so it is never committed and
always describes the files of this build. The footer links to it (docs/overrides/partials/copyright.html).
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

from mkdocs.structure.files import File, Files

_SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "notices.py"


def _notices():
    name = "workbook_build_notices"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, _SCRIPT)
        assert spec and spec.loader
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module  # before it runs: its dataclasses look their module up
        spec.loader.exec_module(module)
    return sys.modules[name]


def on_files(files: Files, config) -> Files:
    notices = _notices()
    files.append(File.generated(config, notices.PAGE, content=notices.markdown()))
    return files
