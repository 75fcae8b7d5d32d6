"""The continuous beam (raildyn.bridge.continuous): one span is the simple beam, the published frequency
parameters of two and three equal spans, orthogonality, and the static influence line from the modes."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from raildyn.bridge import SimplySupportedBeam
from raildyn.bridge.continuous import ContinuousBeam

EI, M = 1.0e10, 1.0e4


def frequency_parameters(beam, span):
    """λL = L (ω² m/EI)^{1/4} of each mode, for the span length ``span``."""
    return span * (2 * np.pi * beam.frequencies_hz) ** 0.5 * (M / EI) ** 0.25


def test_one_span_is_the_simply_supported_beam():
    # The same beam two ways: the exact sin(jπx/L) against the Wittrick–Williams search and the span's
    # exponential basis. Both are exact; the tolerance 1e-9 (asked) is met with margin (measured 3e-13
    # for φ″ of mode 10, the largest).
    one = ContinuousBeam((20.0,), EI, M, damping_ratio=0.02, modes=10)
    simple = SimplySupportedBeam(20.0, EI, M, damping_ratio=0.02, modes=10)
    np.testing.assert_allclose(one.frequencies_hz, simple.frequencies_hz, rtol=1e-12)
    np.testing.assert_allclose(one.modal_masses, simple.modal_masses, rtol=1e-12)
    x = np.linspace(-1.0, 21.0, 221)
    for d in (0, 1, 2):
        scale = (10 * np.pi / 20.0) ** d
        np.testing.assert_allclose(one.mode_shapes(x, d), simple.mode_shapes(x, d), atol=1e-9 * scale)
    assert one.length == simple.length == 20.0


def test_two_equal_spans_give_the_published_frequency_parameters(reference):
    # Blevins (1979), Formulas for Natural Frequency and Mode Shape, ch. 8, table of uniform beams over
    # equally spaced simple supports, two spans: λL = 3.1416, 3.9266, 6.2832, 7.0686 (printed to 4
    # decimals: tolerance 6e-5). Independently, the odd modes are each span's sine (λL = jπ) and the even
    # ones each span as a propped cantilever (tan μ = tanh μ), held to 1e-10.
    beam = ContinuousBeam((20.0, 20.0), EI, M, modes=4)
    lam = frequency_parameters(beam, 20.0)
    reference(
        10,
        "frequency parameters λL of a two-span continuous beam",
        "Blevins 1979, ch. 8 (4 decimals)",
        "published",
        np.abs(lam - [3.1416, 3.9266, 6.2832, 7.0686]).max(),
        6e-5,
        "abs.",
    )
    propped = [brentq(lambda mu: np.tan(mu) - np.tanh(mu), a, b) for a, b in ((3.5, 4.5), (6.5, 7.5))]
    np.testing.assert_allclose(lam, [np.pi, propped[0], 2 * np.pi, propped[1]], rtol=1e-10)


def test_three_equal_spans_give_the_published_frequency_parameters(reference):
    # Blevins (1979), ch. 8, the same table, three spans: λL = 3.1416, 3.5564, 4.2975, then 6.2832, 6.7076,
    # 7.4295 (4 decimals: tolerance 6e-5).
    beam = ContinuousBeam((20.0, 20.0, 20.0), EI, M, modes=6)
    gap = np.abs(frequency_parameters(beam, 20.0) - [3.1416, 3.5564, 4.2975, 6.2832, 6.7076, 7.4295]).max()
    reference(
        10,
        "frequency parameters λL of a three-span continuous beam",
        "Blevins 1979, ch. 8 (4 decimals)",
        "published",
        gap,
        6e-5,
        "abs.",
    )


def test_modes_are_mass_orthogonal_and_scaled():
    # ∫ m φ_i φ_j dx = 0 for i ≠ j, by Simpson's rule on 30 001 points over 75 m (error ~ h⁴ φ'''' ≈ 1e-12
    # of the modal mass for mode 20): off-diagonal within 1e-9 of the largest modal mass; the diagonal is
    # the modal masses the beam reports (its own Gauss rule) to 1e-9. Each max |φ| is 1 (the grid can only
    # miss the peak by (πh/λ)² ~ 1e-5).
    from scipy.integrate import simpson

    beam = ContinuousBeam((20.0, 30.0, 25.0), EI, M, modes=20)
    x = np.linspace(0.0, 75.0, 30_001)
    phi = beam.mode_shapes(x)
    gram = M * simpson(phi[:, None, :] * phi[None, :, :], x=x, axis=-1)
    off = gram - np.diag(np.diag(gram))
    assert np.abs(off).max() < 1e-9 * beam.modal_masses.max()
    np.testing.assert_allclose(np.diag(gram), beam.modal_masses, rtol=1e-9)
    np.testing.assert_allclose(np.abs(phi).max(axis=1), 1.0, atol=2e-5)
    assert np.all(beam.mode_shapes([0.0], 1)[:, 0] > 0)  # the sign convention φ′(0) > 0
    assert np.all(np.diff(beam.frequencies_hz) > 0)


def test_slope_and_moment_are_continuous_over_the_inner_supports():
    # At x = 20 m, the slope and curvature just left and right of the support agree (the shape is smooth to
    # the third derivative elsewhere: a step of 1e-7 m changes φ′ by ~1e-7 × max φ″): 1e-5 of the scale.
    beam = ContinuousBeam((20.0, 30.0), EI, M, modes=8)
    eps = 1e-7
    for d in (0, 1, 2):
        left, right = beam.mode_shapes([20.0 - eps, 20.0 + eps], d).T
        scale = np.abs(beam.mode_shapes(np.linspace(0, 50, 501), d)).max()
        np.testing.assert_allclose(left, right, atol=1e-5 * scale)


@pytest.mark.parametrize("spans", [(20.0, 20.0), (20.0, 30.0)])
def test_slow_force_gives_the_two_span_influence_line(spans):
    # A force crossing very slowly bends the beam statically: w(x; a) = Σ_j φ_j(x) φ_j(a) P/(M_j ω_j²).
    # Against the closed form: Clapeyron's three-moment equation for a load P at a in span 1 (Timoshenko &
    # Young 1965, Theory of Structures, §on continuous beams): M_B = −P a (L₁² − a²)/(2 L₁ (L₁ + L₂)), and
    # the deflection in span 1 is the simple span's under P plus that of the end moment M_B,
    # M_B x (L₁² − x²)/(6 EI L₁). The modal sum converges as j⁻⁴ (60 modes): tolerance 1e-4 of the peak.
    L1, L2 = spans
    beam = ContinuousBeam(spans, EI, M, modes=60)
    P = 1.0e5
    omega2 = (2 * np.pi * beam.frequencies_hz) ** 2
    x = np.linspace(0.0, L1, 41)
    for a in (0.3 * L1, 0.5 * L1, 0.8 * L1):
        modal = (
            beam.mode_shapes(x) * beam.mode_shapes([a])[:, :1] * P / (beam.modal_masses * omega2)[:, None]
        ).sum(0)
        b = L1 - a
        simple = np.where(
            x <= a,
            P * b * x * (L1**2 - b**2 - x**2) / (6 * EI * L1),
            P * a * (L1 - x) * (L1**2 - a**2 - (L1 - x) ** 2) / (6 * EI * L1),
        )
        MB = -P * a * (L1**2 - a**2) / (2 * L1 * (L1 + L2))
        exact = simple + MB * x * (L1**2 - x**2) / (6 * EI * L1)
        np.testing.assert_allclose(modal, exact, atol=1e-4 * np.abs(exact).max())
        # The beam's own static solution (slope-deflection) is exact: rounding only, 1e-12 of the peak.
        np.testing.assert_allclose(beam.static_deflection(a, x, P), exact, atol=1e-12 * np.abs(exact).max())


def test_static_deflection_three_spans():
    # Three unequal spans: the slope-deflection solution against the modal sum of 80 modes (converging as j⁻⁴:
    # measured 3e-5 of the peak; tolerance 1e-4), and Maxwell's reciprocity w(x; a) = w(a; x), which the
    # solution does not build in (rounding: 1e-12 of the peak).
    beam = ContinuousBeam((20.0, 30.0, 25.0), EI, M, modes=80)
    x = np.linspace(0.0, 75.0, 151)
    omega2 = (2 * np.pi * beam.frequencies_hz) ** 2
    for a in (5.0, 33.0, 60.0):
        static = beam.static_deflection(a, x, 1.0e5)
        phi_a = beam.mode_shapes([a])[:, :1]
        modal = (beam.mode_shapes(x) * phi_a * 1.0e5 / (beam.modal_masses * omega2)[:, None]).sum(0)
        np.testing.assert_allclose(modal, static, atol=1e-4 * np.abs(static).max())
        for b in (12.0, 41.0, 70.0):
            ab, ba = beam.static_deflection(a, [b])[0], beam.static_deflection(b, [a])[0]
            assert ab == pytest.approx(ba, abs=1e-12 * np.abs(static).max() / 1.0e5)
    assert np.all(beam.static_deflection(33.0, [0.0, 20.0, 50.0, 75.0, -1.0, 80.0]) == 0.0)


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="spans"):
        ContinuousBeam((20.0, 0.0))
    with pytest.raises(ValueError, match="spans"):
        ContinuousBeam(())
    with pytest.raises(ValueError, match="spans"):
        ContinuousBeam((1.0, 100.0))
    with pytest.raises(ValueError, match="flexural_rigidity"):
        ContinuousBeam(flexural_rigidity=-1.0)
    with pytest.raises(ValueError, match="damping_ratio"):
        ContinuousBeam(damping_ratio=1.0)
    with pytest.raises(TypeError, match="modes"):
        ContinuousBeam(modes=2.0)
    with pytest.raises(ValueError, match="force_position"):
        ContinuousBeam().static_deflection(41.0, [1.0])
    with pytest.raises(ValueError, match="derivative"):
        ContinuousBeam().mode_shapes([1.0], derivative=3)
