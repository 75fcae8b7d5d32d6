"""Chapter 7: critical speed of the freight car on three-piece trucks (empty and loaded) and of the
six-axle locomotive, raildyn against python-control poles on a 1000-point speed grid.

The baseline is the straightforward approach: a ``control.StateSpace`` at each of 1000 speeds,
its poles, and the speed where the largest real part first crosses zero, interpolated. raildyn
(:func:`raildyn.stability.critical_speed`) scans 64 speeds in one batched eigenvalue call and
refines the crossing by bracketed regula falsi (``benchmarks.common.critical_speed_case``).
"""

from __future__ import annotations

from benchmarks.common import critical_speed_case
from raildyn.vehicles import EMPTY_FREIGHT_CAR, LATERAL_LOCOMOTIVE, LOADED_FREIGHT_CAR

FREIGHT_SPEEDS = (2.0, 100.0)  # m/s: 0.1 m/s apart on the grid; both cars cross below 40 m/s
LOCOMOTIVE_SPEEDS = (1.0, 200.0)  # m/s: 0.2 m/s apart; the locomotive crosses near 101 m/s


def cases(repeats: int):
    return [
        critical_speed_case("empty freight car on three-piece trucks (17 dof)", EMPTY_FREIGHT_CAR,
                            FREIGHT_SPEEDS, repeats),
        critical_speed_case("loaded freight car on three-piece trucks (17 dof)", LOADED_FREIGHT_CAR,
                            FREIGHT_SPEEDS, repeats),
        critical_speed_case("six-axle locomotive (19 dof)", LATERAL_LOCOMOTIVE, LOCOMOTIVE_SPEEDS, repeats),
    ]  # fmt: skip
