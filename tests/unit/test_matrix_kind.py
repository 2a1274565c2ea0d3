"""Vector and matrix answers: pasted text, entries, and whole-matrix slips."""

import math

import pytest

from workbook.answer_kinds.matrix import matrix
from workbook.answer_kinds.matrix.slips import whole_matrix_slips
from workbook.expr import InvalidAnswer
from workbook.expr import split_matrix as parse_pasted


def parse_entries(grid, shape):
    """The entries' values, as the matrix kind reads them (InvalidAnswer if any cannot be read)."""
    ans = matrix().build("t.1", key=tuple(tuple(0.0 for _ in range(shape[1])) for _ in range(shape[0])))
    out = ans.read(grid)
    if "message" in out:
        raise InvalidAnswer(out["message"])
    return out["value"]


def wrong_entries(got, key):
    ans = matrix().build("t.1", key=tuple(map(tuple, key)))
    verdict = ans.check([[repr(v) for v in row] for row in got])
    return [tuple(p) for p in verdict.data.get("wrong", [])]

ROT90 = [["0", "-1"], ["1", "0"]]


@pytest.mark.parametrize("text", [
    "[[0,-1],[1,0]]", "[[0, -1], [1, 0]]", "0 -1; 1 0", "[0, -1; 1, 0]", "[0 -1; 1 0]", "0 -1\n1 0", "0, -1\n1, 0",
    "array([[ 0, -1],\n       [ 1,  0]])", "np.array([[0, -1], [1, 0]])", "{{0,-1},{1,0}}", "[[0, −1], [1, 0]]",
    "  0  -1 \n\n  1   0  \n", "[[0, -1],\n [1, 0]]", "0 −1; 1 0",
])
def test_a_pasted_2x2_in_every_form(text):
    assert parse_pasted(text, shape=(2, 2)) == ROT90


def test_a_numpy_repr_with_floats_and_a_dtype():
    grid = parse_pasted("array([[ 0., -1.],\n [ 1.,  0.]])", shape=(2, 2))
    assert parse_entries(grid, (2, 2)) == [[0.0, -1.0], [1.0, 0.0]]
    grid = parse_pasted("array([[1, 0], [0, 1]], dtype=float64)", shape=(2, 2))
    assert grid == [["1", "0"], ["0", "1"]]


@pytest.mark.parametrize("text", ["[1, 2, 3]", "1 2 3", "1; 2; 3", "1\n2\n3", "[[1], [2], [3]]", "(1, 2, 3)",
                                  "array([[1.],\n [2.],\n [3.]])"])
def test_a_column_vector(text):
    grid = parse_pasted(text, shape=(3, 1))
    assert [[float(e)] for row in grid for e in row] == [[1.0], [2.0], [3.0]]
    assert len(grid) == 3 and all(len(row) == 1 for row in grid)


def test_a_flat_list_fills_a_matrix_row_by_row():
    assert parse_pasted("[0, -1, 1, 0]", shape=(2, 2)) == ROT90


@pytest.mark.parametrize("text,entries", [
    ("[[sqrt(2)/2, -sqrt(2)/2], [sqrt(2)/2, sqrt(2)/2]]", [["sqrt(2)/2", "-sqrt(2)/2"], ["sqrt(2)/2", "sqrt(2)/2"]]),
    ("cos(30°) -sin(30°); sin(30°) cos(30°)", [["cos(30°)", "-sin(30°)"], ["sin(30°)", "cos(30°)"]]),
    ("[atan2(1, 2), 1 - 2]", [["atan2(1, 2)", "1 - 2"]]),
    ("1 - 2  3", [["1 - 2", "3"]]),
    ("sqrt(2) / 2  0", [["sqrt(2) / 2", "0"]]),
    ("2 *3 4", [["2 *3", "4"]]),
    ("[1, 2, ]", [["1", "2"]]),
])
def test_entries_that_are_expressions_stay_whole(text, entries):
    assert parse_pasted(text) == entries


@pytest.mark.parametrize("text,shape,fragment", [
    ("", (2, 2), "Paste or type the matrix"), ("1 2; 3 4", (3, 1), "3×1 column vector"),
    ("1 2 3", (2, 2), "2×2 matrix (2 rows of 2)"), ("1 2; 3", (2, 2), "Row 2 has 1 entries"),
    ("[[1, 2], [3, 4]", (2, 2), "brackets do not match"), ("[1, 2] 3", (1, 3), "outside its brackets"),
    ("1 2 3; 4 5 6", (2, 2), "what you pasted is 2×3"),
])
def test_shape_mismatches_say_what_is_needed(text, shape, fragment):
    with pytest.raises(InvalidAnswer) as err:
        parse_pasted(text, shape=shape)
    assert fragment in str(err.value)


def test_parse_entries_reads_expressions_and_units():
    grid = parse_pasted("cos(60°) -sin(60°); sin(60°) cos(60°)", shape=(2, 2))
    got = parse_entries(grid, (2, 2))
    c, s = 0.5, math.sqrt(3) / 2
    assert all(math.isclose(a, b, abs_tol=1e-12) for ra, rb in zip(got, [[c, -s], [s, c]]) for a, b in zip(ra, rb))
    metres = matrix(unit="m").build("t.1", key=((0.2,), (1.0,)))
    assert metres.read([["20 cm"], ["1 m"]]) == {"value": [[0.2], [1.0]]}


def test_every_unreadable_entry_is_reported_at_once():
    ans = matrix(unit="m").build("t.1", key=((1.0, 1.0), (1.0, 1.0), (1.0, 1.0)))
    verdict = ans.check([["1", ""], ["", "2 s"], ["x", "2,5"]])
    assert verdict.status == "invalid"
    assert verdict.data["invalid"] == [[1, 2], [2, 1], [2, 2], [3, 1], [3, 2]]
    assert "Entries (1,2), (2,1) are empty." in verdict.message
    assert "Entry (2,2): This answer is a length in metres; 2 s is a time." in verdict.message
    assert "Entry (3,1): Unknown name “x”" in verdict.message
    assert "Entry (3,2): Use a dot for decimals" in verdict.message


def test_one_empty_entry():
    verdict = matrix().build("t.1", key=((1.0, 0.0), (0.0, 1.0))).check([["1", "0"], [" ", "1"]])
    assert verdict.message == "Entry (2,1) is empty." and verdict.data["invalid"] == [[2, 1]]


def test_a_grid_of_the_wrong_shape_is_refused():
    with pytest.raises(InvalidAnswer, match="2×2"):
        parse_entries([["1", "2"]], (2, 2))


def rot(theta):
    c, s = math.cos(theta), math.sin(theta)
    return [[c, -s], [s, c]]


def tags(got, key, **kw):
    return [t for t, _ in whole_matrix_slips(got, key, **kw)]


def test_slips_of_a_rotation():
    th = math.radians(30)
    key = rot(th)
    assert tags(rot(-th), key, rotation_angle=th) == ["transpose", "inverse", "sine-sign"]
    assert tags(rot(-th), key) == ["transpose", "inverse"]
    assert tags([[-v for v in row] for row in key], key) == ["negated"]
    assert tags([key[1], key[0]], key) == ["rows-swapped"]
    assert tags([[row[1], row[0]] for row in key], key) == ["columns-swapped"]
    assert tags(rot(30.0), key, rotation_angle=th) == ["degrees"]
    assert tags(key, key, rotation_angle=th) == []
    assert tags([[0.1, 0.2], [0.3, 0.4]], key, rotation_angle=th) == []


def test_a_slip_equal_to_the_key_is_never_reported():
    # R(180°): its transpose, inverse and R(−180°) are all R(180°) itself.
    key = rot(math.pi)
    assert whole_matrix_slips(key, key, rotation_angle=math.pi) == []
    # The identity is its own transpose, inverse and sine-flip.
    eye = [[1.0, 0.0], [0.0, 1.0]]
    assert tags([[-1.0, 0.0], [0.0, -1.0]], eye) == ["negated"]


def test_slips_of_a_non_rotation_and_of_a_3x3():
    key = [[1.0, 2.0], [3.0, 4.0]]
    assert tags([[1.0, 3.0], [2.0, 4.0]], key) == ["transpose"]
    assert tags([[-2.0, 1.0], [1.5, -0.5]], key) == ["inverse"]
    th = math.radians(40)
    c, s = math.cos(th), math.sin(th)
    T = [[c, -s, 2.0], [s, c, 1.0], [0.0, 0.0, 1.0]]
    assert tags([[c, s, 2.0], [-s, c, 1.0], [0.0, 0.0, 1.0]], T, rotation_angle=th) == ["sine-sign"]
    assert tags([T[0], T[2], T[1]], T) == ["rows-swapped"]


def test_wrong_entries_are_named_by_position():
    th = math.radians(30)
    key = rot(th)
    got = [row[:] for row in key]
    got[0][1] = -got[0][1]
    assert wrong_entries(got, key) == [(1, 2)]
    assert wrong_entries([[0.866, -0.5], [0.5, 0.866]], key) == []


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

PASTE_PIECES = st.sampled_from(list("0123456789.+-*/^()[]{},; \n°−") + ["cos(", "sqrt(2)", "array(", "x", "1e999", "dtype=float"])


@settings(max_examples=400, deadline=None)
@given(st.one_of(st.text(max_size=80), st.lists(PASTE_PIECES, max_size=40).map("".join)))
def test_any_paste_gives_a_matrix_or_a_message(text):
    try:
        values = parse_entries(parse_pasted(text, shape=(2, 2)), (2, 2))
    except InvalidAnswer as err:
        assert str(err)
    else:
        assert len(values) == 2 and all(len(row) == 2 and all(math.isfinite(v) for v in row) for row in values)


# ---------------------------------------------------------------- the page's own notations, names, units

from workbook.answer_kinds.matrix import matrix as matrix_kind  # noqa: E402

POSE = ((5.866,), (3.5,), (0.6236,))


def pose(**options):
    return matrix_kind(label="x′", names=("x", "y", "theta|th"), **options).build("t.1", key=POSE)


@pytest.mark.parametrize("text", [
    r"\begin{bmatrix} 5.866 \\ 3.5 \\ 0.6236 \end{bmatrix}",
    r"\mathbf{x}' = \begin{bmatrix} 5.866 \\ 3.5 \\ 0.6236 \end{bmatrix}",
    r"\begin{pmatrix} 5.866 & 3.5 & 0.6236 \end{pmatrix}^\top",
    r"$\left[\begin{array}{c} 5.866 \\ 3.5 \\ 0.6236 \end{array}\right]$",
    "(5.866, 3.5, 0.6236)ᵀ", "[5.866 3.5 0.6236]^T", "[5.866 3.5 0.6236]'", "(5.866, 3.5, 0.6236)",
    "x = 5.866, y = 3.5, θ = 0.6236", "θ = 0.6236; x = 5.866; y = 3.5", "y' = 3.5, theta' = 0.6236, x' = 5.866",
    "x′ = 5.866\ny′ = 3.5\nθ′ = 0.6236", r"\theta = 0.6236, x = 5.866, y = 3.5",
])
def test_a_vector_in_every_notation_a_learner_pastes(text):
    assert pose().check(text).status == "correct", (text, pose().check(text))


@pytest.mark.parametrize("text", [r"\begin{vmatrix} 0 & -1 \\ 1 & 0 \end{vmatrix}", r"\begin{bmatrix}0&-1\\1&0\end{bmatrix}",
                                  "[[0, 1], [-1, 0]]ᵀ", r"\begin{bmatrix} \cos 90^\circ & -\sin 90^\circ \\ \sin 90^\circ & \cos 90^\circ \end{bmatrix}"])
def test_a_latex_matrix_and_its_entries(text):
    ans = matrix_kind(label="R").build("t.1", key=((0.0, -1.0), (1.0, 0.0)))
    assert ans.check(text).status == "correct", text


def test_a_transposed_matrix_is_transposed():
    ans = matrix_kind(label="M").build("t.1", key=((1.0, 2.0), (3.0, 4.0)))
    assert ans.check("[[1, 3], [2, 4]]ᵀ").status == "correct"
    assert ans.check("[[1, 2], [3, 4]]ᵀ").tag == "transpose"


def test_names_are_read_by_name_never_by_position():
    right = pose().check("y = 3.5, x = 5.866, θ = 0.6236")
    swapped_values = pose().check("x = 3.5, y = 5.866, θ = 0.6236")
    assert right.status == "correct"
    assert swapped_values.status == "incorrect" and swapped_values.data["wrong"] == [[1, 1], [2, 1]]


@pytest.mark.parametrize("text,fragment", [
    ("x = 5.866, z = 3.5, θ = 0.6236", "no entry named “z”"),
    ("x = 5.866, x = 3.5, θ = 0.6236", "given twice"),
    ("x = 5.866, θ = 0.6236", "y is missing"),
    ("x = 5.866, 3.5, θ = 0.6236", "every entry its name, or none"),
])
def test_names_that_do_not_fit_are_refused_with_a_message(text, fragment):
    verdict = pose().check(text)
    assert verdict.status == "invalid" and fragment in verdict.message, verdict


def test_names_where_the_answer_has_none_are_refused():
    ans = matrix_kind(label="v").build("t.1", key=((1.0,), (2.0,)))
    verdict = ans.check("a = 1, b = 2")
    assert verdict.status == "invalid" and "no names" in verdict.message


def test_names_typed_in_the_boxes_are_placed_by_name():
    assert pose().check([["y = 3.5"], ["x = 5.866"], ["θ = 0.6236"]]).status == "correct"
    partly = pose().check([["y = 3.5"], [""], [""]])
    assert partly.status == "invalid" and partly.data["invalid"] == [[1, 1], [3, 1]]


@settings(max_examples=200, deadline=None)
@given(st.permutations([0, 1, 2]), st.lists(st.sampled_from([5.866, 3.5, 0.6236, 1.0, -2.0]), min_size=3, max_size=3))
def test_any_order_of_named_components_gives_the_verdict_of_reading_order(order, values):
    names = ("x", "y", "θ")
    in_order = pose().check(", ".join(f"{n} = {v}" for n, v in zip(names, values)))
    shuffled = pose().check(", ".join(f"{names[k]} = {values[k]}" for k in order))
    assert (shuffled.status, shuffled.tag, shuffled.message, shuffled.data) == \
        (in_order.status, in_order.tag, in_order.message, in_order.data)


def test_one_value_pasted_into_one_box_stays_in_that_box():
    ans = matrix_kind(label="R").build("t.1", key=((0.0, -1.0), (1.0, 0.0)))
    assert ans.split("cos(30°) - sin(30°)") == {"cell": "cos(30°) - sin(30°)"}
    assert ans.split(r"\frac{\sqrt{3}}{2}") == {"cell": r"\frac{\sqrt{3}}{2}"}
    assert ans.split("0 -1; 1 0") == {"entries": [["0", "-1"], ["1", "0"]]}


@pytest.mark.parametrize("function", ["sin", "cos", "tan", "sqrt", "√", "exp", "ln", "abs", "\\cos", "arctan"])
@pytest.mark.parametrize("argument", ["30°", "120°", "θ", "0.5", "pi", "2", "30 deg", "\\pi"])
@pytest.mark.parametrize("sign", ["", "-", "2 * ", "0.5*"])
def test_a_function_of_a_spaced_argument_stays_one_entry(function, argument, sign):
    """1.6: cos 30° or -sin 120° pasted into one box was split into "1×2 (2 entries)"."""
    ans = matrix_kind(label="R").build("t.1", key=((0.0, -1.0), (1.0, 0.0)))
    text = f"{sign}{function} {argument}"
    assert ans.split(text) == {"cell": text}, text


def test_a_row_of_functions_still_splits_into_its_entries():
    ans = matrix_kind(label="R").build("t.1", key=((0.0, -1.0), (1.0, 0.0)))
    assert ans.split("cos 30° -sin 30°; sin 30° cos 30°") == {
        "entries": [["cos 30°", "-sin 30°"], ["sin 30°", "cos 30°"]]}


def test_entries_with_units_are_converted_and_a_wrong_unit_is_named():
    ans = matrix_kind(label="x′", units=("m", "m", "rad")).build("t.1", key=POSE)
    assert ans.check([["586.6 cm"], ["3.5 m"], ["35.73°"]]).status == "correct"
    wrong = ans.check([["5.866 s"], ["3.5"], ["0.6236"]])
    assert wrong.status == "invalid" and "Entry (1,1): This answer is a length in metres; 5.866 s is a time." in wrong.message


def test_close_entries_are_told_apart_from_wrong_ones():
    key = tuple(tuple(v / 7 for v in row) for row in ((1, 2, 3), (4, 5, 6), (7, 8, 9)))
    ans = matrix_kind(label="M").build("t.1", key=key)
    assert ans.check([[f"{v:.3g}" for v in row] for row in key]).status == "correct"
    rough = [[f"{v:.2g}" for v in row] for row in key]
    verdict = ans.check(rough)
    assert verdict.status == "incorrect" and "close" in verdict.message and verdict.data["close"]
    assert "3 significant figures" in verdict.message
    rough[0][0] = "9"
    mixed = ans.check(rough)
    assert "1 more is wrong" in mixed.message or "more are wrong" in mixed.message


def test_degrees_typed_in_an_entry_are_named():
    th = math.radians(30)
    ans = matrix_kind(label="R(30°)", rotation_angle=th).build("t.1", key=tuple(map(tuple, rot(th))))
    verdict = ans.check([["cos(30)", "-sin(30°)"], ["sin(30°)", "cos(30°)"]])
    assert (verdict.status, verdict.tag) == ("incorrect", "degrees") and "entry (1,1)" in verdict.message


@settings(max_examples=150, deadline=None)
@given(st.lists(st.lists(st.floats(min_value=-1e3, max_value=1e3, allow_nan=False), min_size=2, max_size=2),
                min_size=2, max_size=2))
def test_any_printed_matrix_reads_back(rows):
    ans = matrix_kind(label="M").build("t.1", key=tuple(map(tuple, rows)))
    assert ans.check(ans.worked_text()).status == "correct"
    assert ans.check(ans.worked_tex()).status == "correct"
    assert ans.check(ans.typed(ans.key)).status == "correct"


def test_swapped_components_of_a_named_vector_are_named():
    verdict = pose().check("x = 3.5, y = 5.866, θ = 0.6236")
    assert verdict.tag == "rows-swapped" and verdict.message == "The values of x and y are swapped."


@pytest.mark.parametrize("typed", ["[[0, -1], [1, 0]]", "0 -1; 1 0", "{{0,-1},{1,0}}", "[0 -1; 1 0]",
                                   r"\begin{bmatrix} 0 & -1 \\ 1 & 0 \end{bmatrix}", "array([[0, -1], [1, 0]])"])
@pytest.mark.parametrize("box", [(0, 0), (0, 1), (1, 0), (1, 1)])
def test_a_whole_matrix_typed_into_one_box_is_read_as_if_pasted(typed, box):
    """Issue 28: the page sends the grid with the whole matrix in one box and the others empty."""
    ans = matrix_kind(label="R").build("t.1", key=((0.0, -1.0), (1.0, 0.0)))
    grid = [["", ""], ["", ""]]
    grid[box[0]][box[1]] = typed
    assert ans.check(grid).status == "correct", typed
    one = [["cos 30°", ""], ["", ""]]  # one value in one box stays that box's value
    assert ans.check(one).data["invalid"] == [[1, 2], [2, 1], [2, 2]]
