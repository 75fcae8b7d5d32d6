"""Chapter 7's critical-speed curve builds the car's matrices as an affine family of (λ, k_ψ, k_sψ)."""

import numpy as np
import pytest

from raildyn.vehicles import Car
from raildyn.wheelset import Wheelset
from raildyn.widgets import chapter07

ORIGIN, FAR = chapter07._CURVE_ORIGIN, chapter07._CURVE_FAR
# every corner of the controls, the defaults, and points off the slider's grid
POINTS = [
    (0.03, 2.0e6, 0.0),
    (0.5, 120.0e6, 2.0e6),
    (0.15, 62.8e6, 1.0e6),
    (0.41, 7.0e6, 0.37e6),
    (0.08, 95.0e6, 1.9e6),
]


def _car(lam, k, ks):
    return Car().replace(conicity=lam, yaw_stiffness=k, secondary_yaw_stiffness=ks)


@pytest.mark.parametrize("make", [_car, lambda *p: _car(*p).bogie])
def test_the_family_gives_the_assembled_matrices(make):
    family = chapter07._AffineFamily(make, ORIGIN, FAR)
    assert family.affine
    stacks = family.stacks(POINTS)
    for k, p in enumerate(POINTS):
        assembled = make(*p).linear_system()
        for name in ("M", "C0", "C1", "K"):
            theirs = getattr(assembled, name)
            np.testing.assert_allclose(stacks[name][k], theirs, rtol=0.0, atol=1e-12 * np.abs(theirs).max())


def test_a_system_not_affine_in_the_conicity_is_assembled_at_every_point():
    # ε following λ² rather than λ: the halfway point is off the plane, so nothing is interpolated.
    def make(lam, k):
        return Wheelset(conicity=lam, contact_angle_parameter=lam**2, yaw_stiffness=k)

    family = chapter07._AffineFamily(make, (0.03, 1.0e6), (0.5, 5.0e6))
    assert not family.affine
    points = [(0.1, 2.0e6), (0.3, 4.0e6)]
    stacks = family.stacks(points)
    for k, p in enumerate(points):
        np.testing.assert_array_equal(stacks["K"][k], make(*p).linear_system().K)


def test_a_product_of_two_parameters_is_seen_too():
    # the yaw stiffness scaled by the conicity: affine in each alone, not in both
    def make(lam, k):
        return Wheelset(conicity=lam, yaw_stiffness=k * lam)

    assert not chapter07._AffineFamily(make, (0.03, 1.0e6), (0.5, 5.0e6)).affine
