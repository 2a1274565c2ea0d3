"""MkDocs hook: the workbook as an app a learner can install (issue 48).

After the build it writes ``manifest.webmanifest`` and its icons (``app_icons.py``: an SVG,
PNGs of 192 and 512 pixels, a maskable one) to the site root, before ``offline.py`` lists the
site for the service worker, so the offline copy holds them too. Every URL in the manifest is
relative to it (``./``), so the start URL and the scope are the site root wherever it is
served: ``make serve``, a project path on GitHub Pages, the offline copy. Every page's head
links the manifest and gets the theme colours for the light and the dark scheme
(``theme-color`` with a media query). The start URL carries ``?source=app``: the page
(``docs/assets/js/app.js``) then goes on to the last page read, which it remembers.

The PNGs are drawn once per drawing and size and kept under ``build/app-icons/`` (about 2 s
of pure Python to draw).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from mkdocs.exceptions import PluginError

from app_icons import BACKGROUND, icon_png, icon_svg

MANIFEST = "manifest.webmanifest"
ICONS = "assets/icons/"
START = "./?source=app"  # app.js knows it by its source
SHORT_NAME = "Robotics Math"
THEME = {"light": BACKGROUND, "dark": "#2e303e"}  # the header's indigo; the slate scheme's background
PNGS = (("icon-192.png", 192, False), ("icon-512.png", 512, False), ("maskable-512.png", 512, True))
VIEWPORT = '<meta name="viewport" content="width=device-width,initial-scale=1">'


def manifest(config) -> dict:
    """The web app manifest (URLs relative to its own, at the site root)."""
    icons = [{"src": ICONS + "icon.svg", "sizes": "any", "type": "image/svg+xml", "purpose": "any"}]
    icons += [{"src": ICONS + name, "sizes": f"{size}x{size}", "type": "image/png",
               "purpose": "maskable" if maskable else "any"} for name, size, maskable in PNGS]
    return {
        "id": "./", "name": config.site_name, "short_name": SHORT_NAME,
        "description": config.site_description or "", "lang": config.theme.get("language") or "en",
        "start_url": START, "scope": "./", "display": "standalone",
        "theme_color": THEME["light"], "background_color": "#ffffff", "icons": icons,
    }


def head_tags(root: str) -> str:
    """What every page's head gets; ``root`` is the page's way to the site root ("../../" or "")."""
    return (f'<link rel="manifest" href="{root}{MANIFEST}">'
            f'<link rel="apple-touch-icon" href="{root}{ICONS}icon-192.png">'
            f'<meta name="theme-color" media="(prefers-color-scheme: light)" content="{THEME["light"]}">'
            f'<meta name="theme-color" media="(prefers-color-scheme: dark)" content="{THEME["dark"]}">')


def _with_head(output: str, root: str, where: str) -> str:
    if output.count(VIEWPORT) != 1:
        raise PluginError(f"app hook: expected the theme's {VIEWPORT!r} once in {where}: update docs/hooks/app.py.")
    return output.replace(VIEWPORT, VIEWPORT + head_tags(root))


def on_post_page(output, page, config, **kwargs):
    depth = page.url.count("/") if page.url else 0
    return _with_head(output, "../" * depth, page.file.src_uri)


def on_post_template(output_content, template_name, config, **kwargs):
    if template_name != "404.html":
        return output_content
    return _with_head(output_content, "", template_name)  # the 404 page resolves URLs against its <base>


def _png(cache: Path, size: int, maskable: bool) -> bytes:
    key = hashlib.sha256((Path(__file__).with_name("app_icons.py").read_bytes()) + f"{size}{maskable}".encode())
    path = cache / f"{key.hexdigest()[:16]}.png"
    if not path.exists():
        cache.mkdir(parents=True, exist_ok=True)
        path.write_bytes(icon_png(size, maskable))
    return path.read_bytes()


def on_post_build(config, **kwargs):
    site = Path(config.site_dir)
    cache = Path(config.config_file_path).parent / "build" / "app-icons"
    (site / ICONS).mkdir(parents=True, exist_ok=True)
    (site / ICONS / "icon.svg").write_text(icon_svg())
    for name, size, maskable in PNGS:
        (site / ICONS / name).write_bytes(_png(cache, size, maskable))
    (site / MANIFEST).write_text(json.dumps(manifest(config), ensure_ascii=False, indent=1) + "\n")
