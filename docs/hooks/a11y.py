"""MkDocs hook: accessible names for two elements of the theme's own markup.

mkdocs-material renders the search overlay as ``role="dialog"`` and the instant
navigation's progress bar as ``role="progressbar"``, both without a name; axe
counts each as a serious violation on every page. The fix is one attribute
each, added to the built HTML of every page and of the 404 page (so it holds
without JavaScript too).

Each fix looks for the exact markup the theme writes today. If a theme update
changes it, the build fails and names the markup it expected, rather than
shipping pages that silently lost the fix: look at the theme's new markup, and
change the fix (or drop it if the theme now names the element itself).
"""

from __future__ import annotations

from mkdocs.exceptions import PluginError

FIXES = (
    ('<div class="md-search" data-md-component="search" role="dialog">',
     '<div class="md-search" data-md-component="search" role="dialog" aria-label="Search">'),
    ('data-md-component="progress" role="progressbar"',
     'data-md-component="progress" role="progressbar" aria-label="Loading the page"'),
)


def apply_fixes(output: str, where: str) -> str:
    """``output`` with every fix applied once; PluginError naming the markup a fix did not find."""
    for old, new in FIXES:
        count = output.count(old)
        if count != 1:
            found = "not found" if count == 0 else f"found {count} times"
            raise PluginError(
                f"a11y hook: expected the theme's markup {old!r} once in {where}, {found}. "
                "The theme's HTML changed: update FIXES in docs/hooks/a11y.py."
            )
        output = output.replace(old, new)
    return output


def on_post_page(output, page, config, **kwargs):
    return apply_fixes(output, page.file.src_uri)


def on_post_template(output_content, template_name, config, **kwargs):
    if not template_name.endswith(".html"):
        return output_content  # sitemap.xml and the like
    return apply_fixes(output_content, template_name)
