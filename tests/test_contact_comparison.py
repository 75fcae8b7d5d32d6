"""Tests of raildyn.contact.comparison: every creep law on one sweep, equal to the laws called one by one."""

import dataclasses

import matplotlib.pyplot as plt
import numpy as np
import pytest

from raildyn import contact
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact import CREEP_LAWS, lateral_creep_curves

A, B, N, MU = 6e-3, 4e-3, 100e3, 0.3
ETA = np.linspace(0.0, 0.01, 41)


def test_each_curve_is_its_law_called_alone():
    c = lateral_creep_curves(ETA, N, MU, A, B, spin=0.3)
    f = contact.creep_coefficients(A, B)
    assert c.coefficients == f
    # The same calls with the same arguments: identical numbers.
    np.testing.assert_array_equal(c.kalker_linear, contact.kalker_linear(0.0, ETA, 0.3, f).fy)
    np.testing.assert_array_equal(c.carter, contact.carter(ETA, N, MU, f.f22))
    np.testing.assert_array_equal(c.johnson_vermeulen, contact.johnson_vermeulen(0.0, ETA, N, MU, A, B).fy)
    np.testing.assert_array_equal(
        c.shen_hedrick_elkins, contact.shen_hedrick_elkins(0.0, ETA, 0.3, N, MU, f).fy
    )
    np.testing.assert_array_equal(c.polach, contact.polach(0.0, ETA, 0.3, N, MU, A, B).fy)
    np.testing.assert_array_equal(c.fastsim, contact.fastsim(0.0, ETA, 0.3, N, MU, A, B, fields=False).fy)
    assert dataclasses.is_dataclass(c)
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.polach = None


def test_saturating_laws_stay_below_mu_n_and_start_on_kalker():
    c = lateral_creep_curves(np.array([1e-7, 0.05]), N, MU, A, B)
    lin = c.normalised("Kalker linear")
    # Johnson and Vermeulen start on their own line, G a b C22 with their C22 (not Kalker's).
    jv_slope = (
        STEEL_SHEAR_MODULUS * A * B * contact.johnson_vermeulen_coefficients(A / B, STEEL_POISSON_RATIO).c22
    )
    for label in CREEP_LAWS:
        if label == "Kalker linear":
            continue
        y = c.normalised(label)
        # Bounded by μN (FASTSIM's grid scales its pressure to sum exactly N: rounding only).
        assert y[1] <= 1.0 + 1e-12, label
        # At η = 1e-7, β ~ 1e-4: every law is on its linear law to O(β) (FASTSIM to its 0.125 %
        # grid error): Kalker's for all but Johnson–Vermeulen.
        start = jv_slope * 1e-7 / (MU * N) if label == "Johnson–Vermeulen" else lin[0]
        assert y[0] == pytest.approx(start, rel=2e-3), label


def test_johnson_vermeulen_and_she_part_at_zero_spin_by_their_coefficients():
    # With no spin, SHE is Kalker's linear force through the cubic u − u²/3 + u³/27, and
    # Johnson–Vermeulen is its own linear force through the same cubic (1 − (1 − χ)³, χ = u/3):
    # the curves differ exactly by the ratio of the creep coefficients, C22(JV)/C22(Kalker),
    # 1.13 here, so one law at creepage η is the other at r η (to rounding).
    c = lateral_creep_curves(ETA, N, MU, A, B)
    ratio = (
        contact.johnson_vermeulen_coefficients(A / B, STEEL_POISSON_RATIO).c22
        / c.coefficients.f22
        * (STEEL_SHEAR_MODULUS * A * B)
    )
    assert 1.1 < ratio < 1.2
    she_scaled = lateral_creep_curves(ratio * ETA, N, MU, A, B).shen_hedrick_elkins
    np.testing.assert_allclose(c.johnson_vermeulen, she_scaled, rtol=1e-12, atol=1e-9)
    # ...and so they are two curves, not one: 5.6 % of μN apart at η ≈ 3 ‰.
    gap = np.abs(c.normalised("Johnson–Vermeulen") - c.normalised("Shen–Hedrick–Elkins"))
    assert gap.max() > 0.05


def test_plot_draws_one_line_per_law_and_moves_them():
    c = lateral_creep_curves(ETA, N, MU, A, B)
    _, ax = plt.subplots()
    lines = c.plot(ax)
    assert list(lines) == list(CREEP_LAWS)
    np.testing.assert_allclose(lines["Polach"].get_ydata(), -c.polach / (MU * N), rtol=1e-15)
    spun = lateral_creep_curves(ETA, N, MU, A, B, spin=1.0)
    count = len(ax.lines)
    assert spun.plot(artists=lines) is lines and len(ax.lines) == count
    np.testing.assert_array_equal(lines["FASTSIM"].get_ydata(), spun.normalised("FASTSIM"))


def test_bad_input():
    with pytest.raises(ValueError, match="lateral must be >= 0"):
        lateral_creep_curves([-0.01, 0.0], N, MU, A, B)
    with pytest.raises(ValueError, match="friction"):
        lateral_creep_curves(ETA, N, 0.0, A, B)
    with pytest.raises(ValueError, match="label must be one of"):
        lateral_creep_curves(ETA, N, MU, A, B).normalised("Coulomb")
    with pytest.raises(ValueError, match="lateral must not be empty"):
        lateral_creep_curves([], N, MU, A, B)  # an empty sweep gave empty curves silently
    curves = lateral_creep_curves(ETA, N, MU, A, B)
    with pytest.raises(TypeError, match="label"):
        curves.normalised(None)
    with pytest.raises(TypeError, match="artists"):
        curves.plot(artists="lines")
    fields = {f.name: getattr(curves, f.name) for f in dataclasses.fields(curves)}
    with pytest.raises(ValueError, match="polach"):
        contact.LateralCreepCurves(**{**fields, "polach": curves.polach[:-1]})
