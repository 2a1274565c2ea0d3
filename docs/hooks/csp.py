"""MkDocs hook: a Content-Security-Policy ``<meta>`` on every built page.

The site is static, so its policy travels in each page as
``<meta http-equiv="Content-Security-Policy">``, placed right after
``<meta charset>``: before any script, stylesheet or URL in ``<head>``.
Everything comes from the site's own origin. Scripts are the site's files plus
the few inline scripts the pages really have (mkdocs-material's, and the one in
docs/overrides/main.html that starts the worker), each allowed by its sha256,
computed here from the final HTML after every other hook has changed it.

One policy for the whole site: mkdocs-material's instant navigation swaps the
next page's content into the current document, which keeps the policy of the
page first loaded, so every page allows every page's inline scripts (a handful
that differ only by their relative base URL).

Why each source:

* ``'wasm-unsafe-eval'``: lets the page compile WebAssembly (Pyodide itself runs
  in the worker, whose own policy would come from its response headers).
* ``style-src 'unsafe-inline'``: CodeMirror writes its theme into a ``<style>``
  element it creates at run time, and pages carry ``style`` attributes
  (the performance page's tables); a hash cannot cover either.
* ``img-src data:``: small icons written as data: URLs in the theme's CSS.
* ``worker-src blob:``: the sandbox that runs learner code is started from a
  ``blob:`` URL (``docs/assets/js/sandbox-client.js``) so that it inherits this
  policy: no eval, and nothing fetched, imported or connected outside the
  site's origin, enforced by the browser in that worker too. (A worker started
  from its own URL gets its policy from its response headers, which a static
  host does not send.)

``frame-ancestors`` and ``sandbox`` are left out: browsers ignore them in a
``<meta>``. Under ``mkdocs serve`` no policy is written (its live-reload script
is injected into every page and would be blocked).

The build fails (PluginError) when a page has no ``<meta charset>`` to anchor
the policy, has a script before it, or has inline event handlers or
``javascript:`` URLs (a hash cannot allow them).
"""

from __future__ import annotations

import base64
import hashlib
import logging
import re
from pathlib import Path

from mkdocs.exceptions import PluginError

log = logging.getLogger("mkdocs.hooks.csp")

ANCHOR = '<meta charset="utf-8">'
SCRIPT = re.compile(r"<script\b([^>]*)>(.*?)</script\s*>", re.S | re.I)
SRC = re.compile(r"\bsrc\s*=", re.I)
TYPE = re.compile(r"""\btype\s*=\s*["']?([^"'\s>]+)""", re.I)
EXECUTABLE_TYPES = {"", "module", "text/javascript", "application/javascript"}
HANDLER = re.compile(r"""<[a-z][^>]*\s(on[a-z]+)\s*=\s*["']""", re.I)
JS_URL = re.compile(r"""\b(?:href|src|action)\s*=\s*["']\s*javascript:""", re.I)
_serving = False


def policy(script_hashes: list[str]) -> str:
    scripts = " ".join(["'self'", "'wasm-unsafe-eval'", *(f"'{h}'" for h in script_hashes)])
    return "; ".join([
        "default-src 'self'",
        f"script-src {scripts}",
        "worker-src 'self' blob:",
        "connect-src 'self'",
        "img-src 'self' data:",
        "font-src 'self'",
        "style-src 'self' 'unsafe-inline'",
        "object-src 'none'",
        "base-uri 'self'",
        "form-action 'self'",
    ])


def inline_scripts(html: str) -> list[str]:
    """The text of every inline script the browser would run (not JSON data blocks)."""
    out = []
    for match in SCRIPT.finditer(html):
        attrs, body = match.group(1), match.group(2)
        if SRC.search(attrs):
            continue
        kind = TYPE.search(attrs)
        if (kind.group(1).lower() if kind else "") in EXECUTABLE_TYPES:
            out.append(body)
    return out


def script_hash(body: str) -> str:
    digest = hashlib.sha256(body.replace("\r\n", "\n").encode("utf-8")).digest()
    return "sha256-" + base64.b64encode(digest).decode("ascii")


def with_policy(html: str, meta: str, name: str) -> str:
    """``html`` with ``meta`` right after its ``<meta charset>``; PluginError if that cannot be safe."""
    at = html.find(ANCHOR)
    if at < 0:
        raise PluginError(f"csp: {name} has no {ANCHOR} to put the Content-Security-Policy after")
    head = html[:at]
    if re.search(r"<script\b", head, re.I):
        raise PluginError(f"csp: {name} has a script before {ANCHOR}; the policy would not cover it")
    if 'http-equiv="Content-Security-Policy"' in html:
        raise PluginError(f"csp: {name} already has a Content-Security-Policy meta")
    end = at + len(ANCHOR)
    return html[:end] + "\n    " + meta + html[end:]


def check_no_inline_handlers(html: str, name: str) -> None:
    handler = HANDLER.search(html)
    if handler and not _inside_script(html, handler.start()):
        raise PluginError(f"csp: {name} has an inline event handler ({handler.group(1)}=...), which the policy "
                          "blocks: attach the listener from a script file instead")
    url = JS_URL.search(html)
    if url and not _inside_script(html, url.start()):
        raise PluginError(f"csp: {name} has a javascript: URL, which the policy blocks")


def _inside_script(html: str, pos: int) -> bool:
    return any(m.start() < pos < m.end() for m in SCRIPT.finditer(html))


def on_startup(command, dirty, **kwargs):
    global _serving
    _serving = command == "serve"


def on_post_build(config, **kwargs):
    if _serving:
        log.info("csp: no Content-Security-Policy under mkdocs serve (its live-reload script is inline)")
        return
    site = Path(config.site_dir)
    pages = {path: path.read_text(encoding="utf-8") for path in sorted(site.rglob("*.html"))}
    hashes = sorted({script_hash(body) for html in pages.values() for body in inline_scripts(html)})
    meta = f'<meta http-equiv="Content-Security-Policy" content="{policy(hashes)}">'
    for path, html in pages.items():
        name = path.relative_to(site).as_posix()
        check_no_inline_handlers(html, name)
        path.write_text(with_policy(html, meta, name), encoding="utf-8")
    log.info("csp: policy on %d pages, %d inline script hashes", len(pages), len(hashes))
