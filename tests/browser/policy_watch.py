"""Every browser context the tests open watches the site's Content-Security-Policy.

``watch_every_context()`` makes ``Browser.new_context`` (which pytest-playwright's
``context`` and ``page`` fixtures call too; not ``Browser.new_page``, which only the test of a
page opened from a file uses) add a watcher to each new context: the
document's ``securitypolicyviolation`` events, in every page and frame, and the
console messages of its pages that report a blocked load. (What the policy blocks
inside a dedicated worker reaches neither; the sandbox's attack tests check its
worker themselves.) What
is seen goes into ``BLOCKED``; conftest's ``policy_kept`` fails the test that was
running. So every test that uses the site also checks that nothing it does breaks
the policy (test_csp.py checks that the watcher sees a violation when there is one).
"""

from __future__ import annotations

from playwright.sync_api import Browser, BrowserContext

BLOCKED: list[str] = []  # what the policy blocked since the running test began
_REPORT = """
document.addEventListener("securitypolicyviolation", (e) => {
  window.__wbPolicySeen = (window.__wbPolicySeen || 0) + 1;
  window.__wbPolicyBlocked?.(`${e.effectiveDirective} blocked ${e.blockedURI || "?"} at ${e.sourceFile}:${e.lineNumber} ` +
                             `(${e.sample})`);
});
"""
_CONSOLE_SAYS = ("Content Security Policy", "Content-Security-Policy")


def watch(context: BrowserContext) -> None:
    """Record into ``BLOCKED`` whatever the policy blocks in ``context``."""
    context.expose_binding("__wbPolicyBlocked", lambda source, text: BLOCKED.append(f"{source['page'].url}: {text[:300]}"))
    context.add_init_script(_REPORT)
    context.on("console", lambda msg: BLOCKED.append(f"{msg.page.url if msg.page else '(worker)'}: console: {msg.text[:300]}")
               if any(s in msg.text for s in _CONSOLE_SAYS) else None)


_new_context = Browser.new_context


def _new_context_watched(self: Browser, **kwargs) -> BrowserContext:
    context = _new_context(self, **kwargs)
    watch(context)
    return context


def watch_every_context() -> None:
    Browser.new_context = _new_context_watched  # type: ignore[method-assign]
