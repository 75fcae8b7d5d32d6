"""Chapter 8: a quasi-static curving map of the nonlinear bogie, 40 radii × 30 speeds, raildyn against a
per-point ``scipy.optimize.fsolve`` loop started cold; and the chapter's widgets (the running-safety
chart of ``raildyn.widgets.chapter08_safety`` among them), each update against a new figure per change
(``benchmarks.common.widget_case``).

raildyn (:func:`raildyn.curving.curving_map`) solves all 1200 points together: one Newton's method on
the whole batch, its forces and Jacobian evaluated by the compiled engine
(:meth:`raildyn.wheelset.NonlinearLateral.arc_forces`), started from the linear steady state and
continued from solved neighbours. The first baseline is the
straightforward loop: at each point, ``fsolve`` on the same forces
(:meth:`raildyn.wheelset.NonlinearLateral.arc_forces`) from the centred state. The answers must agree
to 1e-8 m and rad wherever ``fsolve`` converges (from the centred state it can stall near the flange;
the check leaves such points out and the timing keeps them) before the timing counts. The second
baseline is the same map with the same Newton and the forces in numpy: the path a model with a
Python force law takes.

The curve-entry widget makes its runs (a bogie into a curve at four speeds) once, when it is first
built, and keeps them: its first build against a build from the kept runs.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import fsolve

from benchmarks.common import Case, timed, widget_case
from raildyn.curving import curving_map
from raildyn.track import unbalanced_acceleration
from raildyn.vehicles import Bogie
from raildyn.wheelset import NonlinearLateral

RADII = np.geomspace(150.0, 3000.0, 40)  # m
SPEEDS = np.linspace(10.0, 25.0, 30)  # m/s (36 to 90 km/h): every point keeps both wheels loaded
CANT = 0.1  # m


def _cold_loop(model) -> tuple[np.ndarray, np.ndarray]:
    """fsolve from q = 0 at every (R, V); the solutions (r, s, n) and where it converged (r, s)."""
    n = model.system.size
    q = np.empty((RADII.size, SPEEDS.size, n))
    ok = np.empty((RADII.size, SPEEDS.size), dtype=bool)
    for i, R in enumerate(RADII):
        for j, V in enumerate(SPEEDS):
            args = (V, 1.0 / R, unbalanced_acceleration(V, R, CANT))
            x, _, flag, _ = fsolve(model.arc_forces, np.zeros(n), args=args, full_output=True, xtol=1e-12)
            q[i, j] = x
            ok[i, j] = flag == 1 and np.abs(model.arc_forces(x, *args)).max() < 1e-3
    return q, ok


def _entry_case(repeats: int) -> Case:
    """The curve-entry widget built from its kept runs, against its first build (the four runs)."""
    from raildyn.widgets import chapter08

    def cold(i):
        chapter08._entry_runs.cache_clear()
        chapter08.curve_entry_speed()

    slow = timed(cold, max(1, repeats // 5))
    fast = timed(lambda i: chapter08.curve_entry_speed(), repeats)
    return Case(
        "widget ch08 curve_entry_speed built from its kept runs",
        fast,
        slow,
        "first build ≤ 5 s, then ≤ 0.5 s",
        "first build (four curve entries)",
    )


def cases(repeats: int):
    from raildyn.widgets import chapter08, chapter08_safety

    return (
        _map_case(repeats)
        + [_entry_case(repeats)]
        + [
            widget_case(label, recipe, control, values, repeats)
            for label, recipe, control, values in chapter08.BENCH_MOVES + chapter08_safety.BENCH_MOVES
        ]
    )


def _map_case(repeats: int) -> list[Case]:
    model = Bogie().nonlinear()
    ours = curving_map(model, SPEEDS, RADII, CANT)
    theirs, ok = _cold_loop(model)
    system = model.system
    iy = [w[0] for w in system.wheelsets]
    ipsi = [w[1] for w in system.wheelsets]
    x = system.wheelset_positions
    # the baseline's wheelset offsets and yaws relative to the track, outwards (as the map reports them)
    offset = -(theirs[:, :, iy] - 0.5 * x**2 / RADII[:, None, None])
    attack = -(theirs[:, :, ipsi] - x / RADII[:, None, None])
    gap = max(np.abs(offset - ours.offset)[ok].max(), np.abs(attack - ours.angle_of_attack)[ok].max())
    if gap > 1e-8:
        raise AssertionError(f"curving maps disagree by {gap:.3g} where fsolve converged")
    numpy_model = _NumpyForces(model.system, model.contact)
    before = curving_map(numpy_model, SPEEDS, RADII, CANT)
    gap_numpy = max(
        np.abs(before.offset - ours.offset).max(), np.abs(before.angle_of_attack - ours.angle_of_attack).max()
    )
    if gap_numpy > 1e-8:
        raise AssertionError(f"the compiled and the numpy forces disagree by {gap_numpy:.3g}")
    fast = timed(lambda i: curving_map(model, SPEEDS, RADII, CANT), repeats)
    slow = timed(lambda i: _cold_loop(model), max(1, repeats // 5))
    numpy_forces = timed(lambda i: curving_map(numpy_model, SPEEDS, RADII, CANT), repeats)
    name = f"quasi-static curving map of the bogie, 40 radii × 30 speeds ({ok.sum()} of 1200 checked)"
    return [
        Case(
            name, fast, slow, "≥ 20× faster at the same answer (1e-8 m, rad)", "fsolve per point from q = 0"
        ),
        Case(
            name,
            fast,
            numpy_forces,
            "≥ 1.3× (same answer to 1e-8; one law, compiled on both paths)",
            "the same Newton, forces in numpy",
        ),
    ]


class _NumpyForces(NonlinearLateral):
    """The model with the compiled engine refused: its forces in numpy, as a Python force law has them."""

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "compiled_reason", "the benchmark's numpy baseline")
        object.__setattr__(self, "_row", None)
