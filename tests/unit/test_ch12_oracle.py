"""Chapter 12's reference (reference/particles.py), every Derive key and step, and its Build against
independent code, used only here as oracles (none ships in the site): ``filterpy``'s
``monte_carlo.systematic_resample`` for the resampler, NumPy's FFT for the grid's circular convolution,
``scipy.stats.norm`` for the Gaussian range likelihood, each over at least 300 random draws.

filterpy draws its own offset with ``numpy.random.random`` (imported into its module as ``random``):
the tests replace that name with a function returning the draw under test, so both resamplers use
the same offset. filterpy's pointers are (u + k)/N; a pointer exactly on a cumulative weight goes to
the next particle there too (``positions[i] < cumulative_sum[j]``).

``python tests/unit/test_ch12_oracle.py`` prints the draws and the largest differences, for a
closing note.
"""

from __future__ import annotations

import math
import random

import pytest

from oracle_draws import DRAWS, distinct_variants
from workbook import bank
from workbook.bank.ch12_bayes import _drawn_belief, _kernel, _likelihood
from workbook.bank.ch12_code import _SOLUTION
from workbook.bank.ch12_particles import _errors, _resample_parts, _w_of
from workbook.reference.particles import n_eff, particle_step, predict, range_weights, systematic_resample

np = pytest.importorskip("numpy")
stats = pytest.importorskip("scipy.stats")
resampling = pytest.importorskip("filterpy.monte_carlo.resampling")

TOL = 1e-9


def filterpy_resample(weights, u: float) -> list[int]:
    """filterpy's systematic_resample with its random offset set to ``u``."""
    saved = resampling.random
    resampling.random = lambda: u
    try:
        return [int(i) for i in resampling.systematic_resample(np.asarray(weights, float))]
    finally:
        resampling.random = saved


def _weights(rng: random.Random) -> tuple[list[float], float]:
    """Normalised weights of 1 to 12 particles (a third of them equal, with a draw of 0: every pointer a tie;
    some with a weight of 0; some with one dominant), and a draw in [0, 1)."""
    n = rng.randint(1, 12)
    kind = rng.randrange(4)
    if kind == 0:
        return [1.0 / n] * n, rng.choice((0.0, 0.5, rng.random()))
    raw = [rng.random() for _ in range(n)]
    if kind == 1:
        raw[rng.randrange(n)] = 0.0
    if kind == 2:
        raw[rng.randrange(n)] += 50.0
    if sum(raw) == 0:
        raw[0] = 1.0
    total = sum(raw)
    return [w / total for w in raw], rng.choice((0.0, 0.999999, rng.random()))


def resample_mismatches(seed: int = 12) -> tuple[int, int]:
    """systematic_resample against filterpy: how many draws disagree, out of how many compared."""
    rng = random.Random(seed)
    wrong = compared = 0
    for _ in range(DRAWS * 2):
        w, u = _weights(rng)
        try:
            theirs = filterpy_resample(w, u)
        except IndexError:  # filterpy runs off the end when rounding leaves the last sum below a pointer
            continue
        compared += 1
        wrong += systematic_resample(w, u) != theirs
    return wrong, compared


def _fft_predict(belief, kernel) -> np.ndarray:
    """The circular convolution of the belief with the kernel, by NumPy's FFT."""
    k = np.zeros(len(belief))
    for shift, p in kernel.items():
        k[shift % len(belief)] += p
    return np.real(np.fft.ifft(np.fft.fft(np.asarray(belief, float)) * np.fft.fft(k)))


def grid_gaps(seed: int = 5) -> float:
    """predict() against the FFT's circular convolution, and update() against NumPy, on random grids."""
    rng = random.Random(seed)
    gap = 0.0
    for _ in range(DRAWS):
        n = rng.randint(3, 20)
        bel = np.asarray([rng.random() for _ in range(n)])
        bel = bel / bel.sum()
        kernel = {k: rng.random() for k in rng.sample(range(-3, 4), rng.randint(1, 4))}
        gap = max(gap, float(np.max(np.abs(np.asarray(predict(list(bel), kernel)) - _fft_predict(bel, kernel)))))
    return gap


def _scipy_weights(points, z, landmarks, sigma) -> np.ndarray:
    """The product over landmarks of SciPy's normal densities, normalised."""
    P, L = np.asarray(points, float), np.asarray(landmarks, float)
    r = np.linalg.norm(P[:, None, :] - L[None, :, :], axis=2)
    like = np.prod(stats.norm.pdf(np.asarray(z, float)[None, :], loc=r, scale=sigma), axis=1)
    return like / like.sum()


def weight_gaps(seed: int = 8) -> float:
    """range_weights() and n_eff() against SciPy's densities and NumPy, on random clouds."""
    rng = random.Random(seed)
    gap = 0.0
    for _ in range(DRAWS):
        pts = [(rng.uniform(-3, 3), rng.uniform(-3, 3)) for _ in range(rng.randint(1, 10))]
        marks = [(rng.uniform(-5, 5), rng.uniform(-5, 5)) for _ in range(rng.randint(1, 3))]
        z = [math.dist((0.0, 0.0), m) + rng.gauss(0, 0.2) for m in marks]
        sigma = rng.choice((0.5, 1.0, 2.0))
        mine, theirs = np.asarray(range_weights(pts, z, marks, sigma)), _scipy_weights(pts, z, marks, sigma)
        gap = max(gap, float(np.max(np.abs(mine - theirs))), abs(n_eff(list(mine)) - 1 / np.sum(theirs ** 2)))
    return gap


def _flat(rows) -> np.ndarray:
    return np.asarray([r[0] for r in rows], float)


def _gap(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a, float) - np.asarray(b, float))))


def key_gaps() -> dict[str, tuple[int, float]]:
    """Each Derive key and step of the chapter against the oracles, over its distinct variants: (draws, gap)."""
    out: dict[str, tuple[int, float]] = {}
    gaps = []
    for v in distinct_variants("12.1"):
        bel = np.asarray(_drawn_belief(v.params, "b"), float)
        gaps += [_gap(_flat(v.answer.key), _fft_predict(bel, _kernel(v.params))),
                 _gap(_flat(v.step_answers["one"].key), np.roll(bel, 1)),
                 _gap(_flat(v.step_answers["two"].key), np.roll(bel, 2))]
    out["12.1"] = (len(gaps) // 3, max(gaps))
    gaps = []
    for v in distinct_variants("12.2"):
        prod = np.asarray(_likelihood(v.params)) * np.asarray(_drawn_belief(v.params, "a"))
        gaps += [_gap(_flat(v.answer.key), prod / prod.sum()), _gap(_flat(v.step_answers["prod"].key), prod),
                 abs(v.step_answers["eta"].key - prod.sum())]
    out["12.2"] = (len(gaps) // 3, max(gaps))
    gaps = []
    for v in distinct_variants("12.3"):
        s = v.params["sigma"]
        r, _ = _errors(v.params)
        dens = stats.norm.pdf(v.params["z"], loc=np.asarray(r), scale=s)
        like = dens * s * math.sqrt(2 * math.pi)
        gaps += [_gap(_flat(v.answer.key), dens / dens.sum()), _gap(_flat(v.step_answers["like"].key), like),
                 abs(v.step_answers["total"].key - like.sum())]
    out["12.3"] = (len(gaps) // 3, max(gaps))
    gaps = []
    for v in distinct_variants("12.4"):
        w = np.asarray(_w_of(v.params), float)
        gaps += [abs(v.answer.key - 1 / np.sum(w ** 2)), _gap(_flat(v.step_answers["squares"].key), w ** 2),
                 abs(v.step_answers["sq"].key - np.sum(w ** 2))]
    out["12.4"] = (len(gaps) // 3, max(gaps))
    gaps = []
    for v in distinct_variants("12.5"):
        w, r = _resample_parts(v.params)
        picks = np.asarray(filterpy_resample(w, r * 5)) + 1  # Probabilistic Robotics' r in [0, 1/5) is u / 5
        gaps += [_gap(_flat(v.answer.key), picks), _gap(_flat(v.step_answers["cum"].key), np.cumsum(w)),
                 _gap(_flat(v.step_answers["copies"].key), np.bincount(picks - 1, minlength=5))]
    out["12.5"] = (len(gaps) // 3, max(gaps))
    return out


def _oracle_step(particles, u, z, landmarks, rng_uniform):
    moved = np.asarray(particles, float) + np.asarray(u, float)
    w = _scipy_weights(moved, z, landmarks, 0.5)
    return moved[filterpy_resample(w, rng_uniform)], w


def _solution():
    space: dict = {}
    exec(compile(_SOLUTION, "<particle_step solution>", "exec"), space)  # the page's worked solution
    return space["particle_step"]


def build_gaps() -> tuple[int, float]:
    """12.8's reference and the page's solution on the visible and hidden cases (the review seeds 0-14)
    against NumPy, SciPy and filterpy: how many cases, and the largest difference."""
    ex, solution = bank.get("12.8"), _solution()
    gaps = []
    for seed in range(15):
        for args in ex.variant(seed).arguments():
            want = _oracle_step(*args)
            for got in (particle_step(*args), solution(*args)):
                gaps.append(max(_gap(got[0], want[0]), _gap(got[1], want[1])))
    return len(gaps) // 2, max(gaps)


def debug_mismatches() -> tuple[int, int]:
    """12.9's reference resampler against filterpy on its cases and random likelihoods."""
    ex, rng = bank.get("12.9"), random.Random(9)
    cases = list(ex.cases)
    for _ in range(DRAWS):
        n = rng.randint(1, 9)
        cases.append((tuple(float(i) for i in range(n)), tuple(rng.uniform(0.01, 2) for _ in range(n)), rng.random()))
    wrong = 0
    for particles, like, u in cases:
        w = np.asarray(like, float) / np.sum(like)
        wrong += list(ex.reference(particles, like, u)) != [particles[i] for i in filterpy_resample(w, u)]
    return wrong, len(cases)


def test_systematic_resample_agrees_with_filterpy_ties_and_edges_included():
    wrong, compared = resample_mismatches()
    assert wrong == 0 and compared >= DRAWS, (wrong, compared)


def test_the_grid_filter_agrees_with_the_fft_convolution():
    assert grid_gaps() < TOL


def test_range_weights_and_n_eff_agree_with_scipy():
    assert weight_gaps() < 1e-6


def test_every_derive_key_and_step_of_the_chapter_agrees_with_the_oracles():
    for ex_id, (draws, gap) in key_gaps().items():
        assert draws >= DRAWS, (ex_id, draws)
        assert gap < 1e-9, (ex_id, gap)


def test_the_build_reference_and_solution_agree_with_the_oracles_on_every_case():
    count, gap = build_gaps()
    assert count >= 15 * 20 and gap < 1e-9, (count, gap)


def test_the_bug_hunt_s_reference_agrees_with_filterpy():
    assert debug_mismatches()[0] == 0


if __name__ == "__main__":
    print("systematic_resample vs filterpy: %d of %d draws disagree" % resample_mismatches())
    print(f"predict vs FFT convolution: {DRAWS} grids, largest gap {grid_gaps():.2e}")
    print(f"range_weights and n_eff vs scipy.stats.norm: {DRAWS} clouds, largest gap {weight_gaps():.2e}")
    for ex_id, (draws, gap) in key_gaps().items():
        print(f"{ex_id}: {draws} distinct draws, key and steps, largest gap {gap:.2e}")
    print("12.8 cases (reference and solution): %d, largest gap %.2e" % build_gaps())
    print("12.9 reference vs filterpy: %d of %d disagree" % debug_mismatches())
