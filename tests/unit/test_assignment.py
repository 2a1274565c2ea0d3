"""Assignments: the assigned variant (one function in Python and in the page's JavaScript,
checked equal over many inputs), the student id's folding (NFKC and full case folding, equal
in both over every code point), and the name of the slip a wrong answer hit (``data.slip``)."""

from __future__ import annotations

import json
import random
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from workbook import api, bank
from workbook.assignment import MAX_SEED, assigned_variant, fold, tidy
from workbook.slip_names import NAMED, slip_name
from workbook.variants import check_seed

ROOT = Path(__file__).resolve().parents[2]
HASH_JS = ROOT / "docs" / "assets" / "js" / "assignment-hash.js"
TABLE = ROOT / "build" / "casefold.json"  # make writes it (scripts/casefold_table.py); the JS loads it
# Characters that test the tidying and the folding: spaces of every kind, capitals inside and outside
# ASCII, composed and decomposed accents, a combining mark that folds to a letter (U+0345), ligatures
# and compatibility forms, Cherokee (which folds to capitals), emoji, a quote, a newline and a backslash,
# and characters newer than the grader's Unicode (outlined digits, U+A7F1).
ALPHABET = list("aZ09 -_.,'\"\\\n\t") + ["\u00a0", "\u2003", "\u3000", "\u0085", "\u001f", "\ufeff", "É", "é", "e\u0301",
                                         "İ", "ß", "Σ", "ς", "😀", "\u200b", "Ω", "\u212b", "Å", "\u0345", "\u0301", "\u0323",
                                         "ﬁ", "Ⅻ", "①", "ｱ", "\u13a0", "ꭰ", "ǅ", "\u1e9e", "\U0001ccd6", "\ua7f1", "李", "ᾳ"]


def random_text(rng: random.Random, n: int) -> str:
    return "".join(rng.choice(ALPHABET) for _ in range(rng.randint(0, n)))


def inputs(count: int = 3000) -> list[tuple[str, str, str]]:
    rng = random.Random(27)
    ids = [ex.id for ch in bank.chapters() for ex in bank.chapter(ch)]
    return [(random_text(rng, 12), random_text(rng, 16), rng.choice(ids)) for _ in range(count)]


def test_in_range_and_a_valid_seed():
    for code, student, ex_id in inputs(500):
        n = assigned_variant(code, student, ex_id)
        assert 1 <= n <= MAX_SEED and check_seed(n) == n


def test_stable_for_a_student_different_between_students():
    ids = [ex.id for ch in bank.chapters() for ex in bank.chapter(ch) if ex.kind == "derive"]
    a = [assigned_variant("ROB101", "s1001", i) for i in ids]
    assert a == [assigned_variant(" ROB101 ", "S1001", i) for i in ids]  # the same student, typed otherwise
    assert a == [assigned_variant("ROB101", "  s1001\t", i) for i in ids]
    students = [f"s{n}" for n in range(200)]
    for ex_id in ids[:10]:
        drawn = [assigned_variant("ROB101", s, ex_id) for s in students]
        assert len(set(drawn)) >= 195, "200 students share few numbers"  # 999,999 sets: a clash is rare
    assert assigned_variant("ROB101", "s1", "0.1") != assigned_variant("ROB102", "s1", "0.1")


def test_ids_fold_as_the_page_promises():
    assert fold("  Ada \n Lovelace ") == "ada lovelace"
    assert fold("ÉMILE") == fold("Émile") == fold("émile") == fold("E\u0301mile") == "émile"
    assert fold("Straße") == fold("STRASSE") == "strasse" and fold("ﬁsh") == "fish" and fold("\uff21\uff22\uff23") == "abc"
    assert tidy("e\u0301") == "é"  # NFC
    assert assigned_variant("ROB101", "Émile", "0.1") == assigned_variant("ROB101", "émile", "0.1")


def test_plain_ascii_ids_keep_their_numbers():
    """Folding beyond A-Z changes nothing for ASCII ids: the numbers main gave them (computed there)."""
    cases = [("Ada Lovelace", "0.1"), ("  ada   LOVELACE ", "0.4"), ("S1234567", "1.1"), ("x-Y_z.9", "3.2")]
    assert [assigned_variant("ROB101 week 3", s, e) for s, e in cases] == [339841, 615046, 193142, 984224]


def _table() -> None:
    if not TABLE.exists():  # make writes it; a unit run on a fresh clone writes it the same way
        subprocess.run([sys.executable, str(ROOT / "scripts" / "casefold_table.py"), str(TABLE)], check=True)


@pytest.mark.skipif(shutil.which("node") is None, reason="needs Node")
def test_javascript_folds_every_code_point_as_python(tmp_path):
    """The page's fold() against Python's, one code point at a time over all 1,112,064 (surrogates aside):
    the case folding comes from Python's own table, and NFKC leaves alone what Python's Unicode has not
    assigned, whatever Node's newer Unicode knows."""
    _table()
    script = tmp_path / "all.mjs"
    script.write_text(
        f"import {{ fold }} from {json.dumps(HASH_JS.as_uri())};\n"
        "const out = [];\n"
        "for (let c = 0; c <= 0x10ffff; c++) { if (c < 0xd800 || c > 0xdfff) out.push(await fold(String.fromCodePoint(c))); }\n"
        "process.stdout.write(JSON.stringify(out));\n")
    run = subprocess.run(["node", str(script)], capture_output=True, text=True, check=True)
    theirs = json.loads(run.stdout)
    points = [c for c in range(sys.maxunicode + 1) if not 0xD800 <= c <= 0xDFFF]
    assert len(theirs) == len(points) == 1_112_064
    differ = [hex(c) for c, js in zip(points, theirs) if fold(chr(c)) != js]
    assert differ == []


@pytest.mark.skipif(shutil.which("node") is None, reason="needs Node")
def test_javascript_computes_the_same_variants(tmp_path):
    _table()
    cases = inputs()
    script = tmp_path / "run.mjs"
    script.write_text(
        f"import {{ assignedVariant }} from {json.dumps(HASH_JS.as_uri())};\n"
        "import { readFileSync } from 'node:fs';\n"
        "const cases = JSON.parse(readFileSync(process.argv[2], 'utf8'));\n"
        "const out = [];\n"
        "for (const [c, s, e] of cases) out.push(await assignedVariant(c, s, e));\n"
        "process.stdout.write(JSON.stringify(out));\n")
    data = tmp_path / "cases.json"
    data.write_text(json.dumps(cases), encoding="utf-8")
    run = subprocess.run(["node", str(script), str(data)], capture_output=True, text=True, check=True)
    assert json.loads(run.stdout) == [assigned_variant(*case) for case in cases]


def test_slip_names_are_the_same_in_every_variant():
    assert slip_name("slip", "That is x = 2.5, not −1.25 m; see J(1,2).") == "slip: That is x = #, not # m; see J(1,2)."
    assert slip_name("sign", "anything") == "sign"
    assert slip_name("", "Not quite.") is None and slip_name("carried", "x") is None and slip_name("why", "x") is None
    assert len(slip_name("slip", "word " * 100)) <= 80


def test_a_wrong_answer_names_its_slip_in_data():
    """Every own slip of every Derive exercise, over several variants, comes back with data.slip: 'slip: ...';
    a right answer and a plain wrong one carry none."""
    seen = 0
    for ch in bank.chapters():
        for ex0 in bank.chapter(ch):
            if ex0.kind != "derive":
                continue
            for variant in (0, 17, 4242):
                ex = bank.variant(ex0.id, variant)
                for slip in ex.answer.slips:
                    reply = api.dispatch({"op": "grade", "exercise": ex.id, "variant": variant, "answer": ex.answer.typed(slip.value)})
                    verdict = reply["value"]
                    if verdict["tag"] in NAMED:
                        assert verdict["data"]["slip"] == slip_name(verdict["tag"], verdict["message"])
                        seen += 1
                right = api.dispatch({"op": "grade", "exercise": ex.id, "variant": variant, "answer": ex.answer.typed(ex.answer.key)})
                assert "slip" not in right["value"]["data"]
    assert seen > 100
    signs = 0
    for ex in (e for ch in bank.chapters() for e in bank.chapter(ch) if e.kind == "derive" and isinstance(e.answer.key, float)):
        verdict = api.dispatch({"op": "grade", "exercise": ex.id, "answer": ex.answer.typed(-ex.answer.key)})["value"]
        if verdict["tag"] == "sign":
            assert verdict["data"]["slip"] == "sign"
            signs += 1
    assert signs >= 3
    plain = api.dispatch({"op": "grade", "exercise": "0.1", "answer": "12345"})["value"]
    assert plain["tag"] == "" and "slip" not in plain["data"]
