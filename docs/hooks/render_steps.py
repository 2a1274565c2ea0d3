"""Build side: "Work it in steps", the checked steps of a Derive exercise (CONTRACT.md, "Checked steps").

Under the answer of an exercise that declares steps (``ex.steps``), a button
(``work-steps-open``) opens a panel (``work-steps``): an ordered list with, for
each step, its number and label, the step's own answer widget (its answer kind,
``ex.step_answers[name]``, drawn with a base unique to the step), its own Check
(``work-step-check``) and its own feedback (``work-step-feedback``). The list is
kept in a ``<template>`` until the panel first opens (docs/assets/js/steps.js),
so a closed panel adds no second ``answer`` or ``entry`` to the exercise.
"""

from __future__ import annotations

from html import escape
from typing import Any

from workbook.contract import ATTR, ROLE, STATE, role_attr
from workbook.markup import check_button


def step_base(base: str, name: str) -> str:
    """The DOM id prefix of one step's widget: unique in the page."""
    return f"{base}-step-{name}"


def _step_check() -> str:
    return check_button().replace(role_attr(ROLE.check), role_attr(ROLE.work_step_check))


def _step_html(ex: Any, base: str, n: int, step: Any, page: Any) -> str:
    answer = ex.step_answers[step.name]
    sbase = step_base(base, step.name)
    widget = answer.widget(sbase, page)
    if widget.count(check_button()) != 1:
        raise ValueError(f"exercise {ex.id}: step {step.name}'s widget does not hold exactly one Check button")
    kind = {ATTR.answerKind: answer.kind, **answer.attributes()}  # which page module drives its widget
    attributes = "".join(f' {name}="{escape(value)}"' for name, value in kind.items())
    return (f'<li class="wb-work-step" id="{sbase}" {role_attr(ROLE.work_step)} {ATTR.stepName}="{escape(step.name)}" '
            f'{ATTR.state}="{STATE.unanswered}"{attributes}>'
            f'<p class="wb-work-step-title" id="{sbase}-title">Step {n} · {escape(step.label)}</p>'
            f"{widget.replace(check_button(), _step_check())}"
            f'<div class="wb-feedback wb-work-step-feedback" id="{sbase}-feedback" '
            f'{role_attr(ROLE.work_step_feedback)} '
            f'role="status" aria-live="polite"></div></li>')


def steps_html(ex: Any, base: str, page: Any) -> str:
    """The button and the (closed) panel of an exercise's checked steps, or "" when it has none."""
    steps = getattr(ex, "steps", ()) if getattr(ex, "step_answers", None) else ()  # a Design's steps are its own
    if not steps:
        return ""
    items = "".join(_step_html(ex, base, n, step, page) for n, step in enumerate(steps, 1))
    return (f'<div class="wb-work">'
            f'<button type="button" class="md-button wb-help-button" {role_attr(ROLE.work_steps_open)} '
            f'aria-expanded="false" aria-controls="{base}-steps">Work it in steps</button>'
            f'<div class="wb-work-steps" id="{base}-steps" {role_attr(ROLE.work_steps)} role="group" '
            f'aria-label="Steps of exercise {escape(ex.id)}" hidden>'
            f'<template><ol class="wb-work-list">{items}</ol></template></div></div>')
