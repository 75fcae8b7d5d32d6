"""Tests of raildyn.contact.fastsim: Kalker's simplified theory against the linear theory and μN.

Tiers: the small-creepage limit (Kalker's linear theory with L₁ = 8a/(3C₁₁G),
L₂ = 8a/(3C₂₂G), L₃ = πa√(a/b)/(4C₂₃G); Kalker 1982), full sliding (μN), an
independent cell-by-cell implementation, properties, bad input.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn.contact import creep_coefficients, fastsim, fastsim_reference, flexibilities, kalker_linear

PROPERTY = settings(max_examples=50, deadline=None)
A, B, G, NU, N, MU = 6e-3, 4e-3, 8.1e10, 0.3, 1e5, 0.3


def _quadrature_error(n_y):
    # In full adhesion the x-integration is exact (linear traction, exact increments) and the
    # strips are midpoints in y: Σ a(y)² dy for a(y)² ∝ 1 − y²/b² errs by (1/n_y)²/2 relative.
    return 0.5 / n_y**2


@pytest.mark.parametrize("ratio", [0.3, 1.0, 1.5, 4.0])
def test_small_creepage_gives_the_linear_theory(ratio, reference):
    a, b = A, A / ratio
    f = creep_coefficients(a, b, G, NU)
    tol = _quadrature_error(20) * 1.01 + 1e-12
    r = fastsim(1e-7, 0.0, 0.0, N, MU, a, b, G, NU)
    linear = kalker_linear(1e-7, 0.0, 0.0, f).fx
    reference(
        4,
        f"FASTSIM (20 × 20 cells) at a small creepage, b/a = {1 / ratio:.3g}",
        "Kalker's linear theory (1967)",
        "closed form",
        abs(r.fx / linear - 1),
        tol,
    )
    assert bool(r.adhesion.all())
    r = fastsim(0.0, 1e-7, 0.0, N, MU, a, b, G, NU)
    assert r.fy == pytest.approx(kalker_linear(0.0, 1e-7, 0.0, f).fy, rel=tol)
    r = fastsim(0.0, 0.0, 1e-5, N, MU, a, b, G, NU)
    # The spin force integrates a(y)³ ∝ (1 − y²/b²)^{3/2}, whose midpoint error is larger: 0.5 %.
    assert r.fy == pytest.approx(kalker_linear(0.0, 0.0, 1e-5, f).fy, rel=5e-3)


def test_linear_limit_converges_with_the_grid():
    f = creep_coefficients(A, B, G, NU)
    exact = kalker_linear(1e-7, 0.0, 0.0, f).fx
    errors = [
        abs(fastsim(1e-7, 0, 0, N, MU, A, B, G, NU, n_y=n, fields=False).fx / exact - 1) for n in (10, 20, 40)
    ]
    # Second order in 1/n_y: each halving of the strip width divides the error by about 4.
    assert errors[1] / errors[0] == pytest.approx(0.25, rel=0.05)
    assert errors[2] / errors[1] == pytest.approx(0.25, rel=0.05)


@pytest.mark.parametrize("direction", [(1, 0), (0, 1), (1, 1), (-0.3, 0.8)])
def test_large_creepage_saturates_at_mu_n(direction):
    r = fastsim(0.5 * direction[0], 0.5 * direction[1], 0.0, N, MU, A, B, G, NU)
    # The pressure is normalised on the grid, so full sliding in one direction gives μN to rounding.
    assert r.adhesion.mean() < 0.06  # only the first cell of each strip can stick
    assert np.hypot(r.fx, r.fy) == pytest.approx(MU * N, rel=2e-3)


@given(
    st.floats(-5e-3, 5e-3),
    st.floats(-5e-3, 5e-3),
    st.floats(-2.0, 2.0),
    st.floats(0.1, 0.6),
    st.floats(0.3, 3.0),
)
@PROPERTY
def test_compiled_equals_the_cell_by_cell_reference(xi, eta, phi, mu, ratio):
    a, b = A, A / ratio
    r = fastsim(xi, eta, phi, N, mu, a, b, G, NU, fields=False)
    flex = flexibilities(a, b, G, NU)
    ref = fastsim_reference(xi, eta, phi, N, mu, a, b, float(flex.l1), float(flex.l2), float(flex.l3))
    # Same arithmetic in another order: agreement to 1e-9 of μN.
    scale = mu * N
    assert r.fx == pytest.approx(ref.fx, abs=1e-9 * scale)
    assert r.fy == pytest.approx(ref.fy, abs=1e-9 * scale)
    assert r.mz == pytest.approx(ref.mz, abs=1e-9 * scale * A)
    assert np.hypot(r.fx, r.fy) <= scale * (1 + 1e-12)


def test_batch_matches_single_calls_and_the_fields_are_consistent():
    xi = np.array([1e-4, 1e-3, 5e-3])
    batch = fastsim(xi, 0.5 * xi, 0.2, N, MU, A, B, G, NU)
    assert batch.px.shape == (3, 20, 20)
    for i in range(3):
        one = fastsim(xi[i], 0.5 * xi[i], 0.2, N, MU, A, B, G, NU)
        assert one.fx == pytest.approx(batch.fx[i], rel=1e-12)
    # Traction never exceeds μ p_z; the slip is zero where the cell sticks.
    bound = MU * batch.pz
    assert np.all(np.hypot(batch.px, batch.py) <= bound * (1 + 1e-12) + 1e-9)
    assert np.all(batch.slip_x[batch.adhesion] == 0) and np.all(batch.slip_y[batch.adhesion] == 0)
    # The adhesion zone shrinks as the creepage grows.
    frac = batch.adhesion_fraction
    assert frac[0] > frac[1] > frac[2]
    # The summed pressure is N.
    dx = batch.x[..., 0:1] - batch.x[..., 1:2]
    dy = 2 * B / 20
    assert (batch.pz * dx * dy).sum(axis=(-2, -1)) == pytest.approx(np.full(3, N), rel=1e-12)


def test_bad_input():
    with pytest.raises(ValueError, match="friction"):
        fastsim(1e-3, 0, 0, N, 0.0, A, B)
    with pytest.raises(ValueError, match="normal_load"):
        fastsim(1e-3, 0, 0, -N, MU, A, B)
    with pytest.raises(ValueError, match="a/b must be in"):
        fastsim(1e-3, 0, 0, N, MU, A, A / 20)
    with pytest.raises(ValueError, match="n_x"):
        fastsim(1e-3, 0, 0, N, MU, A, B, n_x=1)


def test_defaults_are_the_steel_constants_of_raildyn():
    from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS

    # One source for G: the default is G = E/(2(1 + ν)) of raildyn.constants (80.8 GPa, not 81).
    default = fastsim(1e-4, 2e-4, 0.1, N, MU, A, B, fields=False)
    explicit = fastsim(1e-4, 2e-4, 0.1, N, MU, A, B, STEEL_SHEAR_MODULUS, STEEL_POISSON_RATIO, fields=False)
    assert default == explicit
    assert flexibilities(A, B) == flexibilities(A, B, STEEL_SHEAR_MODULUS, STEEL_POISSON_RATIO)
    # In the linear range the force is proportional to G: the old default 81 GPa gave 0.3 % more.
    old = fastsim(1e-7, 0.0, 0.0, N, MU, A, B, 8.1e10, 0.3, fields=False)
    assert default.fx != old.fx
    tiny = fastsim(1e-7, 0.0, 0.0, N, MU, A, B, fields=False)
    assert tiny.fx / old.fx == pytest.approx(STEEL_SHEAR_MODULUS / 8.1e10, rel=1e-9)


def test_result_knows_its_state_and_the_friction_in_use():
    r = fastsim(np.array([1e-4, 1e-2]), 0.0, 0.0, N, MU, A, B, fields=False)
    np.testing.assert_array_equal(r.friction, [MU, MU])
    # |F|/(μN): small in the linear range, 1 in full sliding (to the grid's rounding, as above)
    assert r.friction_utilisation[0] < 0.1
    assert r.friction_utilisation[1] == pytest.approx(1.0, rel=2e-3)
    f = flexibilities(A, B, G, NU)
    ref = fastsim_reference(1e-3, 0.0, 0.0, N, MU, A, B, f.l1, f.l2, f.l3)
    assert ref.friction_utilisation == pytest.approx(np.hypot(ref.fx, ref.fy) / (MU * N), rel=1e-15)


def test_plot_patch_draws_one_state_and_moves_its_cells():
    import matplotlib.pyplot as plt

    r = fastsim(1e-3, 0.5e-3, 0.0, N, MU, A, B, n_x=12, n_y=12)
    _, ax = plt.subplots()
    art = r.plot_patch(ax)
    assert len(art["stick"].get_offsets()) == int(r.adhesion.sum())
    assert len(art["stick"].get_offsets()) + len(art["slip"].get_offsets()) == 144
    sliding = fastsim(5e-3, 0.0, 0.0, N, MU, A, B, n_x=12, n_y=12)
    assert sliding.plot_patch(artists=art) is art
    assert len(art["stick"].get_offsets()) == int(sliding.adhesion.sum()) < int(r.adhesion.sum())
    with pytest.raises(ValueError, match="fields"):
        fastsim(1e-3, 0.0, 0.0, N, MU, A, B, fields=False).plot_patch(ax)


def test_huge_creepages_give_full_sliding_not_nan():
    # Issue 15: past full sliding the forces depend on the creepages' direction only; huge creepages
    # are scaled down together, so 1e300 gives the full-slip forces of 0.1 instead of NaN.
    slid = fastsim(0.1, 0.05, 0.0, N, MU, A, B, fields=False)
    huge = fastsim(1e300, 5e299, 0.0, N, MU, A, B, fields=False)
    assert (huge.fx, huge.fy) == pytest.approx((slid.fx, slid.fy), rel=1e-9)
    assert math.hypot(huge.fx, huge.fy) == pytest.approx(MU * N, rel=1e-12)
    f = flexibilities(A, B)
    ref = fastsim_reference(1e300, 5e299, 0.0, N, MU, A, B, f.l1, f.l2, f.l3)
    assert (ref.fx, ref.fy) == pytest.approx((huge.fx, huge.fy), rel=1e-9)


def test_reference_and_grid_sizes_are_checked():
    f = flexibilities(A, B)
    with pytest.raises(ValueError, match="n_x"):
        fastsim(1e-3, 0, 0, N, MU, A, B, n_x=10**12)  # bounded: no 7 TiB allocation
    with pytest.raises(ValueError, match="n_y"):
        fastsim_reference(1e-3, 0, 0, N, MU, A, B, f.l1, f.l2, f.l3, n_y=10**12)  # no endless loop
    with pytest.raises(ValueError, match="l1"):
        fastsim_reference(1e-3, 0, 0, N, MU, A, B, 0.0, f.l2, f.l3)
    with pytest.raises(TypeError, match="friction"):
        fastsim_reference(1e-3, 0, 0, N, None, A, B, f.l1, f.l2, f.l3)
    with pytest.raises(TypeError, match="fields"):
        fastsim(1e-3, 0, 0, N, MU, A, B, fields="yes")
