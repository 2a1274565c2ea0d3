"""The page contract, as Python names: read once from ``contract.json``.

``contract.json`` (beside this file) is the one source for the names and limits that
the page, the worker, the build and the tests share, and holds nothing else: the
prose that explains each entry is in ``CONTRACT.md`` at the top of the repository
(both workers and the page bundle the JSON, so every word in it would ship), and
facts another part owns are read from that part (a Build exercise's signature from
the bank, which exercises an op applies to from the kinds and ``api``). The page's
JavaScript imports the same file (``docs/assets/js/contract.js``). Extend it; never
rename an entry.

>>> ROLE.answer, ATTR.state, STATE.pending, TAG.slip
('answer', 'data-state', 'pending', 'slip')
>>> role_attr("move-up")
'data-role="move-up"'
>>> ROLE.move_up
'move-up'
>>> LIMIT.variant, LIMIT.answer
(999999, 10000)
"""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path
from types import SimpleNamespace
from typing import Any

SOURCE = Path(__file__).with_name("contract.json")
# Through importlib.resources: in the page the package is imported from a zip.
DATA: dict[str, Any] = json.loads(resources.files(__package__).joinpath("contract.json").read_text(encoding="utf-8"))


def _names(values) -> SimpleNamespace:
    """A namespace whose attributes are the values (``move-up`` as ``move_up``)."""
    return SimpleNamespace(**{v.replace("-", "_"): v for v in values})


ATTR = SimpleNamespace(**DATA["attributes"])
ROLE = _names(DATA["roles"])
STATE = _names(DATA["states"])
STATUS = _names(DATA["statuses"])
TAG = _names(DATA["tags"])
ERROR = _names(DATA["errors"])
KINDS: tuple[str, ...] = tuple(DATA["kinds"])
ANSWER_KINDS: tuple[str, ...] = tuple(DATA["answerKinds"])
REVIEW_KINDS: tuple[str, ...] = tuple(DATA["reviewKinds"])  # the kinds that join the review queue
STATUSES: tuple[str, ...] = tuple(DATA["statuses"])
ERRORS: tuple[str, ...] = tuple(DATA["errors"])
OPS: dict[str, dict[str, Any]] = DATA["ops"]
LIMIT = SimpleNamespace(**DATA["limits"])  # shared with the page


def role_attr(role: str) -> str:
    """``data-role="NAME"``, for a role the contract defines (others raise KeyError)."""
    if role not in DATA["roles"]:
        raise KeyError(f"no role {role!r} in the contract")
    return f'{ATTR.role}="{role}"'
