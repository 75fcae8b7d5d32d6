"""Tests for raildyn.track: deterministic inputs, the FRA and German spectra, synthesis, the view in time.

Tiers (ARCHITECTURE.md, "Tests"): closed forms (the spectra's formulas and asymptotes,
band variances against adaptive quadrature, V-scaling), the published parameter
tables (FRA classes, German levels; sources in raildyn/track/spectra.py),
Monte Carlo checks with tolerances from the estimators' statistics, hypothesis
properties, and bad input.
"""

import numpy as np
import pytest
import scipy.integrate
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import random_vibration as rv
from raildyn import track
from raildyn.track import (
    COMPONENTS,
    band_variance,
    bump,
    dipped_joints,
    fra_psd,
    german_psd,
    jointed_track,
    sinusoid,
    synthesize_irregularity,
    synthesize_track,
    track_psd,
    wavelength_band,
)

FRA_BAND = wavelength_band((1.524, 304.8))  # 5 ft to 1000 ft, the range the FRA spectra were fitted over
ALL = [("fra", g, c) for g in range(1, 7) for c in COMPONENTS] + [
    ("german", g, c) for g in ("low", "high") for c in COMPONENTS
]


# --------------------------------------------------------------------------- spectra: formulas and tables


# Hamid & Yang (1981) as tabulated by Garg & Dukkipati (1984) and Zhai (2020), written out again here
# in cm²·rad/m and rad/m, independently of the module's table.
FRA_TABLE = {
    1: (1.2107, 3.3634, 0.6046),
    2: (1.0181, 1.2107, 0.9308),
    3: (0.6816, 0.4128, 0.8520),
    4: (0.5376, 0.3027, 1.1312),
    5: (0.2095, 0.0762, 0.8209),
    6: (0.0339, 0.0339, 0.4380),
}
OMEGA = np.array([0.01, 0.1, 0.5, 0.8245, 2.0, 10.0])  # rad/m


@pytest.mark.parametrize("track_class", range(1, 7))
def test_fra_spectra_match_their_formulas(track_class):
    A_v, A_a, w_s = FRA_TABLE[track_class]
    k, w_c, w = 0.25, 0.8245, OMEGA
    to_m2 = 1e-4  # cm² → m²
    expected = {
        "vertical": k * A_v * w_c**2 / (w**2 * (w**2 + w_c**2)),
        "alignment": k * A_a * w_c**2 / (w**2 * (w**2 + w_c**2)),
        "cross_level": 4 * k * A_v * w_c**2 / ((w**2 + w_c**2) * (w**2 + w_s**2)),
        "gauge": 4 * k * A_v * w_c**2 / ((w**2 + w_c**2) * (w**2 + w_s**2)),
    }
    for component, values in expected.items():
        # the same rational function evaluated in a different order: a few roundings
        np.testing.assert_allclose(fra_psd(component, track_class, w), to_m2 * values, rtol=1e-13)


@pytest.mark.parametrize("level", ["low", "high"])
def test_german_spectra_match_their_formulas(level):
    # Zhai (2020, ch. 2): A_v, A_a in m·rad; cross-level angle scaled to a height difference by (2b)².
    A_v, A_a = {"low": (4.032e-7, 2.119e-7), "high": (1.080e-6, 6.125e-7)}[level]
    w_c, w_r, w_s, b, w = 0.8246, 0.0206, 0.4380, 0.75, OMEGA
    base = w_c**2 / ((w**2 + w_r**2) * (w**2 + w_c**2))
    np.testing.assert_allclose(german_psd("vertical", level, w), A_v * base, rtol=1e-13)
    np.testing.assert_allclose(german_psd("alignment", level, w), A_a * base, rtol=1e-13)
    angle = A_v / b**2 * base * w**2 / (w**2 + w_s**2)
    np.testing.assert_allclose(german_psd("cross_level", level, w), (2 * b) ** 2 * angle, rtol=1e-13)
    # gauge: A_g in m·rad (5.32e-8 low, 1.032e-7 high), as coded in the open function PowerSpectrum_German
    # (code index file id 54524734296) with the same A_v, A_a, Ω_c, Ω_r, Ω_s as Zhai (2020, ch. 2).
    A_g = {"low": 5.32e-8, "high": 1.032e-7}[level]
    gauge = A_g * w_c**2 * w**2 / ((w**2 + w_r**2) * (w**2 + w_c**2) * (w**2 + w_s**2))
    np.testing.assert_allclose(german_psd("gauge", level, w), gauge, rtol=1e-13)


def test_german_gauge_spectrum_at_its_peak_by_hand():
    # Ω²/((Ω²+Ω_r²)(Ω²+Ω_c²)(Ω²+Ω_s²)) with Ω_r ≪ Ω_s < Ω_c: at Ω = √(Ω_s Ω_c) the value is, to O(Ω_r²/Ω²)
    # ≈ 1e-3, A_g Ω_c/(Ω_s (Ω_s+Ω_c)²) (a few lines of algebra); it is the peak of the same approximation.
    w_c, w_s = 0.8246, 0.4380
    w = np.sqrt(w_s * w_c)
    for level, A_g in (("low", 5.32e-8), ("high", 1.032e-7)):
        peak = A_g * w_c / (w_s * (w_s + w_c) ** 2)
        assert german_psd("gauge", level, [w])[0] == pytest.approx(peak, rel=2e-3)
    # the high-disturbance gauge spectrum is 1.032e-7/5.32e-8 times the low one at every Ω
    np.testing.assert_allclose(
        german_psd("gauge", "high", OMEGA) / german_psd("gauge", "low", OMEGA), 1.032e-7 / 5.32e-8, rtol=1e-14
    )


def _slope(f, w1, w2):
    return np.log(f(w2) / f(w1)) / np.log(w2 / w1)


@pytest.mark.parametrize(("spectrum", "grade", "component"), ALL)
def test_spectra_asymptotic_slopes(spectrum, grade, component):
    f = track_psd(spectrum, component, grade)
    # Over a decade far above every corner (≤ 1.13 rad/m) the log–log slope is the power of Ω at infinity
    # to within (corner/Ω)² ≈ 1e-5: −4 for FRA profile/alignment and all cross-levels; −4 for German profile.
    assert _slope(f, 1e3, 1e4) == pytest.approx(-4.0, abs=1e-4)
    # Far below: FRA profile and alignment grow as Ω⁻², FRA cross-level/gauge and German profile/alignment
    # flatten (slope 0), the German cross-level falls as Ω² (its numerator Ω²). Corners ≥ 0.0206 rad/m.
    low = {"vertical": -2.0, "alignment": -2.0} if spectrum == "fra" else {"vertical": 0.0, "alignment": 0.0}
    expected = low.get(component, 0.0 if spectrum == "fra" else 2.0)
    assert _slope(f, 1e-7, 1e-6) == pytest.approx(expected, abs=1e-4)


def test_fra_classes_are_ordered_from_worst_to_best():
    # Class 1 is the roughest track: its profile spectrum lies above every better class at every Ω.
    values = np.array([fra_psd("vertical", c, OMEGA) for c in range(1, 7)])
    assert np.all(np.diff(values, axis=0) < 0)


def test_source_form_conversion_keeps_the_variance():
    # A spectrum quoted two-sided per cycles/m (as some sources do) becomes the raildyn form by convert_psd;
    # both integrate to the same variance over the band (trapezoid rule on fine matching grids).
    w = np.geomspace(*FRA_BAND, 20001)
    one = fra_psd("vertical", 4, w)
    two_cyc = rv.convert_psd(one, from_sided="one", from_unit="rad/m", to_sided="two", to_unit="cycles/m")
    n = w / (2 * np.pi)
    two_sided_variance = 2 * np.trapezoid(two_cyc, n)  # even density: both signs of n
    assert two_sided_variance == pytest.approx(np.trapezoid(one, w), rel=1e-12)
    back = rv.convert_psd(two_cyc, from_sided="two", from_unit="cycles/m", to_unit="rad/m")
    np.testing.assert_allclose(back, one, rtol=1e-14)


# --------------------------------------------------------------------------- band variances


@pytest.mark.parametrize(("spectrum", "grade", "component"), ALL)
def test_band_variance_closed_form_against_quadrature(spectrum, grade, component, reference):
    numeric, err = scipy.integrate.quad(
        track_psd(spectrum, component, grade), *FRA_BAND, epsabs=0, epsrel=1e-12, limit=500, points=[0.1, 1]
    )
    # adaptive quadrature to 1e-12 against partial fractions; allow 1e-10 for the nearly equal poles of
    # FRA class 5 (Ω_s = 0.8209 vs Ω_c = 0.8245), where the partial fractions lose ~3 digits.
    got = band_variance(spectrum, component, grade, FRA_BAND)
    track = f"FRA class {grade}" if spectrum == "fra" else f"German {grade}-disturbance"
    reference(
        3,
        f"band variance of the {component.replace('_', '-')} spectrum, {track} track",
        "adaptive quadrature (scipy)",
        "scipy",
        abs(got / numeric - 1),
        1e-10,
    )


def test_band_variance_of_class_4_profile_by_hand():
    # k A_v [1/Ω − atan(Ω/Ω_c)/Ω_c] between the band ends, evaluated here step by step (cm² → m²).
    lo, hi = FRA_BAND
    F = lambda w: -1 / w - np.arctan(w / 0.8245) / 0.8245  # noqa: E731
    expected = 0.25 * 0.5376e-4 * (F(hi) - F(lo))
    assert band_variance("fra", "vertical", 4, FRA_BAND) == pytest.approx(expected, rel=1e-14)


def test_band_variance_scales_with_k():
    # the FRA spectra are linear in k; the German ones ignore it
    half = band_variance("fra", "gauge", 2, FRA_BAND, k=0.125)
    assert half == pytest.approx(0.5 * band_variance("fra", "gauge", 2, FRA_BAND), rel=1e-14)
    assert fra_psd("vertical", 2, [0.3], k=1.0)[0] == pytest.approx(
        4 * fra_psd("vertical", 2, [0.3])[0], rel=1e-14
    )


def test_results_plot_themselves():
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.subplots()
    sample = synthesize_irregularity(track_psd("fra", "vertical", 3), 200.0, 0.5, (2.0, 100.0), rng=0)
    art = sample.plot(ax=ax)
    np.testing.assert_allclose(art["line"].get_ydata(), 1e3 * sample.z)
    axes = Figure().subplots(2, 1)
    lines = synthesize_track("fra", 3, 200.0, 0.5, (2.0, 100.0), rng=0).plot(axes)
    assert set(lines) == {"left_vertical", "right_vertical", "left_lateral", "right_lateral"}


def test_band_variance_limit_of_equal_poles():
    # The double-pole branch (a = b) must agree with the partial fractions just off it.
    from raildyn.track.spectra import _int_two_lorentz

    w = np.array([0.3, 2.0])
    a = 0.8
    near = _int_two_lorentz(w, a, a * (1 + 1e-5))
    np.testing.assert_allclose(_int_two_lorentz(w, a, a), near, rtol=1e-4)  # first-order in the 1e-5 split


# --------------------------------------------------------------------------- synthesis


@pytest.mark.parametrize(("spectrum", "grade", "component"), [ALL[3 * 4], ALL[-1], ALL[5 * 4 + 2]])
def test_sample_variance_equals_the_band_integral(spectrum, grade, component):
    psd = track_psd(spectrum, component, grade)
    sample = synthesize_irregularity(psd, 5000.0, 0.25, (1.524, 304.8), rng=3)
    # Parseval: the mean square over the record is the sum of the line variances (round-off only) ...
    assert np.mean(sample.z**2) == pytest.approx(sample.variance, rel=1e-10)
    # ... and the lines carry the cell integrals of S clipped to the band: 8-point Gauss–Legendre per cell,
    # whose error on these rational spectra is far below 1e-8.
    assert sample.variance == pytest.approx(band_variance(spectrum, component, grade, sample.band), rel=1e-8)


def test_ensemble_variance_at_a_point_matches_the_spectrum():
    # Across N independent samples, z at one point is (nearly) Gaussian with variance σ²; the estimator
    # of σ² then has standard deviation σ²√(2/N). Allow 4 standard deviations.
    psd = track_psd("fra", "alignment", 3)
    N = 2000
    sample = synthesize_irregularity(psd, 500.0, 0.5, (2.0, 250.0), rng=11, n_samples=N)
    estimate = np.mean(sample.z[:, 123] ** 2)
    assert abs(estimate - sample.variance) < 4 * sample.variance * np.sqrt(2 / N)


def test_welch_estimate_of_a_long_sample_follows_the_spectrum():
    psd = track_psd("german", "vertical", "high")
    dx = 0.25
    sample = synthesize_irregularity(psd, 40_000.0, dx, (1.0, 200.0), rng=5)
    estimate = rv.welch_psd(sample.z, dx, nperseg=4096)  # space: rad/m instead of rad/s
    w, s = estimate.omega, estimate.psd
    keep = (w > 0.2) & (w < 5.0)  # well inside the band, away from its edges and the window's leakage
    ratio = s[keep] / psd(w[keep])
    # ~19 half-overlapping segments: each Welch value has a relative standard deviation near 1/√10;
    # the mean of the ratio over ~600 bins scatters far less. Check both the mean and every bin.
    assert np.mean(ratio) == pytest.approx(1.0, abs=0.05)
    assert np.all((ratio > 0.2) & (ratio < 3.0))


def test_same_seed_same_sample_and_different_seed_different_sample():
    psd = track_psd("fra", "vertical", 5)
    a = synthesize_irregularity(psd, 1000.0, 0.25, (2.0, 300.0), rng=42)
    b = synthesize_irregularity(psd, 1000.0, 0.25, (2.0, 300.0), rng=42)
    c = synthesize_irregularity(psd, 1000.0, 0.25, (2.0, 300.0), rng=43)
    np.testing.assert_array_equal(a.z, b.z)
    assert not np.allclose(a.z, c.z)


def test_two_rail_sample_is_consistent():
    t = synthesize_track("fra", 4, 2000.0, 0.25, (1.524, 304.8), rng=7)
    # the rails give back the sampled cross-level and gauge (one subtraction: round-off)
    np.testing.assert_allclose(t.left_vertical - t.right_vertical, t.cross_level, atol=1e-15)
    np.testing.assert_allclose(t.left_lateral - t.right_lateral, t.gauge, atol=1e-15)
    np.testing.assert_allclose(0.5 * (t.left_vertical + t.right_vertical), t.vertical, atol=1e-15)
    for name in COMPONENTS:
        assert np.mean(getattr(t, name) ** 2) == pytest.approx(getattr(t.variances, name), rel=1e-10)
    # independent components: the sample correlation of 8000 points of long-wavelength processes is small
    # but not tiny (few independent wavelengths per record); 0.3 is far above its spread here.
    assert abs(np.corrcoef(t.vertical, t.cross_level)[0, 1]) < 0.3
    g = synthesize_track("german", "low", 2000.0, 0.25, (1.524, 304.8), rng=7)
    np.testing.assert_allclose(g.left_lateral - g.right_lateral, g.gauge, atol=1e-15)
    for name in COMPONENTS:
        assert np.mean(getattr(g, name) ** 2) == pytest.approx(getattr(g.variances, name), rel=1e-10)
    # the German gauge is sampled from its spectrum: its variance is the band integral of S_g (this band
    # lies on the grid, so it is the sampled band; 8-point Gauss–Legendre per cell as in
    # test_sample_variance_equals_the_band_integral, error far below 1e-8) and is not zero
    band = wavelength_band((1.524, 304.8))
    assert g.variances.gauge > 0
    assert g.variances.gauge == pytest.approx(band_variance("german", "gauge", "low", band), rel=1e-8)


@settings(deadline=None, max_examples=40)
@given(
    seed=st.integers(0, 2**32 - 1),
    grade=st.integers(1, 6),
    component=st.sampled_from(COMPONENTS),
    shortest=st.floats(0.5, 5.0),
    longest=st.floats(20.0, 400.0),
)
def test_property_sample_mean_square_is_the_band_variance(seed, grade, component, shortest, longest):
    sample = synthesize_irregularity(
        track_psd("fra", component, grade), 400.0, 0.25, (shortest, longest), seed
    )
    assert np.mean(sample.z**2) == pytest.approx(sample.variance, rel=1e-9)
    assert sample.variance == pytest.approx(band_variance("fra", component, grade, sample.band), rel=1e-8)


# --------------------------------------------------------------------------- space to time


@settings(deadline=None, max_examples=50)
@given(speed=st.floats(1.0, 100.0), grade=st.integers(1, 6))
def test_speed_scaling_conserves_the_variance(speed, grade):
    w_space = np.geomspace(*FRA_BAND, 4001)
    s_space = fra_psd("alignment", grade, w_space)
    in_time = track.spatial_to_temporal(s_space, w_space, speed)
    w_time, s_time = in_time.omega, in_time.psd
    # ω = VΩ and S_t = S/V: the trapezoid sums are the same numbers scaled by V and 1/V (round-off)
    assert rv.mean_square(s_time, w_time) == pytest.approx(rv.mean_square(s_space, w_space), rel=1e-12)
    callable_t = track.temporal_psd(track_psd("fra", "alignment", grade), speed)
    np.testing.assert_allclose(callable_t(w_time), s_time, rtol=1e-13)


def test_excitation_csd_has_the_wheelbase_filter():
    # Two axles 2.5 m apart at 30 m/s: their mean cancels where ωτ = π, i.e. at the wavelength 2 × 2.5 m.
    V, d = 30.0, 2.5
    psd = track_psd("fra", "vertical", 4)
    omega = np.array([np.pi * V / d, 0.5 * np.pi * V / d])
    csd = track.excitation_csd(psd, omega, [0.0, d], V)
    mean = rv.response_psd(np.full((2, 1, 2), 0.5), csd)[:, 0, 0].real
    s_t = track.temporal_psd(psd, V)(omega)
    assert mean[0] == pytest.approx(0.0, abs=1e-14 * s_t[0])
    assert mean[1] == pytest.approx(s_t[1] * np.cos(0.5 * omega[1] * d / V) ** 2, rel=1e-12)
    np.testing.assert_allclose(track.axle_delays([1.0, 3.5, 18.0], 25.0), [0.0, 0.1, 0.68], rtol=1e-14)


# --------------------------------------------------------------------------- deterministic inputs


def test_dipped_joint_is_continuous_with_a_cusp_at_the_joint():
    L, depth, a = track.RAIL_LENGTH, 0.008, 1.5
    h = 1e-7
    x = np.array([0.0, a, L - a, L])
    z_left = dipped_joints(x - h, depth, a)
    z_right = dipped_joints(x + h, depth, a)
    # the profile is continuous everywhere: jumps of O(slope·h) only
    np.testing.assert_allclose(z_left, z_right, atol=3 * 2 * depth / a * h)
    # the slope is continuous at the edges of the dip (zero there) ...
    s = lambda y: dipped_joints(y, depth, a, derivative=1)  # noqa: E731
    assert s(np.array([a - h, a + h])) == pytest.approx([0.0, 0.0], abs=1e-9)
    # ... and jumps by 4δ/a at the joint (the cusp)
    assert s(np.array([h]))[0] - s(np.array([-h]))[0] == pytest.approx(4 * depth / a, rel=1e-6)
    # periodic with the rail length, deepest at the joint
    xs = np.linspace(-3, 3, 61)
    np.testing.assert_allclose(dipped_joints(xs, depth, a), dipped_joints(xs + 5 * L, depth, a), atol=1e-15)
    assert dipped_joints(0.0, depth, a) == pytest.approx(-depth)


@pytest.mark.parametrize(
    ("profile", "kwargs"),
    [
        (dipped_joints, {"depth": 0.01, "half_width": 2.0}),
        (bump, {"height": 0.02, "length": 3.0, "position": 1.0}),
        (sinusoid, {"amplitude": 0.004, "wavelength": 17.0, "phase": 0.3}),
    ],
    ids=["joints", "bump", "sinusoid"],
)
def test_derivatives_match_finite_differences(profile, kwargs):
    # away from the points where a derivative jumps; central differences with h = 1e-5: error O(h²·z''')
    x = np.array([0.37, 1.2, 2.9, 3.3, 5.1, 9.0])
    h = 1e-5
    for order in (1, 2):
        fd = (
            profile(x + h, **kwargs, derivative=order - 1) - profile(x - h, **kwargs, derivative=order - 1)
        ) / (2 * h)
        np.testing.assert_allclose(profile(x, **kwargs, derivative=order), fd, rtol=1e-6, atol=1e-9)


def test_staggered_and_in_phase_joints():
    L = 11.9
    x = np.linspace(0.0, 3 * L, 2001)
    staggered = jointed_track(x, 0.01, 2.0, arrangement="staggered")
    in_phase = jointed_track(x, 0.01, 2.0, arrangement="in_phase")
    np.testing.assert_array_equal(in_phase.cross_level, 0.0)
    # staggered: the right rail is the left one shifted by L/2, so the cross-level is odd under that shift
    np.testing.assert_allclose(staggered.right, dipped_joints(x - L / 2, 0.01, 2.0), atol=1e-15)
    assert staggered.cross_level.min() == pytest.approx(
        -0.01
    ) and staggered.cross_level.max() == pytest.approx(0.01)
    assert track.passing_frequency(119.0 / 3.6) == pytest.approx(119.0 / 3.6 / 11.9)


def test_bump_is_smooth_and_has_its_height():
    x = np.array([-1.0, 0.0, 1.5, 3.0, 4.0])
    z = bump(x, 0.02, 3.0)
    np.testing.assert_allclose(z, [0.0, 0.0, 0.02, 0.0, 0.0], atol=1e-15)
    assert bump(np.array([0.0, 3.0]), 0.02, 3.0, derivative=1) == pytest.approx([0.0, 0.0], abs=1e-15)


# --------------------------------------------------------------------------- bad input


@pytest.mark.parametrize("bad", [0, 7, -1])
def test_bad_fra_class(bad):
    with pytest.raises(ValueError, match=r"track_class must be an integer in \[1, 6\]"):
        fra_psd("vertical", bad, [1.0])


@pytest.mark.parametrize("bad", [2.0, "4", True, None])
def test_fra_class_of_the_wrong_type(bad):
    with pytest.raises(TypeError, match="track_class must be an integer"):
        fra_psd("vertical", bad, [1.0])


@pytest.mark.parametrize("bad", [0, 4.5, "medium", None])
def test_a_bad_grade_is_blamed_on_grade(bad):
    # issue 15: band_variance and track_psd named track_class (or level), a parameter the caller never set
    for spectrum in ("fra", "german"):
        with pytest.raises((ValueError, TypeError), match=r"^grade must be"):
            band_variance(spectrum, "vertical", bad, (0.1, 1.0))
        with pytest.raises((ValueError, TypeError), match=r"^grade must be"):
            track_psd(spectrum, "vertical", bad)


def test_bad_component_level_and_wavenumber():
    with pytest.raises(ValueError, match="component must be one of"):
        fra_psd("twist", 3, [1.0])
    with pytest.raises(ValueError, match="component must be one of"):
        german_psd("twist", "low", [1.0])
    with pytest.raises(ValueError, match=r"level must be one of \['high', 'low'\]"):
        german_psd("vertical", "medium", [1.0])
    with pytest.raises(TypeError, match="component must be a string"):
        fra_psd(None, 3, [1.0])
    with pytest.raises(ValueError, match="wavenumber must be > 0"):
        fra_psd("vertical", 3, [1.0, -0.5])
    with pytest.raises(ValueError, match="wavenumber must be > 0"):
        german_psd("vertical", "low", [0.0])
    with pytest.raises(ValueError, match="finite"):
        fra_psd("vertical", 3, [np.nan])
    with pytest.raises(ValueError, match=r"spectrum must be one of \['fra', 'german'\]"):
        track_psd("sncf", "vertical", 1)
    with pytest.raises(ValueError, match="wavenumber must not be empty"):
        fra_psd("vertical", 3, [])
    with pytest.raises(ValueError, match=r"k must be in \(0.0, 1.0\]"):
        fra_psd("vertical", 3, [1.0], k=2.0)


@pytest.mark.parametrize(
    "band, error",
    [((5.0, 5.0), ValueError), ((10.0, 2.0), ValueError), ((0.0, 10.0), ValueError), ((1.0,), ValueError),
     ("band", TypeError), ((1.0, np.inf), ValueError)],
)  # fmt: skip
def test_empty_or_bad_band(band, error):
    psd = track_psd("fra", "vertical", 4)
    with pytest.raises(error, match="wavelength_band"):
        synthesize_irregularity(psd, 1000.0, 0.25, band, rng=1)


def test_band_outside_the_record():
    psd = track_psd("fra", "vertical", 4)
    with pytest.raises(ValueError, match="Nyquist"):
        synthesize_irregularity(psd, 1000.0, 0.25, (0.3, 100.0), rng=1)
    with pytest.raises(ValueError, match="exceeds the record length"):
        synthesize_irregularity(psd, 100.0, 0.25, (1.0, 300.0), rng=1)
    with pytest.raises(ValueError, match="band must satisfy"):
        band_variance("fra", "vertical", 4, (1.0, 0.5))
    with pytest.raises(ValueError, match="speed must be in"):
        track.spatial_to_temporal([1.0], [1.0], 0.0)


def test_bad_deterministic_input():
    with pytest.raises(ValueError, match="half_width must be in"):
        dipped_joints([0.0], 0.01, 7.0)  # more than half of 11.9 m
    with pytest.raises(ValueError, match="depth must be in"):
        dipped_joints([0.0], -0.01, 1.0)
    with pytest.raises(ValueError, match=r"derivative must be an integer in \[0, 2\]"):
        bump([0.0], 0.01, 1.0, derivative=3)
    with pytest.raises(TypeError, match="derivative must be an integer"):
        bump([0.0], 0.01, 1.0, derivative=1.0)
    with pytest.raises(ValueError, match=r"speed must be in \(0.0, 200.0\]"):
        sinusoid([0.0], 0.01, 1.0, derivative=2, speed=1e300)  # V² would overflow
    with pytest.raises(ValueError, match="x must not be empty"):
        dipped_joints([], 0.01, 1.0)
    with pytest.raises(ValueError, match="arrangement must be"):
        jointed_track([0.0], 0.01, 1.0, arrangement="random")
    with pytest.raises(ValueError, match="wavelength must be in"):
        sinusoid([0.0], 0.01, 0.0)


def test_harmonic_amplitudes_of_a_sum_of_sinusoids():
    x = np.arange(256) / 256
    profile = 0.004 * np.cos(2 * np.pi * x) + 0.001 * np.sin(2 * np.pi * 5 * x + 0.3)
    # A DFT of a whole number of periods separates the harmonics exactly (to rounding, 1e-15 m).
    assert np.allclose(track.harmonic_amplitudes(profile, 6), [0.004, 0, 0, 0, 0.001, 0], atol=1e-15)


def test_harmonic_amplitudes_bad_count():
    with pytest.raises(ValueError, match="count"):
        track.harmonic_amplitudes(np.zeros(8), 4)


# --------------------------------------------------------------------------- rates in time, filters, results


@pytest.mark.parametrize(
    ("profile", "kwargs"),
    [
        (bump, {"height": 0.01, "length": 4.0, "position": 5.0}),
        (sinusoid, {"amplitude": 0.003, "wavelength": 8.0}),
        (dipped_joints, {"depth": 0.008, "half_width": 2.0}),
    ],
)
def test_rates_in_time_are_speed_powers_times_the_derivatives_along_x(profile, kwargs):
    x = np.linspace(0.0, 20.0, 801)
    V = 20.0
    for order in (0, 1, 2):
        along = profile(x, **kwargs, derivative=order)
        # d^k z/dt^k = V^k d^k z/dx^k: one multiplication, exact to rounding.
        np.testing.assert_allclose(
            profile(x, **kwargs, derivative=order, speed=V), V**order * along, rtol=1e-15
        )
    with pytest.raises(ValueError, match="speed must be in"):
        profile(x, **kwargs, derivative=1, speed=0.0)


def test_largest_vertical_velocity_on_a_bump_is_pi_h_v_over_length():
    x = np.linspace(0.0, 20.0, 8001)  # the peak of sin at x = 6 m lies on the grid
    rate = bump(x, -0.01, 4.0, position=5.0, derivative=1, speed=20.0)
    # dz/dt = V (h/2)(2π/ℓ) sin(2π(x − x₀)/ℓ): largest πhV/ℓ, reached on the grid (rounding only).
    assert np.abs(rate).max() == pytest.approx(np.pi * 0.01 * 20.0 / 4.0, rel=1e-12)


def test_passing_speed_inverts_passing_frequency():
    for n in (1, 2, 3):
        V = track.passing_speed(0.9, harmonic=n)
        # harmonic n is met at n V/L = 0.9 Hz (a product and a quotient: rounding)
        assert n * track.passing_frequency(V) == pytest.approx(0.9, rel=1e-15)
    with pytest.raises(ValueError, match="harmonic"):
        track.passing_speed(0.9, harmonic=0)


def test_axle_filter_wavelengths_are_the_zeros_of_the_two_axle_mean():
    d, V = 2.5, 120 / 3.6
    lam = track.axle_filter_wavelengths(d, 4)
    np.testing.assert_allclose(lam, [5.0, 5 / 3, 1.0, 5 / 7], rtol=1e-15)
    # The same zeros in time: ω = 2πV/λ are the cancellation frequencies of τ = d/V.
    np.testing.assert_allclose(2 * np.pi * V / lam, rv.cancellation_frequencies(d / V, 4), rtol=1e-14)
    with pytest.raises(ValueError, match="axle_spacing"):
        track.axle_filter_wavelengths(-1.0, 2)


def test_two_rail_sample_reports_rms_by_component():
    import dataclasses

    t = synthesize_track("german", "high", 1000.0, 0.25, (3.0, 150.0), rng=1)
    assert dataclasses.is_dataclass(t.variances) and not isinstance(t.variances, dict)
    for name in COMPONENTS:
        assert t.rms(name) == pytest.approx(np.sqrt(getattr(t.variances, name)), rel=1e-15)
        # the sample's mean square is its band variance (Parseval over the record: round-off)
        assert t.measured_rms(name) == pytest.approx(t.rms(name), rel=1e-9)
    with pytest.raises(ValueError, match="component must be one of"):
        t.rms("twist")
    s = synthesize_irregularity(
        track_psd("fra", "vertical", 4), 500.0, 0.25, (2.0, 100.0), rng=3, n_samples=2
    )
    assert s.measured_rms == pytest.approx(s.rms, rel=1e-9)


def test_spatial_to_temporal_gives_a_spectrum():
    s = track.spatial_to_temporal([2.0, 2.0, 2.0], [0.0, 0.5, 1.0], 10.0)
    assert isinstance(s, rv.Spectrum)
    # ∫ S_t dω = ∫ S dΩ: S = 2 on [0, 1] rad/m becomes S_t = 0.2 on [0, 10] rad/s; both sums are 2.
    assert s.mean_square == pytest.approx(2.0, rel=1e-15)


def test_jointed_track_plot_draws_and_moves_its_lines():
    import matplotlib.pyplot as plt

    x = np.linspace(0.0, 3 * 11.9, 600)
    staggered = jointed_track(x, 0.008, 2.0, arrangement="staggered")
    _, ax = plt.subplots()
    art = staggered.plot(ax)
    assert set(art) == {"left", "right", "cross_level"}
    np.testing.assert_allclose(art["cross_level"].get_ydata(), 1e3 * staggered.cross_level, rtol=1e-15)
    in_phase = jointed_track(x, 0.008, 2.0, arrangement="in_phase")
    assert in_phase.plot(artists=art) is art and len(ax.lines) == 3
    np.testing.assert_array_equal(art["cross_level"].get_ydata(), 0.0)


# --------------------------------------------------------------------------- issue 15: callbacks and results


def _vertical(w):
    return fra_psd("vertical", 4, w)


@pytest.mark.parametrize(
    ("callback", "message"),
    [
        (lambda w: np.full_like(np.asarray(w, dtype=float), np.nan), "psd returned a non-finite value"),
        (lambda w: -_vertical(w), "psd must return values >= 0"),
        (lambda w: np.stack([_vertical(w), _vertical(w)]), "psd must return an array of shape"),
    ],
    ids=["nan", "negative", "shape"],
)
def test_a_spectrum_callback_is_checked_where_it_is_used(callback, message):
    # issue 15: a callback returning NaN or a negative spectrum passed straight through temporal_psd
    with pytest.raises(ValueError, match=message):
        track.temporal_psd(callback, 30.0)
    with pytest.raises(ValueError, match=message):
        track.excitation_csd(callback, [1.0, 5.0], [0.0, 2.5], 30.0)
    with pytest.raises(ValueError, match=message):
        synthesize_irregularity(callback, 100.0, 1.0, (2.0, 50.0), rng=1)


def test_temporal_psd_checks_every_later_call_too():
    calls = []

    def breaks_later(w):  # fine at the first call, negative afterwards
        calls.append(1)
        return _vertical(w) * (1 if len(calls) == 1 else -1)

    in_time = track.temporal_psd(breaks_later, 30.0)
    with pytest.raises(ValueError, match="psd must return values >= 0"):
        in_time(np.array([1.0, 2.0]))
    with pytest.raises(TypeError, match="psd must be a callable"):
        track.temporal_psd(1.0, 30.0)


def test_results_are_validated():
    x = np.arange(8.0)
    with pytest.raises(ValueError, match="variance must be in"):
        track.IrregularitySample(x, np.zeros(8), (0.1, 1.0), -1.0)
    with pytest.raises(ValueError, match=r"z must have shape \(8,\) or \(n_samples, 8\)"):
        track.IrregularitySample(x, np.zeros(7), (0.1, 1.0), 1.0)
    with pytest.raises(ValueError, match="x must be strictly increasing"):
        track.IrregularitySample(np.zeros(8), np.zeros(8), (0.1, 1.0), 1.0)
    with pytest.raises(ValueError, match="gauge must be in"):
        track.ComponentVariances(1.0, 1.0, 1.0, -1.0)
    with pytest.raises(ValueError, match="left must have the shape of x"):
        track.JointedTrack(x, np.zeros(7), np.zeros(8), "staggered")
    with pytest.raises(TypeError, match="arrangement must be a string"):
        track.JointedTrack(x, np.zeros(8), np.zeros(8), None)


def test_large_values_stay_finite_or_are_refused():
    # the cross-level and gauge spectra at an overflowing Ω²: 0, not inf/inf
    for component in COMPONENTS:
        assert np.all(german_psd(component, "high", [1e200, 1.0]) >= 0)
        assert german_psd(component, "high", [1e200])[0] == 0.0
        assert fra_psd(component, 1, [1e200])[0] == 0.0
    with pytest.raises(ValueError, match="n_samples × length/dx must be at most"):
        synthesize_irregularity(_vertical, 1e300, 1.0, (2.0, 50.0), rng=1)
    with pytest.raises(ValueError, match=r"count must be an integer in \[1, 1000000\]"):
        track.axle_filter_wavelengths(2.5, 10**12)
    with pytest.raises(ValueError, match="one_period must hold at least 3 samples"):
        track.harmonic_amplitudes([], 1)
