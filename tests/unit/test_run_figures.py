"""Run figures: after a Build run, the learner's function drawn beside the reference.

For every Build exercise with a run figure: the solution's drawing matches the
reference (largest error 0); a wrong function's readout names its largest error
and the case; one that raises or returns NaN part-way is drawn as far as it got,
with the message; nothing a function returns makes the figure raise.
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET

import pytest

import many_draws
from workbook import bank
from workbook.api import handle
from workbook.build_judge import read_report
from workbook.contract import ROLE
from workbook.figures import runs
from workbook_sandbox import harness, runner

SVG = "{http://www.w3.org/2000/svg}"
BUILDS = [ex for ex in bank.all_exercises() if ex.kind == "build" and ex.run_figure]
IDS = [ex.id for ex in BUILDS]

ODD = {
    "None": "return None",
    "text": "return 'hello'",
    "three numbers": "return (1, 2, 3)",
    "nested": "return [[1], [2]]",
    "NaN": "return (float('nan'), 1.0)",
    "infinity": "return (float('inf'), float('-inf'))",
    "huge": "return (1e300, -1e300)",
    "huge int": "return (10 ** 400, 1)",
    "a dict": "return {'x': 1, 'y': 2}",
    "raises": "raise ValueError('nope')",
    "exits": "exit()",
    "negative": "return (1.0, -2.0)",
}


def learner(ex, body: str) -> str:
    return f"def {ex.function}(*args):\n    {body}\n"


def figure_of(verdict) -> dict:
    fig = verdict.data.get("figure")
    assert fig is not None, verdict.message
    return fig


def well_formed(fig: dict) -> None:
    assert fig["frames"], fig
    assert 0 <= fig["start"] < len(fig["frames"])
    for frame in fig["frames"]:
        root = ET.fromstring(frame["svg"])
        assert root.tag == f"{SVG}svg" and root.get("role") == "img"
        assert root.find(f"{SVG}title").text
        assert frame["description"] and frame["label"] in frame["description"]
        assert frame["readout"].startswith(frame["label"])
        assert "Traceback" not in frame["description"]


def test_every_build_has_a_run_figure():
    assert {"0.5", "4.5", "6.5", "8.4"} <= set(IDS)
    assert [ex.id for ex in bank.all_exercises() if ex.kind == "build"] == IDS
    assert set(runs.names()) >= {ex.run_figure for ex in BUILDS}


@pytest.mark.parametrize("exercise_id", IDS)
def test_the_solution_draws_the_reference(exercise_id):
    ex = bank.get(exercise_id)
    verdict = ex.check(ex.solution)
    assert verdict.status == "correct"
    fig = figure_of(verdict)
    well_formed(fig)
    assert re.match(r"Largest error 0( m| rad)?: yours agrees with the reference on every case$", fig["readout"])
    for frame in fig["frames"]:
        assert ": error 0" in frame["readout"] and "Your function" not in frame["readout"]


@pytest.mark.parametrize("exercise_id", IDS)
def test_the_starter_names_its_largest_error_and_case(exercise_id):
    ex = bank.get(exercise_id)
    fig = figure_of(ex.check(ex.starter))
    well_formed(fig)
    match = re.match(r"Largest error ([\d.]+)( m| rad)? at (test \d+|hidden case \d+|run \d+)(;|$)", fig["readout"])
    assert match, fig["readout"]
    assert float(match.group(1)) > 0.01
    # the figure opens on the worst case drawn: one that failed outright, or the largest error
    start = fig["frames"][fig["start"]]
    error = re.search(r": error ([\d.]+)", start["readout"])
    assert "Your function" in start["readout"] or float(error.group(1)) > 0, start["readout"]


@pytest.mark.parametrize("exercise_id,odd", many_draws.pairs(IDS, list(ODD)))
def test_odd_outputs_never_break_the_figure(exercise_id, odd):
    ex = bank.get(exercise_id)
    verdict = ex.check(learner(ex, ODD[odd]))
    assert verdict.status == "incorrect"
    fig = figure_of(verdict)
    well_formed(fig)
    assert fig["readout"][0].isupper()
    json.dumps(fig, allow_nan=False)  # the page parses it: no NaN may leak into it


def test_a_closed_loop_run_stops_where_the_function_raised():
    ex = bank.get("8.4")
    code = ex.solution.replace('    new_integral = integral + e * dt\n',
                               '    new_integral = integral + e * dt\n    if 0 < e < 0.5:\n'
                               '        raise ZeroDivisionError("half way")\n')
    fig = figure_of(ex.check(code))
    well_formed(fig)
    assert "raised ZeroDivisionError: half way" in fig["readout"]
    frame = fig["frames"][fig["start"]]
    steps = int(re.search(r"Stopped after (\d+) steps", frame["readout"]).group(1))
    assert 0 < steps < 60
    assert "wb-fig-bad" in frame["svg"] and "half way" in frame["svg"]
    # what it drew agrees with the reference as far as it got
    assert re.search(r": error 0\b", frame["readout"])


def test_a_closed_loop_run_stops_at_nan():
    ex = bank.get("8.4")
    code = ex.solution.replace("    return (p + i + d, new_integral)",
                               "    return (p + i + d if e > 0.5 else float('nan'), new_integral)")
    fig = figure_of(ex.check(code))
    well_formed(fig)
    assert re.search(r"Stopped: sample \d+ is NaN", fig["readout"])


def test_a_wrong_hidden_case_is_drawn_and_named():
    ex = bank.get("6.5")
    code = ex.solution.replace("return (x, y)", "return (x, y) if L1 < 1.5 else (x + 0.25, y)")
    verdict = ex.check(code)
    fig = figure_of(verdict)
    assert re.match(r"Largest error 0\.25(00)? m at (test|hidden case) \d+", fig["readout"]), fig["readout"]
    named = fig["readout"].split(" at ")[1]
    assert named in [f["label"] for f in fig["frames"]]


def test_the_reference_drawn_is_the_graders_own():
    """A report that claims anything cannot change the reference trace: the grader runs it itself."""
    ex = bank.get("8.4")
    job = json.loads(ex.job())
    report = runner.run(job, ex.solution)
    for case in report["figure"]:
        case["value"]["items"] = [{"type": "float", "number": 5.0, "text": "5.0"}] * 61
    fig = figure_of(ex.judge(json.dumps(report)))
    reference = harness.pid_loop(bank.get("8.4").reference, *job["figure"]["cases"][0])
    assert f"ends at {runs.compact(reference[-1])}" in fig["frames"][0]["description"]
    assert fig["readout"].startswith("Largest error 5")


def test_a_forged_figure_section_is_read_as_data():
    ex = bank.get("8.4")
    report = runner.run(json.loads(ex.job()), ex.solution)
    for forged in ([{"value": "x"}], [None, 5], "text", [{"error": 7, "partial": [1]}], [{"value": {"items": 3}}]):
        report["figure"] = forged
        fig = figure_of(ex.judge(json.dumps(report)))
        well_formed(fig)
    read = read_report({"cases": [], "figure": [{}] * 50}, 0, 2)
    assert len(read.figure) == 2


def test_the_api_returns_the_figure_with_the_verdict():
    ex = bank.get("6.5")
    cases = json.loads(handle(json.dumps({"op": "cases", "exercise": "6.5", "code": ex.solution})))
    report = runner.run_json(cases["value"]["job"], ex.solution)
    reply = json.loads(handle(json.dumps({"op": "judge", "exercise": "6.5", "outputs": report})))
    assert reply["ok"] and reply["value"]["data"]["figure"]["name"] == "arm"


def _api(**request):
    return json.loads(handle(json.dumps(request)))


@pytest.mark.parametrize("variant", [0, 7])
def test_the_figure_asked_for_later_is_the_one_the_verdict_would_hold(variant):
    """The page shows the verdict first (judge with figureLater), then asks for the figure
    (run-figure): the same verdict without its figure, and the same figure, for a wrong run too."""
    ex = bank.get("6.5")
    wrong = ex.solution.replace("L1 * math.cos(theta1)", "L1 * math.sin(theta1)")
    assert wrong != ex.solution
    for code in (ex.solution, wrong):
        job = _api(op="cases", exercise="6.5", code=code, variant=variant)["value"]["job"]
        report = runner.run_json(job, code)
        whole = _api(op="judge", exercise="6.5", outputs=report, variant=variant)["value"]
        first = _api(op="judge", exercise="6.5", outputs=report, variant=variant, figureLater=True)["value"]
        later = _api(op="run-figure", exercise="6.5", outputs=report, variant=variant)["value"]
        figure = whole["data"].pop("figure")
        assert "figure" not in first["data"] and first == whole
        assert later == {"figure": figure}
    assert whole["status"] == "incorrect"


def test_a_run_that_did_not_load_has_no_figure_later():
    job = _api(op="cases", exercise="6.5", code="def nope(:\n")["value"]["job"]
    report = runner.run_json(job, "def nope(:\n")
    assert _api(op="run-figure", exercise="6.5", outputs=report)["value"] == {"figure": None}
    assert _api(op="run-figure", exercise="6.5", outputs="not json")["error"]["kind"] == "bad-request"
    assert _api(op="run-figure", exercise="0.1", outputs="{}")["error"]["kind"] == "wrong-op"


def test_the_widget_holds_the_run_figure_roles():
    html = bank.get("6.5").widget("ex-6-5", None)
    for role in ("run_figure", "run_canvas", "run_description", "readout", "run_case", "run_previous", "run_next",
                 "run_case_label"):
        assert f'data-role="{getattr(ROLE, role)}"' in html
    assert 'role="img"' in html and "aria-describedby" in html and " hidden>" in html


HALF_WAY = {  # a solution that raises part-way through a closed loop: (exercise, line to add, the line it follows)
    "8.8": "    if 0 < e < 0.5:\n        raise ZeroDivisionError('half way')\n",
    "3.10": "    if x[0] > 1.0:\n        raise ZeroDivisionError('half way')\n",
    "9.9": "    if x[0] > 1.0:\n        raise ZeroDivisionError('half way')\n",
}


@pytest.mark.parametrize("exercise_id", sorted(HALF_WAY))
def test_every_closed_loop_is_drawn_as_far_as_it_got(exercise_id):
    ex = bank.get(exercise_id)
    head, _, body = ex.solution.partition(f"def {ex.function}(")
    signature, _, rest = body.partition("\n")
    docstring, _, rest = rest.partition("\n")
    code = f"{head}def {ex.function}({signature}\n{docstring}\n{HALF_WAY[exercise_id]}{rest}"
    fig = figure_of(ex.check(code))
    well_formed(fig)
    frame = fig["frames"][fig["start"]]
    steps = int(re.search(r"Stopped after (\d+) steps", frame["readout"]).group(1))
    assert steps > 0, frame["readout"]
    assert "half way" in frame["readout"] and "half way" in frame["svg"]
    assert re.search(r": error 0\b", frame["readout"]), frame["readout"]


def test_6_7_draws_the_angles_given_where_none_was_due_and_opens_on_the_headline_s_case():
    """A function that never refuses: its angles on an unreachable target are still drawn (with the distance
    of the tip from the target, in metres), and the figure opens on the case its readout names first."""
    ex = bank.get("6.7")
    verdict = ex.check("def ik_2link(L1, L2, x, y, elbow_up):\n    return (0.32, 0.0)\n")
    fig = figure_of(verdict)
    well_formed(fig)
    refused = [f for f in fig["frames"] if "out of reach, and the reference returns None" in f["description"]]
    assert refused
    for frame in refused:
        assert "gave no angles" not in frame["description"]
        assert "your angles, θ1 = 18.3346°, θ2 = 0°, put the tip " in frame["description"]
        assert re.search(r"put the tip [\d.]+ m from the target", frame["description"])
        assert 'class="wb-fig-a' in frame["svg"]
    named = re.match(r"Largest error [\d.]+ rad at (test \d+|hidden case \d+)", fig["readout"]).group(1)
    assert fig["frames"][fig["start"]]["label"] == named


@pytest.mark.parametrize("exercise_id", [i for i in IDS if bank.get(i).angles])
def test_a_half_turn_given_as_minus_pi_measures_no_error(exercise_id):
    ex = bank.get(exercise_id)
    fig = figure_of(ex.check(ex.solution))
    assert all(": error 0" in frame["readout"] for frame in fig["frames"])
