"""Chapter 4 widgets driven without a browser: every control changes the picture, in place."""

import numpy as np
import pytest

from raildyn.contact import kalker_coefficients
from raildyn.widgets import chapter04


def test_hertz_status_gives_the_circular_case():
    container, update = chapter04.hertz()
    # Wheel 460 mm on a 460 mm crown with a conical tread: A = B, so θ = 90° and m = n = 1.
    update(wheel_radius_mm=460.0, rail_radius_mm=460.0)
    status = container.children[-2].children[-1].value
    assert "θ = 90.0°" in status and "m = 1.000" in status


def test_fastsim_status_reports_full_sliding():
    container, update = chapter04.fastsim_patch()
    update(xi_permille=5.0, eta_permille=5.0, spin=0.0, friction=0.1)
    status = container.children[-2].children[-1].value
    assert "|F|/μN = 1.000" in status


def test_creep_status_gives_both_lateral_creep_coefficients():
    # Johnson and Vermeulen's own f22 beside Kalker's: the one thing that parts their curve from SHE's.
    import re

    container, update = chapter04.creep_laws()
    update(a_over_b=1.0, spin=0.0)
    status = container.children[-2].children[-1].value
    kalker, jv = map(
        float, re.search(r"f₂₂ = ([\d.]+) MN \(Johnson–Vermeulen's ([\d.]+) MN\)", status).groups()
    )
    # a circle, ν = 0.3: C22 = 16/(4 − ν) against Kalker's (to the status line's 0.01 MN rounding)
    assert jv / kalker == pytest.approx(16 / 3.7 / kalker_coefficients(1.0, 0.3).c22, rel=2e-3)


def test_profile_status_gives_en15302_and_the_first_harmonic():
    container, update = chapter04.profiles()
    update(wheel="cone 1:20", rail="60E1 at 1:40", gauge_mm=1435.0)
    status = container.children[-2].children[-1].value
    # A rolled 1:20 cone on the R300 crown: λ(1 + Rλ/a) = 0.0510 by both methods.
    assert "λ_e(3 mm) = 0.051 (EN 15302; first harmonic 0.051)" in status


def test_wheel_on_rail_touches_where_the_geometry_says_and_jumps_to_the_flange():
    from raildyn.contact import contact_geometry, s1002_wheel, uic60_rail

    container, update = chapter04.wheel_on_rail()
    status = container.children[-2].children[-1]
    g = contact_geometry(s1002_wheel(), uic60_rail(1 / 40), [6.0e-3, 7.0e-3])
    for k, y in enumerate((6.0, 7.0)):
        update(shift_mm=y, wheel="S1002", rail="60E1 at 1:40")
        rail_line, wheel_line, point = container.live.figure.axes[0].lines[:3]
        u, z = point.get_xdata()[0], point.get_ydata()[0]
        # the contact point lies on both drawn surfaces (to the interpolation of the drawn lines)
        assert z == pytest.approx(np.interp(u, *rail_line.get_data()), abs=1e-6)
        assert z == pytest.approx(np.interp(u, *wheel_line.get_data()), abs=1e-6)
        assert u == pytest.approx(1e3 * g.rail_position[0, k], abs=1e-9)
    # 6 mm: still on the tread; 7 mm: jumped to the flange, its tread lifted clear
    update(shift_mm=6.0)
    assert "left: tread" in status.value
    update(shift_mm=7.0)
    assert "left: flange" in status.value and "mm clear" in status.value
