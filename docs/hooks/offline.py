"""MkDocs hook: write the offline service worker to the site root.

After every build, list each file of the built site (pages, the Pyodide runtime
and wheels, KaTeX, bundles, CSS, the search index), hash it, and write
``site/sw.js`` from the template ``docs/assets/js/sw.js`` with:

* ``FILES``, the manifest: ``[url relative to the site root, "sha256-…" integrity,
  size]`` per file (``chapters/00-rotations-2d/`` for
  ``chapters/00-rotations-2d/index.html``); the memory snapshot, which the
  service worker stores inflated, adds the sha256 and size of its inflated bytes.
  The service worker serves a stored file only while it still has these bytes;
* ``VERSION``: a hash over the template and every file, so any change to the
  site gives a new version (and a new cache);
* ``WIRE_BYTES``: what the whole copy downloads, each file gzipped as GitHub
  Pages sends it (text types and wasm, level 6; archives as they are), for the
  notice that announces the copy (the stored size counts the snapshot inflated);
* ``LATER``: files kept when they are first fetched, not copied with the rest
  (their entries as in ``FILES``). The sandbox's memory snapshot is one: 5 MB
  that only a Build run's quick start needs, and without it the sandbox boots
  plainly from files the copy has. It is stored once a Build exercise started
  the sandbox while online, for a learner who wants the copy.

Source maps and the gzipped sitemap are left out (nothing at runtime reads them),
and so are the search's word splitters and stemmers for other languages when the
search is in English only (it then never loads them). So are the compiled core
of the standard library and the compiled grading package (whole, and each chapter's):
only a first visit over a link that is fast but not very fast takes one
(docs/assets/js/boot.js); a stored site starts from its snapshot, and a start
without one takes the sources. ``sitemap.xml`` is left
out too: it holds absolute URLs that hosts and test servers rewrite, so the
service worker writes it from the manifest's pages, for its own scope.
Under ``mkdocs serve`` the service worker only unregisters itself, so a worker
left by ``make serve`` on the same address does not serve stale pages.
"""

from __future__ import annotations

import base64
import gzip
import hashlib
import json
import logging
import mimetypes
import re
from pathlib import Path

log = logging.getLogger("mkdocs.hooks.offline")

TEMPLATE = "assets/js/sw.js"
OUTPUT = "sw.js"
SKIP_SUFFIXES = (".map",)
SKIP_FILES = {"sitemap.xml.gz", "sitemap.xml"}
# The compiled core (the grader's and the sandbox's) and the compiled package: whole, and each chapter's (.chN).
COMPILED_CORES = re.compile(r"assets/vendor/pyodide/(python_stdlib\.core|workbook)\.compiled(\.ch\d+)?\.zip")
INFLATED = ".snapshot.gz"  # stored inflated by the service worker
LATER = ("assets/vendor/pyodide/sandbox.snapshot.gz",)  # kept when first fetched, not with the copy
LUNR_LANGUAGES = "assets/javascripts/lunr/"
# What GitHub Pages gzips on the way (by type), and what it never does (archives, images, fonts).
GZIP_TYPES = ("text/", "application/javascript", "application/json", "application/xml", "image/svg+xml",
              "application/wasm", "application/manifest+json")
NO_GZIP_SUFFIXES = (".gz", ".whl", ".zip", ".png", ".jpg", ".jpeg", ".woff", ".woff2", ".ico")
_serving = False

UNREGISTER = """// mkdocs serve: no offline cache while authoring; remove any earlier worker and its caches.
self.addEventListener("install", () => self.skipWaiting());
self.addEventListener("activate", (event) => event.waitUntil((async () => {
  const prefix = `robotics-workbook:${new URL(self.registration.scope).pathname}:`;
  for (const name of await caches.keys()) if (name.startsWith(prefix)) await caches.delete(name);
  await self.registration.unregister();
})()));
"""


def on_startup(command, dirty, **kwargs):
    global _serving
    _serving = command == "serve"


def _english_only(config) -> bool:
    search = config.plugins.get("material/search") or config.plugins.get("search")
    lang = getattr(search, "config", {}).get("lang") if search else None
    lang = lang or [config.theme.get("language") or "en"]
    return [code for code in lang if code != "en"] == []


def integrity(data: bytes) -> str:
    return "sha256-" + base64.b64encode(hashlib.sha256(data).digest()).decode("ascii")


def wire_size(name: str, data: bytes) -> int:
    """The bytes of one file on the wire: gzipped (level 6) if the host compresses its type.

    >>> wire_size("a.js", b"x" * 1000) < 100, wire_size("a.whl", b"x" * 1000)
    (True, 1000)
    """
    if name.lower().endswith(NO_GZIP_SUFFIXES):
        return len(data)
    ctype = mimetypes.guess_type(name)[0] or ("application/wasm" if name.endswith(".wasm") else "")
    if not ctype.startswith(GZIP_TYPES):
        return len(data)
    return min(len(data), len(gzip.compress(data, compresslevel=6, mtime=0)))


def precache_list(site: Path, english_only: bool = True, wire: list[int] | None = None) -> list[list]:
    """The manifest: [url, integrity, size] for every file the site serves at runtime, sorted;
    the snapshot adds [integrity, size] of its inflated bytes. ``wire``, if given, gets each
    file's size on the wire (:func:`wire_size`), in the same order."""
    out = []
    for path in sorted(site.rglob("*")):
        rel = path.relative_to(site).as_posix()
        if not path.is_file() or rel == OUTPUT or rel.endswith(SKIP_SUFFIXES) or rel in SKIP_FILES \
                or COMPILED_CORES.fullmatch(rel):
            continue
        if english_only and rel.startswith(LUNR_LANGUAGES):
            continue
        if any(part.startswith(".") for part in rel.split("/")):
            continue  # build stamps and the like
        data = path.read_bytes()
        url = rel.removesuffix("index.html") if rel == "index.html" or rel.endswith("/index.html") else rel
        entry = [url or "./", integrity(data), len(data)]
        if rel.endswith(INFLATED):
            inflated = gzip.decompress(data)
            entry += [integrity(inflated), len(inflated)]
        out.append(entry)
        if wire is not None:
            wire.append(wire_size(rel, data))
    return out


def on_post_build(config, **kwargs):
    site = Path(config.site_dir)
    if _serving:
        (site / OUTPUT).write_text(UNREGISTER)
        return
    template = (Path(config.docs_dir) / TEMPLATE).read_text()
    sizes: list[int] = []
    every = precache_list(site, _english_only(config), sizes)
    files = [e for e in every if e[0] not in LATER]
    later = [e for e in every if e[0] in LATER]
    wire = [n for e, n in zip(every, sizes, strict=True) if e[0] not in LATER]
    h = hashlib.sha256(template.encode())
    for url, digest, *_ in every:
        h.update(f"\n{url} {digest}".encode())
    version = h.hexdigest()[:16]
    listing = "[\n" + ",\n".join(json.dumps(entry) for entry in files) + "\n]"
    text = template.replace("__WB_VERSION__", json.dumps(version)).replace("__WB_FILES__", listing)
    text = text.replace("__WB_LATER__", json.dumps(later)).replace("__WB_WIRE_BYTES__", str(sum(wire)))
    (site / OUTPUT).write_text(text)
    total = sum(entry[-1] for entry in files)
    log.info("offline: sw.js version %s: a manifest of %d files, %d bytes stored, %d on the wire", version,
             len(files), total, sum(wire))
