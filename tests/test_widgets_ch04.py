"""Chapter 4 widgets driven without a browser: every control changes the picture, in place."""

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
