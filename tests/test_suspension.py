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
