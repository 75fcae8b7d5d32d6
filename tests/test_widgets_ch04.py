"""Chapter 4 widgets driven without a browser: every control changes the picture, in place."""

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
