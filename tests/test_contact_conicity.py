"""Tests of raildyn.contact.conicity: EN 15302's equivalent conicity and the first-harmonic one.

Tiers: the standard's own reference cases (EN 15302 Annex E, within its Annex F tolerance);
closed forms (a cone, a step of Δr); an independent integration of the kinematic wheelset
equation; properties and bad input.
"""

import csv
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from raildyn import contact
from raildyn.contact import harmonic_conicity, kinematic_conicity

DATA = Path(__file__).resolve().parents[1] / "raildyn" / "contact" / "data"


def _annex_e():
    """{case: (y (m), Δr (m), ŷ (m), tan γ_e)} from the transcription of EN 15302 Annex E (data README)."""
    with open(DATA / "en15302_annex_e_delta_r.csv") as f:
        table = list(csv.DictReader(f))
    with open(DATA / "en15302_annex_e_conicity.csv") as f:
        refs = list(csv.DictReader(f))
    cases = {}
    for case in sorted({row["case"] for row in table}):
        y = 1e-3 * np.array([float(r["y_mm"]) for r in table if r["case"] == case])
        dr = 1e-3 * np.array([float(r["delta_r_mm"]) for r in table if r["case"] == case])
        amp = 1e-3 * np.array([float(r["amplitude_mm"]) for r in refs if r["case"] == case])
        lam = np.array([float(r["tan_gamma_e"]) for r in refs if r["case"] == case])
        cases[case] = (y, dr, amp, lam)
    return cases


ANNEX_E = _annex_e()


def _reach(y, dr):
    """The table's reach as the refusal states it (m)."""
    with pytest.raises(ValueError, match="reach of the table") as err:
        kinematic_conicity(y, dr, 1.0)
    return float(str(err.value).split("table, ")[1].split(" m")[0])


def test_annex_e_reference_cases_within_annex_f_tolerance(reference):
    # EN 15302 Annex E: nine reference Δr functions (E1–E4 symmetric, E5–E9 not) with tan γ_e
    # against ŷ; Annex F accepts ±min(0.05, 0.5 tan γ_e). Every amplitude whose motion the Δr
    # table holds is checked (the tables stop at about ±6.8 mm, the references at 7.5 mm).
    errors = []
    for case, (y, dr, amp, ref) in ANNEX_E.items():
        keep = amp <= _reach(y, dr) * (1 + 1e-9)
        assert keep.sum() >= 40, case  # at least 1.0 to 4.9 mm of each case
        lam = kinematic_conicity(y, dr, amp[keep])
        tol = np.minimum(0.05, 0.5 * ref[keep])
        worst = np.abs(lam - ref[keep]).max()
        share = np.max(np.abs(lam - ref[keep]) / np.where(tol > 0, tol, np.inf), initial=0.0)
        reference(4, f"EN 15302 equivalent conicity, case {case}", "EN 15302 Annex E", "published",
                  share, 1.0, unit="of Annex F's tolerance")  # fmt: skip
        assert np.all(np.abs(lam - ref[keep]) <= tol), (case, worst)
        errors.append(lam - ref[keep])
    errors = np.concatenate(errors)
    # Far inside the tolerance: the references are printed to 0.001 and the Δr tables to 1 µm on a
    # 0.1 mm grid, so the mean error is of the order of that rounding (largest, 0.006, in E5 at
    # ŷ ≈ 1.5 mm, where its Δr table has steps of 0.07 mm between neighbouring shifts).
    assert np.abs(errors).mean() < 1e-3
    assert np.abs(errors).max() < 0.01


def test_annex_e_flat_band_gives_zero_conicity():
    # E4's Δr is exactly zero over a band around the centre: the reference tan γ_e is 0 up to
    # ŷ = 1.8 mm (no steering, an infinite wavelength), and so is the kinematic value.
    y, dr, amp, ref = ANNEX_E["E4"]
    small = ref == 0.0
    assert small.sum() >= 5
    assert np.all(kinematic_conicity(y, dr, amp[small]) == 0.0)


def test_first_harmonic_is_not_en15302():
    # The quantity the package called EN 15302's equivalent conicity before was the first harmonic:
    # it leaves Annex F's tolerance on the cases with a jump of Δr (E3, E4) and on every asymmetric
    # one, where a sine about y = 0 is not the wheelset's motion at all.
    outside = {}
    for case, (y, dr, amp, ref) in ANNEX_E.items():
        keep = amp <= min(-y[0], y[-1])
        lam = harmonic_conicity(y, dr, amp[keep])
        outside[case] = int(np.sum(np.abs(lam - ref[keep]) > np.minimum(0.05, 0.5 * ref[keep])))
    assert all(outside[case] > 0 for case in ("E3", "E4", "E5", "E6", "E7", "E8", "E9")), outside


@pytest.mark.parametrize("centre", [0.0, 1.3e-3])
def test_cone_gives_its_slope_wherever_it_is_centred(centre):
    # Δr = 2λ(y − y₀) is a cone whose motion is centred on y₀: S is a parabola and the
    # integral is exact for a linear Δr, so λ_e = λ to rounding (1e-12).
    y = np.linspace(-0.01, 0.01, 41)
    amp = np.array([0.5e-3, 3e-3, 8.7e-3 - centre])
    np.testing.assert_allclose(kinematic_conicity(y, 2 * 0.05 * (y - centre), amp), 0.05, rtol=1e-12)


def test_step_of_delta_r_has_its_closed_form():
    # Δr = δ sign(y): S = δ|y|, C = δŷ, ∫ dy/√(C − S) = 4√(ŷ/δ), so λ_e = π²δ/(16ŷ); the first
    # harmonic is 2δ/(πŷ), 32/π³ = 1.032 times as large. The step is a ramp 2e-12 m wide: a
    # relative change of O(1e-12/ŷ) ≤ 1e-9.
    delta = 1e-3
    y = np.array([-0.01, -1e-12, 1e-12, 0.01])
    amp = np.array([1e-3, 4e-3, 9e-3])
    exact = np.pi**2 * delta / (16 * amp)
    np.testing.assert_allclose(kinematic_conicity(y, delta * np.sign(y), amp), exact, rtol=1e-9)
    harmonic = harmonic_conicity(
        np.linspace(-0.01, 0.01, 20001), delta * np.sign(np.linspace(-0.01, 0.01, 20001)), amp, samples=4096
    )
    np.testing.assert_allclose(harmonic / exact, 32 / np.pi**3, rtol=2e-3)  # 2e-3: the ramp of the grid


def _klingel_by_integration(y, dr, start, r0=0.46, e0=0.75):
    """λ_e and ŷ of the motion released at rest from y = start, by integrating y'' = −Δr(y)/(2 r₀ e₀).

    The wavelength is twice the distance run to the next turning point; ŷ is half the distance
    between the two turning points; λ_e from Klingel's L = 2π√(r₀ e₀/λ_e).
    """

    def rhs(x, state):
        return [state[1], -np.interp(state[0], y, dr) / (2 * r0 * e0)]

    def turning(x, state):
        return state[1]

    turning.terminal = True
    turning.direction = -1 if start < 0 else 1
    sol = solve_ivp(rhs, (0.0, 500.0), [start, 0.0], method="DOP853", rtol=1e-12, atol=1e-15, events=turning)
    half, other = sol.t_events[0][0], sol.y_events[0][0][0]
    return 4 * np.pi**2 * r0 * e0 / (2 * half) ** 2, 0.5 * abs(other - start)


@pytest.mark.parametrize(("case", "start"), [("E3", -3.0e-3), ("E7", -4.0e-3), ("E8", -6.5e-3)])
def test_agrees_with_an_integration_of_the_kinematic_equation(case, start):
    # An independent computation: the wheelset's kinematic equation integrated step by step
    # (DOP853, rtol 1e-12) through the tabulated Δr, its wavelength turned into λ_e by Klingel's
    # formula with r₀ = 0.46 m and e₀ = 0.75 m (which cancel). Asymmetric E7 and E8 also hold the
    # amplitude to the standard's meaning: half the peak-to-peak excursion. The step size
    # control across the kinks of the interpolated Δr limits the agreement to about 1e-7.
    y, dr, _, _ = ANNEX_E[case]
    lam, amp = _klingel_by_integration(y, dr, start)
    assert kinematic_conicity(y, dr, amp)[0] == pytest.approx(lam, rel=1e-6)


def test_profile_pair_uses_the_kinematic_method():
    # equivalent_conicity(wheel, rail) and the table method give EN 15302's value: for S1002 on
    # 60E1 1:40 the same Δr tabulated on two grids (801 shifts over ±5 mm, and 401 over ±10 mm)
    # agrees to the interpolation of Δr between them: S1002's Δr jumps by 0.5 mm within 0.5 mm of
    # the centre, which the coarser grid (0.05 mm) resolves less well, 2.5e-3 relative at ŷ = 1 mm.
    wheel, rail = contact.s1002_wheel(), contact.uic60_rail(1 / 40)
    amp = np.array([1e-3, 3e-3, 5e-3])
    lam = contact.equivalent_conicity(wheel, rail, amp)
    g = contact.contact_geometry(wheel, rail, np.linspace(-10e-3, 10e-3, 401))
    np.testing.assert_allclose(g.equivalent_conicity(amp), lam, rtol=3e-3)
    y = np.linspace(-5e-3, 5e-3, 801)
    dr = contact.rolling_radius_difference(wheel, rail, y)
    np.testing.assert_allclose(kinematic_conicity(y, 0.5 * (dr - dr[::-1]), amp), lam, rtol=1e-12)


def test_bad_input_is_refused_with_the_reason():
    y = np.linspace(-0.01, 0.01, 21)
    with pytest.raises(ValueError, match="delta_r must rise through zero"):
        kinematic_conicity(y, -0.1 * y, 2e-3)  # an unstable, negative conicity
    with pytest.raises(ValueError, match="delta_r must rise through zero"):
        kinematic_conicity(y, np.full(21, 1e-3), 2e-3)  # no zero crossing
    with pytest.raises(ValueError, match="amplitudes must lie within the reach of the table, 0.007"):
        kinematic_conicity(y, 0.1 * (y - 3e-3), 8e-3)  # centred at 3 mm: 7 mm either way
    with pytest.raises(ValueError, match="amplitudes must be > 0"):
        kinematic_conicity(y, 0.1 * y, [0.0])
    with pytest.raises(ValueError, match="shifts must be strictly increasing"):
        kinematic_conicity(y[::-1], 0.1 * y, 1e-3)
    with pytest.raises(ValueError, match="delta_r must have shape"):
        kinematic_conicity(y, 0.1 * y[:-1], 1e-3)
    # A cylinder steers nothing: λ_e = 0 (an infinite wavelength), as the first harmonic gives.
    assert kinematic_conicity(y, np.zeros(21), [1e-3, 1e-2]).tolist() == [0.0, 0.0]
