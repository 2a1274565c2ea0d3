"""How many cases the many-case tests take (the variants of test_variants, test_printed,
test_steps and test_steps_bank; the hostile requests of test_fuzz_api; the review seeds of
test_build_holdout, and its programs; the odd outputs each Build exercise returns in
test_run_figures): all of them in ``make test`` and CI; a share of them in ``make test-unit``,
the developer's quick loop (``WORKBOOK_DRAW_SHARE=0.2``), which still draws from every exercise."""

from __future__ import annotations

import os

SHARE = float(os.environ.get("WORKBOOK_DRAW_SHARE", "1"))


def share_of(items: tuple) -> tuple:
    """All of ``items`` in the whole suite; the first share of them (at least one) in the quick loop."""
    return items if SHARE >= 1 else items[:max(1, round(len(items) * SHARE))]


def count(full: int) -> int:
    """``full`` draws in the whole suite; the share of them (at least 20) in the quick loop."""
    return full if SHARE >= 1 else max(20, round(full * SHARE))


def pairs(firsts: list, seconds: list) -> list[tuple]:
    """Every pair in the whole suite; in the quick loop, each of ``firsts`` with its share of
    ``seconds``, the share turning from one to the next (and any second left over with the first),
    so that every first and every second still comes."""
    if SHARE >= 1:
        return [(a, b) for a in firsts for b in seconds]
    each = max(1, round(len(seconds) * SHARE))
    chosen = [(a, seconds[(i * each + k) % len(seconds)]) for i, a in enumerate(firsts) for k in range(each)]
    seen = {b for _, b in chosen}
    return chosen + [(firsts[0], b) for b in seconds if b not in seen]
