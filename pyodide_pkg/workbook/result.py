"""One small result shape for every checker, rendered by one widget."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any

STATUSES = ("correct", "incorrect", "invalid", "error")


@dataclass
class Result:
    """``status`` is one of :data:`STATUSES`; ``message`` is for the learner.

    ``tag`` names the kind of feedback (``close``, ``radians``, ``sign``,
    ``slip``, ``syntax``, ...) so the page and the tests can tell them apart;
    ``data`` carries extras such as a Build run's test rows.
    """

    status: str
    message: str
    tag: str = ""
    data: dict[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"unknown status {self.status!r}")

    @property
    def correct(self) -> bool:
        return self.status == "correct"

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)
