"""The draws the oracle tests (test_ch11_oracle, test_ch12_oracle, test_ch13_oracle) cross-check:
every Derive exercise of a chapter over DRAWS variants with different numbers."""

from __future__ import annotations

from workbook import bank

DRAWS = 300


def distinct_variants(ex_id: str, count: int = DRAWS) -> list:
    """Up to ``count`` variants of ``ex_id`` with different numbers (seeds 0, 1, … up to 4 × count)."""
    seen, out = set(), []
    for seed in range(count * 4):
        v = bank.variant(ex_id, seed)
        key = tuple(sorted(v.params.items()))
        if key not in seen:
            seen.add(key)
            out.append(v)
        if len(out) == count:
            break
    return out
