"""Forces a train makes on itself: traction by notch, dynamic brake and the automatic air brake.

Tractive effort follows the usual diesel-electric envelope: limited by adhesion
at low speed, then constant power (force ∝ 1/speed) above, both scaled by the
throttle notch (1–8). The dynamic brake rises with speed to its maximum, then
falls at constant power. The automatic air brake is applied from the front: the
brake-pipe signal travels along the train at a set speed and each vehicle's
cylinder pressure then builds up exponentially {cole2006}.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks

NOTCHES = 8


def tractive_effort(speed, notch, max_tractive_effort: float, rail_power: float):
    """Tractive effort of a locomotive, N.

    ``F = (notch/8) · min(F_adhesion, P_rail/|v|)``: the adhesion-limited effort at
    low speed, constant rail power above the crossover speed ``P/F``.

    Parameters
    ----------
    speed : float or array
        m/s (its sign is ignored).
    notch : int or float
        Throttle notch, 0 (idle) to 8.
    max_tractive_effort : float
        Adhesion-limited effort at notch 8, N (>= 0).
    rail_power : float
        Power at the rail at notch 8, W (>= 0).
    """
    v = np.abs(_checks.array("speed", speed))
    notch = _checks.scalar("notch", notch, low=0, high=NOTCHES)
    f_max = _checks.nonnegative("max_tractive_effort", max_tractive_effort)
    power = _checks.nonnegative("rail_power", rail_power)
    limited = np.minimum(f_max, power / np.maximum(v, 1e-6))  # the power limit is finite at standstill
    out = notch / NOTCHES * limited
    return out if out.ndim else float(out)


def dynamic_brake_force(speed, level, max_force: float, peak_speed: float = 8.0, fade_speed: float = 20.0):
    """Retarding force of a dynamic brake, N (>= 0).

    Rises linearly to ``level · max_force`` at ``peak_speed`` (m/s), holds it to
    ``fade_speed`` and then falls as ``fade_speed/|v|`` (constant power); an
    extended-range characteristic with assumed corner speeds.
    """
    v = np.abs(_checks.array("speed", speed))
    level = _checks.scalar("level", level, low=0.0, high=1.0)
    f = _checks.nonnegative("max_force", max_force)
    peak = _checks.positive("peak_speed", peak_speed)
    fade = _checks.scalar("fade_speed", fade_speed, low=peak)
    shape = np.minimum(v / peak, np.minimum(1.0, fade / np.maximum(v, 1e-12)))
    out = level * f * shape
    return out if out.ndim else float(out)


@dataclass(frozen=True)
class AirBrake:
    """An automatic air-brake application made at the front of the train.

    Parameters
    ----------
    start : float
        Time of the application at the front, s (>= 0).
    propagation_speed : float
        Speed of the brake-pipe signal along the train, m/s (> 0). Emergency
        applications propagate at roughly 250–290 m/s, service ones more slowly
        {cole2006}.
    build_up_time : float
        Time constant of the brake-cylinder pressure rise at each vehicle, s (> 0).
    level : float
        Fraction of the full (emergency) brake force, in (0, 1].
    """

    start: float = 0.0
    propagation_speed: float = 250.0
    build_up_time: float = 3.0
    level: float = 1.0

    def __post_init__(self):
        _checks.nonnegative("start", self.start)
        _checks.positive("propagation_speed", self.propagation_speed)
        _checks.positive("build_up_time", self.build_up_time)
        _checks.scalar("level", self.level, low=0.0, high=1.0, low_open=True)

    def arrival(self, distance):
        """Time the signal reaches a vehicle ``distance`` m behind the front, s."""
        return self.start + np.asarray(distance, float) / self.propagation_speed

    def fraction(self, t, distance):
        """Cylinder pressure as a fraction of full, ``level·(1 − exp(−(t − t_arrival)/τ))`` after arrival.

        ``t`` and ``distance`` broadcast against each other.
        """
        since = np.asarray(t, float) - self.arrival(distance)
        return self.level * -np.expm1(-np.maximum(since, 0.0) / self.build_up_time)
