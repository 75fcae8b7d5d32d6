"""Chapter 5 and 7 widgets driven without a browser: every control changes the picture, in place."""

import re

import pytest

from raildyn import stability, wheelset
from raildyn.widgets import chapter05


def _status(container):
    return container.children[-2].children[-1].value


def test_klingel_status_gives_the_wavelength():
    container, update = chapter05.klingel()
    update(conicity=0.1, rolling_radius_mm=500.0)
    expected = wheelset.kinematic_wavelength(0.5, 0.75, 0.1)
    assert f"{expected:.2f} m" in _status(container)


def test_wheelset_roots_status_gives_the_critical_speed():
    container, update = chapter05.wheelset_roots()
    update(conicity=0.2, yaw_stiffness=2.0, lateral_stiffness=1.0)
    ws = wheelset.Wheelset(conicity=0.2, yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
    cs = stability.critical_speed(ws, (2.0, 120.0))
    # The widget's root is found to 0.05 m/s and printed to 0.1 m/s.
    shown = float(re.search(r"critical speed ([\d.]+) m/s", _status(container)).group(1))
    assert shown == pytest.approx(cs.speed, abs=0.1)


def test_free_wheelset_is_reported_unstable():
    container, update = chapter05.wheelset_roots()
    update(yaw_stiffness=0.0, lateral_stiffness=0.0)
    assert "unstable at the lowest speed" in _status(container)
