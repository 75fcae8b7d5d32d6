"""Tests for raildyn.ride: Sperling's ride index and the ISO 2631-1 weightings.

Tiers: published tables (ISO 2631-1:1997 table 3 weights; Sperling's correction
factor F(f) against the rational filter B(f)), closed forms (a harmonic's index),
an independent route (spectrum against history), properties and bad input.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import ride

# ISO 2631-1:1997, table 3 (weights ×1000, rounded to 3 digits).
ISO_WK = {0.5: 418, 1.0: 482, 2.0: 531, 4.0: 967, 8.0: 1036, 10.0: 988, 31.5: 405, 63.0: 186}
ISO_WD = {1.0: 1011, 2.0: 890, 4.0: 512, 8.0: 253, 16.0: 125, 31.5: 63}


@pytest.mark.parametrize(("name", "table"), [("Wk", ISO_WK), ("Wd", ISO_WD)])
def test_iso_weightings_match_table(name, table, reference):
    f = np.array(list(table))
    got = np.abs(ride.iso2631_weighting(f, name)) * 1000
    # the table is the same filters rounded to 3 significant digits: half a unit in the last digit
    np.testing.assert_allclose(got, list(table.values()), atol=0.51 + 1e-9, rtol=0.0015)
    worst = (np.abs(got - list(table.values())) / np.array(list(table.values()))).max()
    reference(
        6,
        f"ISO 2631 weighting {name}",
        "ISO 2631-1:1997 table 3 (3 digits)",
        "published",
        worst,
        0.0015 + 0.51 / 63,
    )


def test_sperling_filter_approximates_the_correction_factor():
    f = np.linspace(1.0, 10.0, 40)
    exact = (0.896**10 * ride.sperling_correction(f) / f) ** (1 / 3)
    # the rational B(f) is a smooth fit of Sperling's piecewise F(f): within 4 % from 1 to 10 Hz,
    # except near the corner of F at 5.9 Hz, which no smooth filter follows (7 % there)
    away = np.abs(f - 5.9) > 1.0
    np.testing.assert_allclose(ride.sperling_weighting(f[away]), exact[away], rtol=0.04)
    np.testing.assert_allclose(ride.sperling_weighting(f), exact, rtol=0.075)


@pytest.mark.parametrize("freq", [1.0, 2.5, 4.0, 8.0])
def test_harmonic_history_gives_sperling_index(freq):
    dt, n = 0.005, 2**15
    t = np.arange(n) * dt
    f = round(freq * n * dt) / (n * dt)  # a whole number of cycles: no leakage
    A = 0.3  # m/s² peak
    rq = ride.ride_quality_history(A * np.sin(2 * np.pi * f * t), dt)
    # Wz = (aB)^0.3 with B from the fit (≤ 4 % off F(f)) → index within 0.3 · 4 % ≈ 1.2 %
    assert rq.wz == pytest.approx(float(ride.sperling_harmonic(A, f)), rel=0.015)
    assert rq.rms == pytest.approx(A / np.sqrt(2), rel=1e-12)
    # ISO: |W_k(f)| times the RMS, exactly for a single line
    assert rq.iso_rms == pytest.approx(abs(ride.iso2631_weighting(f)) * A / np.sqrt(2), rel=1e-10)


def test_sperling_index_closed_form():
    # Wz = (100√2 σ_w)^0.3: σ_w = 1/(100√2) gives 1 exactly; 4.42 σ^0.3 otherwise
    assert ride.sperling_index(1 / (100 * np.sqrt(2))) == pytest.approx(1.0, rel=1e-14)
    assert ride.sperling_index(0.1) == pytest.approx(4.42 * 0.1**0.3, rel=1e-3)


@settings(max_examples=50, deadline=None)
@given(level=st.floats(1e-6, 1e-1), fc=st.floats(0.5, 20.0))
def test_property_spectrum_and_scaling(level, fc):
    w = np.linspace(0.1, 2 * np.pi * 80, 4000)
    S = level / (1 + (w / (2 * np.pi * fc)) ** 4)
    a = ride.ride_quality(S, w)
    b = ride.ride_quality(4 * S, w)
    # RMS doubles with 4× the PSD; Wz grows by 2^0.3
    assert b.rms == pytest.approx(2 * a.rms, rel=1e-12)
    assert b.wz == pytest.approx(2**0.3 * a.wz, rel=1e-12)
    # both weights are below 1.06 everywhere (table 3 maximum 1.054), so weighted <= 1.06 × rms
    assert a.iso_rms <= 1.06 * a.rms


def test_bad_input():
    with pytest.raises(ValueError, match="direction"):
        ride.sperling_weighting([1.0], "diagonal")
    with pytest.raises(ValueError, match="weighting"):
        ride.iso2631_weighting([1.0], "Wx")
    with pytest.raises(ValueError, match="frequency"):
        ride.sperling_correction([0.1])
    with pytest.raises(ValueError, match="weighted_rms"):
        ride.sperling_index(-1.0)
    with pytest.raises(ValueError, match="acceleration"):
        ride.ride_quality_history([1.0, 2.0], 0.01)
    with pytest.raises(ValueError, match="dt"):
        ride.ride_quality_history(np.ones(10), 0.0)
    with pytest.raises(TypeError, match="psd must be a number or an array"):
        ride.ride_quality("abc", np.linspace(0.0, 10.0, 5))  # was "could not convert string to float"
    with pytest.raises(ValueError, match=r"psd must have shape \(5\), got shape \(4,\)"):
        ride.ride_quality(np.ones(4), np.linspace(0.0, 10.0, 5))
    with pytest.raises(ValueError, match="psd must be >= 0"):
        ride.ride_quality(-np.ones(5), np.linspace(0.0, 10.0, 5))
    with pytest.raises(ValueError, match="frequency must not be empty"):
        ride.sperling_weighting([])
    with pytest.raises(TypeError, match="direction must be a string"):
        ride.sperling_harmonic(0.3, 4.0, None)
    with pytest.raises(ValueError, match="rms must be in"):
        ride.RideQuality(-0.1, 0.0, 0.0, 0.0)


def test_the_weightings_are_the_plain_quotients_and_stay_finite_far_up():
    f = np.array([0.0, 0.3, 1.0, 4.0, 12.5, 80.0, 400.0])
    s = 2j * np.pi * f
    w1, w2, w3, w4, w5, w6 = (2 * np.pi * x for x in (0.4, 100.0, 12.5, 12.5, 2.37, 3.35))
    q1 = 1 / np.sqrt(2)
    direct = (
        s**2 / (s**2 + w1 * s / q1 + w1**2)
        * w2**2 / (s**2 + w2 * s / q1 + w2**2)
        * (1 + s / w3) / (1 + s / (0.63 * w4) + (s / w4) ** 2)
        * (1 + s / (0.91 * w5) + (s / w5) ** 2) / (1 + s / (0.91 * w6) + (s / w6) ** 2) * (w5 / w6) ** 2
    )  # fmt: skip
    np.testing.assert_allclose(ride.iso2631_weighting(f, "Wk"), direct, rtol=1e-13, atol=1e-300)
    c, n1, n2, d1, d2, d3 = 0.588, 1.911, 0.25, 0.277, 1.563, 0.0368
    plain = c * np.sqrt((n1 * f**2 + (n2 * f**2) ** 2) / ((1 - d1 * f**2) ** 2 + (d2 * f - d3 * f**3) ** 2))
    np.testing.assert_allclose(ride.sperling_weighting(f), plain, rtol=1e-13)
    huge = np.array([1e6, 1e150, 1e300])
    for weight in (ride.sperling_weighting(huge), np.abs(ride.iso2631_weighting(huge, "Wd"))):
        assert np.all(np.isfinite(weight)) and np.all(np.diff(weight) <= 0)


def test_large_accelerations_stay_finite():
    # (a³F/f)^0.1 overflowed for a = 1e300; the index is a^0.3 (F/f)^0.1
    assert ride.sperling_harmonic(1e300, 4.0) == pytest.approx(
        ride.sperling_harmonic(0.3, 4.0) * (1e300 / 0.3) ** 0.3
    )
    t = np.arange(4000) * 0.005
    a = np.sin(2 * np.pi * 2.0 * t)
    small, large = ride.ride_quality_history(a, 0.005), ride.ride_quality_history(1e300 * a, 0.005)
    assert large.rms == pytest.approx(1e300 * small.rms, rel=1e-12)
    assert large.iso_rms == pytest.approx(1e300 * small.iso_rms, rel=1e-12)
