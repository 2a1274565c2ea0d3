"""Every learner-facing message is pinned in tests/golden/transcript.json (reviewed)."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "golden"))

import transcript as golden  # noqa: E402


def test_the_grader_says_what_the_golden_transcript_says():
    assert golden.FILE.exists(), "run: python tests/golden/transcript.py --write, then review it"
    now = golden.dumps(golden.transcript())
    was = golden.FILE.read_text(encoding="utf-8")
    if now != was:
        changed = [ex for ex, entry in golden.transcript().items()
                   if golden.dumps({ex: entry}) != golden.dumps({ex: __import__("json").loads(was).get(ex)})]
        raise AssertionError(
            f"the grader's words changed for {', '.join(changed) or 'the file layout'}: "
            "run `python tests/golden/transcript.py --write` and review the diff"
        )
