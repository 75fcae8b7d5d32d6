"""The live bifurcation diagram of chapter 7 (raildyn.widgets.chapter07.bifurcation).

Its frames are the model's answers: the diagram it draws is the one bifurcation_diagram gives for the
same car, whether it came from the batch of the kernel-free grid or from a single run.
"""

import numpy as np
import pytest
from widget_helpers import status_line, widgets_of

from raildyn import stability
from raildyn.widgets import chapter07

pytestmark = widgets_of("chapter07")  # the grid's batch is made once, with chapter 7's other widget tests


def _car(conicity, yaw_stiffness):
    return chapter07._bifurcation_car(conicity, yaw_stiffness)


def test_the_grids_batch_is_each_cars_own_diagram():
    assert chapter07.BIFURCATION.prepare is chapter07._bifurcation_family  # the kernel-free copy's batch
    family = chapter07._bifurcation_family()
    grid = chapter07._BIFURCATION_GRID
    assert len(family) == len(grid["conicity"]) * len(grid["yaw_stiffness"])
    key = (grid["conicity"][-1], grid["yaw_stiffness"][0])
    alone = stability.bifurcation_diagram(
        _car(*key).nonlinear(), chapter07._BIFURCATION_SPEEDS, **chapter07._BIFURCATION_RUN
    )
    np.testing.assert_array_equal(family[key].amplitudes, alone.amplitudes)
    assert family[key].nonlinear_critical_speed == alone.nonlinear_critical_speed


def test_an_off_grid_value_runs_its_own_diagram_and_the_status_says_what_it_shows():
    container, update = chapter07.bifurcation()
    update(conicity=0.17)
    diagram, linear = chapter07._bifurcation(0.17, chapter07._K_PSI)
    assert (0.17, chapter07._K_PSI) not in chapter07._bifurcation_family()
    alone = stability.bifurcation_diagram(
        _car(0.17, chapter07._K_PSI).nonlinear(), chapter07._BIFURCATION_SPEEDS, **chapter07._BIFURCATION_RUN
    )
    np.testing.assert_array_equal(diagram.amplitudes, alone.amplitudes)
    # The car at λ = 0.17 hunts below its linear critical speed: the status names the subcritical band.
    assert diagram.nonlinear_critical_speed < linear.speed
    status = status_line(container)
    assert f"{3.6 * diagram.nonlinear_critical_speed:.0f} km/h" in status and "subcritical" in status


@pytest.mark.parametrize("conicity", [0.05, 0.3])
def test_a_steeper_cone_lowers_both_critical_speeds(conicity):
    # The grid's ends against the car's own conicity (0.15), at the car's yaw stiffness.
    diagram, linear = chapter07._bifurcation(conicity, chapter07._K_PSI)
    middle, middle_linear = chapter07._bifurcation(0.15, chapter07._K_PSI)
    sign = 1.0 if conicity < 0.15 else -1.0
    assert sign * (diagram.nonlinear_critical_speed - middle.nonlinear_critical_speed) > 0
    assert sign * (linear.speed - middle_linear.speed) > 0
