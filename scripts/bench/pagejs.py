"""The in-page JavaScript (``js/*.js``, read at run time) and the contract names it is given.

No selector is written in the JavaScript: the page scripts receive ``C`` (built
here from ``workbook.contract``) and build theirs from it.
"""

from __future__ import annotations

import functools
import json
from pathlib import Path

from workbook.contract import ATTR, ROLE, STATE, role_attr

JS_DIR = Path(__file__).with_name("js")

# The roles the bench's scripts touch.
_ROLES = (ROLE.answer, ROLE.choice, ROLE.line, ROLE.check, ROLE.run, ROLE.editor, ROLE.feedback, ROLE.test_result,
          ROLE.new_variant, ROLE.runtime_status, ROLE.runtime_progress)


def role(name: str) -> str:
    """A CSS selector for a contract role (the attribute and value from the contract)."""
    return f"[{role_attr(name)}]"


def exercise(ex_id: str) -> str:
    """A CSS selector for one exercise by id."""
    return f'[{ATTR.exercise}="{ex_id}"]'


def contract() -> dict:
    """``C``: the names the page scripts need, from the contract."""
    return {
        "attr": {"exercise": ATTR.exercise, "state": ATTR.state, "runtime": ATTR.runtime, "passed": ATTR.passed,
                 "offline": ATTR.offline, "variant": ATTR.variant, "phase": ATTR.phase},
        "sel": {name: role(name) for name in _ROLES},
        "state": {"pending": STATE.pending, "unanswered": STATE.unanswered},
    }


@functools.cache
def source(name: str) -> str:
    """The function in ``js/NAME.js``: the file without its leading comment lines."""
    lines = (JS_DIR / f"{name}.js").read_text(encoding="utf-8").strip().splitlines()
    while lines and lines[0].lstrip().startswith("//"):
        lines.pop(0)
    return "\n".join(lines)


def init_script(name: str = "init") -> str:
    """The instrumentation, as an init script: ``js/init.js`` (or ``js/NAME.js``) called with ``C``."""
    return f"({source(name).strip()})({json.dumps(contract())});"


def run(page, name: str, args: dict | None = None):
    """Evaluate ``js/NAME.js`` (a function) in the page with ``args`` plus ``C``."""
    if args is None:
        return page.evaluate(source(name))
    return page.evaluate(source(name), {**args, "C": contract()})
