"""Parameter identification (raildyn.validation.identification): known parameters recovered from synthetic
records within their intervals, the intervals' coverage over seeded repetitions, chapter 1's logarithmic
decrement beside the fit, and bad input refused."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate, stats

from raildyn.bridge import SimplySupportedBeam
from raildyn.train import davis_resistance
from raildyn.validation.bridge_wim import WeighInMotionFit, weigh_in_motion
from raildyn.validation.identification import (
    CoastDownFit,
    FreeDecayFit,
    bridge_free_vibration,
    coast_down,
    free_decay,
)

# Coverage: of N independent 95 % intervals, the number holding the truth is Binomial(N, 0.95). The
# tests accept the central 99.9 % of that distribution, [179, 198] of 200 (scipy.stats.binom.ppf and
# .isf at 0.0005), so a correct interval fails such a test once in a thousand seeds, and an interval
# with true coverage 90 % or less (expected 180 or fewer) fails it about half the time or more.
REPEATS = 200
LOW, HIGH = stats.binom.ppf(0.0005, REPEATS, 0.95), stats.binom.isf(0.0005, REPEATS, 0.95)


def decay(t, f, xi, amplitude=1.0, phase=0.3, offset=0.0):
    """x(t) = A e^(−ξω_n t) cos(ω_d t + φ) + offset (Garg & Dukkipati 1984, eqs. 1.12-1.14), written out."""
    wn = 2 * np.pi * f
    return amplitude * np.exp(-xi * wn * t) * np.cos(wn * np.sqrt(1 - xi**2) * t + phase) + offset


# -- free decay --------------------------------------------------------------------------------------------


def test_a_noise_free_decay_is_fitted_exactly_and_the_decrement_agrees(reference):
    # No noise: the fit is exact but for the solver's tolerance (1e-8 relative on f and ξ is 1e4 times
    # looser than the default xtol). The decrement reads the sampled maxima, which miss the true ones by
    # up to half a step: at 2000 samples per second and 2.5 Hz the peak values err by (ω dt)²/8 ~ 1e-5
    # relative, so δ and its ξ agree with the truth to 1e-3 relative.
    t = np.arange(0.0, 6.0, 5e-4)
    fit = free_decay(t, decay(t, 2.5, 0.03, offset=0.2))
    assert isinstance(fit, FreeDecayFit)
    assert fit.frequency_hz == pytest.approx(2.5, rel=1e-8)
    assert fit.damping_ratio == pytest.approx(0.03, rel=1e-8)
    assert fit.value("offset") == pytest.approx(0.2, rel=1e-8)
    reference(
        11,
        "free-decay fit: damping ratio ξ",
        "the noise-free damped sinusoid (eqs. 1.12-1.14)",
        "closed form",
        abs(fit.damping_ratio - 0.03) / 0.03,
        1e-8,
    )
    reference(
        11,
        "logarithmic decrement of the maxima: ξ",
        "the damped sinusoid's ξ (eq. 1.17)",
        "closed form",
        abs(fit.decrement_damping_ratio - 0.03) / 0.03,
        1e-3,
    )
    assert fit.log_decrement == pytest.approx(2 * np.pi * 0.03 / np.sqrt(1 - 0.03**2), rel=1e-3)


def noisy_decay(seed, f=2.5, xi=0.03, sigma=0.05):
    t = np.arange(0.0, 6.0, 0.01)
    return t, decay(t, f, xi) + np.random.default_rng(seed).normal(0.0, sigma, t.size)


def test_a_noisy_decay_recovers_frequency_and_damping_within_their_intervals():
    # σ = 5 % of the initial amplitude: the truth lies within the 95 % intervals for this seed.
    t, x = noisy_decay(7)
    fit = free_decay(t, x)
    for name, truth in (("frequency_hz", 2.5), ("damping_ratio", 0.03)):
        lo, hi = fit.bounds(name)
        assert lo <= truth <= hi, (name, lo, hi)
    assert fit.residual_rms == pytest.approx(0.05, rel=0.1)  # the noise σ, to its sampling error (~3 %)
    assert fit.confidence == 0.95


def test_under_noise_the_fit_beats_the_decrement_of_two_maxima():
    # Chapter 1's decrement reads two maxima; the fit uses every sample. Over 20 seeds at σ = 5 % the fit's
    # mean |ξ error| is below a tenth of the decrement's (measured 3e-4 against 1.0e-2: the last maximum
    # clear of the noise is biased upwards by it, so the decrement's ξ comes out low).
    fit_err, dec_err = [], []
    for seed in range(20):
        fit = free_decay(*noisy_decay(seed))
        fit_err.append(abs(fit.damping_ratio - 0.03))
        dec_err.append(abs(fit.decrement_damping_ratio - 0.03))
    assert np.mean(fit_err) < 0.1 * np.mean(dec_err)


def test_free_decay_intervals_cover_the_truth_at_their_stated_rate():
    hits = np.zeros(2, int)
    for seed in range(REPEATS):
        fit = free_decay(*noisy_decay(seed))
        hits += [fit.bounds("frequency_hz")[0] <= 2.5 <= fit.bounds("frequency_hz")[1],
                 fit.bounds("damping_ratio")[0] <= 0.03 <= fit.bounds("damping_ratio")[1]]  # fmt: skip
    assert np.all((hits >= LOW) & (hits <= HIGH)), hits


def test_a_lower_confidence_gives_a_narrower_interval_by_the_t_ratio():
    # Same fit, 90 % against 95 %: the half-widths scale as t(0.95, n−p)/t(0.975, n−p) exactly.
    t, x = noisy_decay(3)
    wide, narrow = free_decay(t, x), free_decay(t, x, confidence=0.9)
    ratio = np.diff(narrow.interval, axis=1) / np.diff(wide.interval, axis=1)
    dof = t.size - 5
    np.testing.assert_allclose(ratio, stats.t.ppf(0.95, dof) / stats.t.ppf(0.975, dof), rtol=1e-9)


def test_the_bridge_frequency_and_damping_from_the_free_vibration_after_the_train():
    # A forced part (a half-sine hump while the train is on) and then the free decay of a 6 Hz, ζ = 1.5 %
    # mode, with noise: only the samples after `leaves` are fitted, and the truth lies in the intervals.
    t = np.arange(0.0, 8.0, 1.0 / 200)
    leaves = 2.0
    free = decay(t - leaves, 6.0, 0.015, amplitude=0.3, phase=-np.pi / 2)
    x = np.where(t < leaves, np.sin(np.pi * t / leaves), free)
    x = x + np.random.default_rng(11).normal(0.0, 0.01, t.size)
    fit = bridge_free_vibration(t, x, leaves)
    assert fit.time[0] >= leaves
    for name, truth in (("frequency_hz", 6.0), ("damping_ratio", 0.015)):
        lo, hi = fit.bounds(name)
        assert lo <= truth <= hi, (name, lo, hi)
    # fitted over the whole record instead, the forced hump would spoil the fit (a check that the
    # window matters): its residual is many times the noise
    assert free_decay(t, x).residual_rms > 5 * fit.residual_rms


# -- bridge weigh-in-motion --------------------------------------------------------------------------------


def moment_by_reactions(span, x, a):
    """Moment at x under a unit force at a on a simple span, from the left reaction: R_A x − (x − a)₊."""
    on = (a >= 0.0) & (a <= span)
    r_a = (span - a) / span
    return np.where(on, r_a * x - np.maximum(x - a, 0.0), 0.0)


BEAM = SimplySupportedBeam(12.0, 2.0e9, 5.0e3)
C = 0.3  # m, neutral axis to gauge
POSITIONS = np.array([5.0, 7.0])
SPACINGS = np.array([2.6, 11.0, 2.6])
LOADS = np.array([1.2e5, 1.1e5, 1.5e5, 1.4e5])


def strain_record(seed, speed=22.0, arrival=0.3, sigma_fraction=0.02):
    t = np.arange(0.0, 1.8, 1.0 / 256)
    d = np.concatenate([[0.0], np.cumsum(SPACINGS)])
    a = speed * (t[None, :, None] - arrival) - d[None, None, :]
    eps = C / BEAM.flexural_rigidity * (moment_by_reactions(12.0, POSITIONS[:, None, None], a) @ LOADS)
    sigma = sigma_fraction * eps.max()
    return t, eps + np.random.default_rng(seed).normal(0.0, sigma, eps.shape)


def test_weigh_in_motion_recovers_speed_spacings_and_loads_within_their_intervals():
    # Noise 2 % of the peak strain: every parameter's 95 % interval holds the truth for this seed, and
    # the loads come out within 3 % (their standard errors are about 0.5 %).
    t, eps = strain_record(5)
    fit = weigh_in_motion(BEAM, t, eps, POSITIONS, SPACINGS * 1.05, fibre_distance=C)
    assert isinstance(fit, WeighInMotionFit)
    truth = {"speed": 22.0, "arrival": 0.3}
    truth |= {f"spacing_{i + 1}": s for i, s in enumerate(SPACINGS)}
    truth |= {f"load_{i + 1}": p for i, p in enumerate(LOADS)}
    for name, value in truth.items():
        lo, hi = fit.bounds(name)
        assert lo <= value <= hi, (name, lo, value, hi)
    np.testing.assert_allclose(fit.loads, LOADS, rtol=0.03)


def test_weigh_in_motion_finds_the_speed_without_a_start():
    # speed=None: the start comes from the cross-correlation of the equal-load template over a grid of
    # speeds 3.2 % apart; the fit then lands on the truth (within 1 %, some 10 standard errors).
    t, eps = strain_record(6, speed=31.0)
    fit = weigh_in_motion(BEAM, t, eps, POSITIONS, SPACINGS, fibre_distance=C, fit_spacings=False)
    assert fit.speed == pytest.approx(31.0, rel=0.01)
    np.testing.assert_array_equal(fit.spacings, SPACINGS)


@pytest.mark.slow
def test_weigh_in_motion_intervals_cover_the_truth_at_their_stated_rate():
    hits = np.zeros(3, int)
    for seed in range(REPEATS):
        t, eps = strain_record(1000 + seed)
        fit = weigh_in_motion(BEAM, t, eps, POSITIONS, SPACINGS, fibre_distance=C, speed=22.0)
        for k, (name, value) in enumerate((("speed", 22.0), ("spacing_2", 11.0), ("load_3", 1.5e5))):
            lo, hi = fit.bounds(name)
            hits[k] += lo <= value <= hi
    assert np.all((hits >= LOW) & (hits <= HIGH)), hits


# -- coast-down --------------------------------------------------------------------------------------------

MASS, AXLES, AREA = 1.3e5, 4, 10.0  # a four-axle locomotive, kg, -, m²


def davis_abc():
    """A, B, C of the train module's Davis law for the locomotive: the quadratic through v = 0, 1, 2 m/s."""
    r0, r1, r2 = (davis_resistance(v, MASS, AXLES, AREA, kind="locomotive") for v in (0.0, 1.0, 2.0))
    c = 0.5 * (r2 - 2 * r1 + r0)
    return np.array([r0, r1 - r0 - c, c])


def coast_record(seed, sigma=0.05):
    # m dv/dt = −R(v) integrated by scipy's RK45 at rtol 1e-10 with the train module's resistance law,
    # sampled each second for 300 s from 40 m/s, plus speedometer noise σ = 0.05 m/s.
    t = np.arange(0.0, 300.0, 1.0)
    sol = integrate.solve_ivp(
        lambda _, v: [-davis_resistance(v[0], MASS, AXLES, AREA, kind="locomotive") / MASS],
        (0.0, t[-1]),
        [40.0],
        t_eval=t,
        rtol=1e-10,
        atol=1e-10,
    )
    return t, sol.y[0] + np.random.default_rng(seed).normal(0.0, sigma, t.size)


def test_a_noise_free_coast_down_gives_the_davis_coefficients(reference):
    # Without noise the closed-form solution the fit uses meets scipy's integration of the train module's
    # law: A, B, C to 1e-4 relative (the integration's rtol 1e-10 over 300 steps, amplified by the
    # near-collinearity of 1, v, v² over 16-40 m/s).
    t, v = coast_record(0, sigma=0.0)
    fit = coast_down(t, v, MASS)
    assert isinstance(fit, CoastDownFit)
    error = np.max(np.abs(fit.estimate[:3] - davis_abc()) / davis_abc())
    reference(11, "coast-down fit: Davis A, B, C", "scipy RK45 of the Davis law", "scipy", error, 1e-4)
    np.testing.assert_allclose(fit.resistance([10.0, 30.0]), davis_resistance(
        np.array([10.0, 30.0]), MASS, AXLES, AREA, kind="locomotive"), rtol=1e-5)  # fmt: skip


def test_a_noisy_coast_down_recovers_a_b_c_within_their_intervals():
    t, v = coast_record(21)
    fit = coast_down(t, v, MASS)
    for name, truth in zip(("A", "B", "C", "initial_speed"), [*davis_abc(), 40.0], strict=True):
        lo, hi = fit.bounds(name)
        assert lo <= truth <= hi, (name, lo, truth, hi)


def test_coast_down_intervals_cover_the_truth_at_their_stated_rate():
    truth = davis_abc()
    t, clean = coast_record(0, sigma=0.0)
    rng = np.random.default_rng(2024)
    hits = np.zeros(3, int)
    for _ in range(REPEATS):
        fit = coast_down(t, clean + rng.normal(0.0, 0.05, t.size), MASS)
        hits += (fit.interval[:3, 0] <= truth) & (truth <= fit.interval[:3, 1])
    assert np.all((hits >= LOW) & (hits <= HIGH)), hits


# -- bad input ---------------------------------------------------------------------------------------------

T = np.arange(0.0, 2.0, 0.01)
X = decay(T, 2.0, 0.05)
V = 30.0 - 0.01 * T


@pytest.mark.parametrize(
    "call, word",
    [
        (lambda: free_decay(T, X[:-1]), "response"),  # unequal lengths
        (lambda: free_decay(np.r_[T[:50], T[51:]], np.r_[X[:50], X[51:]]), "time"),  # a missing sample
        (lambda: free_decay([], []), "time"),  # empty
        (lambda: free_decay(T, np.where(T == T[9], np.nan, X)), "response"),  # NaN
        (lambda: bridge_free_vibration(T, X[:-1], 1.0), "response"),
        (lambda: bridge_free_vibration(T, X, 5.0), "leaves"),
        (lambda: coast_down(T, V[:-1], 1e5), "speed"),
        (lambda: coast_down(T[::-1], V, 1e5), "time"),
        (lambda: coast_down(T, np.where(T == T[3], np.nan, V), 1e5), "speed"),
        (lambda: coast_down(T, V, -1.0), "mass"),
        (lambda: weigh_in_motion(BEAM, T, np.ones((2, T.size - 1)), POSITIONS, SPACINGS), "strain"),
        (lambda: weigh_in_motion(BEAM, T, np.ones((2, T.size)), [5.0, 13.0], SPACINGS), "positions"),
        (lambda: weigh_in_motion(BEAM, T[[0, 1, 3]], np.ones((2, 3)), POSITIONS, SPACINGS), "time"),
        (lambda: weigh_in_motion(BEAM, T, np.full((2, T.size), np.nan), POSITIONS, SPACINGS), "strain"),
        (lambda: free_decay(T, X, confidence=1.0), "confidence"),
    ],
)
def test_bad_records_are_refused_naming_the_parameter(call, word):
    with pytest.raises(ValueError, match=word):
        call()


def test_a_fit_plots_the_record_and_the_model():
    t, x = noisy_decay(1)
    drawn = free_decay(t, x).plot()
    assert len(drawn["measured"]) == len(drawn["fitted"]) == 1
    np.testing.assert_array_equal(drawn["measured"][0].get_xdata(), t)
