"""Tests for raildyn.suspension: the force laws' closed forms, limits, symmetry and bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from raildyn import suspension as sus


def test_linear_laws_and_broadcasting():
    d = np.linspace(-0.02, 0.02, 5)
    k = np.array([[1.0e5], [2.0e6]])  # two springs against five deflections: shape (2, 5)
    np.testing.assert_allclose(sus.spring_force(d, k, preload=50.0), k * d + 50.0, rtol=1e-15)
    assert sus.damper_force(d, 3.0e4).shape == (5,)
    np.testing.assert_allclose(sus.damper_force(d, 3.0e4), 3.0e4 * d, rtol=1e-15)


def test_ideal_coulomb_friction():
    np.testing.assert_array_equal(
        sus.coulomb_friction([-2.0, -1e-12, 0.0, 1e-12, 3.0], 400.0), [-400, -400, 0, 400, 400]
    )


def test_smooth_friction_limits():
    F, eps = 1200.0, 0.01
    # tends to the ideal law far from v = 0 (tanh(10) = 1 − 4e-9) ...
    assert sus.coulomb_friction(0.05, F, velocity_scale=eps / 2) == pytest.approx(F, rel=1e-8)
    # ... is a viscous damper of F/v_ε at small v (tanh u = u − u³/3: relative error 1e-8/3 at u = 1e-4)
    assert sus.coulomb_friction(1e-6, F, velocity_scale=eps) == pytest.approx(F * 1e-6 / eps, rel=1e-7)
    # and v_ε → 0 recovers sgn v at any fixed v ≠ 0
    assert sus.coulomb_friction(-1e-3, F, velocity_scale=1e-6) == pytest.approx(-F, rel=1e-12)


@settings(deadline=None, max_examples=50)
@given(v=st.floats(-1.0, 1.0).filter(lambda v: v != 0), eps=st.floats(1e-4, 0.1), F=st.floats(0.0, 1e5))
def test_smooth_friction_error_within_its_stated_bound(v, eps, F):
    smooth = sus.coulomb_friction(v, F, velocity_scale=eps)
    ideal = sus.coulomb_friction(v, F)
    bound = sus.friction_error_bound(v, F, eps)
    assert abs(smooth - ideal) <= bound + 1e-12 * F
    assert abs(smooth) <= F  # never more than the friction force


def test_clearance_and_bump_stop():
    g, ks, k = 0.01, 5.0e6, 1.0e5
    d = np.array([-0.03, -0.01, -0.004, 0.0, 0.004, 0.01, 0.03])
    # a free gap: no force inside, a stop of k_s beyond
    np.testing.assert_allclose(sus.clearance_force(d, g, ks), ks * np.maximum(np.abs(d) - g, 0) * np.sign(d))
    assert np.all(sus.clearance_force(d[2:5], g, ks) == 0.0)
    # a spring with a bump stop: k δ inside, k δ + k_s(|δ| − g) sgn δ beyond; continuous at |δ| = g
    h = 1e-9
    inside, outside = sus.clearance_force([g - h, g + h], g, ks, stiffness=k)
    assert outside - inside == pytest.approx(2 * k * h + ks * h, rel=1e-6)
    # zero clearance and stop stiffness: an ordinary spring
    np.testing.assert_allclose(sus.clearance_force(d, 0.0, 0.0, stiffness=k), k * d, rtol=1e-15)


@settings(deadline=None, max_examples=50)
@given(d=st.floats(-0.1, 0.1), g=st.floats(0.0, 0.05), ks=st.floats(0.0, 1e7), k=st.floats(0.0, 1e6))
def test_clearance_force_is_odd_and_monotone(d, g, ks, k):
    f = sus.clearance_force(d, g, ks, stiffness=k)
    assert sus.clearance_force(-d, g, ks, stiffness=k) == pytest.approx(-f, abs=1e-9)
    assert sus.clearance_force(d + 1e-4, g, ks, stiffness=k) >= f - 1e-9


def test_bad_suspension_input():
    with pytest.raises(ValueError, match="stiffness must be >= 0"):
        sus.spring_force(0.01, -1.0)
    with pytest.raises(ValueError, match="damping must be >= 0"):
        sus.damper_force(0.1, [1.0, -2.0])
    with pytest.raises(ValueError, match="velocity_scale must be > 0"):
        sus.coulomb_friction(0.1, 100.0, velocity_scale=0.0)
    with pytest.raises(ValueError, match="friction_force must be >= 0"):
        sus.coulomb_friction(0.1, -100.0)
    with pytest.raises(ValueError, match="clearance must be >= 0"):
        sus.clearance_force(0.1, -0.01, 1e6)
    with pytest.raises(ValueError, match="deflection must contain only finite"):
        sus.spring_force(np.nan, 1.0)


# ---------------------------------------------------------------- the friction law's slope and the damper


@settings(deadline=None, max_examples=100)
@given(v=st.floats(-0.05, 0.05), eps=st.floats(1e-4, 0.1), F=st.floats(1.0, 1e5))
def test_friction_slope_matches_a_central_difference(v, eps, F):
    # Central difference with h = 1e-4 v_ε: truncation error F/v_ε·O((h/v_ε)²) ≈ 1e-8 F/v_ε, and
    # rounding ≈ 1e-16 F / h = 1e-12 F/v_ε: within 1e-6 of the slope's peak F/v_ε.
    h = 1e-4 * eps
    fd = (
        sus.coulomb_friction(v + h, F, velocity_scale=eps)
        - sus.coulomb_friction(v - h, F, velocity_scale=eps)
    ) / (2 * h)
    assert sus.coulomb_friction_slope(v, F, velocity_scale=eps) == pytest.approx(fd, abs=1e-6 * F / eps)


def test_friction_slope_closed_forms_and_far_field():
    F, eps = 1.0e4, 1.0e-3
    # At v = 0 the smooth law is a damper of F/v_ε; the slope is even in v and never negative.
    assert sus.coulomb_friction_slope(0.0, F, velocity_scale=eps) == pytest.approx(F / eps, rel=1e-15)
    v = np.linspace(0.0, 0.01, 21)
    slope = sus.coulomb_friction_slope(v, F, velocity_scale=eps)
    np.testing.assert_array_equal(slope, sus.coulomb_friction_slope(-v, F, velocity_scale=eps))
    assert np.all(slope >= 0) and np.all(np.diff(slope) < 0)
    # sech² u written as 4e^{−2|u|}/(1 + e^{−2|u|})² stays finite and exact far out (no overflow warning):
    # at u = 500, sech² u = 4e^{−1000} underflows to 0; at u = 20, 4e^{−40}(1 − 2e^{−40}) to 1e-15.
    assert sus.coulomb_friction_slope(0.5, F, velocity_scale=eps) == 0.0
    far = sus.coulomb_friction_slope(0.02, F, velocity_scale=eps)
    assert far == pytest.approx(F / eps * 4 * np.exp(-40.0), rel=1e-15)
    with pytest.raises(ValueError, match="velocity_scale must be > 0"):
        sus.coulomb_friction_slope(0.1, F, velocity_scale=0.0)


@settings(deadline=None, max_examples=50)
@given(
    v=st.lists(st.floats(-0.05, 0.05), min_size=1, max_size=3),
    eps=st.floats(1e-3, 0.1),
    F=st.floats(1.0, 1e4),
)
def test_friction_damper_jacobian_matches_finite_differences(v, eps, F):
    v = np.array(v)
    n = v.size
    damper = sus.FrictionDamper(friction_force=F, velocity_scale=eps)
    x = np.zeros(n)
    J = damper.jacobian(0.0, x, v)
    h = 1e-4 * eps
    fd = np.column_stack(
        [(damper.force(0.0, x, v + h * e) - damper.force(0.0, x, v - h * e)) / (2 * h) for e in np.eye(n)]
    )
    # As above: central differences within 1e-6 of the peak slope F/v_ε.
    np.testing.assert_allclose(J.wrt_velocity, fd, atol=1e-6 * F / eps, rtol=0)
    assert np.all(J.wrt_displacement == 0.0) and J.wrt_velocity.shape == (n, n)
    np.testing.assert_allclose(damper.force(0.0, x, v), -sus.coulomb_friction(v, F, velocity_scale=eps))


def test_friction_damper_per_coordinate_and_bad_input():
    damper = sus.FrictionDamper(friction_force=[100.0, 200.0], velocity_scale=0.01)
    np.testing.assert_allclose(damper.force(0.0, [0, 0], [1.0, -1.0]), [-100.0, 200.0], rtol=1e-12)
    np.testing.assert_allclose(np.diag(damper.jacobian(0.0, [0, 0], [0.0, 0.0]).wrt_velocity), [-1e4, -2e4])
    with pytest.raises(ValueError, match="v must have 2 entries, one per friction_force, got 3"):
        damper.force(0.0, np.zeros(3), np.zeros(3))
    with pytest.raises(ValueError, match="velocity_scale must be > 0"):
        sus.FrictionDamper(friction_force=10.0, velocity_scale=0.0)
    with pytest.raises(ValueError, match="friction_force must be >= 0"):
        sus.FrictionDamper(friction_force=-1.0, velocity_scale=0.01)
    with pytest.raises(ValueError, match="friction_force must be a number or a vector"):
        sus.FrictionDamper(friction_force=np.ones((2, 2)), velocity_scale=0.01)


def test_friction_amplitude_loss_against_a_simulation():
    # The chapter 2 example: 25 t on 5 MN/m with F_f = 10 kN loses 4F_f/k = 8 mm a cycle (Den Hartog 1956).
    from scipy.signal import find_peaks

    from raildyn import integrators

    m, k, F, eps = 25e3, 5e6, 10e3, 1e-3
    assert float(sus.friction_amplitude_loss(F, k)) == pytest.approx(0.008, rel=1e-15)
    damper = sus.FrictionDamper(F, eps)
    t = np.linspace(0.0, 1.0, 1001)
    run = integrators.stiff(
        m, 0.0, k, t, 0.03, 0.0, damper.force, jacobian=damper.jacobian, rtol=1e-9, atol=1e-12
    )
    # Released at its first maximum, 30 mm: the next maxima at 22 and 14 mm. The smoothing leaves a viscous
    # damper of F/v_ε near v = 0 that the mass crosses in a few ms: the drop is 8 mm within 0.1 mm.
    peaks = run.x[0][find_peaks(run.x[0])[0]]
    drops = -np.diff(np.r_[0.03, peaks[:2]])
    np.testing.assert_allclose(drops, sus.friction_amplitude_loss(F, k), atol=1e-4)
    with pytest.raises(ValueError, match="stiffness must be > 0"):
        sus.friction_amplitude_loss(F, 0.0)


def test_bad_input_is_refused_by_name():
    with pytest.raises(
        ValueError, match=r"clearance has shape \(2,\), which does not broadcast against deflection"
    ):
        sus.clearance_force([-0.02, 0.0, 0.02], [0.01, 0.02], 1.0e6)
    with pytest.raises(ValueError, match="velocity must not be empty"):
        sus.damper_force([], 1.0e4)
    damper = sus.FrictionDamper(100.0, 1e-3)
    with pytest.raises(ValueError, match="t must be a finite number"):
        damper.force(np.nan, np.zeros(1), np.zeros(1))
    with pytest.raises(ValueError, match=r"x must have the shape of v"):
        damper.jacobian(0.0, np.zeros(2), np.zeros(1))
