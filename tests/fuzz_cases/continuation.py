"""Fuzz registry: the branch of limit cycles by continuation (raildyn.stability.continuation).

The valid call follows the soft suspended wheelset of chapter 5 (linear critical speed 54.5 m/s)
for two steps from its flange-contact cycle at 60 m/s, found by shooting: a few hundredths of a
second of compiled runs.
"""

from __future__ import annotations

import functools

from fuzzing import call, fuzz, on
from matplotlib.figure import Figure

from raildyn import stability as st
from raildyn import wheelset as wh

NW = wh.NonlinearWheelset(wh.Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))


@functools.cache
def start():
    """The wheelset's cycle at 60 m/s (shooting converges in one step from this guess)."""
    return st.periodic_orbit(NW, 60.0, [0.0103, -1.1e-4, 0.0, -0.229], 0.1742, rtol=1e-6, tol=1e-4)


@functools.cache
def branch():
    return st.limit_cycle_branch(NW, start(), max_points=3, rtol=1e-8)


def branch_call():
    b = branch()
    return call(
        b.speeds, b.amplitudes, b.periods, b.stable, b.multipliers, b.states, b.arclength,
        float(b.speeds[1]), float(b.amplitudes[1]),
    )  # fmt: skip


ENTRIES = [
    fuzz(
        "raildyn.stability.limit_cycle_branch",
        lambda: call(NW, start(), speed_range=(20.0, 80.0), max_points=3, rtol=1e-8),
        # A smaller end amplitude only stops later; a tolerance a thousand times coarser is a tolerance.
        accepts={"end_amplitude": "tiny", "rtol": "mm", "tol": "mm"},
        infinite=("fold_speed",),  # no fold on these two steps: +inf
    ),
    fuzz(
        "raildyn.stability.LimitCycleBranch",
        branch_call,
        accepts={
            "amplitudes": "zero",
            "stable": "bool",
            "multipliers": "zero negative complex",
            "states": "zero negative huge",  # the model's state, in its units: any finite numbers
            "fold_speed": "inf",
            "fold_amplitude": "zero big mm tiny",
        },
        infinite=("fold_speed",),  # no fold: +inf
    ),
    fuzz(
        "raildyn.stability.LimitCycleBranch.plot",
        lambda: on(branch(), Figure().subplots()),
        accepts={"ax": "none", "artists": "none"},  # None: new axes, new artists
    ),
]
