"""The bench's browser flags (scripts/bench/browser.py, ``launch_args``): the features it switches off
are added to Playwright's own list in one ``--disable-features`` flag, which replaces Playwright's
(Chromium reads only the last such flag), so that none of Playwright's is lost."""

from __future__ import annotations

from bench.browser import launch_args
from bench.config import BROWSER_UI_FEATURES_OFF, CHROMIUM_ARGS


class FakeBrowser:
    def __init__(self, line: list[str]):
        self.line, self.closed = line, False

    def new_browser_cdp_session(self):
        line = self.line

        class Session:
            def send(self, method):
                assert method == "Browser.getBrowserCommandLine"
                return {"arguments": line}

        return Session()

    def close(self):
        self.closed = True


class FakePlaywright:
    def __init__(self, line: list[str]):
        self.browser = FakeBrowser(line)
        self.chromium = self
        self.launched: dict = {}

    def launch(self, **options):
        self.launched = options
        return self.browser


def test_the_bench_s_features_join_playwright_s_in_one_flag_that_replaces_it():
    theirs = "--disable-features=PaintHolding,MediaRouter,WebUIOmniboxPopup"
    pw = FakePlaywright(["/usr/bin/chromium", "--headless", theirs, "--no-sandbox"])
    args, ignored = launch_args(pw, "/usr/bin/chromium")
    assert pw.browser.closed
    assert "--enable-automation" in pw.launched["args"]  # the command line is returned only then
    assert args[:len(CHROMIUM_ARGS)] == CHROMIUM_ARGS
    flags = [a for a in args if a.startswith("--disable-features=")]
    assert len(flags) == 1
    features = flags[0].split("=", 1)[1].split(",")
    assert features[:3] == ["PaintHolding", "MediaRouter", "WebUIOmniboxPopup"]  # Playwright's, kept in order
    assert set(BROWSER_UI_FEATURES_OFF) <= set(features) and len(features) == len(set(features))
    assert ignored == [theirs]  # Playwright's own flag is left out, so the merged one is the only one


def test_without_a_flag_of_playwright_s_the_bench_s_features_are_the_flag():
    pw = FakePlaywright(["/usr/bin/chromium", "--headless"])
    args, ignored = launch_args(pw, "/usr/bin/chromium")
    assert ignored == []
    assert args[-1] == "--disable-features=" + ",".join(BROWSER_UI_FEATURES_OFF)


def test_the_flags_are_read_once_for_every_profile_of_a_run():
    pw = FakePlaywright(["/usr/bin/chromium", "--disable-features=PaintHolding"])
    first = launch_args(pw, "/usr/bin/chromium")
    pw.launched = {}
    assert launch_args(pw, "/usr/bin/chromium") == first
    assert pw.launched == {}  # no second throwaway browser
