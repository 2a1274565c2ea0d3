"""The stock page: chapter 0's Markdown on the stock mkdocs-material theme, nothing of ours.

Built by the bench with the site's own MkDocs and theme versions, the same theme features,
palette and Markdown extensions as mkdocs.yml, and none of our hooks, CSS or JavaScript
(so no grader, no KaTeX, no exercises). Its total blocking time, measured like ours from
the navigation to the load event plus 5 s on the same profile in the same run, is the
theme's own floor: "ours minus stock" is the blocking that our code adds.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import yaml  # type: ignore[import-untyped]

from . import ROOT

CHAPTER0 = ROOT / "docs" / "chapters" / "00-rotations-2d.md"
SETTLE_MS = 5_000  # after the load event, as the measurements
KEPT = ("theme", "plugins", "markdown_extensions")


class _Loader(yaml.SafeLoader):
    """mkdocs.yml's tags (!ENV) read as plain values: the stock build needs none of them."""


_Loader.add_multi_constructor("!", lambda loader, suffix, node: None)


def stock_config(docs: Path, site_dir: Path) -> dict:
    ours = yaml.load((ROOT / "mkdocs.yml").read_text(), Loader=_Loader)
    config = {key: ours[key] for key in KEPT if key in ours}
    config["theme"] = {k: v for k, v in config["theme"].items() if k != "custom_dir"}  # the theme as shipped
    return {"site_name": "Stock page", "docs_dir": str(docs), "site_dir": str(site_dir), **config}


def build_stock(folder: Path) -> Path:
    """Build the stock page into `folder`/site; return that folder."""
    docs, site_dir = folder / "docs", folder / "site"
    docs.mkdir(parents=True, exist_ok=True)
    (docs / "index.md").write_text(CHAPTER0.read_text())
    cfg = folder / "mkdocs.yml"
    cfg.write_text(json.dumps(stock_config(docs, site_dir)))  # JSON is YAML
    subprocess.run([sys.executable, "-m", "mkdocs", "build", "--quiet", "-f", str(cfg)], check=True,
                   env={"NO_MKDOCS_2_WARNING": "1", "PATH": "/usr/bin:/bin"})
    return site_dir
