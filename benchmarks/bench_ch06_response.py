"""Chapter 6: RMS car-body acceleration over 2000 frequencies for 50 speeds.

raildyn (:func:`raildyn.vehicles.response.rms_over_speeds`) solves the 6×6
dynamic-stiffness system for all 2000 frequencies in one batched call (the axle
FRFs do not depend on speed) and forms each speed's delayed sum and temporal
spectrum as array operations. The baseline is the straightforward loop: for
each speed and each frequency, one ``np.linalg.solve``, the delayed sum over the
four axles and the spectrum, then the trapezoid rule. The chapter's ride and wheel-unloading
widgets are timed against a new figure per change.
"""

from __future__ import annotations

import numpy as np

from benchmarks.common import Case, timed, widget_case
from raildyn import track
from raildyn.vehicles.response import rms_over_speeds
from raildyn.vehicles.vertical import MANCHESTER_VERTICAL
from raildyn.widgets import chapter06

OMEGA = np.linspace(0.2, 2 * np.pi * 30.0, 2000)  # rad/s
SPEEDS = np.linspace(10.0, 60.0, 50)  # m/s


def _psd(w):
    return track.fra_psd("vertical", 4, w)


def _loop(vehicle) -> np.ndarray:
    out = np.empty(SPEEDS.size)
    o = np.zeros(vehicle.size)
    o[0] = 1.0
    for i, V in enumerate(SPEEDS):
        tau = vehicle.input_positions / V
        S = np.empty(OMEGA.size)
        mats = vehicle.matrices(V)
        for k, w in enumerate(OMEGA):
            Z = mats.K - w**2 * mats.M + 1j * w * mats.C
            X = np.linalg.solve(Z, vehicle.GK + 1j * w * vehicle.GC)
            H = -(w**2) * (o @ X) @ np.exp(-1j * w * tau)
            S[k] = abs(H) ** 2 * _psd(np.array([w / V]))[0] / V
        out[i] = np.sqrt(np.trapezoid(S, OMEGA))
    return out


def cases(repeats: int):
    vehicle = MANCHESTER_VERTICAL.linear_system()
    fast_result = rms_over_speeds(vehicle, _psd, SPEEDS, OMEGA, component="vertical")
    slow_result = _loop(vehicle)
    # the same numbers by both routes (rounding only), or the timing means nothing
    np.testing.assert_allclose(fast_result, slow_result, rtol=1e-10)
    fast = timed(
        lambda i: rms_over_speeds(vehicle, _psd, SPEEDS, OMEGA, component="vertical"), max(repeats, 3)
    )
    slow = timed(lambda i: _loop(vehicle), max(1, repeats // 3))
    return [
        Case(
            "car-body RMS acceleration, 2000 frequencies × 50 speeds",
            fast,
            slow,
            "≥ 20× faster",
            "per-frequency Python loop",
        ),
        widget_case("ch06 ride quality", chapter06.RIDE, "speed_kmh", [80.0, 120.0, 160.0, 200.0], repeats),
        # the rocking car's runs are made once, when the widget is built (chapter06.unloading_sweep):
        # an update, like a new figure, only draws
        widget_case(
            "ch06 wheel unloading", chapter06.WHEEL_UNLOADING, "speed_kmh", [22.0, 26.0, 30.0, 34.0], repeats
        ),
    ]
