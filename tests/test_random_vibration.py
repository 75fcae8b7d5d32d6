"""Tests for raildyn.random_vibration: PSD conventions, response spectra, mean squares, synthesis.

Tiers (ARCHITECTURE.md, "Tests"): closed forms (white-noise oscillator, band-limited
spectra, delayed inputs), an independent solver (the Lyapunov equation), a
property test (Parseval for synthesized samples) and Monte Carlo checks whose
tolerances are derived from the estimators' sampling statistics.
"""

import numpy as np
import pytest
import scipy.integrate
import scipy.linalg
import scipy.signal
import scipy.stats
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from raildyn import random_vibration as rv

# An SDOF with railway-vehicle magnitudes: 1 t on 1 MN/m (f_n ≈ 5 Hz), 5 % damping.
MASS = 1000.0
STIFFNESS = 1.0e6
ZETA = 0.05
OMEGA_N = np.sqrt(STIFFNESS / MASS)
DAMPING = 2.0 * ZETA * np.sqrt(STIFFNESS * MASS)


def receptance(omega, m=MASS, c=DAMPING, k=STIFFNESS):
    """SDOF receptance H(ω) = 1/(k − mω² + icω), m/N (written here, not imported from raildyn.vibration)."""
    return 1.0 / (k - m * omega**2 + 1j * c * omega)


# --------------------------------------------------------------------------- convert_psd

FORMS_TIME = [("one", "rad/s"), ("two", "rad/s"), ("one", "Hz"), ("two", "Hz")]
FORMS_SPACE = [("one", "rad/m"), ("two", "rad/m"), ("one", "cycles/m"), ("two", "cycles/m")]


@pytest.mark.parametrize("forms", [FORMS_TIME, FORMS_SPACE], ids=["time", "space"])
def test_convert_psd_round_trips(forms):
    values = np.array([0.0, 1e-9, 0.3, 2.0, 7.5e4])
    for a_sided, a_unit in forms:
        for b_sided, b_unit in forms:
            there = rv.convert_psd(
                values, from_sided=a_sided, from_unit=a_unit, to_sided=b_sided, to_unit=b_unit
            )
            back = rv.convert_psd(
                there, from_sided=b_sided, from_unit=b_unit, to_sided=a_sided, to_unit=a_unit
            )
            # at most four multiplications by 2 or 2π each way: a few ulps
            np.testing.assert_allclose(back, values, rtol=1e-14, atol=0)


def test_convert_psd_known_factors():
    # S₁ = 2 S₂ and S_Hz = 2π S₁ (module docstring); exact powers of two and one rounding of π
    assert rv.convert_psd(1.0, from_sided="two", from_unit="rad/s") == 2.0
    assert rv.convert_psd(2.0 * np.pi, from_sided="one", from_unit="Hz") == pytest.approx(1.0, rel=1e-15)
    assert rv.convert_psd(1.0, from_sided="one", from_unit="rad/m", to_unit="cycles/m") == pytest.approx(
        2.0 * np.pi, rel=1e-15
    )
    assert rv.convert_psd(np.pi, from_sided="two", from_unit="Hz") == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize(
    ("forms", "radian_unit"), [(FORMS_TIME, "rad/s"), (FORMS_SPACE, "rad/m")], ids=["time", "space"]
)
def test_band_limited_white_has_one_variance_in_every_form(forms, radian_unit):
    # one-sided level G on ω1 <= ω <= ω2 (rad/s or rad/m): variance G (ω2 − ω1) exactly
    G, w1, w2 = 0.37, 2.0, 55.0
    exact = G * (w2 - w1)
    w = np.linspace(w1, w2, 2001)
    level = np.full_like(w, G)
    for sided, unit in forms:
        values = rv.convert_psd(level, from_sided="one", from_unit=radian_unit, to_sided=sided, to_unit=unit)
        axis = w if unit == radian_unit else w / (2.0 * np.pi)  # the frequency axis converts by ω = 2πf
        if sided == "one":
            variance = np.trapezoid(values, axis)
        else:  # an even density on (−∞, ∞): integrate the band at negative and at positive frequency
            variance = np.trapezoid(values[::-1], -axis[::-1]) + np.trapezoid(values, axis)
        # the trapezoid rule is exact for a constant; what is left is rounding over 2000 steps
        assert variance == pytest.approx(exact, rel=1e-12), (sided, unit)


# --------------------------------------------------------------------------- mean square and moments


def test_mean_square_of_a_lorentzian_against_its_integral():
    # S = a/(b² + ω²) on [0, W]: ∫ = (a/b) arctan(W/b)
    a, b, W = 3.0, 2.0, 40.0
    w = np.linspace(0.0, W, 40001)
    h = w[1] - w[0]
    exact = a / b * np.arctan(W / b)
    # composite trapezoid error <= (W h²/12) max|S''|, and max|S''| = |S''(0)| = 2a/b⁴
    bound = W * h**2 / 12.0 * 2.0 * a / b**4
    assert abs(rv.mean_square(a / (b**2 + w**2), w) - exact) <= bound
    assert rv.rms(a / (b**2 + w**2), w) == pytest.approx(np.sqrt(exact), abs=bound / np.sqrt(exact))


def test_spectral_moments_and_rates_of_band_limited_white_noise():
    # flat G on [0, W]: m_k = G W^(k+1)/(k+1); ν₀⁺ = W/(2π√3), ν_p = (W/2π)√(3/5), α = √5/3
    G, W = 0.8, 10.0
    w = np.linspace(0.0, W, 10001)  # step h = 1e-3
    S = np.full_like(w, G)
    m = dict(zip((0, 2, 4), rv.spectral_moments(S, w, orders=(0, 2, 4)), strict=True))  # m[k] = m_k
    # Euler-Maclaurin: trapezoid error of ω² is (h²/12)·2W·G exactly, i.e. h²/(2W²) = 5e-9 relative;
    # of ω⁴ it is (5/3)h²/W² ≈ 1.7e-8 relative to leading order; 1e-7 covers both
    assert m[0] == pytest.approx(G * W, rel=1e-13)
    assert m[2] == pytest.approx(G * W**3 / 3, rel=1e-7)
    assert m[4] == pytest.approx(G * W**5 / 5, rel=1e-7)
    assert rv.zero_upcrossing_rate(S, w) == pytest.approx(W / (2 * np.pi * np.sqrt(3)), rel=1e-7)
    assert rv.peak_rate(S, w) == pytest.approx(W / (2 * np.pi) * np.sqrt(3 / 5), rel=1e-7)
    assert rv.irregularity_factor(S, w) == pytest.approx(np.sqrt(5) / 3, rel=1e-7)
    assert 0.0 < rv.irregularity_factor(S, w) <= 1.0
    assert rv.spectral_moments(S, w, orders=np.array([2]))[0] == m[2]  # an array of orders works too


# --------------------------------------------------------------------------- SDOF under white noise


def test_sdof_closed_form_one_and_two_sided_agree():
    G0 = 4.0e4
    one = rv.sdof_white_noise_mean_square(MASS, DAMPING, STIFFNESS, G0, sided="one")
    two = rv.sdof_white_noise_mean_square(MASS, DAMPING, STIFFNESS, G0 / 2, sided="two")
    assert one == pytest.approx(np.pi * G0 / (2 * STIFFNESS * DAMPING), rel=1e-15)
    assert two == pytest.approx(one, rel=1e-15)
    # the mass drops out (Crandall & Mark 1963)
    assert rv.sdof_white_noise_mean_square(5 * MASS, DAMPING, STIFFNESS, G0) == pytest.approx(one, rel=1e-15)


def test_sdof_white_noise_numerical_integral_matches_closed_form():
    G0 = 4.0e4  # N²/(rad/s), one-sided
    exact = rv.sdof_white_noise_mean_square(MASS, DAMPING, STIFFNESS, G0)
    top = 100.0 * OMEGA_N
    w = np.linspace(0.0, top, 400_001)  # h ≈ 0.008 rad/s: ~400 steps across the half-power band 2ζω_n
    h = w[1] - w[0]
    Sy = rv.response_psd(receptance(w), np.full_like(w, G0))
    numeric = rv.mean_square(Sy, w)
    # truncation: for ω > Ω, |H|² <= 1/(m²ω⁴(1 − ω_n²/Ω²)²), so the missing tail is at most
    # G0/(3 m² Ω³ (1 − ω_n²/Ω²)²) (about 2e-8 of the total here)
    tail = G0 / (3 * MASS**2 * top**3 * (1 - (OMEGA_N / top) ** 2) ** 2)
    # discretisation: trapezoid error = (h²/12) Σ h f''(η_i) <= (h²/12) ∫|f''| dω, f'' estimated on the
    # grid; a factor 2 covers using grid values for the maxima within each step
    f2 = np.gradient(np.gradient(Sy, h), h)
    discretisation = 2.0 * h**2 / 12.0 * np.trapezoid(np.abs(f2), w)
    assert abs(numeric - exact) <= tail + discretisation
    assert discretisation < 1e-4 * exact  # the bound is meaningful, not vacuous


def test_sdof_white_noise_against_lyapunov(reference):
    # state z = (x, ẋ), ż = A z + B F. One-sided G0 per rad/s is two-sided G0/2, whose autocorrelation
    # is 2π(G0/2) δ(τ): noise intensity W = π G0. The stationary covariance P solves A P + P Aᵀ + B W Bᵀ = 0.
    G0 = 4.0e4
    A = np.array([[0.0, 1.0], [-STIFFNESS / MASS, -DAMPING / MASS]])
    B = np.array([[0.0], [1.0 / MASS]])
    P = scipy.linalg.solve_continuous_lyapunov(A, -(B @ B.T) * np.pi * G0)
    # Bartels-Stewart on a 2x2: error ~ condition (~1/ζ) times machine epsilon; 1e-10 is ample
    ours = rv.sdof_white_noise_mean_square(MASS, DAMPING, STIFFNESS, G0)
    reference(
        1,
        "SDOF mean square under white noise",
        "Lyapunov equation (scipy)",
        "scipy",
        abs(ours / P[0, 0] - 1),
        1e-10,
    )
    # velocity: σ_v² = π G0/(2 m c) (Crandall & Mark 1963, with G0 = 2 S0)
    assert P[1, 1] == pytest.approx(np.pi * G0 / (2 * MASS * DAMPING), rel=1e-10)
    assert abs(P[0, 1]) <= 1e-10 * np.sqrt(P[0, 0] * P[1, 1])  # x and ẋ are uncorrelated when stationary


# --------------------------------------------------------------------------- response_psd and cross-spectra


def test_response_psd_mimo_with_one_input_equals_siso():
    w = np.linspace(0.0, 200.0, 501)
    H = receptance(w)
    S = 1e4 / (1 + (w / 50.0) ** 2)
    siso = rv.response_psd(H, S)
    mimo = rv.response_psd(H[:, None, None], S[:, None, None].astype(complex))
    row = rv.response_psd(H[:, None], S[:, None, None])
    assert mimo.shape == (w.size, 1, 1) and row.shape == (w.size,)
    # the same products in a different order: a few ulps
    np.testing.assert_allclose(mimo[:, 0, 0].real, siso, rtol=1e-13)
    np.testing.assert_array_equal(mimo[:, 0, 0].imag, 0.0)
    np.testing.assert_allclose(row, siso, rtol=1e-13)


def test_response_psd_matches_explicit_products():
    rng = np.random.default_rng(3)
    n, p, q = 7, 2, 3
    H = rng.normal(size=(n, p, q)) + 1j * rng.normal(size=(n, p, q))
    L = rng.normal(size=(n, q, q)) + 1j * rng.normal(size=(n, q, q))
    S = L @ np.conj(np.swapaxes(L, 1, 2))  # Hermitian, positive semi-definite
    Sy = rv.response_psd(H, S)
    expected = np.array([H[i] @ S[i] @ H[i].conj().T for i in range(n)])
    np.testing.assert_allclose(Sy, expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())
    np.testing.assert_array_equal(Sy, np.conj(np.swapaxes(Sy, 1, 2)))  # exactly Hermitian
    # a single-output row gives the (0, 0) entry of the same product
    np.testing.assert_allclose(rv.response_psd(H[:, 0, :], S), expected[:, 0, 0].real, rtol=1e-12)


def test_two_axles_with_a_delay_give_the_comb_filter():
    # y = x1 + x2 with x2 = x1 delayed by τ: S_y = S |1 + e^{−iωτ}|² = 2 S (1 + cos ωτ)
    tau = 2.5 / 30.0  # 2.5 m axle spacing at 30 m/s
    zeros = np.pi / tau * (2 * np.arange(5) + 1)
    w = np.sort(np.concatenate([np.linspace(0.0, 200.0, 801), zeros]))
    S = 1.0 / (1.0 + (w / 20.0) ** 2)
    csd = rv.delayed_input_csd(S, w, [0.0, tau])
    Sy = rv.response_psd(np.ones((w.size, 2)), csd)
    # exp and cos are correctly rounded to ~1 ulp; the sum of four O(S) terms leaves ~1e-15 S
    np.testing.assert_allclose(Sy, 2 * S * (1 + np.cos(w * tau)), rtol=0, atol=1e-13 * S.max())
    at_zeros = np.isin(w, zeros)
    assert np.all(np.abs(Sy[at_zeros]) <= 1e-13 * S[at_zeros])
    # the general (n, p, q) form agrees, and only differences of delays matter
    shifted = rv.delayed_input_csd(S, w, [1.0, 1.0 + tau])
    np.testing.assert_allclose(
        rv.response_psd(np.ones((w.size, 1, 2)), shifted)[:, 0, 0].real, Sy, atol=1e-13
    )


def test_delayed_csd_sign_against_monte_carlo_cross_spectrum():
    # x1 = u(t), x2 = u(t − τ). synthesize gives a record periodic in n·dt, so a circular shift by m
    # samples is an exact delay τ = m·dt. scipy.signal.csd(a, b) estimates E[A* B], so S_12 = E[X1 X2*]
    # (the raildyn convention) is csd(x2, x1).
    dt, n, m, nperseg = 0.01, 2**16, 6, 1024
    G, band = 0.5, (5.0, 250.0)
    u = rv.synthesize(lambda w: G, dt, n, rng=11, band=band)
    x1, x2 = u, np.roll(u, m)
    f, P21 = scipy.signal.csd(x2, x1, fs=1 / dt, nperseg=nperseg)
    _, P11 = scipy.signal.welch(x1, fs=1 / dt, nperseg=nperseg)
    _, P22 = scipy.signal.welch(x2, fs=1 / dt, nperseg=nperseg)
    w = 2 * np.pi * f
    dw = w[1] - w[0]
    inner = (w >= band[0] + 4 * dw) & (w <= band[1] - 4 * dw)  # away from leakage at the band edges
    model = rv.delayed_input_csd(np.full(w.size, G), w, [0.0, m * dt])
    coherency = P21[inner] / np.sqrt(P11[inner] * P22[inner])
    # Both records are the same data; the estimate departs from e^{iωτ} only because the Hann taper
    # sits m samples differently on them. That mismatch is ‖w(·+m) − w‖/‖w‖ ≈ (2π/√3)·m/N ≈ 0.02 for
    # N = nperseg; 0.05 allows for it. The opposite sign convention would miss by up to 2 (ωτ reaches 15 rad).
    assert np.max(np.abs(coherency - model[inner, 0, 1] / G)) < 0.05
    assert np.max(np.abs(coherency - model[inner, 1, 0] / G)) > 1.5


# --------------------------------------------------------------------------- synthesis


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    seed=st.integers(0, 2**32 - 1),
    n=st.integers(4, 4096),
    dt=st.floats(1e-3, 1.0),
    corner=st.floats(0.1, 100.0),
    n_samples=st.integers(1, 3),
)
def test_synthesize_mean_square_is_exactly_the_line_sum(seed, n, dt, corner, n_samples):
    # Parseval: lines at the record's own Fourier frequencies are orthogonal over the record, so each
    # sample's mean square is Σ S(ω_k) Δω up to round-off (relative ~ n·eps from the FFT; 1e-10 is ample)
    def psd(w):
        return 1.0 / (1.0 + (w / corner) ** 2)

    x = np.atleast_2d(rv.synthesize(psd, dt, n, rng=seed, n_samples=n_samples))
    d_omega = 2 * np.pi / (n * dt)
    lines = d_omega * np.arange(1, (n - 1) // 2 + 1)  # k = 1 … ⌈n/2⌉ − 1, computed here independently
    target = np.sum(psd(lines)) * d_omega
    np.testing.assert_allclose(np.mean(x**2, axis=1), target, rtol=1e-10)
    # no zero-frequency line, so the record mean is zero up to round-off
    np.testing.assert_allclose(np.mean(x, axis=1), 0.0, atol=1e-12 * np.sqrt(target))


def test_synthesize_shapes_grid_psd_and_band():
    omega_grid = np.array([0.0, 10.0, 20.0])
    values = np.array([1.0, 1.0, 0.0])
    assert rv.synthesize((omega_grid, values), 0.01, 101, rng=0).shape == (101,)
    assert rv.synthesize((omega_grid, values), 0.01, 100, rng=0, n_samples=3).shape == (3, 100)
    lines = rv.synthesis_lines((omega_grid, values), 0.01, 1000)
    w, s, dw = lines.omega, lines.psd, lines.d_omega
    np.testing.assert_allclose(s, np.interp(w, omega_grid, values, left=0.0, right=0.0), rtol=1e-15)
    assert np.all(s[w > 20.0] == 0.0)
    # a band keeps the same phases on the lines it keeps: same as zeroing the PSD outside it
    band = (30.0, 90.0)
    inside = rv.synthesize(lambda w: 2.0, 0.01, 1000, rng=4, band=band)
    masked = rv.synthesize(lambda w: 2.0 * ((w >= band[0]) & (w <= band[1])), 0.01, 1000, rng=4)
    np.testing.assert_allclose(inside, masked, rtol=0, atol=1e-14)
    kept = rv.synthesis_lines(lambda w: 2.0, 0.01, 1000, band=band)
    wb, sb = kept.omega, kept.psd
    assert wb.min() >= band[0] and wb.max() <= band[1]
    assert np.mean(inside**2) == pytest.approx(np.sum(sb) * dw, rel=1e-12)


def test_synthesize_same_seed_same_sample_different_seed_different():
    def psd(w):
        return 1.0 / (1.0 + w**2)

    a = rv.synthesize(psd, 0.05, 512, rng=123, n_samples=2)
    b = rv.synthesize(psd, 0.05, 512, rng=123, n_samples=2)
    c = rv.synthesize(psd, 0.05, 512, rng=124, n_samples=2)
    g = rv.synthesize(psd, 0.05, 512, rng=np.random.default_rng(123), n_samples=2)
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(a, g)
    assert not np.allclose(a, c)
    assert not np.allclose(a[0], a[1])  # the records of one call are independent


def test_monte_carlo_rms_of_sdof_response_to_band_limited_force():
    # Force: flat one-sided G0 on a band around resonance, R records of T = n·dt seconds. Response by the
    # first-order-hold discretisation of the SDOF (what scipy.signal.lsim uses, exact for an input linear
    # between samples), run through lfilter for speed; the start-up transient is dropped.
    m, wn, zeta = 1000.0, 2 * np.pi, 0.05
    k = m * wn**2
    c = 2 * zeta * np.sqrt(k * m)
    G0, band = 1.0e6, (0.2 * wn, 5 * wn)
    dt, n, R = 0.01, 2**17, 16
    force = rv.synthesize(lambda w: G0, dt, n, rng=20240611, n_samples=R, band=band)
    A = np.array([[0.0, 1.0], [-k / m, -c / m]])
    B = np.array([[0.0], [1.0 / m]])
    C, D = np.array([[1.0, 0.0]]), np.zeros((1, 1))
    Ad, Bd, Cd, Dd, _ = scipy.signal.cont2discrete((A, B, C, D), dt, method="foh")
    num, den = scipy.signal.ss2tf(Ad, Bd, Cd, Dd)
    x = scipy.signal.lfilter(num[0], den, force, axis=-1)
    settle = int(np.ceil(10 / (zeta * wn) / dt))  # ten decay times: transient energy down by e^-20
    estimate = np.mean(x[:, settle:] ** 2)

    def Sy(w):
        return G0 * np.abs(receptance(w, m, c, k)) ** 2

    exact, _ = scipy.integrate.quad(Sy, *band, points=[wn], epsabs=0, epsrel=1e-12, limit=200)
    # Standard error: for a Gaussian process the time average of x² over T has relative variance
    # 1/(B_s T), B_s = (∫S dω)²/(2π ∫S² dω) the statistical bandwidth (Bendat & Piersol, *Random Data*,
    # ch. 8). Fixed-amplitude random-phase samples scatter less than that, so this is conservative.
    T = (n - settle) * dt
    w = np.linspace(*band, 200_001)
    rel_var = 2 * np.pi * np.trapezoid(Sy(w) ** 2, w) / (exact**2 * T)
    sigma = np.sqrt(rel_var / R)  # R independent records (≈ 1.2 % here)
    # bias: linear interpolation of the force between samples scales its power by sinc⁴(ωdt/2) ≈
    # 1 − (ω dt)²/6, 7e-4 at resonance; the line spacing 2π/T resolves the half-power band with ~60 lines
    bias = 1e-3
    assert abs(estimate / exact - 1) < 4 * sigma + bias
    assert np.sqrt(estimate) == pytest.approx(np.sqrt(exact), rel=2 * sigma + bias)


def test_welch_estimate_matches_target_psd_within_chi_square_bounds():
    dt, n, nperseg = 0.01, 2**18, 512
    G, band = 0.5, (5.0, 250.0)
    x = rv.synthesize(lambda w: G, dt, n, rng=7, band=band)
    estimate = rv.welch_psd(x, dt, nperseg=nperseg)
    w, p = estimate.omega, estimate.psd
    assert w[-1] == pytest.approx(np.pi / dt)
    dw = w[1] - w[0]
    inner = (w >= band[0] + 4 * dw) & (w <= band[1] - 4 * dw)  # Hann leakage from the band edges stays out
    # Welch with a Hann window and 50 % overlap: K segments give ν ≈ 2K/(1 + 2ρ²) degrees of freedom,
    # ρ = 0.167 the correlation of overlapping Hann segments (Welch 1967; Harris, Proc. IEEE 66, 1978).
    # Each bin is then S·χ²_ν/ν; Bonferroni over the bins keeps the chance of any false failure below 1e-6.
    K = (n - nperseg) // (nperseg // 2) + 1
    nu = 2 * K / (1 + 2 * 0.167**2)
    alpha = 1e-6 / inner.sum()
    lo, hi = scipy.stats.chi2.ppf([alpha / 2, 1 - alpha / 2], nu) / nu
    ratio = p[inner] / G
    assert lo < ratio.min() and ratio.max() < hi
    # and outside the band (away from its edges) there is next to nothing
    outside = w > band[1] + 4 * dw
    assert np.all(p[outside] < 1e-3 * G)


# --------------------------------------------------------------------------- bad input


def test_negative_frequency_is_refused_with_its_value():
    with pytest.raises(ValueError, match=r"omega must be >= 0.*-1\.0"):
        rv.mean_square([1.0, 1.0, 1.0], [-1.0, 0.0, 1.0])
    with pytest.raises(ValueError, match=r"omega must be >= 0.*-1\.0"):
        rv.delayed_input_csd([1.0, 1.0], [-1.0, 0.0], [0.0, 0.1])


@pytest.mark.parametrize(
    ("psd", "omega", "match"),
    [
        ([1.0, np.nan, 1.0], [0.0, 1.0, 2.0], "psd must contain only finite"),
        ([1.0, 1.0, 1.0], [0.0, np.inf, 2.0], "omega must contain only finite"),
        ([1.0, 1.0], [0.0, 1.0, 2.0], r"psd and omega must have the same length"),
        ([1.0, -2.0, 1.0], [0.0, 1.0, 2.0], "psd must be >= 0"),
        ([1.0, 1.0, 1.0], [0.0, 2.0, 2.0], "omega must be strictly increasing"),
        ([1.0], [1.0], "omega must hold at least 2"),
    ],
)
def test_bad_spectrum_grids(psd, omega, match):
    with pytest.raises(ValueError, match=match):
        rv.mean_square(psd, omega)


def test_bad_spectral_moment_input():
    with pytest.raises(ValueError, match="orders"):
        rv.spectral_moments([1.0, 1.0], [0.0, 1.0], orders=(0, -2))
    with pytest.raises(ValueError, match="psd must not be zero"):
        rv.zero_upcrossing_rate([0.0, 0.0], [0.0, 1.0])


def test_bad_response_psd_input():
    with pytest.raises(ValueError, match=r"frf shape \(5, 2\).*input_psd shape \(5, 3, 3\)"):
        rv.response_psd(np.ones((5, 2)), np.ones((5, 3, 3)))
    with pytest.raises(ValueError, match=r"frf shape \(5,\).*input_psd shape \(4,\)"):
        rv.response_psd(np.ones(5), np.ones(4))
    with pytest.raises(ValueError, match=r"frf shape \(5, 2, 3\).*input_psd shape \(5,\)"):
        rv.response_psd(np.ones((5, 2, 3)), np.ones(5))
    not_hermitian = np.zeros((5, 2, 2), dtype=complex)
    not_hermitian[:, 0, 0] = not_hermitian[:, 1, 1] = 1.0
    not_hermitian[3, 0, 1] = 0.5j  # its mirror entry is 0, not −0.5i
    with pytest.raises(ValueError, match="input_psd must be Hermitian"):
        rv.response_psd(np.ones((5, 2)), not_hermitian)
    with pytest.raises(ValueError, match="input_psd must be >= 0"):
        rv.response_psd(np.ones(3), [1.0, -1.0, 1.0])
    with pytest.raises(ValueError, match="frf must contain only finite"):
        rv.response_psd([1.0, np.nan], [1.0, 1.0])


def test_bad_delays():
    with pytest.raises(ValueError, match="delays must contain only finite"):
        rv.delayed_input_csd([1.0], [1.0], [0.0, np.nan])
    with pytest.raises(ValueError, match="delays must be a 1-dimensional"):
        rv.delayed_input_csd([1.0], [1.0], [[0.0, 0.1]])


def test_bad_convert_psd_input():
    with pytest.raises(ValueError, match="values must be >= 0"):
        rv.convert_psd([1.0, -0.1], from_sided="one", from_unit="Hz")
    with pytest.raises(ValueError, match="from_unit 'Hz' and to_unit 'rad/m'"):
        rv.convert_psd(1.0, from_sided="one", from_unit="Hz", to_unit="rad/m")
    with pytest.raises(ValueError, match="from_sided must be one of"):
        rv.convert_psd(1.0, from_sided="double", from_unit="Hz")
    with pytest.raises(ValueError, match="to_unit must be one of"):
        rv.convert_psd(1.0, from_sided="one", from_unit="Hz", to_unit="rpm")
    with pytest.raises(ValueError, match="values must contain only finite"):
        rv.convert_psd(np.nan, from_sided="one", from_unit="Hz")


def test_bad_sdof_input():
    with pytest.raises(ValueError, match="mass"):
        rv.sdof_white_noise_mean_square(0.0, DAMPING, STIFFNESS, 1.0)
    with pytest.raises(ValueError, match="damping"):
        rv.sdof_white_noise_mean_square(MASS, 0.0, STIFFNESS, 1.0)
    with pytest.raises(ValueError, match="stiffness"):
        rv.sdof_white_noise_mean_square(MASS, DAMPING, -1.0, 1.0)
    with pytest.raises(ValueError, match="psd_level"):
        rv.sdof_white_noise_mean_square(MASS, DAMPING, STIFFNESS, -1.0)
    with pytest.raises(ValueError, match="sided must be one of"):
        rv.sdof_white_noise_mean_square(MASS, DAMPING, STIFFNESS, 1.0, sided="both")


def flat(w):
    return 1.0


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"band": (50.0, 50.0)}, "band must satisfy 0 <= omega_lo < omega_hi"),
        ({"band": (60.0, 50.0)}, "band must satisfy 0 <= omega_lo < omega_hi"),
        ({"band": (-1.0, 50.0)}, "band must satisfy 0 <= omega_lo < omega_hi"),
        ({"band": (1.0, 400.0)}, r"band must satisfy .*pi/dt = 314\.159"),  # above Nyquist π/dt
        ({"band": (1.0, 2.0, 3.0)}, "band must be a pair"),
        ({"band": (100.0, 100.1)}, "band .* holds none of the synthesis frequencies"),
        ({"dt": 0.0}, "dt must be in"),
        ({"n": 3}, "n must be an integer in"),
        ({"n_samples": 0}, "n_samples must be an integer in"),
        ({"rng": -1}, "rng must be"),
        ({"psd": lambda w: -w}, r"psd must return values >= 0"),
        ({"psd": lambda w: np.ones(3)}, r"psd must return an array of shape"),
        ({"psd": lambda w: np.full(w.shape, np.nan)}, r"psd returned a non-finite value"),
        ({"n": 2**30}, "n must be an integer in"),  # a bound on memory, not a hang or a MemoryError
        ({"n_samples": 10**12}, r"n_samples \* n must be at most"),
        ({"psd": (np.array([0.0, 5.0, 1.0]), np.ones(3))}, "omega must be strictly increasing"),
    ],
)
def test_bad_synthesis_input(kwargs, match):
    args = {"psd": flat, "dt": 0.01, "n": 256, "rng": 0} | kwargs
    with pytest.raises(ValueError, match=match):
        rv.synthesize(args.pop("psd"), args.pop("dt"), args.pop("n"), args.pop("rng"), **args)


def test_synthesis_type_errors():
    with pytest.raises(TypeError, match="n must be an integer"):
        rv.synthesize(flat, 0.01, 256.0)
    with pytest.raises(TypeError, match="psd must be a callable"):
        rv.synthesize(np.ones(10), 0.01, 256)


def test_bad_welch_input():
    with pytest.raises(ValueError, match="nperseg must be an integer in"):
        rv.welch_psd(np.zeros(100), 0.01, nperseg=200)
    with pytest.raises(ValueError, match="x must contain only finite"):
        rv.welch_psd([0.0, 1.0, np.nan, 0.0, 1.0], 0.01)
    with pytest.raises(ValueError, match="dt must be in"):
        rv.welch_psd(np.zeros(100), -0.01)


# ---------------------------------------------------------------- result shapes and the delay filter


def test_results_are_frozen_dataclasses_with_their_mean_square():
    import dataclasses

    x = rv.synthesize(lambda w: 0.5, 0.01, 4096, rng=3)
    lines = rv.synthesis_lines(lambda w: 0.5, 0.01, 4096)
    estimate = rv.welch_psd(x, 0.01, nperseg=512)
    for result in (lines, estimate):
        assert dataclasses.is_dataclass(result) and not isinstance(result, tuple)
        with pytest.raises(dataclasses.FrozenInstanceError):
            result.omega = None
    # Parseval over the record: the mean square of the sample is the sum over its lines, to rounding.
    assert lines.mean_square == pytest.approx(np.mean(x**2), rel=1e-12)
    # The Spectrum's mean square is the trapezoid rule over its grid, as mean_square computes it.
    assert estimate.mean_square == pytest.approx(rv.mean_square(estimate.psd, estimate.omega), rel=1e-15)
    assert estimate.rms == pytest.approx(np.sqrt(estimate.mean_square), rel=1e-15)


def test_spectral_moments_come_in_the_order_asked():
    w = np.linspace(0.0, 2.0, 201)
    m = rv.spectral_moments(np.ones_like(w), w, orders=(4, 0, 2))
    # Trapezoid rule on ω^k, step 0.01: m_0 exact, m_2 and m_4 within (h²/12)·(max |f''|)·W ≲ 2e-4.
    assert m.shape == (3,)
    np.testing.assert_allclose(m, [2.0**5 / 5, 2.0, 2.0**3 / 3], rtol=2e-4)


@given(st.floats(0.01, 1.0), st.integers(2, 4))
@settings(max_examples=30, deadline=None)
def test_delayed_mean_psd_is_the_response_to_the_cross_spectral_matrix(tau, q):
    w = np.linspace(0.0, 200.0, 801)
    S = 1.0 / (1.0 + w**2)
    delays = tau * np.arange(q) ** 1.5
    csd = rv.delayed_input_csd(S, w, delays)
    # Two routes to the PSD of the mean (1/q) Σ u(t − τ_j): H S Hᴴ with H = 1/q, and S|mean e^{−iωτ}|².
    expected = rv.response_psd(np.full((w.size, q), 1.0 / q), csd)
    np.testing.assert_allclose(rv.delayed_mean_psd(S, w, delays), expected, rtol=1e-12, atol=1e-15)


def test_mean_of_two_delayed_inputs_vanishes_at_the_cancellation_frequencies():
    tau = 2.5 / 30.0
    w = rv.cancellation_frequencies(tau, 4)
    np.testing.assert_allclose(w, np.array([1, 3, 5, 7]) * np.pi / tau, rtol=1e-15)
    # cos²(ωτ/2) = 0 there: rounding of the phase (~ωτ ε ≈ 2e-15) squared.
    assert np.all(rv.delayed_mean_psd(np.ones(4), w, [0.0, tau]) < 1e-28)
    with pytest.raises(ValueError, match="delay"):
        rv.cancellation_frequencies(0.0, 2)
    with pytest.raises(ValueError, match="count"):
        rv.cancellation_frequencies(0.1, 0)
    with pytest.raises(ValueError, match="delays must hold at least one"):
        rv.delayed_mean_psd([1.0], [1.0], [])


def test_huge_inputs_are_refused_rather_than_overflowing_silently():
    # issue 15: 1e300 must not come back as inf or NaN
    w = np.array([0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="orders"):
        rv.spectral_moments(np.ones(3), w * 10.0, orders=(1e300,))
    with pytest.raises(ValueError, match="frf"):
        rv.response_psd(np.array([1e300, 1.0, 1.0]), np.ones(3))
    with pytest.raises(ValueError, match="x and dt"):
        rv.welch_psd(np.r_[1e300, np.zeros(63)], 0.01, nperseg=32)
    with pytest.raises(ValueError, match="count"):
        rv.cancellation_frequencies(0.1, 10**12)


def test_results_refuse_what_no_spectrum_holds():
    with pytest.raises(ValueError, match="psd"):
        rv.Spectrum(np.array([0.0, 1.0]), np.array([1.0, -1.0]))
    with pytest.raises(ValueError, match="omega must be strictly increasing"):
        rv.Spectrum(np.array([1.0, 0.0]), np.ones(2))
    with pytest.raises(ValueError, match="d_omega"):
        rv.SpectralLines(np.array([1.0, 2.0]), np.ones(2), 0.0)
    with pytest.raises(TypeError, match="from_unit"):
        rv.convert_psd(1.0, from_sided="one", from_unit=2.0)


def test_an_output_that_cancels_has_a_response_psd_of_zero_not_rounding_below_it():
    # Two inputs that are one process (no delay between them) and an output that is their difference:
    # the response PSD is exactly 0, and the sum of q² terms leaves rounding on either side of it. It is
    # returned as 0 (at most rounding above), one output or several; a cross-spectral matrix that is not
    # positive semi-definite still gives its negative value, which is no rounding.
    rng = np.random.default_rng(7)
    omega = np.linspace(0.1, 10.0, 200)
    S = rv.delayed_input_csd(rng.uniform(0.5, 2.0, omega.size), omega, [0.0, 0.0])
    h = rng.normal(size=omega.size) + 1j * rng.normal(size=omega.size)
    H = np.stack([h, -h], axis=1) * np.exp(1j * rng.uniform(0, 2 * np.pi, (omega.size, 1)))
    scale = 4 * np.abs(h) ** 2 * np.abs(S[:, 0, 0])
    single = rv.response_psd(H, S)
    assert np.all(single >= 0.0) and np.all(single <= 16 * np.finfo(float).eps * scale)
    several = rv.response_psd(np.stack([H, 2 * H], axis=1), S)
    assert np.all(np.diagonal(several, axis1=1, axis2=2).real >= 0.0)
    indefinite = np.broadcast_to(np.array([[1.0, 2.0], [2.0, 1.0]]), (omega.size, 2, 2))
    assert np.allclose(rv.response_psd(np.ones((omega.size, 2)) * [1.0, -1.0], indefinite), -2.0)
