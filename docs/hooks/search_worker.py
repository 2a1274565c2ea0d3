"""MkDocs hook: the theme's search index is built when it is wanted, not at every page load.

mkdocs-material starts its search worker as each page loads and hands it the whole
site's index, which the worker then builds: about half a CPU-second on a 2-core
machine, in competition with the grader's start. This hook points the theme's
configuration (``<script id="__config">``, its ``search`` entry) at
``assets/dist/search-worker.js`` (``docs/assets/js/search-worker.js``), with the
theme's own worker file named after the ``#``. That worker holds the index until
the page says search is wanted (``docs/assets/js/search-start.js``), then loads
the theme's worker and hands it on.

The theme's page also fetches the index as it loads (97 kB gzipped, more than
any of the page's own files), so the index's documents move to
``search/search_index.docs.json`` and ``search/search_index.json`` keeps only its
configuration: the page fetches those few bytes, and the waiting worker fetches
the documents when search is wanted, and puts them in the index it hands on.

The build fails (PluginError) if a page's configuration names no search worker,
or another one than the theme's: the swap would otherwise be silently lost.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

from mkdocs.exceptions import PluginError

CONFIG = re.compile(r'(<script id="__config" type="application/json">)(.*?)(</script>)', re.S)
THEME_WORKER = re.compile(r"^(?P<base>.*)assets/javascripts/workers/(?P<name>search\.[0-9a-f]+\.min\.js)$")
OURS = "assets/dist/search-worker.js"
INDEX = "search/search_index.json"  # the theme's page fetches it as it loads
DOCS = "search/search_index.docs.json"  # search-worker.js fetches it when search is wanted


def searched_later(html: str, where: str) -> str:
    """``html`` with its theme configuration's search worker swapped for the one that waits."""
    match = CONFIG.search(html)
    if not match:
        raise PluginError(f"{where}: no theme configuration (<script id=\"__config\">) to point the search at")
    config = json.loads(match.group(2))
    worker = THEME_WORKER.match(str(config.get("search", "")))
    if not worker:
        raise PluginError(f"{where}: the theme's search worker is not where this hook expects it: "
                          f"{config.get('search')!r}")
    config["search"] = f"{worker['base']}{OURS}#{worker['name']}"
    text = json.dumps(config, ensure_ascii=False)
    for char, escaped in (("&", "\\u0026"), ("<", "\\u003c"), (">", "\\u003e"), ("'", "\\u0027")):
        text = text.replace(char, escaped)  # safe inside <script>, as the theme's own tojson writes it
    return html[:match.start(2)] + text + html[match.end(2):]


def on_post_page(output, page, config, **kwargs):
    return searched_later(output, page.file.src_uri)


def on_post_template(output_content, template_name, config, **kwargs):
    """The 404 page, rendered without a ``page``, has the theme's configuration too."""
    return searched_later(output_content, template_name) if template_name.endswith(".html") else output_content


def on_post_build(config, **kwargs):
    """Move the index's documents to DOCS, leaving the theme's page an index without them."""
    site = Path(config["site_dir"])
    index = site / INDEX
    if not index.is_file():
        raise PluginError(f"no {INDEX} to split: is the search plugin on, and before this hook?")
    data = json.loads(index.read_text(encoding="utf-8"))
    if not isinstance(data.get("docs"), list):
        raise PluginError(f"{INDEX} has no list of documents")
    (site / DOCS).write_text(json.dumps(data["docs"], ensure_ascii=False, separators=(",", ":")), encoding="utf-8")
    index.write_text(json.dumps({**data, "docs": []}, separators=(",", ":")), encoding="utf-8")
