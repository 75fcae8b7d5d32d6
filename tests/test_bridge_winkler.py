"""The infinite beam on a Winkler foundation under a moving force (raildyn.bridge.winkler): Hetényi's static
deflection, the closed form against the Fourier integral of the same equation, the critical speed, and the
foundation carrying the whole load."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from raildyn.bridge.winkler import WinklerBeam

P = 1.0e5
RAIL = WinklerBeam()
# The rail's critical speed on its ballasted bed, 770 m/s, lies far above the speeds raildyn accepts
# (raildyn.constants.MAXIMUM_SPEED, 200 m/s), so the moving force runs on the same rail over a bed
# S⁴ = 20736 times softer: v_cr/S = 64 m/s, and the characteristic length S times as long. In the
# module docstring's dimensionless form (x β, v/v_cr and ζ) it is the same problem, so each test keeps
# its ratios, its damping ratios ζ (c scaled by 1/S²) and its points x β (x scaled by S).
S = 12.0
SOFT = WinklerBeam(foundation_modulus=RAIL.foundation_modulus / S**4)


def soft(damping):
    """The soft beam with the damping ratio the rail has with ``damping`` (N·s/m²) on its own bed."""
    return WinklerBeam(foundation_modulus=SOFT.foundation_modulus, damping=damping / S**2)


def fourier(beam, x, speed, force):
    """w(x) = (1/2π) ∫ P e^{iξx}/D(ξ) dξ, D(ξ) = EIξ⁴ − m v² ξ² − i c v ξ + k, by scipy's quad.

    The equation EI w'''' + m v² w'' − c v w' + k w = P δ(x) transformed term by term (w ∝ e^{iξx}); D(−ξ)
    is D(ξ)'s conjugate, so the integral is twice the real part over ξ > 0. Cut at Ξ = 2000 β: the tail is
    below ∫_Ξ^∞ dξ/(EIξ⁴) = 1/(3EIΞ³), (8/3)(β/Ξ)³ = 3e-10 of the static deflection.
    """
    EI, m, k, c = beam.flexural_rigidity, beam.mass_per_length, beam.foundation_modulus, beam.damping
    v = speed

    def inverse(xi):
        return 1.0 / (EI * xi**4 - m * v**2 * xi**2 + k - 1j * c * v * xi)

    top = 2000 * beam.characteristic_length
    options = dict(epsabs=0.0, epsrel=1e-11, limit=2000)
    if x == 0.0:
        real = quad(lambda xi: inverse(xi).real, 0, top, **options)[0]
        return force / np.pi * real
    cos_part = quad(lambda xi: inverse(xi).real, 0, top, weight="cos", wvar=x, **options)[0]
    sin_part = quad(lambda xi: inverse(xi).imag, 0, top, weight="sin", wvar=x, **options)[0]
    return force / np.pi * (cos_part - sin_part)


def test_hetenyi_static_deflection():
    # Hetényi (1946): w(0) = Pβ/(2k), the first zero at β|x| = 3π/4, symmetric; by hand for β and the
    # deflection (rounding only).
    beam = WinklerBeam(1.0e7, 60.0, 4.0e7)
    beta = (4.0e7 / 4.0e7) ** 0.25
    assert beam.characteristic_length == pytest.approx(beta, rel=1e-15)
    assert beam.static_deflection([0.0], P)[0] == pytest.approx(P * beta / (2 * 4.0e7), rel=1e-15)
    assert beam.static_deflection([3 * np.pi / 4], P)[0] == pytest.approx(0.0, abs=1e-15 * P / 4.0e7)
    x = np.linspace(0, 8, 17)
    np.testing.assert_allclose(beam.static_deflection(x, P), beam.static_deflection(-x, P), rtol=1e-15)


def test_critical_speed_formula():
    # v_cr = (4kEI/m²)^{1/4} (Kenney 1954; Frýba 1972, ch. 9), by hand for EI = 1e7, k = 4e7, m = 100:
    # (16e14/1e4)^{1/4} = (1.6e11)^{1/4}.
    beam = WinklerBeam(1.0e7, 100.0, 4.0e7)
    assert beam.critical_speed == pytest.approx(1.6e11**0.25, rel=1e-14)


def test_slow_force_is_the_static_deflection(reference):
    # v → 0: the steady state is Hetényi's static deflection. At v = 1e-6 v_cr the speed enters as α² = 1e-12;
    # tolerance 1e-9 of the peak (measured 1e-13).
    x = S * np.linspace(-8.0, 8.0, 41)
    slow = SOFT.steady_deflection(x, 1e-6 * SOFT.critical_speed, P)
    static = SOFT.static_deflection(x, P)
    reference(
        10,
        "Winkler beam under a slow force (v = 1e-6 v_cr)",
        "Hetényi 1946 static deflection",
        "closed form",
        np.abs(slow - static).max() / static.max(),
        1e-9,
    )
    np.testing.assert_allclose(SOFT.steady_deflection(x, 0.0, P), static, atol=1e-12 * static.max())


@pytest.mark.parametrize(
    ("damping", "ratio"),
    [(0.0, 0.3), (0.0, 0.7), (0.0, 0.9), (2.0e4, 0.5), (2.0e4, 1.5), (2.0e5, 3.0)],
)
def test_closed_form_is_the_fourier_integral(damping, ratio, reference):
    # The residue sum against the integral it sums, by adaptive quadrature (relative tolerance 1e-11, tail
    # 3e-10): agreement to 1e-7 of the peak (measured 3e-9 to 2e-8). Undamped below the critical speed; with
    # damping (ζ = 0.18 and 1.8) below and beyond it. ``damping`` is the rail's c on its own bed (the
    # label on the validation page), run on the soft bed at the same ζ (see ``soft``).
    beam = soft(damping)
    v = ratio * beam.critical_speed
    x = S * np.array([-3.0, -1.0, -0.2, 0.0, 0.7, 2.5, 5.0])
    closed = beam.steady_deflection(x, v, P)
    numeric = np.array([fourier(beam, xx, v, P) for xx in x])
    reference(
        10,
        f"Winkler beam under a moving force, v/v_cr = {ratio:g}, c = {damping:g} N·s/m²",
        "Fourier integral by quadrature (scipy)",
        "scipy",
        np.abs(closed - numeric).max() / np.abs(closed).max(),
        1e-7,
    )


def test_undamped_deflection_grows_without_bound_towards_the_critical_speed():
    # Undamped, the roots ρ = ±√(1 − α²) ± i√(1 + α²) give w(0) = (Pβ/2k)/√(1 − α²) (derived from the
    # residues; held here to rounding, 1e-9): the deflection under the load grows without bound as α → 1,
    # ~22 times the static one at α = 0.999.
    static = SOFT.static_deflection([0.0], P)[0]
    ratios = np.array([0.5, 0.9, 0.99, 0.999, 0.99999])
    w0 = np.array([SOFT.steady_deflection([0.0], a * SOFT.critical_speed, P)[0] for a in ratios])
    np.testing.assert_allclose(w0 / static, 1 / np.sqrt(1 - ratios**2), rtol=1e-9)
    assert np.all(np.diff(w0) > 0) and w0[-1] > 200 * static


def test_damping_keeps_the_critical_speed_finite_and_puts_the_peak_behind():
    # With damping the steady state exists at v_cr; the peak of the deflection lags behind the force (x < 0),
    # as the dashpots resist the rail going down ahead of it (a sign check of −c v w′).
    beam = soft(5.0e4)
    x = S * np.linspace(-3, 3, 601)
    w = beam.steady_deflection(x, beam.critical_speed, P)
    assert np.isfinite(w).all() and x[np.argmax(w)] < 0
    with pytest.raises(ValueError, match="speed"):
        SOFT.steady_deflection([0.0], SOFT.critical_speed, P)
    with pytest.raises(ValueError, match="speed"):
        SOFT.steady_deflection([0.0], 1.2 * SOFT.critical_speed, P)


@pytest.mark.parametrize(("damping", "ratio"), [(0.0, 0.0), (0.0, 0.8), (3.0e4, 0.8), (3.0e4, 2.0)])
def test_foundation_carries_the_whole_load(damping, ratio):
    # ∫ k w dx = P: the springs react the force (the dashpots' ∫ c v w′ dx vanishes as w → 0 both ways). By
    # quad over each side to 50 decay lengths of the slowest root (e^{−50} ~ 2e-22): rel 1e-9.
    beam = soft(damping)
    v = ratio * beam.critical_speed
    k = beam.foundation_modulus
    alpha, zeta = ratio, beam.damping_ratio
    slowest = np.abs(np.roots([0.25, 0.0, alpha**2, -2 * zeta * alpha, 1.0]).real).min()
    reach = 50.0 / (slowest * beam.characteristic_length)

    def w(xx):
        return beam.steady_deflection([xx], v, P)[0]

    total = sum(
        quad(w, a, b, epsabs=0.0, epsrel=1e-12, limit=500)[0] for a, b in ((-reach, 0.0), (0.0, reach))
    )
    assert k * total == pytest.approx(P, rel=1e-9)


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="flexural_rigidity"):
        WinklerBeam(flexural_rigidity=-1.0)
    with pytest.raises(ValueError, match="foundation_modulus"):
        WinklerBeam(foundation_modulus=0.0)
    with pytest.raises(ValueError, match="damping"):
        WinklerBeam(damping=-1.0)
    with pytest.raises(ValueError, match="speed"):
        RAIL.steady_deflection([0.0], -1.0, P)
    with pytest.raises(ValueError, match=r"speed must be in \[0.0, 200.0\] m/s"):
        RAIL.steady_deflection([0.0], 0.5 * RAIL.critical_speed, P)  # 385 m/s: above any train
    with pytest.raises(ValueError, match="x"):
        RAIL.static_deflection([], P)
