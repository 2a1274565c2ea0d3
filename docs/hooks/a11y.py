"""MkDocs hook: accessibility fixes to the theme's own markup, and a skip link.

mkdocs-material renders the search overlay as ``role="dialog"`` and the instant
navigation's progress bar as ``role="progressbar"``, both without a name; axe
counts each as a serious violation on every page. The bar also sits outside
every landmark (axe's best-practice rule "region"): it moves into the header,
where it is drawn anyway (it is fixed to the top of the window). The fixes are
applied to the built HTML of every page and of the 404 page (so they hold
without JavaScript too).

A page with exercises gets a "Skip to exercises" link first in the tab order,
to the list of its exercises (``exercises.py`` puts it under the title).

Each fix looks for the exact markup the theme writes today. If a theme update
changes it, the build fails and names the markup it expected, rather than
shipping pages that silently lost the fix: look at the theme's new markup, and
change the fix (or drop it if the theme now names the element itself).
"""

from __future__ import annotations

from mkdocs.exceptions import PluginError

PROGRESS = '<div class="md-progress" data-md-component="progress" role="progressbar"></div>'
HEADER = '<header class="md-header md-header--shadow" data-md-component="header">'
FIXES = (
    ('<div class="md-search" data-md-component="search" role="dialog">',
     '<div class="md-search" data-md-component="search" role="dialog" aria-label="Search">'),
    (PROGRESS, ""),
    (HEADER, HEADER + PROGRESS.replace('role="progressbar"', 'role="progressbar" aria-label="Loading the page"')),
)
SKIP = '<div data-md-component="skip">'
EXERCISES = 'id="wb-exercises"'
SKIP_LINK = '<a href="#wb-exercises" class="md-skip" data-wb-skip>Skip to exercises</a>'


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


def add_skip_link(output: str, where: str) -> str:
    """A page with an exercise list: "Skip to exercises" before the theme's "Skip to content"."""
    if EXERCISES not in output:
        return output
    if output.count(SKIP) != 1:
        raise PluginError(f"a11y hook: expected the theme's markup {SKIP!r} once in {where}: update "
                          "docs/hooks/a11y.py.")
    return output.replace(SKIP, SKIP + SKIP_LINK)


def on_post_page(output, page, config, **kwargs):
    return add_skip_link(apply_fixes(output, page.file.src_uri), page.file.src_uri)


def on_post_template(output_content, template_name, config, **kwargs):
    if not template_name.endswith(".html"):
        return output_content  # sitemap.xml and the like
    return apply_fixes(output_content, template_name)
