"""Chapter 7's critical-speed curve assembles the car at three conicities and interpolates the rest."""

import numpy as np
import pytest

from raildyn.vehicles import Car
from raildyn.wheelset import Wheelset
from raildyn.widgets import chapter07

LAMBDAS = [float(v) for v in chapter07._CONICITIES]


@pytest.mark.parametrize(
    "make",
    [
        lambda lam: Car().replace(conicity=lam, yaw_stiffness=7.0e6),
        lambda lam: Car().replace(conicity=lam).bogie,
        lambda lam: Wheelset(conicity=lam, yaw_stiffness=2.0e6, lateral_stiffness=1.0e6),
    ],
)
def test_systems_in_between_are_the_assembled_ones(make):
    systems = chapter07._systems_over_conicity(make, LAMBDAS)
    assert sorted(systems) == LAMBDAS
    for lam in LAMBDAS:
        assembled = make(lam).linear_system()
        for name in ("M", "C0", "C1", "K"):
            mine, theirs = getattr(systems[lam], name), getattr(assembled, name)
            np.testing.assert_allclose(mine, theirs, rtol=0.0, atol=1e-12 * np.abs(theirs).max())
        assert systems[lam].labels == assembled.labels


def test_a_system_not_affine_in_the_conicity_is_assembled_at_every_one():
    # ε following λ² rather than λ: the middle conicity is off the line, so nothing is interpolated.
    def make(lam):
        return Wheelset(conicity=lam, contact_angle_parameter=lam**2, yaw_stiffness=2.0e6)

    systems = chapter07._systems_over_conicity(make, LAMBDAS)
    for lam in LAMBDAS:
        np.testing.assert_array_equal(systems[lam].K, make(lam).linear_system().K)
