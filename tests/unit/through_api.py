"""A grade through the production path: one "grade" request to ``workbook.api.handle``, as the
page sends it, with the steps the learner has sent and (optionally) the step being checked."""

from __future__ import annotations

import json

from workbook.api import handle


def grade(v, answer, step=None, sent=None) -> dict:
    """The reply's value for ``answer`` to variant ``v`` (asserting the request was accepted)."""
    request = {"op": "grade", "exercise": v.id, "variant": v.seed, "answer": answer, "steps": sent or {}}
    if step is not None:
        request["step"] = step
    reply = json.loads(handle(json.dumps(request)))
    assert reply["ok"], reply
    return reply["value"]
