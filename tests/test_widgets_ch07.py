"""Chapter 7's critical-speed curve builds the car's and the bogie's matrices as affine families of
(λ, k_ψ, k_sψ) (``raildyn.linear_model._AffineFamily``): they must be the assembled ones."""

import numpy as np
import pytest

from raildyn.vehicles import Car
from raildyn.widgets import chapter07

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


@pytest.mark.parametrize(("which", "make"), [(0, _car), (1, lambda *p: _car(*p).bogie)])
def test_the_widgets_families_give_the_assembled_matrices(which, make):
    family = chapter07._curve_families()[which]
    assert family.affine
    stacks = family.stacks(POINTS)
    for k, p in enumerate(POINTS):
        assembled = make(*p).linear_system()
        for name in ("M", "C0", "C1", "K"):
            theirs = getattr(assembled, name)
            np.testing.assert_allclose(stacks[name][k], theirs, rtol=0.0, atol=1e-12 * np.abs(theirs).max())
