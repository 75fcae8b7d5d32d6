"""Chapter 7: critical speed of the six-axle locomotive, raildyn against python-control poles on a speed grid.

The baseline is the straightforward approach: build a ``control.StateSpace`` of the
19-coordinate locomotive at each of 1000 speeds, take its poles, and interpolate the
speed where the largest real part crosses zero. raildyn scans 64 speeds in one batched
eigenvalue call and refines the crossing with Brent's method. Both answers are checked
to agree within 0.1 m/s (the baseline's grid spacing is 0.2 m/s, and its linear
interpolation is far better than that) before timing counts.
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed
from raildyn import stability, vibration
from raildyn.vehicles import LATERAL_LOCOMOTIVE

SPEED_RANGE = (1.0, 200.0)  # m/s


def _poles_on_grid(system, n: int = 1000) -> float:
    import control

    speeds = np.linspace(*SPEED_RANGE, n)
    B = np.ones((system.size, 1))
    g = np.empty(n)
    for i, V in enumerate(speeds):
        mats = system.matrices(V)
        g[i] = control.poles(vibration.to_control(mats.M, mats.C, mats.K, B)).real.max()
    k = int(np.flatnonzero((g[:-1] < 0) & (g[1:] >= 0))[0])
    return float(speeds[k] - g[k] * (speeds[k + 1] - speeds[k]) / (g[k + 1] - g[k]))


def _critical_speed_case(repeats: int) -> Case:
    loco = LATERAL_LOCOMOTIVE
    ours = stability.critical_speed(loco.linear_system(), SPEED_RANGE).speed
    theirs = _poles_on_grid(loco.linear_system())
    if abs(ours - theirs) > 0.1:
        raise AssertionError(
            f"critical speeds disagree: raildyn {ours:.3f}, python-control grid {theirs:.3f} m/s"
        )
    fast = timed(lambda i: stability.critical_speed(loco.linear_system(), SPEED_RANGE), repeats)
    slow = timed(lambda i: _poles_on_grid(loco.linear_system()), max(1, repeats // 3))
    return Case(
        "critical speed of the six-axle locomotive (19 dof)",
        fast,
        slow,
        "≥ 20× faster at equal accuracy (0.1 m/s)",
        "python-control poles, 1000-point grid",
    )


def cases(repeats: int):
    return [_critical_speed_case(repeats)]
