"""MkDocs hook: accessible names for two elements of the theme's own markup.

mkdocs-material renders the search overlay as ``role="dialog"`` and the instant
navigation's progress bar as ``role="progressbar"``, both without a name; axe
counts each as a serious violation on every page. The fix is one attribute
each, added to the built HTML (so it holds without JavaScript too).
"""

from __future__ import annotations

FIXES = (
    ('<div class="md-search" data-md-component="search" role="dialog">',
     '<div class="md-search" data-md-component="search" role="dialog" aria-label="Search">'),
    ('data-md-component="progress" role="progressbar"',
     'data-md-component="progress" role="progressbar" aria-label="Loading the page"'),
)


def on_post_page(output, page, config, **kwargs):
    for old, new in FIXES:
        output = output.replace(old, new, 1)
    return output
