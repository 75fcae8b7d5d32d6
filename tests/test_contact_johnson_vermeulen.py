"""Tests of Johnson and Vermeulen's creep law with its own creep coefficients (raildyn.contact.creep).

Tiers: the elliptic integrals against their defining quadratures; the creep coefficients
against an independent computation (Cerruti's surface displacement of the theory's traction,
integrated numerically) and the circular closed form; the saturation against its cubic.
"""

import numpy as np
import pytest
from scipy.integrate import quad

from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact import (
    creep_coefficients,
    johnson_vermeulen,
    johnson_vermeulen_coefficients,
    kalker_coefficients,
    shen_hedrick_elkins,
)
from raildyn.contact.johnson_vermeulen import _elliptic_bcd


@pytest.mark.parametrize("m", [0.0, 1e-6, 0.05, 0.0999, 0.1001, 0.5, 0.9, 0.99])
def test_elliptic_integrals_match_their_definitions(m):
    # B = ∫cos²/Δ, C = ∫sin²cos²/Δ³, D = ∫sin²/Δ over [0, π/2], Δ = √(1 − m sin²): the series below
    # m = 0.1 and the closed forms in K and E above it, against adaptive quadrature (1e-12).
    delta = lambda p: np.sqrt(1 - m * np.sin(p) ** 2)  # noqa: E731
    want = [
        quad(lambda p: np.cos(p) ** 2 / delta(p), 0, np.pi / 2, epsrel=1e-13)[0],
        quad(lambda p: (np.sin(p) * np.cos(p)) ** 2 / delta(p) ** 3, 0, np.pi / 2, epsrel=1e-13)[0],
        quad(lambda p: np.sin(p) ** 2 / delta(p), 0, np.pi / 2, epsrel=1e-13)[0],
    ]
    np.testing.assert_allclose(_elliptic_bcd(np.array(m)), want, rtol=1e-12)


def _cerruti_curvature(a, b, nu, direction, n=4000):
    """κ of u(x, 0) = u₀ − κx²: the relative surface displacement, along the traction, of two like
    half-spaces (G = 1) under the Hertz-shaped traction q = √(1 − x²/a² − y²/b²) in ``direction``.

    Cerruti: u = (1/πG) ∬ q [(1 − ν) + ν ((s·e)/ρ)²]/ρ dA, s the offset, e the traction direction; in
    polar coordinates about the field point the 1/ρ cancels the area element, and the integral
    of q along each ray is an arc of an ellipse, in closed form. The θ integral of a smooth
    periodic function by the rectangle rule converges spectrally.
    """

    def along_rays(x0, theta):
        c, s = np.cos(theta), np.sin(theta)
        alpha, beta, gamma = 1 - x0**2 / a**2, x0 * c / a**2, c**2 / a**2 + s**2 / b**2
        rho2 = (alpha * gamma + beta**2) / gamma**2
        t0 = beta / gamma
        return (
            np.sqrt(gamma)
            / 2
            * (rho2 * np.pi / 2 - t0 * np.sqrt(rho2 - t0**2) - rho2 * np.arcsin(t0 / np.sqrt(rho2)))
        )

    theta = 2 * np.pi * (np.arange(n) + 0.5) / n
    weight = (1 - nu) + nu * (np.cos(theta) if direction == "x" else np.sin(theta)) ** 2

    def u(x0):
        return 2 * (weight * along_rays(x0, theta)).mean()  # (1/π) × 2π × mean

    x0 = 0.4 * a
    return (u(0.0) - u(x0)) / x0**2


@pytest.mark.parametrize("ratio", [0.2, 1.0, 3.0])
@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_coefficients_match_cerruti_integrated_numerically(ratio, nu, reference):
    # In Vermeulen and Johnson's theory the creepage is the gradient of that displacement in the
    # rolling direction: ξ = 2κ(a − a')·μp₀/G, with p₀ = 3N/(2πab) and F = μN(1 − (a'/a)³), so the
    # initial slope is f = πGab/(κa), i.e. C = π/(κa) (G = q₀ = 1). An independent route to the
    # elliptic-integral formulas: agreement to the quadrature's rounding (1e-12).
    c = johnson_vermeulen_coefficients(ratio, nu)
    a, b = ratio, 1.0
    for name, mine, direction in (("C11", c.c11, "x"), ("C22", c.c22, "y")):
        want = np.pi / (_cerruti_curvature(a, b, nu, direction) * a)
        reference(4, f"Johnson–Vermeulen {name} at a/b = {ratio:g}, ν = {nu:g}",
                  "Cerruti's solution integrated numerically", "independent model",
                  abs(mine / want - 1), 1e-12)  # fmt: skip


@pytest.mark.parametrize("nu", [0.0, 0.25, 0.3, 0.5])
def test_circle_gives_the_rolling_sphere(nu):
    # A circle: B = D = π/4, C = π/16, so C11 = 16/(4 − 3ν) and C22 = 16/(4 − ν), Johnson's (1958)
    # rolling sphere (the two sides of the formulas, a ≤ b and a ≥ b, meet here: 1e-12).
    for ratio in (1.0, 1.0 - 1e-9, 1.0 + 1e-9):
        c = johnson_vermeulen_coefficients(ratio, nu)
        assert c.c11 == pytest.approx(16 / (4 - 3 * nu), rel=1e-8)
        assert c.c22 == pytest.approx(16 / (4 - nu), rel=1e-8)


def test_coefficients_exceed_kalkers_by_up_to_a_quarter():
    # Their theory's no-slip traction is an approximation; Kalker's exact linear theory gives a
    # softer contact everywhere in his table, by 8 % (long ellipses) to 27 % (narrow ones).
    ratios = np.concatenate([np.arange(1, 11) / 10, 10 / np.arange(9, 0, -1)])
    for nu in (0.0, 0.25, 0.5):
        jv, k = johnson_vermeulen_coefficients(ratios, nu), kalker_coefficients(ratios, nu)
        for mine, kalker in ((jv.c11, k.c11), (jv.c22, k.c22)):
            assert np.all(mine / kalker > 1.05) and np.all(mine / kalker < 1.3)


def test_saturation_is_the_cubic_along_the_linear_force():
    # F/μN = 1 − (1 − χ)³ with χ = |f₁₁γ_x, f₂₂γ_y|/(3μN) their own coefficients, μN beyond χ = 1,
    # the force against (f₁₁γ_x, f₂₂γ_y): exact algebra, to rounding.
    a, b, n, mu = 6e-3, 4e-3, 1e5, 0.3
    c = johnson_vermeulen_coefficients(a / b, STEEL_POISSON_RATIO)
    f11, f22 = (STEEL_SHEAR_MODULUS * a * b * k for k in (c.c11, c.c22))
    xi, eta = np.linspace(0, 1e-2, 41), np.linspace(0, 5e-3, 41)  # χ from 0 to 1.3
    r = johnson_vermeulen(xi, eta, n, mu, a, b)
    lin = np.hypot(f11 * xi, f22 * eta)
    chi = lin / (3 * mu * n)
    want = mu * n * np.where(chi < 1, 1 - (1 - np.minimum(chi, 1)) ** 3, 1.0)
    np.testing.assert_allclose(r.resultant, want, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(r.fx[1:] * (f22 * eta[1:]), r.fy[1:] * (f11 * xi[1:]), rtol=1e-12)
    assert np.any(chi >= 1) and np.all(r.resultant[chi >= 1] == pytest.approx(mu * n, rel=1e-12))


def test_she_at_zero_spin_is_johnson_vermeulen_with_kalkers_coefficients():
    # The one real coincidence of the two laws: SHE's β − β²/3 + β³/27 is 1 − (1 − β/3)³. With the
    # creepage scaled by C(JV)/C(Kalker), SHE gives Johnson and Vermeulen's force (to rounding).
    a, b, n, mu = 6e-3, 4e-3, 1e5, 0.3
    ratio = (
        johnson_vermeulen_coefficients(a / b, STEEL_POISSON_RATIO).c11
        / kalker_coefficients(a / b, STEEL_POISSON_RATIO).c11
    )
    xi = np.linspace(0, 5e-3, 21)
    she = shen_hedrick_elkins(ratio * xi, 0.0, 0.0, n, mu, creep_coefficients(a, b))
    np.testing.assert_allclose(johnson_vermeulen(xi, 0.0, n, mu, a, b).fx, she.fx, rtol=1e-12, atol=1e-9)


def test_bad_input():
    with pytest.raises(ValueError, match="a_over_b"):
        johnson_vermeulen_coefficients(0.0, 0.3)
    with pytest.raises(ValueError, match="a_over_b"):
        johnson_vermeulen_coefficients(5e3, 0.3)
    with pytest.raises(ValueError, match="poisson_ratio"):
        johnson_vermeulen_coefficients(1.0, 0.7)
    with pytest.raises(ValueError, match="b"):
        johnson_vermeulen(1e-3, 0.0, 1e5, 0.3, 6e-3, -4e-3)
    with pytest.raises(ValueError, match="shear_modulus"):
        johnson_vermeulen(1e-3, 0.0, 1e5, 0.3, 6e-3, 4e-3, shear_modulus=0.0)
