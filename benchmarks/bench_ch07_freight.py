"""Chapter 7: critical speed of the freight car on three-piece trucks, empty and loaded, raildyn against
python-control poles on a speed grid.

The baseline is the straightforward approach: build a ``control.StateSpace`` of the
17-coordinate car at each of 1000 speeds from 2 to 100 m/s (0.1 m/s apart), take its
poles, and interpolate the speed where the largest real part first crosses zero. raildyn
(:func:`raildyn.stability.critical_speed`) scans 64 speeds in one batched eigenvalue call
and refines the crossing with Brent's method to 0.01 m/s. Both answers are checked to agree
within 0.1 m/s (the grid's spacing; its linear interpolation is far better than that)
before timing counts.
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed
from raildyn import stability, vibration
from raildyn.vehicles import EMPTY_FREIGHT_CAR, LOADED_FREIGHT_CAR

SPEED_RANGE = (2.0, 100.0)  # m/s


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


def _critical_speed_case(label: str, car, repeats: int) -> Case:
    ours = stability.critical_speed(car.linear_system(), SPEED_RANGE).speed
    theirs = _poles_on_grid(car.linear_system())
    if abs(ours - theirs) > 0.1:
        raise AssertionError(
            f"critical speeds of the {label} car disagree: raildyn {ours:.3f}, python-control grid "
            f"{theirs:.3f} m/s"
        )
    fast = timed(lambda i: stability.critical_speed(car.linear_system(), SPEED_RANGE), repeats)
    slow = timed(lambda i: _poles_on_grid(car.linear_system()), max(1, repeats // 3))
    return Case(
        f"critical speed of the {label} freight car on three-piece trucks (17 dof, {ours:.2f} m/s)",
        fast,
        slow,
        "≥ 20× faster at equal accuracy (0.1 m/s)",
        "python-control poles, 1000-point grid",
    )


def cases(repeats: int):
    return [
        _critical_speed_case("empty", EMPTY_FREIGHT_CAR, repeats),
        _critical_speed_case("loaded", LOADED_FREIGHT_CAR, repeats),
    ]
