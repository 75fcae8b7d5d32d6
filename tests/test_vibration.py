"""Tests of raildyn.vibration (book chapter 1): closed forms, properties, independent computations, bad input.

Every tolerance says where it comes from: rounding (a few ε = 2.2e-16 times the
size of the quantity and of the condition of the operation), an ODE solver's
tolerance, or a stated discretisation-error bound.
"""

import dataclasses
import math

import control
import numpy as np
import pytest
import scipy.linalg
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.integrate import solve_ivp

from raildyn import vibration as vib
from raildyn.vibration import SDOF

EPS = np.finfo(float).eps
PROPERTY = settings(max_examples=50, deadline=None)

# One oscillator per regime (m = 3 kg, ω_n = 2π rad/s), reused below.
REGIMES = {
    "undamped": 0.0,
    "underdamped": 0.1,
    "critically damped": 1.0,
    "overdamped": 2.5,
}


def _system(xi, wn=2 * np.pi, m=3.0):
    return SDOF.from_modal(wn, xi, mass=m)


def _fixed_fixed_chain(n, m, k):
    """n equal masses between two walls, n + 1 equal springs."""
    chain = vib.chain_matrices([m] * n, [k] * n)
    M, K = chain.M, chain.K
    K[-1, -1] += k  # the last mass is tied to the far wall as well
    return M, K


def _foh_reference(A, B, z0, t, u):
    """Whole-system state stepping with the input linear between samples (augmented-matrix expm).

    Independent of the modal route: it never splits the system into modes and
    never uses the SDOF closed forms.
    """
    n, m = B.shape
    h = t[1] - t[0]
    aug = np.zeros((n + 2 * m, n + 2 * m))
    aug[:n, :n], aug[:n, n : n + m], aug[n : n + m, n + m :] = A, B, np.eye(m)
    E = scipy.linalg.expm(aug * h)
    phi, g0, g1 = E[:n, :n], E[:n, n : n + m], E[:n, n + m :] / h
    z = np.empty((n, t.size))
    z[:, 0] = z0
    for k in range(t.size - 1):
        z[:, k + 1] = phi @ z[:, k] + (g0 - g1) @ u[:, k] + g1 @ u[:, k + 1]
    return z


# ---------------------------------------------------------------------------
# Tier 1: closed forms


def test_parameters_and_derived_quantities():
    s = SDOF(mass=1000.0, damping=2000.0, stiffness=4.0e5)
    # Hand values: ω_n = √(4e5/1e3) = 20, c_c = 2√(4e8) = 4e4, ξ = 2000/4e4 = 0.05.
    assert s.natural_frequency == pytest.approx(20.0, rel=4 * EPS)
    assert s.critical_damping == pytest.approx(4.0e4, rel=4 * EPS)
    assert s.damping_ratio == pytest.approx(0.05, rel=4 * EPS)
    assert s.damped_frequency == pytest.approx(20.0 * math.sqrt(1 - 0.05**2), rel=8 * EPS)
    assert s.damped_period == pytest.approx(2 * math.pi / s.damped_frequency, rel=4 * EPS)
    assert s.log_decrement == pytest.approx(2 * math.pi * 0.05 / math.sqrt(1 - 0.05**2), rel=8 * EPS)
    # from_modal is the inverse map (a few roundings in √ and products).
    back = SDOF.from_modal(s.natural_frequency, s.damping_ratio, mass=s.mass)
    assert dataclasses.astuple(back) == pytest.approx(dataclasses.astuple(s), rel=8 * EPS)
    assert isinstance(s.mass, float)
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.mass = 2.0


@pytest.mark.parametrize(("name", "xi"), list(REGIMES.items()))
def test_regime_and_no_oscillation_quantities(name, xi):
    s = _system(xi)
    assert s.regime == name
    if xi >= 1.0:
        assert s.damped_frequency == 0.0
        assert s.damped_period == math.inf and s.log_decrement == math.inf


def test_regime_tolerance_at_critical_damping():
    # |ξ − 1| <= 1e-9 is critical; 1e-8 away is not.
    assert _system(1.0 + 5e-10).regime == "critically damped"
    assert _system(1.0 - 5e-10).regime == "critically damped"
    assert _system(1.0 + 1e-8).regime == "overdamped"
    assert _system(1.0 - 1e-8).regime == "underdamped"


@pytest.mark.parametrize("xi", [0.02, 0.1, 0.3, 0.6])
def test_log_decrement_from_a_sampled_free_response(xi):
    s = _system(xi)
    t1 = 0.37  # any time at which x is not zero
    x1, x2 = s.free_response([t1, t1 + s.damped_period], 0.01, 0.2)
    # Eq. (1.17). Both samples come from the closed form, so only rounding separates them (the ratio
    # of two e^(−σt) cos(...) values: a few ε, magnified by at most 1/|cos| at t1).
    assert math.log(x1 / x2) == pytest.approx(2 * math.pi * xi / math.sqrt(1 - xi**2), rel=1e-11)
    assert vib.log_decrement(xi) == pytest.approx(s.log_decrement, rel=4 * EPS)
    # The inverse relation, δ → ξ, to rounding.
    assert vib.damping_ratio_from_decrement(s.log_decrement) == pytest.approx(xi, rel=8 * EPS)


def test_decay_peaks_are_maxima_one_period_apart():
    s = _system(0.1)
    peaks = s.decay_peaks(0.01, 0.3, count=3)
    times, values = peaks.times, peaks.values
    assert np.diff(times) == pytest.approx([s.damped_period] * 2, rel=1e-12)
    # At a maximum the velocity vanishes (to rounding of x' ~ ω_n x), and x > 0.
    assert np.all(np.abs(s.free_velocity(times, 0.01, 0.3)) < 1e-12 * s.natural_frequency * values.max())
    assert np.all(values > 0)
    assert np.log(values[0] / values[1]) == pytest.approx(s.log_decrement, rel=1e-12)
    # Starting at rest from a positive displacement, the first maximum is t = 0 itself.
    peaks = s.decay_peaks(0.02, 0.0, count=1)
    t0, x0 = peaks.times, peaks.values
    assert t0[0] == pytest.approx(0.0, abs=1e-12) and x0[0] == pytest.approx(0.02, rel=1e-12)
    # x = A e^(−σt) cos θ peaks where cos θ = √(1 − ξ²), just before it touches the envelope A e^(−σt);
    # closed forms on both sides, so rounding only.
    env = s.envelope(times, 0.01, 0.3)
    np.testing.assert_allclose(values, env * math.sqrt(1 - 0.1**2), rtol=1e-12)
    # Without oscillation the "envelope" is |x| itself.
    over = _system(2.0)
    np.testing.assert_array_equal(over.envelope(T, 0.01, -0.5), np.abs(over.free_response(T, 0.01, -0.5)))


@pytest.mark.parametrize("xi", [0.05, 0.2, 0.5, 0.9])
def test_magnification_and_phase_against_hand_values(xi):
    r = np.array([0.0, 0.5, 1.0, 2.0])
    # By hand from 1/√((1 − r²)² + (2ξr)²) and atan2(2ξr, 1 − r²) with the r values substituted:
    magnification = [1.0, 1 / math.sqrt(0.75**2 + xi**2), 1 / (2 * xi), 1 / math.sqrt(9 + 16 * xi**2)]
    phase = [0.0, math.atan(xi / 0.75), math.pi / 2, math.pi - math.atan(4 * xi / 3)]
    # A handful of roundings in squares, hypot and division: 8 ε.
    assert vib.magnification_factor(r, xi) == pytest.approx(magnification, rel=8 * EPS)
    assert vib.phase_angle(r, xi) == pytest.approx(phase, rel=8 * EPS, abs=8 * EPS)


def test_harmonic_curves_broadcast_and_limits():
    r = np.linspace(0.0, 3.0, 7)[:, None]
    xi = np.array([0.0, 0.1, 0.5])
    assert vib.magnification_factor(r, xi).shape == (7, 3)
    # The undamped system at resonance: unbounded amplitude, lag π/2 (the ξ → 0 limit), no NaN.
    assert vib.magnification_factor(1.0, 0.0) == math.inf
    assert vib.transmissibility_ratio(1.0, 0.0) == math.inf
    assert vib.phase_angle(1.0, 0.0) == pytest.approx(math.pi / 2, rel=EPS)
    assert vib.phase_angle([0.5, 2.0], 0.0) == pytest.approx([0.0, math.pi], abs=EPS)
    assert SDOF(1.0, 0.0, 4.0).receptance(2.0) == complex(math.inf, 0.0)
    assert SDOF(1.0, 0.0, 4.0).transmissibility(2.0) == math.inf


def test_transmissibility_is_one_at_root_two_for_every_damping():
    xi = np.array([0.0, 0.01, 0.1, 0.3, 0.7, 1.0, 2.0, 10.0])
    # At r = √2, (1 − r²)² = 1 and the two square roots coincide; √2 squared is 2 + 2ε, hence 4 ε.
    assert vib.transmissibility_ratio(np.sqrt(2.0), xi) == pytest.approx(1.0, abs=4 * EPS)
    for value in xi:
        s = _system(value)
        assert s.transmissibility(np.sqrt(2.0) * s.natural_frequency) == pytest.approx(1.0, abs=16 * EPS)


def test_base_frf_and_receptance_agree_with_the_ratio_forms():
    s = _system(0.2)
    w = np.linspace(0.0, 4 * s.natural_frequency, 41)
    r = w / s.natural_frequency
    xi = s.damping_ratio
    # X/F times k is (1 − r² + 2iξr)⁻¹; X/Y is (1 + 2iξr) times that. Rounding only: 16 ε.
    np.testing.assert_allclose(s.receptance(w) * s.stiffness, 1 / (1 - r**2 + 2j * xi * r), rtol=16 * EPS)
    np.testing.assert_allclose(s.base_frf(w), (1 + 2j * xi * r) / (1 - r**2 + 2j * xi * r), rtol=16 * EPS)
    np.testing.assert_allclose(s.transmissibility(w), vib.transmissibility_ratio(r, xi), rtol=16 * EPS)
    np.testing.assert_allclose(
        np.abs(s.receptance(w)) * s.stiffness, vib.magnification_factor(r, xi), rtol=16 * EPS
    )
    np.testing.assert_allclose(-np.angle(s.receptance(w)), vib.phase_angle(r, xi), rtol=16 * EPS, atol=EPS)


def test_roots_in_each_regime():
    wn = 2 * np.pi
    under, crit, over, none = (_system(x).roots() for x in (0.3, 1.0, 2.5, 0.0))
    # Rounding only in every comparison below: 8 ε relative to ω_n.
    tol = 8 * EPS * wn
    assert np.abs(under) == pytest.approx([wn, wn], abs=tol)  # on the circle of radius ω_n
    assert under[0].imag > 0 and under[1] == np.conj(under[0])
    assert crit == pytest.approx([-wn, -wn], abs=tol)  # the double root −ω_n
    assert np.all(over.imag == 0) and np.all(over.real < 0) and over[0].real > over[1].real
    assert none == pytest.approx([1j * wn, -1j * wn], abs=tol)
    for xi, s in ((0.3, under), (1.0, crit), (2.5, over), (0.0, none)):
        assert s[0] * s[1] == pytest.approx(wn**2, rel=8 * EPS)  # product of the roots of eq. (1.8)
        assert s[0] + s[1] == pytest.approx(-2 * xi * wn, abs=tol)  # and their sum


def test_roots_of_a_heavily_overdamped_system_keep_their_accuracy():
    s = _system(1.0e4, wn=1.0)
    # s₁ = ω_n(−ξ + √(ξ² − 1)) ≈ −1/(2ξ) − 1/(8ξ³): cancellation would leave only ~8 digits.
    expected = -1 / (2e4) - 1 / (8e12)
    assert s.roots()[0].real == pytest.approx(expected, rel=8 * EPS)


def test_root_locus_matches_the_roots_and_the_book_limits():
    xi = np.linspace(0.0, 3.0, 31)
    locus = vib.root_locus(2.0, xi).roots
    assert locus.shape == (31, 2) and locus.dtype == complex
    for row, value in zip(locus, xi, strict=True):
        np.testing.assert_array_equal(row, SDOF.from_modal(2.0, value).roots())
    # Fig. 1.4: ξ = 0 gives ±iω_n; as ξ grows, s₁ → 0 and s₂ → −∞ (s₁ ≈ −ω_n/(2ξ)).
    assert locus[0] == pytest.approx([2j, -2j], abs=4 * EPS)
    far = vib.root_locus(2.0, [1e6]).roots[0]
    assert far[0].real == pytest.approx(-1e-6, rel=1e-9) and far[1].real < -1e6


def test_two_dof_fixed_free_chain():
    m, k = 2.0, 50.0
    chain = vib.chain_matrices([m, m], [k, k])
    M, K = chain.M, chain.K
    np.testing.assert_array_equal(K, [[2 * k, -k], [-k, k]])
    modes = vib.modal_analysis(M, K)
    # ω² = (3 ∓ √5)/2 · k/m; shapes [1, (1 + √5)/2] and [1, (1 − √5)/2] before normalisation.
    expected = np.sqrt((3 - np.array([1, -1]) * np.sqrt(5)) / 2 * k / m)
    assert modes.natural_frequencies == pytest.approx(expected, rel=1e-14)  # eigh: backward stable
    golden = (1 + np.sqrt(5)) / 2
    shapes = np.array([[1.0, golden], [golden, -1.0]]).T  # columns; largest entry made positive
    shapes /= np.sqrt(m * (shapes**2).sum(axis=0))
    np.testing.assert_allclose(modes.mode_shapes, shapes, atol=1e-14)


def test_three_dof_chains_fixed_free_and_fixed_fixed():
    n, m, k = 3, 2.0, 50.0
    j = np.arange(1, n + 1)
    # Fixed-free chain of equal masses: ω_j = 2√(k/m) sin((2j − 1)π / (2(2n + 1))).
    chain = vib.chain_matrices([m] * n, [k] * n)
    M, K = chain.M, chain.K
    expected = 2 * np.sqrt(k / m) * np.sin((2 * j - 1) * np.pi / (2 * (2 * n + 1)))
    assert vib.modal_analysis(M, K).natural_frequencies == pytest.approx(expected, rel=1e-14)
    # Fixed-fixed chain: ω_j = 2√(k/m) sin(jπ/(2(n + 1))), shapes φ_ij ∝ sin(ijπ/(n + 1)).
    M, K = _fixed_fixed_chain(n, m, k)
    modes = vib.modal_analysis(M, K)
    assert modes.natural_frequencies == pytest.approx(
        2 * np.sqrt(k / m) * np.sin(j * np.pi / (2 * (n + 1))), rel=1e-14
    )
    shapes = np.sin(np.outer(j, j) * np.pi / (n + 1)) * np.sqrt(2 / ((n + 1) * m))
    # Sign convention: the largest entry positive, the first of equal ones for mode 2 ([1, 0, −1]).
    shapes[:, 2] *= -1
    np.testing.assert_allclose(modes.mode_shapes, shapes, atol=1e-14)


def test_free_free_chain_has_a_rigid_body_mode():
    chain = vib.chain_matrices([1.0, 2.0, 3.0], [10.0, 20.0], grounded=False)
    M, K = chain.M, chain.K
    modes = vib.modal_analysis(M, K)
    assert modes.natural_frequencies[0] == 0.0  # exactly: rounding-level eigenvalues are zeroed
    assert modes.natural_frequencies[1] > 1.0
    # The rigid mode moves every mass alike, normalised by the total mass 6 kg.
    np.testing.assert_allclose(modes.mode_shapes[:, 0], np.full(3, 1 / np.sqrt(6.0)), rtol=1e-13)


@pytest.mark.parametrize("xi", list(REGIMES.values()), ids=list(REGIMES))
def test_free_response_against_solve_ivp(xi):
    s = _system(xi)
    x0, v0 = 0.02, -0.3
    t = np.linspace(0.0, 3.0, 61)
    m, c, k = s.mass, s.damping, s.stiffness
    sol = solve_ivp(
        lambda _, y: [y[1], -(c * y[1] + k * y[0]) / m],
        (0, t[-1]),
        [x0, v0],
        t_eval=t,
        method="DOP853",
        rtol=1e-10,
        atol=1e-14,
    )
    assert sol.success
    # DOP853 at rtol 1e-10 keeps the global error over these few hundred steps below ~100 rtol of the
    # amplitude (about 0.05 m here): 100 × 1e-10 × 0.05 = 5e-10 m.
    scale = 0.05
    np.testing.assert_allclose(s.free_response(t, x0, v0), sol.y[0], rtol=0, atol=100 * 1e-10 * scale)
    np.testing.assert_allclose(
        s.free_velocity(t, x0, v0), sol.y[1], rtol=0, atol=100 * 1e-10 * scale * s.natural_frequency
    )


def test_free_response_is_smooth_through_critical_damping():
    wn, x0, v0 = 3.0, 0.02, 0.5
    t = np.linspace(0.0, 5.0, 101)
    critical = (x0 + (v0 + wn * x0) * t) * np.exp(-wn * t)  # eq. (1.13) with its constants
    critical_v = (v0 - (v0 + wn * x0) * wn * t) * np.exp(-wn * t)
    for xi in (1.0 - 1e-9, 1.0, 1.0 + 1e-9):
        s = SDOF.from_modal(wn, xi)
        # x depends smoothly on ξ with |∂x/∂ξ| <= ~1 here, so 1e-9 away from critical it differs by
        # about 1e-9 x-scale; no 1/ω_d blow-up may appear.
        np.testing.assert_allclose(s.free_response(t, x0, v0), critical, rtol=0, atol=1e-9 * 0.1)
        np.testing.assert_allclose(s.free_velocity(t, x0, v0), critical_v, rtol=0, atol=1e-9 * 1.0)
    # And the three regimes meet without a step even at the last representable distances from ξ = 1.
    for xi in (1.0 - EPS, 1.0 + 2 * EPS):
        np.testing.assert_allclose(SDOF.from_modal(wn, xi).free_response(t, x0, v0), critical, atol=1e-14)


def test_free_response_shapes_and_long_times():
    s = _system(2.5)
    assert s.free_response(np.zeros((2, 3)), 1.0, 0.0).shape == (2, 3)
    assert np.ndim(s.free_response(0.5, 1.0, 0.0)) == 0
    # Overdamped at a very long time: e^(s₁ t) underflows to 0 cleanly, no overflow from cosh/sinh.
    assert s.free_response(1e5, 1.0, 0.0) == 0.0


@pytest.mark.parametrize("xi", [0.0, 0.05, 1.0, 2.0])
def test_forced_response_to_a_step_is_exact(xi):
    s = _system(xi)
    t = np.linspace(0.0, 6.0, 3001)
    F0 = 40.0
    x = s.forced_response(t, np.full(t.size, F0))
    # Step from rest: x = F0/k (1 − free response from x = 1, v = 0). A step is piecewise linear, so the
    # first-order hold is exact; what remains is rounding in the FFT convolution (~ε log n times the
    # kernel sum, itself ~ the static deflection/ξ): 1e-12 of F0/k is ample.
    expected = F0 / s.stiffness * (1 - s.free_response(t, 1.0, 0.0))
    np.testing.assert_allclose(x, expected, rtol=0, atol=1e-12 * F0 / s.stiffness)


def test_forced_response_to_a_ramp_against_its_closed_form():
    s = _system(0.15)
    wn, wd, xi, k = s.natural_frequency, s.damped_frequency, s.damping_ratio, s.stiffness
    t = np.linspace(0.0, 5.0, 2001)
    a = 30.0  # N/s
    # Standard ramp response from rest: (a/k)[t − 2ξ/ω_n + e^(−ξω_n t)((2ξ/ω_n) cos ω_d t
    # + ((2ξ² − 1)/ω_d) sin ω_d t)].
    expected = (
        a
        / k
        * (
            t
            - 2 * xi / wn
            + np.exp(-xi * wn * t) * (2 * xi / wn * np.cos(wd * t) + (2 * xi**2 - 1) / wd * np.sin(wd * t))
        )
    )
    # Exact for a linear input up to rounding, taken relative to the largest value (a t_max / k).
    np.testing.assert_allclose(s.forced_response(t, a * t), expected, rtol=0, atol=1e-12 * a * t[-1] / k)


def test_forced_response_to_a_sine_is_steady_state_plus_transient():
    s = _system(0.05, m=1.0)
    wn, wd, k, m = s.natural_frequency, s.damped_frequency, s.stiffness, s.mass
    sigma = s.damping_ratio * wn
    W, F0 = 0.8 * wn, 10.0
    t = np.linspace(0.0, 10.0, 20001)
    h = t[1] - t[0]
    r = W / wn
    X = F0 / k * vib.magnification_factor(r, s.damping_ratio)
    phi = vib.phase_angle(r, s.damping_ratio)
    steady = X * np.sin(W * t - phi)
    # The transient cancels the steady state's initial displacement X sin φ and velocity X W cos φ.
    a, b = X * np.sin(phi), -X * W * np.cos(phi)
    transient = np.exp(-sigma * t) * (a * np.cos(wd * t) + (b + sigma * a) / wd * np.sin(wd * t))
    x = s.forced_response(t, F0 * np.sin(W * t))
    # The only error is the first-order hold's: a sine differs from its chords by at most F0 (Wh)²/8,
    # and a force error e gives a response error at most max|e| ∫|h(t)| dt <= max|e| / (m ω_d σ).
    bound = F0 * (W * h) ** 2 / 8 / (m * wd * sigma)
    np.testing.assert_allclose(x, steady + transient, rtol=0, atol=bound)
    assert bound < 1e-5 * X  # ... and that bound is tight enough for the test to mean something


def test_forced_response_with_initial_conditions_and_a_late_start():
    s = _system(0.3)
    t = 5.0 + np.linspace(0.0, 2.0, 801)
    F0, x0, v0 = 20.0, 0.01, -0.2
    x = s.forced_response(t, np.full(t.size, F0), x0, v0)
    # Constant force: the motion relaxes to F0/k from (x0, v0), counted from t[0]. Rounding only.
    expected = F0 / s.stiffness + s.free_response(t - t[0], x0 - F0 / s.stiffness, v0)
    np.testing.assert_allclose(x, expected, rtol=0, atol=1e-13)
    assert s.forced_response([1.0], [3.0], 0.5) == pytest.approx([0.5])


@pytest.mark.parametrize("xi", [0.0, 0.1, 2.0])
def test_impulse_response_is_the_derivative_of_the_step_response(xi):
    s = _system(xi)
    t = np.linspace(0.0, 2.0, 4001)
    h = t[1] - t[0]
    step = s.forced_response(t, np.ones(t.size))  # unit step of force
    slope = (step[2:] - step[:-2]) / (2 * h)
    # Central differences err by h²/6 max|step'''| = h²/6 max|h''|, and h'' = Σ ±s² e^(st)/(m(s₁ − s₂))
    # is bounded by (|s₁|² + |s₂|²)/(m|s₁ − s₂|).
    s1, s2 = s.roots()
    bound = h**2 / 6 * (abs(s1) ** 2 + abs(s2) ** 2) / (s.mass * abs(s1 - s2))
    np.testing.assert_allclose(s.impulse_response(t[1:-1]), slope, rtol=0, atol=bound)
    # The definition: the free motion after an impulse of 1 N·s, i.e. starting at v = 1/m.
    np.testing.assert_allclose(s.impulse_response(t), s.free_response(t, 0.0, 1 / s.mass), rtol=4 * EPS)


def test_forced_response_handles_a_long_record():
    # 10⁵ samples by FFT, not by a loop over them: how fast is benchmarks/bench_ch01_widgets.py's.
    s = _system(0.02)
    t = np.arange(100_000) * 1e-3
    force = np.sin(3.0 * t)
    x = s.forced_response(t, force)
    assert np.all(np.isfinite(x))
    # After 90 s (11 times 1/(ξω_n)) the transient is below 1e-4 of the steady state, |H(3)| sin(3t + ∠H(3)).
    w = 3.0
    H = 1.0 / (s.stiffness - s.mass * w**2 + 1j * s.damping * w)
    tail = t > 90.0
    np.testing.assert_allclose(
        x[tail], np.abs(H) * np.sin(w * t[tail] + np.angle(H)), rtol=0, atol=1e-4 * np.abs(H)
    )


def test_modal_superposition_against_direct_state_space():
    # A damped 3-DOF chain with classical (modal) damping, started moving and pushed.
    chain = vib.chain_matrices([2.0, 1.0, 1.5], [400.0, 300.0, 200.0])
    M, K = chain.M, chain.K
    modes = vib.modal_analysis(M, K)
    xi = np.array([0.02, 0.05, 0.1])
    phi, w = modes.mode_shapes, modes.natural_frequencies
    C = M @ phi @ np.diag(2 * xi * w) @ phi.T @ M  # the damping matrix with these modal ratios
    assert vib.modal_damping_ratios(M, C, K) == pytest.approx(xi, rel=1e-12)
    t = np.linspace(0.0, 4.0, 801)
    x0, v0 = np.array([0.01, 0.0, -0.02]), np.array([0.0, 0.1, 0.0])
    force = np.vstack([10 * np.sin(7.0 * t), np.zeros_like(t), 5.0 * (t > 1.0)])
    x = vib.modal_superposition(M, K, t, x0=x0, v0=v0, force=force, damping_ratios=xi)
    matrices = vib.state_space_matrices(M, C, K, np.eye(3))
    A, B = matrices.A, matrices.B
    reference = _foh_reference(A, B, np.r_[x0, v0], t, force)[:3]
    # Both are exact for the same piecewise-linear force; they differ by rounding accumulated over 800
    # steps (~800 ε times the response, ~0.05 m): 1e-12 m.
    np.testing.assert_allclose(x, reference, rtol=0, atol=1e-12)
    # Free motion alone, against the matrix exponential at each time.
    free = vib.modal_superposition(M, K, t[:50], x0=x0, v0=v0, damping_ratios=xi)
    direct = np.stack([scipy.linalg.expm(A * ti) @ np.r_[x0, v0] for ti in t[:50]], axis=1)[:3]
    np.testing.assert_allclose(free, direct, rtol=0, atol=1e-14)


def test_modal_superposition_of_a_free_free_chain_with_a_rigid_body_mode():
    chain = vib.chain_matrices([1.0, 2.0], [50.0], grounded=False)
    M, K = chain.M, chain.K
    t = np.linspace(0.0, 3.0, 601)
    force = np.vstack([np.where(t < 1.0, 4.0 * t, 0.0), np.zeros_like(t)])  # a ramp, then released
    x0, v0 = np.array([0.0, 0.01]), np.array([0.1, 0.0])
    x = vib.modal_superposition(M, K, t, x0=x0, v0=v0, force=force)
    matrices = vib.state_space_matrices(M, np.zeros((2, 2)), K, np.eye(2))
    A, B = matrices.A, matrices.B
    # Exact for the piecewise-linear force both ways; the rigid mode drifts, so allow rounding on the
    # growing displacement (~1 m): 1e-12.
    np.testing.assert_allclose(x, _foh_reference(A, B, np.r_[x0, v0], t, force)[:2], rtol=0, atol=1e-12)


def test_rayleigh_damping_hits_its_two_targets():
    coefficients = vib.rayleigh_coefficients(2.0, 20.0, 0.02, 0.05)
    alpha, beta = coefficients.alpha, coefficients.beta
    for w, target in ((2.0, 0.02), (20.0, 0.05)):
        assert alpha / (2 * w) + beta * w / 2 == pytest.approx(target, rel=8 * EPS)
    chain = vib.chain_matrices([1.0, 1.0, 1.0], [100.0, 100.0, 100.0])
    M, K = chain.M, chain.K
    C = vib.rayleigh_damping(M, K, alpha, beta)
    np.testing.assert_allclose(C, alpha * M + beta * K, rtol=EPS)
    w = vib.modal_analysis(M, K).natural_frequencies
    # Φᵀ(αM + βK)Φ = αI + β diag(ω²) exactly in exact arithmetic; eigh's rounding ~1e-14.
    np.testing.assert_allclose(vib.modal_damping_ratios(M, C, K), alpha / (2 * w) + beta * w / 2, rtol=1e-13)


def test_complex_modes_of_proportional_damping_are_the_damped_undamped_modes():
    chain = vib.chain_matrices([1.0, 2.0, 1.0], [100.0, 80.0, 60.0])
    M, K = chain.M, chain.K
    modes = vib.modal_analysis(M, K)
    xi = np.array([0.05, 0.3, 1.5])  # the last mode overdamped: two real eigenvalues
    phi, w = modes.mode_shapes, modes.natural_frequencies
    C = M @ phi @ np.diag(2 * xi * w) @ phi.T @ M
    cm = vib.complex_modes(M, C, K)
    assert cm.eigenvalues.shape == (6,) and cm.mode_shapes.shape == (3, 6)
    expected = np.concatenate([vib.root_locus(wj, [x]).roots[0] for wj, x in zip(w, xi, strict=True)])
    # Order: by |λ| (conjugates have equal moduli, so a stable sort keeps s₁ before s₂); the
    # overdamped mode splits into two real roots that need not sit next to each other.
    expected = expected[np.argsort(np.abs(expected), kind="stable")]
    # eig is backward stable; the eigenvalues are well conditioned here: 1e-12 relative.
    np.testing.assert_allclose(cm.eigenvalues, expected, rtol=1e-12)
    assert cm.eigenvalues[1] == np.conj(cm.eigenvalues[0]) and cm.eigenvalues[0].imag > 0
    np.testing.assert_allclose(cm.natural_frequencies[[0, 1, 3, 4]], np.repeat(w[:2], 2), rtol=1e-12)
    np.testing.assert_allclose(cm.damping_ratios[[0, 1, 3, 4]], np.repeat(xi[:2], 2), rtol=1e-11)
    np.testing.assert_allclose(cm.damping_ratios[[2, 5]], 1.0, rtol=4 * EPS)  # real eigenvalues
    # Each column solves (λ²M + λC + K)φ = 0 and has largest entry 1 + 0j.
    for lam, shape in zip(cm.eigenvalues, cm.mode_shapes.T, strict=True):
        residual = (lam**2 * M + lam * C + K) @ shape
        assert np.abs(residual).max() < 1e-12 * np.abs(K).max()
        assert shape[np.argmax(np.abs(shape))] == 1.0
    # Proportional damping keeps the undamped (real) shapes.
    for j, col in ((0, 0), (1, 3), (2, 2), (2, 5)):
        np.testing.assert_allclose(
            cm.mode_shapes[:, col], phi[:, j] / phi[np.argmax(np.abs(phi[:, j])), j], atol=1e-12
        )


def test_state_space_outputs():
    M = np.diag([2.0, 1.0])
    K = np.array([[300.0, -100.0], [-100.0, 100.0]])
    C = np.array([[3.0, -1.0], [-1.0, 1.0]])
    B = np.array([1.0, 0.0])  # one force on the first mass, given as a vector
    matrices = vib.state_space_matrices(M, C, K, B)
    A, Bs, Cs, D = matrices.A, matrices.B, matrices.C, matrices.D
    assert (A.shape, Bs.shape, Cs.shape, D.shape) == ((4, 4), (4, 1), (2, 4), (2, 1))
    np.testing.assert_allclose(A[2:], -np.linalg.solve(M, np.hstack([K, C])), rtol=EPS)
    w = 3.0
    H = vib.frf_matrix(M, C, K, w)[0] @ B
    # Each output's frequency response, C_s (iωI − A)⁻¹ B_s + D, must be iω or −ω² times the receptance.
    for output, factor in (("displacement", 1.0), ("velocity", 1j * w), ("acceleration", -(w**2))):
        matrices = vib.state_space_matrices(M, C, K, B, output=output)
        A, Bs, Cs, D = matrices.A, matrices.B, matrices.C, matrices.D
        g = Cs @ np.linalg.solve(1j * w * np.eye(4) - A, Bs) + D
        np.testing.assert_allclose(g[:, 0], factor * H, rtol=1e-13)
    matrices = vib.state_space_matrices(M, C, K, B, output="acceleration")
    A, Bs, Cs, D = matrices.A, matrices.B, matrices.C, matrices.D
    np.testing.assert_allclose(D, np.linalg.solve(M, B[:, None]), rtol=EPS)
    matrices = vib.state_space_matrices(M, C, K, B, output="state")
    A, Bs, Cs, D = matrices.A, matrices.B, matrices.C, matrices.D
    np.testing.assert_array_equal(Cs, np.eye(4))
    # The SDOF view is the 1x1 case.
    s = SDOF(2.0, 0.4, 8.0)
    matrices = s.state_space_matrices()
    A, Bs, Cs, D = matrices.A, matrices.B, matrices.C, matrices.D
    np.testing.assert_allclose(A, [[0, 1], [-4.0, -0.2]], rtol=EPS)
    np.testing.assert_allclose(Bs, [[0], [0.5]], rtol=EPS)


def test_frf_matrix_is_batched_symmetric_and_matches_the_sdof_receptance():
    s = _system(0.1)
    w = np.linspace(0.0, 20.0, 11)
    H = vib.frf_matrix([[s.mass]], [[s.damping]], [[s.stiffness]], w)
    assert H.shape == (11, 1, 1)
    np.testing.assert_allclose(H[:, 0, 0], s.receptance(w), rtol=1e-14)
    chain = vib.chain_matrices([1.0, 2.0, 1.0], [100.0, 80.0, 60.0])
    M, K = chain.M, chain.K
    C = vib.rayleigh_damping(M, K, 0.1, 0.001)
    H = vib.frf_matrix(M, C, K, w)
    # Maxwell reciprocity for symmetric M, C, K: H = Hᵀ (to the solver's rounding).
    np.testing.assert_allclose(H, np.swapaxes(H, 1, 2), rtol=1e-12, atol=1e-16)
    assert vib.frf_matrix(M, C, K, 1.0).shape == (1, 3, 3)


# ---------------------------------------------------------------------------
# Tier 2: properties


@st.composite
def _spd_pair(draw):
    """A random symmetric positive definite M and positive semi-definite K, n from 1 to 5."""
    n = draw(st.integers(1, 5))
    entries = st.floats(-1.0, 1.0, allow_nan=False)
    a = draw(arrays(float, (n, n), elements=entries))
    b = draw(arrays(float, (n, n), elements=entries))
    return a @ a.T + 0.5 * np.eye(n), b @ b.T  # λ_min(M) >= 0.5, so cond(M) <= 2 n² + 1


@PROPERTY
@given(_spd_pair())
def test_modes_are_mass_orthonormal(pair):
    M, K = pair
    modes = vib.modal_analysis(M, K)
    phi, w = modes.mode_shapes, modes.natural_frequencies
    assert np.all(np.diff(w) >= 0) and np.all(w >= 0)
    # eigh's rounding, ~n ε cond(M) ‖·‖ with cond(M) <= 51 and ‖K‖ <= 25: 1e-11 absolute.
    np.testing.assert_allclose(phi.T @ M @ phi, np.eye(len(w)), atol=1e-11)
    # Eigenvalues under the rounding floor are set to zero, so compare with that floor as slack.
    np.testing.assert_allclose(phi.T @ K @ phi, np.diag(w**2), atol=1e-10)


@PROPERTY
@given(
    st.floats(0.1, 100.0),  # ω_n, rad/s
    st.floats(0.1, 1000.0),  # m, kg
    st.floats(-1.0, 1.0),  # x0, m
    st.floats(-10.0, 10.0),  # v0, m/s
)
def test_undamped_free_response_conserves_energy(wn, m, x0, v0):
    s = SDOF.from_modal(wn, 0.0, mass=m)
    t = np.linspace(0.0, 50.0 / wn, 101)
    x, v = s.free_response(t, x0, v0), s.free_velocity(t, x0, v0)
    energy = 0.5 * m * v**2 + 0.5 * s.stiffness * x**2
    start = 0.5 * m * v0**2 + 0.5 * s.stiffness * x0**2
    # x and v are a rotation of (x0, v0/ω_n) by cos/sin of the same angle, so only rounding (~10 ε)
    # separates the energies; plus a floor for the all-zero start.
    np.testing.assert_allclose(energy, start, rtol=1e-13, atol=1e-300)


@PROPERTY
@given(st.floats(0.01, 1 / math.sqrt(2) - 0.01))
def test_magnification_peaks_at_its_closed_form(xi):
    peak = 1 / (2 * xi * math.sqrt(1 - xi**2))
    r = np.linspace(0.0, 3.0, 3001)
    # The bound holds everywhere to rounding, and is reached at r = √(1 − 2ξ²).
    assert np.all(vib.magnification_factor(r, xi) <= peak * (1 + 8 * EPS))
    assert vib.magnification_factor(math.sqrt(1 - 2 * xi**2), xi) == pytest.approx(peak, rel=8 * EPS)


@PROPERTY
@given(st.floats(0.001, 5.0))
def test_phase_rises_monotonically_from_zero_to_pi(xi):
    r = np.linspace(0.0, 20.0, 2001)
    phase = vib.phase_angle(r, xi)
    assert phase[0] == 0.0 and np.all(np.diff(phase) > 0) and np.all(phase < math.pi)


@PROPERTY
@given(st.floats(0.0, 3.0), st.floats(-1.0, 1.0), st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))
def test_forced_response_is_linear(xi, x0, v0, a):
    s = _system(xi)
    t = np.linspace(0.0, 2.0, 201)
    f1, f2 = np.sin(5 * t), np.where(t > 0.5, 1.0, 0.0)
    whole = s.forced_response(t, f1 + a * f2, x0, v0)
    parts = s.forced_response(t, f1) + a * s.forced_response(t, f2) + s.free_response(t, x0, v0)
    np.testing.assert_allclose(whole, parts, rtol=0, atol=1e-14)  # rounding of responses ~0.1 m


# ---------------------------------------------------------------------------
# Tier 3: independent computation with python-control


@pytest.mark.parametrize("xi", [0.0, 0.1, 1.0, 2.5])
def test_poles_from_python_control_are_the_roots(xi):
    s = _system(xi)
    poles = np.sort_complex(control.poles(s.to_control()))
    # A double root (ξ = 1) is ill-conditioned: a perturbation ε ω_n² moves it by √ε ω_n ~ 1e-7 ω_n.
    tol = 1e-6 * s.natural_frequency if xi == 1.0 else 1e-12 * s.natural_frequency
    np.testing.assert_allclose(poles, np.sort_complex(s.roots()), rtol=0, atol=tol)


def test_poles_of_a_three_dof_system_from_python_control(reference):
    M = np.diag([1.0, 2.0, 3.0])
    K = 100 * np.array([[3.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.0]])
    C = np.diag([1.0, 0.0, 2.0])  # dampers on two masses only: not proportional
    with pytest.raises(ValueError, match="complex_modes"):
        vib.modal_damping_ratios(M, C, K)
    cm = vib.complex_modes(M, C, K)
    poles = control.poles(vib.to_control(M, C, K, np.eye(3)))
    # Distinct, well separated eigenvalues: agreement to eig's rounding, 1e-12 of their size.
    gap = np.abs(np.sort_complex(poles) - np.sort_complex(cm.eigenvalues)) / np.abs(cm.eigenvalues)
    reference(
        1,
        "complex modes of a non-proportionally damped 3-DOF chain",
        "python-control poles",
        "python-control",
        gap.max(),
        1e-12,
    )
    # and the sort order that complex_modes promises:
    assert np.all(np.diff(np.abs(cm.eigenvalues)[::2]) > 0)
    upper, lower = cm.eigenvalues[::2], cm.eigenvalues[1::2]
    assert np.all(upper.imag > 0) and np.all(lower == np.conj(upper))


def test_frequency_response_from_python_control(reference):
    s = _system(0.2)
    w = np.linspace(0.0, 30.0, 61)
    # Evaluating the state-space realisation is an independent route (a linear solve per frequency).
    np.testing.assert_allclose(s.to_control()(1j * w), s.receptance(w), rtol=1e-12)
    chain = vib.chain_matrices([1.0, 2.0, 1.0], [100.0, 80.0, 60.0])
    M, K = chain.M, chain.K
    C = np.diag([0.5, 0.0, 1.5])
    response = control.frequency_response(vib.to_control(M, C, K, np.eye(3)), w[1:])
    fresp = np.moveaxis(response.frdata, -1, 0)  # (outputs, inputs, ω) → (ω, outputs, inputs)
    ours = vib.frf_matrix(M, C, K, w[1:])
    reference(
        1,
        "FRF matrix of a damped 3-DOF chain",
        "python-control's frequency response",
        "python-control",
        np.abs(fresp - ours).max() / np.abs(ours).max(),
        1e-10,
    )


# ---------------------------------------------------------------------------
# Bad input: ValueError (TypeError for a non-number) naming the parameter

M2 = np.diag([1.0, 2.0])
K2 = np.array([[3.0, -1.0], [-1.0, 1.0]])
T = np.linspace(0.0, 1.0, 11)

BAD = {
    "negative mass": (lambda: SDOF(-1.0, 0.0, 1.0), "mass"),
    "NaN stiffness": (lambda: SDOF(1.0, 0.0, float("nan")), "stiffness"),
    "negative damping": (lambda: SDOF(1.0, -0.1, 1.0), "damping"),
    "zero natural frequency": (lambda: SDOF.from_modal(0.0, 0.1), "natural_frequency"),
    "negative damping ratio": (lambda: SDOF.from_modal(1.0, -0.1), "damping_ratio"),
    "negative time": (lambda: SDOF(1.0, 0.0, 1.0).free_response([-1.0, 0.0], 1.0, 0.0), "t must be >= 0"),
    "infinite x0": (lambda: SDOF(1.0, 0.0, 1.0).free_response(T, math.inf, 0.0), "x0"),
    "negative omega": (lambda: SDOF(1.0, 0.1, 1.0).receptance([1.0, -2.0]), "omega"),
    "non-uniform t": (lambda: SDOF(1.0, 0.1, 1.0).forced_response(np.r_[T, 1.5], np.zeros(12)), "uniformly"),
    "decreasing t": (lambda: SDOF(1.0, 0.1, 1.0).forced_response(T[::-1], np.zeros(11)), "strictly incr"),
    "force length": (lambda: SDOF(1.0, 0.1, 1.0).forced_response(T, np.zeros(10)), "force"),
    "overdamped peaks": (lambda: SDOF.from_modal(1.0, 1.5).decay_peaks(1.0, 0.0), "damping ratio"),
    "zero peak count": (lambda: SDOF.from_modal(1.0, 0.1).decay_peaks(1.0, 0.0, count=0), "count"),
    "negative ratio r": (lambda: vib.magnification_factor(-0.5, 0.1), "frequency_ratio"),
    "negative ξ": (lambda: vib.phase_angle(0.5, -0.1), "damping_ratio"),
    "NaN ξ": (lambda: vib.transmissibility_ratio(0.5, float("nan")), "damping_ratio"),
    "negative ξ decrement": (lambda: vib.log_decrement(-0.1), "damping_ratio"),
    "NaN delta": (lambda: vib.damping_ratio_from_decrement(float("nan")), "delta"),
    "negative ξ locus": (lambda: vib.root_locus(1.0, [0.1, -0.2]), "damping_ratios"),
    "asymmetric M": (lambda: vib.modal_analysis([[1.0, 0.5], [0.0, 1.0]], K2), "M must be symmetric"),
    "indefinite M": (lambda: vib.modal_analysis(np.diag([1.0, -1.0]), K2), "M must be positive definite"),
    "indefinite K": (lambda: vib.modal_analysis(M2, [[1.0, 0.0], [0.0, -1.0]]), "K must be positive semi"),
    "mismatched K": (lambda: vib.modal_analysis(M2, np.eye(3)), "K must be 2x2"),
    "NaN in K": (lambda: vib.modal_analysis(M2, [[1.0, np.nan], [np.nan, 1.0]]), "K must contain only"),
    "spring count": (lambda: vib.chain_matrices([1.0, 1.0], [1.0, 1.0, 1.0]), "stiffnesses must have 2"),
    "free-free spring count": (
        lambda: vib.chain_matrices([1.0, 1.0], [1.0, 1.0], grounded=False),
        "stiffnesses must have 1",
    ),
    "negative chain mass": (lambda: vib.chain_matrices([1.0, -1.0], [1.0, 1.0]), "masses"),
    "equal Rayleigh frequencies": (lambda: vib.rayleigh_coefficients(2.0, 2.0, 0.01, 0.02), "omega2"),
    "negative Rayleigh ξ": (lambda: vib.rayleigh_coefficients(1.0, 2.0, -0.01, 0.02), "xi1"),
    "x0 length": (lambda: vib.modal_superposition(M2, K2, T, x0=[1.0, 2.0, 3.0]), "x0"),
    "v0 length": (lambda: vib.modal_superposition(M2, K2, T, v0=[1.0]), "v0"),
    "modal force shape": (lambda: vib.modal_superposition(M2, K2, T, force=np.zeros((2, 5))), "force"),
    "modal ξ length": (
        lambda: vib.modal_superposition(M2, K2, T, damping_ratios=[0.1, 0.1, 0.1]),
        "damping_ratios",
    ),
    "modal uneven t": (lambda: vib.modal_superposition(M2, K2, T**2, force=np.zeros((2, 11))), "uniform"),
    "C shape": (lambda: vib.complex_modes(M2, np.eye(3), K2), "C must be 2x2"),
    "B rows": (
        lambda: vib.state_space_matrices(M2, np.zeros((2, 2)), K2, np.ones((3, 1))),
        "B must have shape",
    ),
    "output name": (
        lambda: vib.state_space_matrices(M2, np.zeros((2, 2)), K2, np.ones(2), output="force"),
        "output",
    ),
    "frf negative omega": (lambda: vib.frf_matrix(M2, np.zeros((2, 2)), K2, [-1.0]), "omega"),
    "frf at resonance": (lambda: vib.frf_matrix([[1.0]], [[0.0]], [[4.0]], [1.0, 2.0]), "singular at omega"),
    # issue 15: domains stated and refused by name, never an overflow, a MemoryError or a silent inf
    "huge natural frequency": (lambda: SDOF.from_modal(1e300, 0.1), "natural_frequency"),
    "huge damping ratio": (lambda: SDOF.from_modal(10.0, 1e300), "damping_ratio"),
    "rate k/m overflows": (lambda: SDOF(1e-10, 0.0, 1e300), "stiffness and mass"),
    "a million peaks": (lambda: SDOF.from_modal(1.0, 0.1).decay_peaks(1.0, 0.0, count=10**12), "count"),
    "empty times": (lambda: SDOF(1.0, 0.1, 1.0).free_response([], 1.0, 0.0), "t must not be empty"),
    "decrement of ξ >= 1": (lambda: vib.log_decrement([0.5, 1.0]), "damping_ratio must be < 1"),
    "ξ against r": (lambda: vib.magnification_factor([0.5, 1.0, 2.0], [0.1, 0.2]), "damping_ratio"),
    "damped rigid-body mode": (
        lambda: vib.modal_damping_ratios(M2, np.eye(2), np.zeros((2, 2))),
        "rigid-body",
    ),
    "step too long": (lambda: SDOF.from_modal(1e14, 0.1).forced_response(T, np.zeros(11)), "omega_n h"),
    "uniform chain too long": (lambda: vib.uniform_chain_frequencies(10**12, 1.0, 1.0), "count"),
}


@pytest.mark.parametrize("case", list(BAD), ids=list(BAD))
def test_bad_input_is_refused_with_a_message_naming_the_parameter(case):
    call, match = BAD[case]
    with pytest.raises(ValueError, match=match):
        call()


def test_non_numbers_raise_type_error():
    with pytest.raises(TypeError, match="mass"):
        SDOF("heavy", 0.0, 1.0)
    with pytest.raises(TypeError, match="grounded"):
        vib.chain_matrices([1.0], [1.0], grounded="yes")


def test_heavily_overdamped_free_response_stays_finite():
    # issue 15: ξ = 1e200 gave NaN at t = 0; the mass now creeps back at the slow root −ω_n/(2ξ)
    s = SDOF.from_modal(1.0, 1e200)
    assert s.free_response([0.0, 0.5], 0.01, 0.0).tolist() == [0.01, 0.01]
    assert np.isfinite(s.free_velocity([0.0, 0.5], 0.01, 0.0)).all()
    assert s.roots() == pytest.approx([-0.5e-200, -2e200], rel=1e-15)
    # and a huge ω or r gives a receptance or a ratio that tends to zero, not NaN
    assert SDOF.from_modal(10.0, 0.05).receptance([1e300])[0] == 0.0
    assert vib.magnification_factor(1e300, 1e300) == 0.0
    assert np.all(vib.frf_matrix(M2, np.eye(2), K2, [1e300]) == 0.0)


def test_plot_helpers_and_solver_error_refuse_bad_arguments_by_name():
    from raildyn import plots
    from raildyn.errors import SolverError

    with pytest.raises(TypeError, match=r"\bax\b"):
        plots.axes_or_new("abc")
    with pytest.raises(ValueError, match="t must be strictly increasing"):
        plots.time_history(T[::-1], T)
    with pytest.raises(TypeError, match="time"):
        SolverError("diverged", time="abc")
    with pytest.raises(ValueError, match="step"):
        SolverError("diverged", step=-1)


def test_error_message_states_the_value_and_the_allowed_range():
    with pytest.raises(ValueError, match=r"mass must be in \(0\.0, inf\], got -1\.0"):
        SDOF(-1.0, 0.0, 1.0)


# ---------------------------------------------------------------------------
# Results are frozen dataclasses with named fields (units in the name where it could be read two ways)


def test_every_result_is_a_frozen_dataclass():
    chain = vib.chain_matrices([1.0, 2.0], [100.0, 80.0], dampings=[1.0, 0.5])
    s = _system(0.1)
    results = [
        chain,
        vib.modal_analysis(chain.M, chain.K),
        vib.complex_modes(chain.M, chain.C, chain.K),
        vib.rayleigh_coefficients(2.0, 20.0, 0.02, 0.05),
        vib.state_space_matrices(chain.M, chain.C, chain.K, np.eye(2)),
        vib.root_locus(1.0, [0.0, 0.5]),
        s.decay_peaks(0.01, 0.0, count=2),
        s.free_vibration(T, 0.01, 0.0),
    ]
    for result in results:
        assert dataclasses.is_dataclass(result) and not isinstance(result, tuple), type(result)
        field = dataclasses.fields(result)[0].name
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(result, field, None)


def test_natural_frequencies_in_hz_are_those_in_rad_per_s_over_two_pi():
    chain = vib.chain_matrices([1.0, 2.0], [100.0, 80.0], dampings=[1.0, 0.5])
    modes = vib.modal_analysis(chain.M, chain.K)
    # f = ω/(2π): one division, exact to rounding.
    np.testing.assert_allclose(
        modes.natural_frequencies_hz, modes.natural_frequencies / (2 * np.pi), rtol=EPS
    )
    cm = vib.complex_modes(chain.M, chain.C, chain.K)
    np.testing.assert_allclose(cm.natural_frequencies_hz, np.abs(cm.eigenvalues) / (2 * np.pi), rtol=4 * EPS)


def test_modal_matrix_diagonalises_mass_and_stiffness():
    chain = vib.chain_matrices([1.0, 2.0, 1.5], [100.0, 80.0, 60.0])
    modes = vib.modal_analysis(chain.M, chain.K)
    # Φᵀ M Φ = I, Φᵀ K Φ = diag(ω²): eigh's rounding on entries of order 1 and ‖K‖/m ~ 200: 1e-12.
    np.testing.assert_allclose(modes.modal_matrix(chain.M), np.eye(3), atol=1e-13)
    np.testing.assert_allclose(modes.modal_matrix(chain.K), np.diag(modes.natural_frequencies**2), atol=1e-12)
    with pytest.raises(ValueError, match="matrix must be 3x3"):
        modes.modal_matrix(np.eye(2))


def test_relative_phase_is_zero_or_pi_for_real_modes_and_shows_coupling_otherwise():
    chain = vib.chain_matrices([1.0, 1.0], [1.0, 1.0])
    real = vib.complex_modes(chain.M, 0.01 * chain.K, chain.K)  # proportional: real shapes
    # Mode 1 moves both masses together, mode 2 against each other: 0 and π exactly up to eig's rounding.
    np.testing.assert_allclose(np.abs(real.relative_phase(1, 0)[::2]), [0.0, np.pi], atol=1e-10)
    coupled = vib.complex_modes(chain.M, np.diag([0.5, 0.0]), chain.K)  # damper on one mass only
    assert np.all(np.abs(np.sin(coupled.relative_phase(1, 0)[::2])) > 1e-3)
    # Its definition, checked directly: the argument of the ratio of the two entries.
    np.testing.assert_allclose(
        coupled.relative_phase(1, 0), np.angle(coupled.mode_shapes[1] / coupled.mode_shapes[0]), rtol=EPS
    )
    with pytest.raises(ValueError, match="coordinate must be an integer in"):
        coupled.relative_phase(2, 0)


def test_chain_dampers_assemble_like_the_springs():
    masses, springs = [1.0, 2.0, 3.0], [10.0, 20.0, 30.0]
    chain = vib.chain_matrices(masses, springs, dampings=[0.1, 0.2, 0.3])
    # The same assembly rule with the damper values: exactly the stiffness matrix of springs 0.1, 0.2, 0.3.
    np.testing.assert_array_equal(chain.C, vib.chain_matrices(masses, [0.1, 0.2, 0.3]).K)
    # A zero damper is allowed (a zero spring is not): as in notebook 01's bogie and body.
    np.testing.assert_array_equal(
        vib.chain_matrices(masses, springs, dampings=[0.1, 0.0, 0.3]).C,
        [[0.1, 0.0, 0.0], [0.0, 0.3, -0.3], [0.0, -0.3, 0.3]],
    )
    np.testing.assert_array_equal(vib.chain_matrices(masses, springs).C, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="dampings must have 1 entries"):
        vib.chain_matrices(masses[:2], [1.0], dampings=[1.0, 1.0], grounded=False)
    with pytest.raises(ValueError, match="dampings must be >= 0"):
        vib.chain_matrices(masses, springs, dampings=[1.0, -1.0, 0.0])


@pytest.mark.parametrize("n", [1, 2, 3, 7])
def test_uniform_chain_frequencies_match_the_eigen_solution(n):
    m, k = 2.0, 50.0
    chain = vib.chain_matrices([m] * n, [k] * n)
    # Closed form against eigh, which is backward stable: 1e-13 relative.
    np.testing.assert_allclose(
        vib.uniform_chain_frequencies(n, m, k),
        vib.modal_analysis(chain.M, chain.K).natural_frequencies,
        rtol=1e-13,
    )
    with pytest.raises(ValueError, match="count"):
        vib.uniform_chain_frequencies(0, m, k)


def test_rayleigh_coefficients_give_their_damping_ratio_and_matrix():
    c = vib.rayleigh_coefficients(2.0, 20.0, 0.02, 0.05)
    # ξ(ω) = α/(2ω) + βω/2 at the two target frequencies: the targets, to rounding.
    np.testing.assert_allclose(c.damping_ratio([2.0, 20.0]), [0.02, 0.05], rtol=8 * EPS)
    chain = vib.chain_matrices([1.0, 1.0], [100.0, 100.0])
    np.testing.assert_array_equal(
        c.damping_matrix(chain.M, chain.K), vib.rayleigh_damping(chain.M, chain.K, c.alpha, c.beta)
    )
    with pytest.raises(ValueError, match="omega"):
        c.damping_ratio(0.0)


def test_decrement_from_peaks_several_cycles_apart():
    s = _system(0.05)
    peaks = s.decay_peaks(0.01, 0.0, count=6)
    # ln(x₀/x₅)/5 = δ: the peaks come from the closed form, so rounding only.
    assert vib.decrement_from_peaks(peaks.values[0], peaks.values[5], cycles=5) == pytest.approx(
        s.log_decrement, rel=1e-12
    )
    assert peaks.log_decrement == pytest.approx(s.log_decrement, rel=1e-12)
    assert vib.decrement_from_peaks(12.0, 3.0, cycles=5) == pytest.approx(math.log(4.0) / 5, rel=EPS)
    with pytest.raises(ValueError, match="later"):
        vib.decrement_from_peaks(1.0, 0.0)
    with pytest.raises(ValueError, match="cycles"):
        vib.decrement_from_peaks(1.0, 0.5, cycles=0)


def test_free_vibration_holds_response_envelope_and_peaks_and_plots_them():
    import matplotlib.pyplot as plt

    s = _system(0.1)
    t = np.linspace(0.0, 3.0, 601)
    r = s.free_vibration(t, 0.01, 0.2, peaks=3)
    np.testing.assert_array_equal(r.displacement, s.free_response(t, 0.01, 0.2))
    np.testing.assert_array_equal(r.envelope, s.envelope(t, 0.01, 0.2))
    np.testing.assert_array_equal(r.peaks.times, s.decay_peaks(0.01, 0.2, count=3).times)
    fig, ax = plt.subplots()
    art = r.plot(ax)
    assert set(art) == {"line", "upper", "lower", "peaks"}
    np.testing.assert_array_equal(art["peaks"].get_xdata(), r.peaks.times)
    # A second response moves the same artists (a widget's update): no new line on the axes.
    count = len(ax.lines)
    other = _system(2.0).free_vibration(t, 0.01, 0.2)
    assert other.peaks.times.size == 0  # overdamped: no maxima to mark
    assert other.plot(artists=art) is art and len(ax.lines) == count
    np.testing.assert_array_equal(art["line"].get_ydata(), other.displacement)
    np.testing.assert_array_equal(art["lower"].get_ydata(), -other.envelope)


def test_root_locus_plot_draws_both_branches_and_the_marked_roots():
    import matplotlib.pyplot as plt

    locus = vib.root_locus(2.0, np.linspace(0.0, 3.0, 31))
    _, ax = plt.subplots()
    art = locus.plot(ax, mark=locus.roots[5], normalised=True)
    # Normalised: s/ω_n, so the branches start at ±i.
    np.testing.assert_allclose(art["branch1"].get_xydata()[0], [0.0, 1.0], atol=4 * EPS)
    np.testing.assert_allclose(art["roots"].get_xdata(), locus.roots[5].real / 2.0, rtol=EPS)
    assert art["roots"].get_visible()
    hidden = locus.plot(ax)["roots"]
    assert not hidden.get_visible()


@pytest.mark.parametrize(("start", "order"), [(0.0, 2), (1.0, 1)])
def test_duhamel_rectangle_rule_converges_to_the_exact_response(start, order):
    s = SDOF.from_modal(2 * np.pi, 0.2, mass=8000.0)
    errors = []
    for n in (2001, 4001):
        t = np.linspace(0.0, 2.0, n)
        force = 2e4 * (start + np.sin(np.pi * t / 0.2) * (t < 0.2))  # F(0) = 2e4·start
        errors.append(np.abs(s.duhamel_response(t, force) - s.forced_response(t, force)).max())
    # Halving Δt divides the error by 2^order: first order when F(t₀) ≠ 0 (the τ = t₀ term counted
    # whole), second when it vanishes. 10 % slack for the higher-order terms at these steps.
    assert errors[1] / errors[0] == pytest.approx(0.5**order, rel=0.1)
