"""Chapter 7: critical speed of the full car, raildyn against python-control poles on a speed grid.

The baseline is the straightforward approach: build a ``control.StateSpace`` at
each of 1000 speeds, take its poles, and interpolate the speed where the largest
real part crosses zero. raildyn scans 64 speeds in one batched eigenvalue call
and refines the crossing by bracketed regula falsi. Both answers are checked to agree
within 0.1 m/s (the grid spacing of the baseline is 0.2 m/s, and its linear
interpolation is far better than that) before timing counts.
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, critical_speed_case, fresh_frame, timed, widget_case
from raildyn import stability
from raildyn.vehicles import LateralCar

SPEED_RANGE = (1.0, 200.0)  # m/s


def _bifurcation_case(repeats: int) -> Case:
    # One bifurcation diagram of the nonlinear car: 11 speeds from 100 down to 50 m/s, 8 s each, and 4
    # bisections on the nonlinear critical speed. raildyn's compiled engine against the same diagram
    # integrated by scipy's RK45 on the numpy right-hand side (engine="scipy", the path the engine
    # replaced); both take the same steps, and the diagrams must agree before the timing counts.
    car = LateralCar().nonlinear()
    speeds = np.linspace(50.0, 100.0, 11)

    def diagram(engine):
        return stability.bifurcation_diagram(car, speeds, progress=False, engine=engine)

    stability.limit_cycle_amplitude(car, 80.0, duration=0.1)  # loads the compiled engine: not timed
    results = {}
    slow_times = timed(lambda i: results.setdefault("scipy", diagram("scipy")), 1)
    fast_times = timed(lambda i: results.setdefault("compiled", diagram("compiled")), repeats)
    fast, slow = results["compiled"], results["scipy"]
    np.testing.assert_array_equal(fast.hunting, slow.hunting)
    agree = float(np.abs(fast.amplitudes - slow.amplitudes).max())
    assert agree < 1e-4 * slow.amplitudes.max()
    assert fast.nonlinear_critical_speed == slow.nonlinear_critical_speed
    return Case(
        f"bifurcation diagram of the car, 11 speeds × 8 s + 4 bisections (agree to {1e6 * agree:.1f} µm)",
        fast_times,
        slow_times,
        "≤ 1 s and ≥ 15× faster",
        "scipy RK45 on the numpy right-hand side",
    )


def _bifurcation_widget_case(repeats: int) -> Case:
    # The live bifurcation diagram moved off its kernel-free grid: every move runs one diagram (13
    # speeds of 4 s, three bisections), each at a conicity not run before, so that no cache answers.
    # Its goal is the diagram's, 1 s, not the 30 ms of the widgets that draw a closed form.
    from raildyn.widgets import chapter07

    _, update = chapter07.BIFURCATION.build()
    live = timed(lambda i: update(conicity=0.101 + 0.002 * i), repeats)
    naive = timed(lambda i: fresh_frame(chapter07.BIFURCATION, conicity=0.201 + 0.002 * i), repeats)
    return Case(
        "widget ch07 bifurcation λ (off the grid: one diagram a move)",
        live,
        naive,
        "≤ 1 s (one diagram)",
        "new figure per change",
    )


def cases(repeats: int):
    from raildyn.widgets import chapter05, chapter07

    result = [critical_speed_case("Manchester car (15 dof)", LateralCar(), SPEED_RANGE, repeats)]
    for label, recipe, control_name, values in chapter05.BENCH_MOVES + chapter07.BENCH_MOVES:
        result.append(widget_case(label, recipe, control_name, values, repeats))
    result.append(_bifurcation_case(repeats))
    result.append(_bifurcation_widget_case(repeats))
    return result
