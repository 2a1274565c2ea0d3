"""The page hooks that rewrite built HTML: docs/hooks/a11y.py and docs/hooks/csp.py.

Both fail the build (PluginError, naming what they expected) rather than ship a
page that silently lost its fix or its policy."""

from __future__ import annotations

import base64
import hashlib

import pytest
from mkdocs.exceptions import PluginError

import a11y  # docs/hooks/a11y.py
import csp  # docs/hooks/csp.py

THEME_HTML = (
    '<div data-md-component="skip"><a href="#x" class="md-skip">Skip to content</a></div>'
    '<header class="md-header md-header--shadow" data-md-component="header"><nav></nav></header>'
    '<div class="md-search" data-md-component="search" role="dialog"><input></div>'
    '<div class="md-progress" data-md-component="progress" role="progressbar"></div>'
)


def test_a11y_names_the_search_dialog_and_moves_the_named_progress_bar_into_the_header():
    out = a11y.apply_fixes(THEME_HTML, "index.md")
    assert 'role="dialog" aria-label="Search"' in out
    header = out[out.index("<header"):out.index("</header>")]
    assert 'role="progressbar" aria-label="Loading the page"' in header
    assert out.count('data-md-component="progress"') == 1


def test_a11y_adds_skip_to_exercises_first_only_where_a_page_lists_exercises():
    plain = a11y.add_skip_link(THEME_HTML, "related.md")
    assert "Skip to exercises" not in plain
    page = THEME_HTML + '<nav id="wb-exercises"></nav>'
    out = a11y.add_skip_link(page, "chapters/00-rotations-2d.md")
    assert out.index("Skip to exercises") < out.index("Skip to content")
    assert 'href="#wb-exercises"' in out


def test_a11y_fails_loudly_when_the_theme_markup_changed():
    changed = THEME_HTML.replace('role="dialog"', 'role="dialog" aria-modal="true"')
    with pytest.raises(PluginError) as err:
        a11y.apply_fixes(changed, "chapters/00-rotations-2d.md")
    message = str(err.value)
    assert '<div class="md-search" data-md-component="search" role="dialog">' in message
    assert "chapters/00-rotations-2d.md" in message and "not found" in message


def test_a11y_fails_when_the_markup_is_there_twice():
    with pytest.raises(PluginError, match="found 2 times"):
        a11y.apply_fixes(THEME_HTML + THEME_HTML, "404.html")


PAGE = """<!doctype html><html><head>
<meta charset="utf-8">
<script>var a = 1;</script>
<script src="x.js"></script>
<script type="module">import "./y.js";</script>
<script id="__config" type="application/json">{"base": "."}</script>
</head><body><p>a &lt;script&gt; in prose</p></body></html>"""


def test_csp_hashes_only_the_inline_scripts_a_browser_runs():
    assert csp.inline_scripts(PAGE) == ["var a = 1;", 'import "./y.js";']
    expected = "sha256-" + base64.b64encode(hashlib.sha256(b"var a = 1;").digest()).decode()
    assert csp.script_hash("var a = 1;") == expected


def test_csp_meta_goes_right_after_the_charset():
    out = csp.with_policy(PAGE, '<meta http-equiv="Content-Security-Policy" content="x">', "index.html")
    assert out.index("Content-Security-Policy") < out.index("<script")
    assert out.index('<meta charset="utf-8">') < out.index("Content-Security-Policy")


def test_csp_refuses_pages_it_cannot_protect():
    meta = '<meta http-equiv="Content-Security-Policy" content="x">'
    with pytest.raises(PluginError, match="no <meta charset"):
        csp.with_policy(PAGE.replace('<meta charset="utf-8">', ""), meta, "a.html")
    with pytest.raises(PluginError, match="script before"):
        csp.with_policy(PAGE.replace("<head>", "<head><script>1</script>"), meta, "b.html")
    with pytest.raises(PluginError, match="inline event handler"):
        csp.check_no_inline_handlers('<button onclick="go()">Go</button>', "c.html")
    with pytest.raises(PluginError, match="javascript: URL"):
        csp.check_no_inline_handlers('<a href="javascript:go()">Go</a>', "d.html")
    csp.check_no_inline_handlers('<script>el.onclick = "x"; var s = \'<a onclick="y">\';</script>', "e.html")


def test_csp_policy_lists_each_hash():
    text = csp.policy(["sha256-AAA", "sha256-BBB"])
    assert "script-src 'self' 'wasm-unsafe-eval' 'sha256-AAA' 'sha256-BBB';" in text
    assert "default-src 'self'" in text and "object-src 'none'" in text
    assert "frame-ancestors" not in text  # ignored in a <meta>


def test_search_text_reads_formulas_as_unicode_and_keeps_the_rest():
    import search_text  # docs/hooks/search_text.py

    text = r"Turn \(R(\theta)\) by \(\theta = \pi/6\): \[ \det R = \cos^2\theta + \sin^2\theta \] &amp; done"
    out = search_text.math_as_text(text)
    assert "\\" not in out
    assert "R(θ)" in out and "π/6" in out and "det R" in out and "cos" in out
    assert out.startswith("Turn ") and out.endswith("&amp; done")
    # Text that comes out with markup characters is escaped again for the index's HTML.
    assert search_text.math_as_text(r"\(a < b\)") == "a &lt; b"


@pytest.mark.parametrize("tex, text", [
    (r"v\cos\theta\,dt", "v cos θ dt"),
    (r"3\times3", "3 × 3"),
    (r"3 \times 3", "3 × 3"),
    (r"\theta = \pi/6", "θ = π/6"),
    (r"\theta=\pi/6", "θ = π/6"),
    (r"2\sin\theta\cos\theta", "2 sin θ cos θ"),
    (r"-\sin\theta", "-sin θ"),
    (r"y = -\cos x", "y = -cos x"),
    (r"f(\cos x)", "f(cos x)"),
    (r"\sin(\theta)", "sin(θ)"),
    (r"x \le y", "x ≤ y"),
    (r"a\cdot b", "a · b"),
    (r"x \to 0", "x → 0"),
    (r"(x, y)", "(x, y)"),
    (r"a - b", "a - b"),
])
def test_search_text_spaces_formulas_as_they_are_read(tex, text):
    import search_text  # docs/hooks/search_text.py

    assert search_text.math_as_text(rf"\({tex}\)") == text
    assert search_text.math_as_text(rf"see \[{tex}\] here") == f"see {text} here"
