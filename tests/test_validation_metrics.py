"""Tests of raildyn.validation.metrics: each metric on signals whose answer is known in closed form.

Sources of the closed forms: Sprague & Geers (2004) and Schwer (2007) for M, P and C;
Theil (1961) for U; IEC 61260-1:2014 for the one-third-octave band edges (base 10);
Bendat & Piersol (2010), ch. 6 and 9, for H1, the coherence and their random errors;
Welch (1967) for the PSD; the asymptotic normality of a central sample quantile (e.g. H. A.
David and H. N. Nagaraja, *Order Statistics*, 3rd ed., Wiley, 2003, ch. 10) for its
standard error.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pytest
import scipy.integrate
import scipy.signal
import scipy.stats
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.random_vibration import welch_psd
from raildyn.validation import (
    Agreement,
    compare,
    correlation,
    frequency_response_h1,
    nrmse,
    percentiles,
    section_maxima,
    sliding_rms,
    sprague_geers,
    theil_u,
    third_octave_rms,
)

# A record of 4 whole periods of 2 Hz, sampled at 1 kHz: the trapezoid rule over whole periods
# integrates sin², cos² and sin·cos exactly (to rounding), so the closed forms hold to ~1e-15.
DT = 1e-3
T = np.arange(2001) * DT
OMEGA = 2 * np.pi * 2.0
SINE = np.sin(OMEGA * T)


def _rng(seed=19):
    return np.random.default_rng(seed)


# --------------------------------------------------------------------------- pure gain


@pytest.mark.parametrize("gain", [0.25, 0.9, 1.0, 1.3, 3.0])
def test_pure_gain_closed_forms(gain, reference):
    # A record with a mean and two harmonics, so that nothing rests on the record being a pure sine.
    m = 0.3 + SINE + 0.2 * np.cos(3 * OMEGA * T)
    p = gain * m
    sg = sprague_geers(m, p, T)
    # M = √(ψ_pp/ψ_mm) − 1 = g − 1 exactly (Sprague & Geers 2004); rounding only: 1e-12.
    reference(
        11,
        f"Sprague–Geers magnitude of a pure gain {gain:g}",
        "M = g − 1 (Sprague & Geers 2004)",
        "closed form",
        abs(sg.magnitude - (gain - 1.0)),
        1e-12,
        "abs.",
    )
    # P = arccos(1)/π = 0; arccos near 1 magnifies a rounding ε of the cosine to √(2ε)/π ≈ 5e-9.
    assert sg.phase == pytest.approx(0.0, abs=1e-7)
    assert sg.combined == pytest.approx(abs(gain - 1.0), abs=1e-7)
    # Theil (1961): U = |g − 1|·rms/((g + 1)·rms) = |g − 1|/(g + 1); rounding only.
    assert theil_u(m, p) == pytest.approx(abs(gain - 1.0) / (gain + 1.0), abs=1e-12)
    # Pearson's r of a positive gain is 1; rounding only.
    assert correlation(m, p) == pytest.approx(1.0, abs=1e-12)
    # RMS error |g − 1|·rms(m): normalised by rms(m) it is |g − 1|; by the range, |g − 1| rms/range.
    rms = np.sqrt(np.mean(m**2))
    assert nrmse(m, p, normalisation="rms") == pytest.approx(abs(gain - 1.0), abs=1e-12)
    assert nrmse(m, p) == pytest.approx(abs(gain - 1.0) * rms / np.ptp(m), abs=1e-12)


def test_sign_reversal_is_the_worst_case():
    # p = −k m: r = −1, P = arccos(−1)/π = 1, U = (k + 1)/(k + 1) = 1 (Theil 1961's upper bound).
    p = -2.0 * SINE
    assert correlation(SINE, p) == pytest.approx(-1.0, abs=1e-12)
    assert sprague_geers(SINE, p, DT).phase == pytest.approx(1.0, abs=1e-7)
    assert theil_u(SINE, p) == pytest.approx(1.0, abs=1e-12)


# --------------------------------------------------------------------------- pure delay


@pytest.mark.parametrize("delay", [0.01, 0.05, 0.125, 0.2, 0.3])
def test_pure_delay_closed_forms(delay):
    # A sine delayed by τ, over whole periods: ψ_pp = ψ_mm and ψ_mp/ψ_mm = cos ωτ, so M = 0 and
    # P = arccos(cos ωτ)/π = ωτ/π for ωτ <= π, 2 − ωτ/π beyond (ωτ = 2π·2·0.3 = 1.2π here).
    p = np.sin(OMEGA * (T - delay))
    sg = sprague_geers(SINE, p, T)
    wt = OMEGA * delay
    expected = wt / np.pi if wt <= np.pi else 2.0 - wt / np.pi
    # The trapezoid rule is exact over whole periods; 1e-9 allows for arccos's sensitivity near 0 and 1.
    assert sg.magnitude == pytest.approx(0.0, abs=1e-12)
    assert sg.phase == pytest.approx(expected, abs=1e-9)
    assert sg.combined == pytest.approx(expected, abs=1e-9)
    # Pearson's r of two sines of one frequency is cos ωτ; Theil's U is |2 sin(ωτ/2)|·rms/(2 rms).
    # These use plain means, exact over whole periods without the repeated end sample.
    assert correlation(SINE[:-1], p[:-1]) == pytest.approx(np.cos(wt), abs=1e-9)
    assert theil_u(SINE[:-1], p[:-1]) == pytest.approx(abs(np.sin(wt / 2)), abs=1e-9)


def test_sprague_geers_against_its_integrals():
    # An independent computation: the three integrals by scipy's trapezoid rule on the time grid.
    rng = _rng(1)
    m, p = rng.standard_normal(500), rng.standard_normal(500) + 0.5
    t = 3.0 + np.arange(500) * 0.02
    psi_mm = scipy.integrate.trapezoid(m * m, t)
    psi_pp = scipy.integrate.trapezoid(p * p, t)
    psi_mp = scipy.integrate.trapezoid(m * p, t)
    M = np.sqrt(psi_pp / psi_mm) - 1.0
    P = np.arccos(psi_mp / np.sqrt(psi_mm * psi_pp)) / np.pi
    sg = sprague_geers(m, p, t)
    # Same sums in another order: 1e-12.
    assert sg.magnitude == pytest.approx(M, abs=1e-12)
    assert sg.phase == pytest.approx(P, abs=1e-12)
    assert sg.combined == pytest.approx(np.hypot(M, P), abs=1e-12)


def test_time_metrics_against_their_definitions():
    # Independent computations: scipy.stats.pearsonr, and each normalisation written out.
    rng = _rng(2)
    m = np.cumsum(rng.standard_normal(800)) + 5.0
    p = m + rng.standard_normal(800)
    # Rounding only: 1e-12.
    assert correlation(m, p) == pytest.approx(scipy.stats.pearsonr(m, p).statistic, abs=1e-12)
    rmse = np.sqrt(np.mean((p - m) ** 2))
    norms = {"range": np.ptp(m), "rms": np.sqrt(np.mean(m**2)), "std": np.std(m), "mean": abs(np.mean(m))}
    for name, norm in norms.items():
        assert nrmse(m, p, normalisation=name) == pytest.approx(rmse / norm, rel=1e-12)
    u = rmse / (np.sqrt(np.mean(p**2)) + np.sqrt(np.mean(m**2)))
    assert theil_u(m, p) == pytest.approx(u, rel=1e-12)


@pytest.mark.parametrize("scale", [1e-200, 1e-3, 1e3, 1e200])
def test_compare_is_scale_free(scale):
    # Every metric is a ratio: records in another unit (or near the floating-point limits, where a
    # naive sum of squares under- or overflows) give the same numbers, to rounding (1e-12).
    rng = _rng(3)
    m = rng.standard_normal(300)
    p = 0.8 * m + 0.3 * rng.standard_normal(300)
    a, b = compare(m, p, DT), compare(scale * m, scale * p, DT)
    for name in ("nrmse", "correlation", "theil_u", "magnitude", "phase", "combined"):
        assert getattr(b, name) == pytest.approx(getattr(a, name), rel=1e-12, abs=1e-12), name


def test_compare_gathers_the_single_metrics_and_plots():
    rng = _rng(4)
    m = SINE + 0.1 * rng.standard_normal(T.size)
    p = 1.1 * np.sin(OMEGA * (T - 0.01))
    a = compare(m, p, T, normalisation="std")
    sg = sprague_geers(m, p, T)
    assert isinstance(a, Agreement)
    # The same functions on the same records: equal to the last bit.
    assert a.nrmse == nrmse(m, p, normalisation="std")
    assert (a.correlation, a.theil_u) == (correlation(m, p), theil_u(m, p))
    assert (a.magnitude, a.phase, a.combined) == (sg.magnitude, sg.phase, sg.combined)
    lines = a.plot()
    np.testing.assert_array_equal(lines["measured"].get_ydata(), m)
    np.testing.assert_array_equal(lines["predicted"].get_xdata(), T)
    assert f"{a.nrmse:.3g}" in lines["measured"].axes.get_title()
    # Without a time base the records are drawn against the sample number.
    _, ax = plt.subplots()
    lines = compare(m, p).plot(ax)
    np.testing.assert_array_equal(lines["measured"].get_xdata(), np.arange(m.size))


@given(st.integers(0, 2**32 - 1), st.integers(3, 400), st.floats(-3.0, 3.0), st.floats(0.0, 2.0))
@settings(max_examples=60, deadline=None)
def test_metric_bounds_and_identities(seed, n, offset, noise):
    # Invariants of the definitions, on arbitrary records: r in [−1, 1], U in [0, 1] (Theil 1961,
    # by the triangle inequality), P in [0, 1] and M >= −1 (Sprague & Geers 2004), C² = M² + P²;
    # swapping the records keeps r and U and maps 1 + M to 1/(1 + M); a record against itself
    # scores perfectly. Rounding only: 1e-12, and 1e-7 for P of a record against itself (arccos
    # magnifies a rounding ε of the cosine to √(2ε)/π ≈ 5e-9 there).
    rng = np.random.default_rng(seed)
    m = offset + rng.standard_normal(n)
    p = rng.standard_normal() * m + noise * rng.standard_normal(n)
    a = compare(m, p)
    assert -1.0 <= a.correlation <= 1.0 and 0.0 <= a.theil_u <= 1.0
    assert 0.0 <= a.phase <= 1.0 and a.magnitude >= -1.0 and a.nrmse >= 0.0
    assert a.combined == pytest.approx(np.hypot(a.magnitude, a.phase), abs=1e-12)
    b = compare(p, m)
    assert b.correlation == pytest.approx(a.correlation, abs=1e-12)
    assert b.theil_u == pytest.approx(a.theil_u, abs=1e-12)
    # M = ratio − 1 is rounded at its own size, so 1 + M carries ε·max(1, M) relative to itself: the
    # product's tolerance grows with the gain's distance from 1 (a gain of 1e-3 makes the swapped M 1e3).
    spread = 1.0 + abs(a.magnitude) + abs(b.magnitude)
    assert (1.0 + b.magnitude) * (1.0 + a.magnitude) == pytest.approx(1.0, rel=1e-12 * spread)
    assert b.phase == pytest.approx(a.phase, abs=1e-12)
    same = compare(m, m.copy())
    assert same.nrmse == 0.0 and same.theil_u == 0.0 and same.magnitude == pytest.approx(0.0, abs=1e-12)
    assert same.correlation == pytest.approx(1.0, abs=1e-12) and same.phase < 1e-7


# --------------------------------------------------------------------------- frequency


def test_white_noise_psd_level_and_parseval():
    # White noise of variance σ² sampled every dt has the flat one-sided PSD σ² dt/π per rad/s on
    # [0, π/dt] (its variance spread over the band; raildyn.random_vibration's convention), and the
    # PSD integrates back to the variance (Parseval).
    sigma, dt, n = 2.0, 0.01, 2**16
    x = sigma * _rng(5).standard_normal(n)
    est = welch_psd(x, dt, nperseg=1024)
    level = np.mean(est.psd[1:-1])
    # 127 half-overlapped segments, 511 bins: the mean level's relative standard error is about
    # 1/√(127·511/2) ≈ 0.6 % (neighbouring Hann bins are correlated); 3 % is five of them.
    assert level == pytest.approx(sigma**2 * dt / np.pi, rel=0.03)
    # Parseval against the sample variance of this record (not σ²): the Hann-windowed estimate and
    # the variance differ by the estimator's scatter, ≈ 0.6 % again; 3 %.
    assert est.mean_square == pytest.approx(np.var(x), rel=0.03)


def test_third_octave_band_edges_follow_iec_61260():
    # IEC 61260-1:2014 base 10: f_m = 1000·10^(3x/30) Hz, edges f_m·10^(∓3/60); 1000 Hz and the
    # decades are exact mid-band frequencies, and neighbouring bands share their edges.
    x = np.sin(2 * np.pi * 50.0 * np.arange(40000) * 2e-4)
    bands = third_octave_rms(x, 2e-4)
    for decade in (10.0, 100.0, 1000.0):
        assert np.min(np.abs(bands.centre_hz / decade - 1.0)) < 1e-12
    np.testing.assert_allclose(bands.upper_hz / bands.centre_hz, 10.0 ** (1 / 20), rtol=1e-12)
    np.testing.assert_allclose(bands.lower_hz[1:], bands.upper_hz[:-1], rtol=1e-12)
    np.testing.assert_allclose(bands.centre_hz[1:] / bands.centre_hz[:-1], 10.0**0.1, rtol=1e-12)
    # Every band lies below the Nyquist frequency and spans at least 4 bins of 1/(n dt).
    assert bands.upper_hz[-1] <= 0.5 / 2e-4
    assert (bands.upper_hz[0] - bands.lower_hz[0]) >= 4 / (40000 * 2e-4)


def test_third_octave_rms_of_tones_and_parseval():
    # Tones of amplitudes A_i at 10, 25 and 100 Hz (each on a Welch bin: Δf = 0.05 Hz) each put
    # A_i/√2 in their band and nothing elsewhere; together the bands hold the mean square
    # Σ A_i²/2 = mean x² (Parseval). With bin-centred tones the Hann periodogram is exact to rounding:
    # 1e-9 of the largest band.
    dt, n = 1e-3, 20000
    t = np.arange(n) * dt
    tones = {10.0: 1.0, 25.0: 0.5, 100.0: 2.0}
    x = sum(a * np.sin(2 * np.pi * f * t + f) for f, a in tones.items())
    bands = third_octave_rms(x, dt)
    expected = np.zeros(bands.rms.size)
    for f, a in tones.items():
        band = (bands.lower_hz <= f) & (f < bands.upper_hz)
        assert band.sum() == 1
        expected[band] = a / np.sqrt(2)
    np.testing.assert_allclose(bands.rms, expected, atol=1e-9 * 2.0)
    assert bands.mean_square == pytest.approx(np.mean(x**2), rel=1e-9)


def test_third_octave_rms_of_an_off_bin_tone():
    # A tone between bins (12.34 Hz, Δf = 0.05 Hz) leaks by the Hann window's side lobes, which fall
    # at 18 dB per octave: its band (11.2–14.1 Hz) reaches ≥ 17 bins either side of the tone, where
    # the lobes are below 1e-4 of the peak. Measured: the band holds the RMS to 5e-10 and the largest
    # neighbour 2.1e-5 of the amplitude; the bounds are 1e-6 and 1e-4.
    t = np.arange(20000) * 1e-3
    bands = third_octave_rms(3.0 * np.sin(2 * np.pi * 12.34 * t), 1e-3)
    i = int(np.argmax((bands.lower_hz <= 12.34) & (12.34 < bands.upper_hz)))
    assert bands.rms[i] == pytest.approx(3.0 / np.sqrt(2), rel=1e-6)
    assert np.delete(bands.rms, i).max() < 1e-4 * 3.0


def test_third_octave_rms_of_white_noise():
    # White noise of variance σ² has, in a band [f1, f2), the mean square σ²(f2 − f1)/f_Nyquist.
    # With one Hann segment the band sums ~N = (f2 − f1)/Δf periodogram bins; their scatter, with
    # Hann-correlated neighbours, is about √(2/N) of the band's mean square: the tolerance is 5 of it.
    sigma, dt, n = 1.5, 1e-3, 2**16
    x = sigma * _rng(6).standard_normal(n)
    bands = third_octave_rms(x, dt, f_min=20.0, f_max=300.0)
    width = bands.upper_hz - bands.lower_hz
    bins = width * n * dt
    expected = sigma**2 * width / (0.5 / dt)
    ratio = bands.rms**2 / expected
    assert np.all(np.abs(ratio - 1.0) < 5 * np.sqrt(2 / bins)), ratio
    assert bands.centre_hz[0] >= 20.0 and bands.centre_hz[-1] <= 300.0


def test_h1_of_noise_through_a_known_filter(reference):
    # Broadband noise through scipy.signal.lfilter (a 2nd-order Butterworth low-pass at 50 Hz): H1
    # equals the filter's frequency response from scipy.signal.freqz. Without output noise γ² ≈ 1
    # and the random error of |H1|, √(1 − γ²)/(|γ|√(2 n_d)) (Bendat & Piersol 2010, ch. 9), is below
    # 0.5 %; the Hann window's bias adds a little where |H| falls steeply: 2 % up to half Nyquist.
    dt, n = 1e-3, 2**16
    x = _rng(7).standard_normal(n)
    b, a = scipy.signal.butter(2, 50.0, fs=1 / dt)
    y = scipy.signal.lfilter(b, a, x)
    est = frequency_response_h1(x, y, dt, nperseg=1024)
    _, H = scipy.signal.freqz(b, a, worN=est.omega * dt)
    keep = (est.omega > 0) & (est.omega <= 2 * np.pi * 250.0)
    reference(
        11,
        "H1 estimate of noise through a Butterworth filter",
        "the filter's response (scipy freqz)",
        "scipy",
        (np.abs(est.h1[keep] - H[keep]) / np.abs(H[keep])).max(),
        0.02,
    )
    assert est.coherence[keep].min() > 0.99


def test_h1_is_unbiased_by_output_noise_and_the_coherence_follows():
    # Output noise of PSD S_n leaves H1 unbiased and lowers the coherence to
    # γ² = |H|² S_x/(|H|² S_x + S_n) (Bendat & Piersol 2010, ch. 6). Input and noise both white,
    # variances 1 and 0.25, H = 2 e^{−iω·3dt} (a gain and a 3-sample delay): γ² = 4/(4 + 0.25).
    dt, n = 1e-3, 2**17
    rng = _rng(8)
    x = rng.standard_normal(n)
    y = 2.0 * np.roll(x, 3) + 0.5 * rng.standard_normal(n)
    est = frequency_response_h1(x, y, dt, nperseg=512)
    H = 2.0 * np.exp(-1j * est.omega * 3 * dt)
    ratio = est.h1[1:-1] / H[1:-1]
    gamma2 = 4.0 / 4.25
    # The normalised random error of |H1| and of its phase (rad) is each
    # ε = √(1 − γ²)/(|γ|√(2 n_d)) (Bendat & Piersol 2010, ch. 9): ≈ 0.78 % with n_d = 511 segments,
    # so |H1/H − 1| has the RMS √2 ε. Measured 1.17 % against 1.10 %: the test allows ±25 % for the
    # scatter of an RMS over 255 bins and the overlap of the segments.
    eps = np.sqrt(1 - gamma2) / (np.sqrt(gamma2) * np.sqrt(2 * 511))
    assert np.sqrt(np.mean(np.abs(ratio - 1) ** 2)) == pytest.approx(np.sqrt(2) * eps, rel=0.25)
    # Unbiased: the mean of H1/H over 255 bins is 1 to within 3 of its standard errors (√2 ε/√255).
    assert abs(np.mean(ratio) - 1) < 3 * np.sqrt(2) * eps / np.sqrt(255)
    # The mean coherence over 255 bins has a standard error ~2(1 − γ²)/√(2·511·255) ≈ 2e-4 plus the
    # 1/n_d bias: 0.005.
    assert np.mean(est.coherence[1:-1]) == pytest.approx(gamma2, abs=0.005)


def test_coherence_of_independent_noise_is_near_zero():
    # Two independent records have coherence 0; its Welch estimate from n_d segments is biased up to
    # about 1/n_d (Bendat & Piersol 2010, ch. 9); half-overlapped Hann segments are slightly
    # correlated, so the effective n_d is a little smaller: the mean lies in [0.7, 1.5]/n_d.
    dt, n, nperseg = 1e-3, 2**16, 512
    rng = _rng(9)
    est = frequency_response_h1(rng.standard_normal(n), rng.standard_normal(n), dt, nperseg=nperseg)
    segments = (n - nperseg // 2) // (nperseg // 2)
    mean = np.mean(est.coherence[1:-1])
    assert 0.7 / segments < mean < 1.5 / segments


def test_frequency_results_plot():
    t = np.arange(8192) * 1e-3
    x = _rng(10).standard_normal(t.size)
    est = frequency_response_h1(x, 3.0 * x, 1e-3)
    artists = est.plot()
    np.testing.assert_allclose(artists["h1"].get_ydata(), 3.0, rtol=1e-9)
    bands = third_octave_rms(np.sin(2 * np.pi * 20 * t), 1e-3)
    assert bands.plot()["line"] is not None


# --------------------------------------------------------------------------- acceptance statistics


def test_percentiles_of_a_gaussian_record():
    # For a Gaussian record the 0.15 % and 99.85 % percentiles lie at ∓2.968σ (scipy.stats.norm.ppf).
    # The standard error of a sample quantile is √(p(1 − p)/n)/φ(z) (David & Nagaraja 2003, ch. 10):
    # 0.018σ here; the test allows 5 of them.
    n, sigma = 200_000, 3.0
    x = sigma * _rng(11).standard_normal(n)
    lo, hi = percentiles(x)
    z = scipy.stats.norm.ppf(0.9985)
    se = np.sqrt(0.0015 * 0.9985 / n) / scipy.stats.norm.pdf(z) * sigma
    assert lo == pytest.approx(-z * sigma, abs=5 * se)
    assert hi == pytest.approx(z * sigma, abs=5 * se)


def test_percentiles_of_a_ramp_are_exact():
    # A ramp of n + 1 equal steps from 0 to 1: the linear-interpolation percentile q is q/100 (rounding).
    x = np.linspace(0.0, 1.0, 1001)
    q = np.array([0.0, 0.15, 12.5, 50.0, 99.85, 100.0])
    np.testing.assert_allclose(percentiles(x, q), q / 100, atol=1e-12)


def test_sliding_rms_against_a_direct_loop():
    # An independent computation: the RMS of each window by a Python loop (rounding only: 1e-12).
    rng = _rng(12)
    x = 1e3 + rng.standard_normal(1000)  # a large mean: the running sum must not lose the small part
    spacing, window, step = 0.5, 25.0, 5.0
    r = sliding_rms(x, spacing, window, step=step)
    w, k = 50, 10
    starts = range(0, x.size - w + 1, k)
    direct = [np.sqrt(np.mean(x[s : s + w] ** 2)) for s in starts]
    np.testing.assert_allclose(r.rms, direct, rtol=1e-12)
    np.testing.assert_allclose(r.position, [(s + (w - 1) / 2) * spacing for s in starts], rtol=1e-12)
    assert r.window == window
    assert r.plot()["line"].get_xdata().size == len(direct)


def test_sliding_rms_of_a_sine_over_whole_periods():
    # Over a whole number of periods a sine of amplitude A has RMS A/√2 wherever the window starts.
    s = np.arange(4000) * 0.25  # every 0.25 m
    r = sliding_rms(2.0 * np.sin(2 * np.pi * s / 12.5), 0.25, 100.0)
    np.testing.assert_allclose(r.rms, np.sqrt(2.0), rtol=1e-12)


def test_section_maxima_against_a_direct_loop():
    rng = _rng(13)
    x = rng.standard_normal(1050)
    sm = section_maxima(x, 0.1, 10.0)  # sections of 100 samples; the 50-sample tail is left out
    sections = [x[i : i + 100] for i in range(0, 1000, 100)]
    assert sm.upper.tolist() == [max(s) for s in sections]
    assert sm.lower.tolist() == [min(s) for s in sections]
    np.testing.assert_allclose(sm.start, np.arange(10) * 10.0, rtol=1e-12)
    # The per-section percentiles of UIC 518 / EN 14363, the same rule as percentiles().
    sp = section_maxima(x, 0.1, 10.0, percent=(0.15, 99.85))
    for i, s in enumerate(sections):
        np.testing.assert_array_equal([sp.lower[i], sp.upper[i]], percentiles(s))
    artists = sp.plot()
    assert set(artists) == {"lower", "upper"}


# --------------------------------------------------------------------------- bad input


@pytest.mark.parametrize("function", [compare, sprague_geers, nrmse, correlation, theil_u])
def test_bad_records_are_refused_by_name(function):
    m = SINE[:100]
    with pytest.raises(ValueError, match="predicted must have as many samples as measured"):
        function(m, SINE[:99])
    with pytest.raises(ValueError, match="measured must not be empty"):
        function([], m)
    with pytest.raises(ValueError, match="measured must contain only finite"):
        function(np.where(np.arange(100) == 7, np.nan, m), m)
    with pytest.raises(ValueError, match="predicted must contain only finite"):
        function(m, np.where(np.arange(100) == 7, np.inf, m))
    with pytest.raises(ValueError, match="measured must be a 1-dimensional"):
        function(np.stack([m, m]), m)


def test_bad_time_bases_are_refused_by_name():
    m = SINE[:100]
    t = np.arange(100) * 0.01
    t[50] += 0.003  # one late sample: a non-uniform step
    for function in (compare, sprague_geers):
        with pytest.raises(ValueError, match="time must be uniformly spaced"):
            function(m, m, t)
        with pytest.raises(ValueError, match="time must hold one time per sample"):
            function(m, m, np.arange(99) * 0.01)
        with pytest.raises(ValueError, match="time must be"):
            function(m, m, -0.01)


def test_degenerate_records_are_refused_by_name():
    m = SINE[:100]
    with pytest.raises(ValueError, match="measured must not be constant"):
        correlation(np.full(100, 0.1), m)
    with pytest.raises(ValueError, match="predicted must not be zero"):
        sprague_geers(m, np.zeros(100))
    with pytest.raises(ValueError, match="measured must not have a zero range"):
        nrmse(np.ones(100), m)
    with pytest.raises(ValueError, match="normalisation must be one of"):
        nrmse(m, m, normalisation="max")
    with pytest.raises(ValueError, match="excitation must not be constant"):
        frequency_response_h1(np.zeros(100), m, 0.01)
    with pytest.raises(ValueError, match="excitation must not be constant"):
        frequency_response_h1(np.full(100, 0.1), m, 0.01)
    with pytest.raises(ValueError, match="response must have as many samples as excitation"):
        frequency_response_h1(m, m[:90], 0.01)
    with pytest.raises(ValueError, match="resolves no one-third-octave band"):
        third_octave_rms(m[:16], 0.01)
    with pytest.raises(ValueError, match="window must span 1 to 100 samples"):
        sliding_rms(m, 0.5, 60.0)
    with pytest.raises(ValueError, match="length must span"):
        section_maxima(m, 0.5, 0.1)
    with pytest.raises(ValueError, match="percent must be a pair"):
        section_maxima(m, 0.5, 5.0, percent=(99.85, 0.15))
    with pytest.raises(ValueError, match="percent must hold percentages"):
        percentiles(m, [101.0])
