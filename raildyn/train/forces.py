"""Forces a train makes on itself: traction by notch, dynamic brake and the automatic air brake.

Tractive effort follows the usual diesel-electric envelope: limited by adhesion
at low speed, then constant power (force ∝ 1/speed) above, both scaled by the
throttle notch (1–8). The dynamic brake rises with speed to its maximum, then
falls at constant power. The automatic air brake is applied from the front: the
brake-pipe signal travels along the train at a set speed and each vehicle's
cylinder pressure then builds up exponentially {cole2006}.

The corner speeds of the dynamic brake, ``DYNAMIC_BRAKE_PEAK_SPEED`` and
``DYNAMIC_BRAKE_FADE_SPEED``, are defined here once: the train's compiled
right-hand side reads them from this module when a model is built.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks

__all__ = [
    "DYNAMIC_BRAKE_FADE_SPEED",
    "DYNAMIC_BRAKE_PEAK_SPEED",
    "NOTCHES",
    "AirBrake",
    "dynamic_brake_force",
    "tractive_effort",
]

#: Throttle notches of a North American diesel-electric locomotive (idle, then 1 to 8).
NOTCHES = 8

#: Speed at which the dynamic brake reaches its largest force, m/s (about 29 km/h). An
#: assumed extended-range characteristic: the grid current limit holds the force down to
#: a few m/s, below which it falls with the motors' EMF (Cole 2006 {cole2006} shows the
#: shape; these corner speeds are typical assumed values, not one locomotive's data).
DYNAMIC_BRAKE_PEAK_SPEED = 8.0
#: Speed above which the dynamic brake falls at constant power (force ∝ 1/speed), m/s
#: (72 km/h); assumed, as ``DYNAMIC_BRAKE_PEAK_SPEED``.
DYNAMIC_BRAKE_FADE_SPEED = 20.0

# Fastest brake-pipe signal, m/s: the speed of sound in air at 20 °C; a pressure wave in the pipe
# cannot outrun it (emergency applications travel at about 250-290 m/s {cole2006}).
_SOUND_SPEED = 343.0
# Slowest: a signal slower than 10 m/s (36 km/h) would be outrun by the train it brakes.
_SLOWEST_SIGNAL = 10.0


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

    Returns
    -------
    float or ndarray
        Tractive effort, N (>= 0), the shape of ``speed``.

    Examples
    --------
    >>> round(tractive_effort(2.0, 8, 500e3, 2e6) / 1e3)  # adhesion-limited
    500
    >>> round(tractive_effort(20.0, 4, 500e3, 2e6) / 1e3)  # half of 2 MW / 20 m/s
    50
    """
    v = np.abs(_checks.plausible_array("speed", speed, "speed", signed=True, allow_empty=False))
    notch = _checks.scalar("notch", notch, low=0, high=NOTCHES)
    f_max = _checks.nonnegative("max_tractive_effort", max_tractive_effort)
    power = _checks.nonnegative("rail_power", rail_power)
    limited = np.minimum(f_max, power / np.maximum(v, 1e-6))  # the power limit is finite at standstill
    out = notch / NOTCHES * limited
    return out if out.ndim else float(out)


def dynamic_brake_force(speed, level, max_force: float, peak_speed=None, fade_speed=None):
    """Retarding force of a dynamic brake, N (>= 0).

    Rises linearly to ``level · max_force`` at ``peak_speed``, holds it to
    ``fade_speed`` and then falls as ``fade_speed/|v|`` (constant power):

    ``D = level · max_force · min(|v|/v_peak, 1, v_fade/|v|)``.

    Parameters
    ----------
    speed : float or array
        m/s (its sign is ignored).
    level : float
        Dynamic-brake handle position, 0 to 1.
    max_force : float
        Largest retarding force at full level, N (>= 0).
    peak_speed : float, optional
        Corner speed where the force reaches its maximum, m/s, in (0,
        :data:`~raildyn.constants.MAXIMUM_SPEED`]; default ``DYNAMIC_BRAKE_PEAK_SPEED``.
    fade_speed : float, optional
        Corner speed above which the force falls at constant power, m/s
        (>= ``peak_speed``, at most :data:`~raildyn.constants.MAXIMUM_SPEED`); default
        ``DYNAMIC_BRAKE_FADE_SPEED``.

    Returns
    -------
    float or ndarray
        Retarding force, N (>= 0), the shape of ``speed``.

    Examples
    --------
    >>> dynamic_brake_force([4.0, 12.0, 40.0], 1.0, 300e3) / 1e3
    array([150., 300., 150.])
    """
    v = np.abs(_checks.plausible_array("speed", speed, "speed", signed=True, allow_empty=False))
    level = _checks.scalar("level", level, low=0.0, high=1.0)
    f = _checks.nonnegative("max_force", max_force)
    peak = _checks.speed("peak_speed", DYNAMIC_BRAKE_PEAK_SPEED if peak_speed is None else peak_speed)
    fade = _checks.speed(
        "fade_speed", DYNAMIC_BRAKE_FADE_SPEED if fade_speed is None else fade_speed, low=peak, low_open=False
    )
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
        Speed of the brake-pipe signal along the train, m/s, in [10, 343]. Emergency
        applications propagate at roughly 250–290 m/s, service ones more slowly
        {cole2006}; a pressure signal in air cannot outrun sound (343 m/s at 20 °C), so a
        faster one is a slip (e.g. km/h typed for m/s), and one slower than 10 m/s would be
        outrun by the train.
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
        _checks.scalar("propagation_speed", self.propagation_speed, low=_SLOWEST_SIGNAL, high=_SOUND_SPEED)
        _checks.positive("build_up_time", self.build_up_time)
        _checks.scalar("level", self.level, low=0.0, high=1.0, low_open=True)

    def arrival(self, distance):
        """Time the brake-pipe signal reaches a vehicle ``distance`` behind the front, s.

        Parameters
        ----------
        distance : float or array
            Distance behind the front of the train, m (>= 0).

        Returns
        -------
        float or ndarray
            ``start + distance / propagation_speed``, s, the shape of ``distance``.

        Examples
        --------
        >>> AirBrake(start=1.0, propagation_speed=250.0).arrival(1000.0)
        5.0
        """
        d = _checks.array("distance", distance, low=0.0, allow_empty=False)
        out = self.start + d / self.propagation_speed
        return out if out.ndim else float(out)

    def fraction(self, t, distance):
        """Cylinder pressure as a fraction of full, ``level·(1 − exp(−(t − t_arrival)/τ))`` after arrival.

        Parameters
        ----------
        t : float or array
            Time, s.
        distance : float or array
            Distance behind the front of the train, m (>= 0); broadcasts against ``t``.

        Returns
        -------
        float or ndarray
            Fraction of the full brake force, 0 before the signal arrives, rising to ``level``.
        """
        t = _checks.array("t", t, allow_empty=False)
        since = t - self.arrival(distance)
        out = self.level * -np.expm1(-np.maximum(since, 0.0) / self.build_up_time)
        return out if np.ndim(out) else float(out)
