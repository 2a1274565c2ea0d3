"""Write the Unicode case folding of the Python that runs this (``str.casefold``) as JSON, for
the page: a student's id is folded the same way in Python (workbook/assignment.py) and in the
browser (docs/assets/js/assignment-hash.js), whatever Unicode version the browser knows.

Usage: python scripts/casefold_table.py OUT.json

The table: ``runs`` [[first, count, step, delta], ...], code points first, first + step, ...
(count of them) that fold to the one code point ``cp + delta``; ``multi`` [[cp, text], ...],
those that fold to more than one (ß to ss); ``unassigned`` [[gap, count], ...], the code
points this Unicode version has not assigned (each run starts ``gap`` after the previous
one's end), which this Python's NFKC leaves as they are and a browser that knows a newer
version might not; ``unicode``, the version of the data.
"""

from __future__ import annotations

import json
import sys
import unicodedata
from pathlib import Path


def singles_and_multi() -> tuple[list[tuple[int, int]], list[tuple[int, str]]]:
    singles: list[tuple[int, int]] = []
    multi: list[tuple[int, str]] = []
    for cp in range(sys.maxunicode + 1):
        if 0xD800 <= cp <= 0xDFFF:
            continue
        folded = chr(cp).casefold()
        if folded == chr(cp):
            continue
        if len(folded) == 1:
            singles.append((cp, ord(folded) - cp))
        else:
            multi.append((cp, folded))
    return singles, multi


def runs(singles: list[tuple[int, int]]) -> list[list[int]]:
    """Consecutive mappings with one delta and one step (1: a block of capitals; 2: capitals and
    small letters alternating)."""
    out: list[list[int]] = []
    for cp, delta in singles:
        if out:
            first, count, step, last_delta = out[-1]
            last = first + (count - 1) * step
            if delta == last_delta and (cp - last == step or (count == 1 and cp - last in (1, 2))):
                out[-1] = [first, count + 1, cp - last, delta]
                continue
        out.append([cp, 1, 1, delta])
    return out


def unassigned() -> list[list[int]]:
    out: list[list[int]] = []
    end = 0  # where the previous run ended
    start = None
    for cp in range(sys.maxunicode + 2):
        gap = cp <= sys.maxunicode and not 0xD800 <= cp <= 0xDFFF and unicodedata.category(chr(cp)) == "Cn"
        if gap and start is None:
            start = cp
        elif not gap and start is not None:
            out.append([start - end, cp - start])
            end, start = cp, None
    return out


def table() -> dict:
    singles, multi = singles_and_multi()
    return {"unicode": unicodedata.unidata_version, "runs": runs(singles), "multi": [[cp, text] for cp, text in multi],
            "unassigned": unassigned()}


if __name__ == "__main__":
    target = Path(sys.argv[1])
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(json.dumps(table(), ensure_ascii=False, separators=(",", ":")) + "\n", encoding="utf-8")
