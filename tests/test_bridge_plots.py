"""Chapter 10's curves: one drawing (plot_amplification, BridgeCrossing.plot) for figures and widgets."""

import numpy as np
import pytest
from matplotlib.figure import Figure

from raildyn import figures
from raildyn.bridge import (
    SimplySupportedBeam,
    crossing,
    moving_force_response,
    plot_amplification,
    sprung_mass,
)
from raildyn.widgets import chapter10

BEAM = SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.01, modes=3)


def test_the_amplification_is_drawn_against_kmh_or_alpha_and_moved_in_place():
    r = moving_force_response(BEAM, [20.0, 40.0, 60.0], 1.0e5)
    ax = Figure().subplots()
    drawn = r.plot(ax)
    np.testing.assert_array_equal(drawn["line"].get_xdata(), 3.6 * r.speeds)
    np.testing.assert_array_equal(drawn["line"].get_ydata(), r.amplification)
    scale = 2 * BEAM.frequencies_hz[0] * BEAM.span
    other = moving_force_response(BEAM, [30.0, 50.0, 70.0], 1.0e5)
    assert other.plot(alpha_speed=scale, artists=drawn) is drawn
    np.testing.assert_allclose(drawn["line"].get_xdata(), other.speeds / scale, rtol=1e-15)
    assert len(ax.lines) == 1  # moved, not drawn anew
    with pytest.raises(ValueError, match="amplification must have shape"):
        plot_amplification([20.0, 40.0], [1.0], ax)


def test_a_crossing_draws_its_deflection_and_its_bodys_acceleration():
    load = sprung_mass(5000.0, 1.0e6)
    run = crossing(BEAM, load, 40.0, time_step=1e-3)
    ax = Figure().subplots()
    drawn = run.plot(ax, color="k")
    np.testing.assert_array_equal(drawn["line"].get_ydata(), 1e3 * run.deflection)
    np.testing.assert_array_equal(drawn["static"].get_ydata(), 1e3 * run.static_deflection)
    assert ax.lines[0] is drawn["static"]  # the slow crossing first, under the others
    assert ax.yaxis_inverted()
    run.plot(ax, static=False)  # a second crossing on the same axes keeps downwards drawn down
    assert ax.yaxis_inverted()  # (the former drawing inverted the axis at every call)
    body = Figure().subplots()
    accel = run.plot(body, quantity="body acceleration")["line"]
    np.testing.assert_array_equal(accel.get_ydata(), run.vehicle_acceleration("body z"))
    forces = crossing(BEAM, moving_force_load(), 40.0, time_step=1e-3)
    with pytest.raises(ValueError, match="no body"):
        forces.plot(body, quantity="body acceleration")


def moving_force_load():
    from raildyn.bridge import AxleSequence

    return AxleSequence([0.0], [1.0e5])


def test_the_figures_and_the_widgets_draw_the_same_curves():
    # the train's resonance: figure and widget at d = 18 m, L = 20 m, f₁ = 4 Hz, by the closed form at
    # their own samples (3000 against the widget's banded 200–2000): peaks within 1 %, as the widget's
    # comment measures against 10 000 samples
    fig = figures.make("fig10.train_resonance").axes[0].lines[0]
    container, update = chapter10.train_resonance()
    update(coach_length=18.0, span=20.0, frequency_hz=4.0)
    widget = container.live.figure.axes[0].lines[4]
    at = widget.get_xdata()[20:60]
    np.testing.assert_allclose(
        np.interp(at, fig.get_xdata(), fig.get_ydata()), widget.get_ydata()[20:60], rtol=0.02
    )
    assert fig.axes.get_xlabel() == widget.axes.get_xlabel() == "V (km/h)"
