"""The 404 page under a sub-path: once the service worker is installed, an
unknown address deep in the site, online or offline, shows the site's own 404
page, styled (every stylesheet loaded), with working links, search and scripts.

MkDocs writes the 404 page's URLs from the path of site_url; the tests serve the
site at /workbook/ while site_url says "/", as any host at another path would.
The page is built with URLs relative to the site root and a <base>, which the
service worker points at its own scope."""

from __future__ import annotations

import pytest
from playwright.sync_api import expect

from helpers import network_is_off
from workbook.contract import ATTR

LONG = 120_000
DEEP = "chapters/no-such-chapter/no-such-page/"
HEADER_COLOUR = "getComputedStyle(document.querySelector('.md-header')).backgroundColor"


def assert_styled_404(page, site_url, header_colour: str) -> None:
    expect(page.locator("h1")).to_contain_text("404")
    sheets = page.evaluate("""() => [...document.querySelectorAll('link[rel=stylesheet]')].map(l => ({
      href: l.href, rules: l.sheet ? l.sheet.cssRules.length : 0 }))""")
    assert len(sheets) >= 4
    for sheet in sheets:
        assert sheet["href"].startswith(site_url + "assets/"), sheet
        assert sheet["rules"] > 0, f"stylesheet not loaded: {sheet['href']}"
    assert page.evaluate(HEADER_COLOUR) == header_colour  # the theme's palette stylesheet applies
    assert page.evaluate("window.__workbookBase") == site_url
    assert page.locator("a.md-header__button.md-logo").evaluate("a => a.href") == site_url
    assert page.evaluate("a => document.documentElement.getAttribute(a)", ATTR.runtime) in ("loading", "ready")


@pytest.mark.browser_context_args(service_workers="allow")  # offline, the service worker serves it
def test_unknown_deep_address_shows_the_styled_404_online_and_offline(page, context, site_url):
    page.goto(site_url)
    page.wait_for_function("a => document.documentElement.getAttribute(a) === 'ready'", arg=ATTR.offline,
                           timeout=LONG)
    header_colour = page.evaluate(HEADER_COLOUR)

    response = page.goto(site_url + DEEP)
    assert response.status == 404 and page.url == site_url + DEEP
    assert_styled_404(page, site_url, header_colour)
    page.goto(site_url + "404.html")  # the page's own address, too
    assert_styled_404(page, site_url, header_colour)
    page.goto(site_url + DEEP)
    # The theme's scripts find the site root too: search loads its index from there.
    page.locator("input.md-search__input").click()
    page.locator("input.md-search__input").press_sequentially("jacobian", delay=20)
    expect(page.locator(".md-search-result__item").first).to_be_visible(timeout=LONG)
    page.keyboard.press("Escape")

    context.set_offline(True)
    try:
        response = page.goto(site_url + DEEP + "?offline")
        assert response.status == 404
        assert network_is_off(page)
        assert_styled_404(page, site_url, header_colour)
        # Its links lead back into the site, still offline.
        page.locator("a.md-header__button.md-logo").click()
        page.wait_for_url(site_url)
        expect(page.locator("h1").first).to_be_visible()
    finally:
        context.set_offline(False)
