"""Wheel climb (book chapter 8): Nadal's limit and Weinstock's axle-sum criterion.

A flanging wheel pressed against the rail with a lateral force Y under a vertical load Q
(the L and V of American practice) is held at its flange contact, inclined at the flange
angle ϑ_f, by the normal force N and the friction μN. Rolling with a positive angle of
attack, the flange slides down the rail's gauge face, so the friction on the wheel acts up
the flange face: Y = N sin ϑ_f − μN cos ϑ_f and Q = N cos ϑ_f + μN sin ϑ_f, with the
friction saturated. The largest quotient the contact can hold is Nadal's (1908); above it
the wheel climbs:

    Y/Q = (tan ϑ_f − μ) / (1 + μ tan ϑ_f),

(Garg & Dukkipati 1984, ch. 8; derived in notebook 08). Nadal's limit is conservative when
the angle of attack is small and the friction at the flange is not saturated. Weinstock
(1984) noticed that the other wheel of the axle, sliding sideways on its tread, carries a
saturated lateral creep force μ₂Q₂ that the flange must carry too, and proposed to compare
the *sum* of the two wheels' |Y/Q| with Nadal's limit of the flanging wheel plus the friction
coefficient of the other wheel:

    |Y₁/Q₁| + |Y₂/Q₂| ≤ (tan ϑ_f − μ)/(1 + μ tan ϑ_f) + μ₂.

Angles in rad, forces in N; the quotients are ratios.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import scalar
from raildyn.constants import PLAUSIBLE_RANGES

__all__ = [
    "MAXIMUM_FRICTION",
    "WheelClimb",
    "nadal_limit",
    "plot_nadal_limit",
    "weinstock_limit",
    "wheel_climb",
]

MAXIMUM_FRICTION = PLAUSIBLE_RANGES["friction"].high
"""The largest friction coefficient accepted, 1 (``raildyn.constants.PLAUSIBLE_RANGES["friction"]``).
Dry, clean wheel–rail steel reaches about 0.6; 1 is a generous bound, beyond which the number is
most likely a percentage."""


def _values(name: str, value, *, low: float, high: float, low_open: bool = False, high_open: bool = False):
    """``value`` as a non-empty finite array within the bounds, checked by :mod:`raildyn._checks`."""
    arr = _checks.array(name, value, low=low, low_open=low_open, allow_empty=False)
    scalar(name, arr.max(), low=low, low_open=low_open, high=high, high_open=high_open)
    return arr


def _flange_angle(value) -> np.ndarray:
    # rad, strictly between 0 and π/2 (a flange angle given in degrees is refused here).
    return _values("flange_angle", value, low=0.0, low_open=True, high=np.pi / 2, high_open=True)


def _friction(name: str, value) -> np.ndarray:
    return _values(name, value, low=0.0, high=MAXIMUM_FRICTION)


def _result(value: np.ndarray, *inputs):
    return float(value) if all(np.ndim(x) == 0 for x in inputs) else value


def nadal_limit(flange_angle, friction):
    """Nadal's limit of the flanging wheel's Y/Q before it climbs the rail.

    Y/Q = (tan ϑ_f − μ) / (1 + μ tan ϑ_f) (Nadal 1908; Garg & Dukkipati 1984, ch. 8): equal to
    tan ϑ_f without friction, smaller as μ grows (negative once μ > tan ϑ_f).

    Parameters
    ----------
    flange_angle : float or array_like
        ϑ_f, the largest angle of the flange to the horizontal, rad, in (0, π/2)
        (typically 60° to 75°).
    friction : float or array_like
        μ at the flange contact, in [0, :data:`MAXIMUM_FRICTION`]; broadcast against
        ``flange_angle``.

    Returns
    -------
    float or ndarray
        The limiting Y/Q (a float for single numbers).

    Examples
    --------
    >>> round(nadal_limit(np.radians(70.0), 0.36), 3)  # the 1.2 of UIC 518 and EN 14363
    1.2
    >>> round(nadal_limit(np.radians(75.0), 0.5), 3)
    1.128
    """
    delta = _flange_angle(flange_angle)
    mu = _friction("friction", friction)
    _checks.broadcast(flange_angle=delta, friction=mu)
    t = np.tan(delta)
    return _result((t - mu) / (1.0 + mu * t), flange_angle, friction)


def weinstock_limit(flange_angle, friction, other_friction=None):
    """Weinstock's limit of an axle's sum of |Y/Q|: Nadal's limit of the flanging wheel plus μ₂.

    Σ|Y/Q| ≤ (tan ϑ_f − μ)/(1 + μ tan ϑ_f) + μ₂ (Weinstock 1984), with μ₂ the friction of the
    axle's other (non-flanging) wheel on its rail head. Never below :func:`nadal_limit`.

    Parameters
    ----------
    flange_angle : float or array_like
        ϑ_f, rad, in (0, π/2).
    friction : float or array_like
        μ at the flange contact, in [0, :data:`MAXIMUM_FRICTION`].
    other_friction : float or array_like, optional
        μ₂ at the other wheel's tread, in [0, :data:`MAXIMUM_FRICTION`]; ``friction`` if None.

    Returns
    -------
    float or ndarray
        The limiting axle sum Σ|Y/Q|.

    Examples
    --------
    >>> round(weinstock_limit(np.radians(75.0), 0.5), 3)
    1.628
    """
    nadal = np.asarray(nadal_limit(flange_angle, friction))
    other = friction if other_friction is None else other_friction
    mu2 = _friction("other_friction", other)
    _checks.broadcast(flange_angle=flange_angle, friction=friction, other_friction=mu2)
    return _result(nadal + mu2, flange_angle, friction, other)


@dataclass(frozen=True)
class WheelClimb:
    """The wheel-climb quotients of an axle (or of a history of an axle's forces) against their limits.

    Attributes
    ----------
    wheel_quotient : ndarray, shape (..., 2)
        Y/Q of each wheel, signed as the forces given.
    flanging_wheel : int or ndarray of int, shape (...)
        0 or 1: the wheel of the larger |Y/Q|, taken as the flanging one.
    flange_quotient : float or ndarray, shape (...)
        |Y/Q| of the flanging wheel (≥ 0), to compare with ``nadal_limit``.
    axle_sum : float or ndarray, shape (...)
        |Y₁/Q₁| + |Y₂/Q₂| (≥ 0), to compare with ``weinstock_limit``.
    nadal_limit : float
        :func:`nadal_limit` of the flange angle and friction.
    weinstock_limit : float
        :func:`weinstock_limit`: ``nadal_limit`` plus the other wheel's friction.
    flange_angle : float
        ϑ_f, rad, in (0, π/2).
    friction : float
        μ at the flange, in [0, :data:`MAXIMUM_FRICTION`].
    other_friction : float
        μ₂ at the other wheel, in [0, :data:`MAXIMUM_FRICTION`].
    """

    wheel_quotient: np.ndarray
    flanging_wheel: int | np.ndarray
    flange_quotient: float | np.ndarray
    axle_sum: float | np.ndarray
    nadal_limit: float
    weinstock_limit: float
    flange_angle: float
    friction: float
    other_friction: float

    def __post_init__(self):
        _checks.fields(self)

    @property
    def nadal_exceeded(self):
        """Whether the flanging wheel's |Y/Q| passes Nadal's limit (bool, or an array of them)."""
        return np.asarray(self.flange_quotient) > self.nadal_limit

    @property
    def weinstock_exceeded(self):
        """Whether the axle sum passes Weinstock's limit (bool, or an array of them)."""
        return np.asarray(self.axle_sum) > self.weinstock_limit

    def plot(self, ax=None) -> dict:
        """Draw the flanging wheel's |Y/Q| and the axle sum against their limits, sample by sample.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            The artists: ``flange`` and ``axle_sum`` (markers and lines over the samples),
            ``nadal`` and ``weinstock`` (the two limits, horizontal lines).
        """
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        flange = np.atleast_1d(self.flange_quotient)
        total = np.atleast_1d(self.axle_sum)
        n = np.arange(flange.size)
        with matplotlib.rc_context(plots.STYLE):
            (f_line,) = ax.plot(n, flange, "o-", color=plots.COLORS[0], label="flanging wheel $|Y/Q|$")
            (s_line,) = ax.plot(n, total, "s-", color=plots.COLORS[1], label="axle sum $\\Sigma|Y/Q|$")
            nadal = ax.axhline(self.nadal_limit, ls="--", color=plots.COLORS[0], label="Nadal's limit")
            weinstock = ax.axhline(
                self.weinstock_limit, ls="--", color=plots.COLORS[1], label="Weinstock's limit"
            )
            ax.set_xlabel("sample")
            ax.set_ylabel("$Y/Q$")
            ax.legend()
        return {"flange": f_line, "axle_sum": s_line, "nadal": nadal, "weinstock": weinstock}


def wheel_climb(lateral, vertical, flange_angle, friction, other_friction=None) -> WheelClimb:
    """Both wheel-climb criteria for an axle's wheel forces: Nadal's and Weinstock's.

    The flanging wheel is the one of the larger |Y/Q|; its quotient is held to Nadal's
    limit (Garg & Dukkipati 1984, ch. 8), and the axle's sum |Y₁/Q₁| + |Y₂/Q₂| to
    Weinstock's (Weinstock 1984).

    Parameters
    ----------
    lateral : array_like, shape (..., 2)
        Y, the lateral force of the rail on each wheel, N (either sign); one row per
        axle or per instant.
    vertical : array_like, shape (..., 2)
        Q, the vertical load of each wheel, N (> 0: an unloaded wheel has no quotient),
        shaped like ``lateral``.
    flange_angle : float
        ϑ_f, rad, in (0, π/2).
    friction : float
        μ at the flange contact, in [0, :data:`MAXIMUM_FRICTION`].
    other_friction : float, optional
        μ₂ at the other wheel's tread, in [0, :data:`MAXIMUM_FRICTION`]; ``friction`` if None.

    Returns
    -------
    WheelClimb
        The quotients and the limits.

    Examples
    --------
    >>> r = wheel_climb([45e3, -20e3], [60e3, 50e3], np.radians(70.0), 0.3)
    >>> round(r.flange_quotient, 3), round(r.nadal_limit, 3), bool(r.nadal_exceeded)
    (0.75, 1.342, False)
    >>> round(r.axle_sum, 3), round(r.weinstock_limit, 3)
    (1.15, 1.642)
    """
    Y = _checks.array("lateral", lateral, allow_empty=False)
    Q = _checks.array("vertical", vertical, low=0.0, low_open=True, allow_empty=False)
    if Y.ndim == 0 or Y.shape[-1] != 2:
        raise ValueError(f"lateral must have shape (..., 2): one force per wheel, got shape {Y.shape}")
    if Q.shape != Y.shape:
        raise ValueError(f"vertical must have the shape of lateral {Y.shape}, got shape {Q.shape}")
    delta = scalar("flange_angle", flange_angle, low=0.0, high=np.pi / 2, low_open=True, high_open=True)
    mu = scalar("friction", friction, low=0.0, high=MAXIMUM_FRICTION)
    mu2 = (
        mu
        if other_friction is None
        else scalar("other_friction", other_friction, low=0.0, high=MAXIMUM_FRICTION)
    )
    quotient = Y / Q
    size = np.abs(quotient)
    flanging = np.argmax(size, axis=-1)
    flange = np.take_along_axis(size, flanging[..., None], axis=-1)[..., 0]
    total = size.sum(axis=-1)
    scalar_out = Y.ndim == 1
    return WheelClimb(
        wheel_quotient=quotient,
        flanging_wheel=int(flanging) if scalar_out else flanging,
        flange_quotient=float(flange) if scalar_out else flange,
        axle_sum=float(total) if scalar_out else total,
        nadal_limit=nadal_limit(delta, mu),
        weinstock_limit=weinstock_limit(delta, mu, mu2),
        flange_angle=delta,
        friction=mu,
        other_friction=mu2,
    )


def plot_nadal_limit(ax=None, *, friction=(0.1, 0.3, 0.5), flange_angle=None) -> dict:
    """Draw Nadal's limit against the flange angle, one curve per friction coefficient.

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes on a new pyplot figure if None.
    friction : sequence of float
        The friction coefficients μ, each in [0, :data:`MAXIMUM_FRICTION`] (1-D, not empty).
    flange_angle : array_like, optional
        ϑ_f, rad, 1-D, strictly increasing, in (0, π/2); 50° to 80° by default (drawn in degrees).

    Returns
    -------
    dict
        The artists: one line per friction coefficient, keyed ``"friction 0.3"`` and so on.
    """
    import matplotlib

    from raildyn import plots

    mu = _friction("friction", friction)
    if mu.ndim != 1:
        raise ValueError(f"friction must be a 1-D sequence of coefficients, got shape {mu.shape}")
    if flange_angle is None:
        delta = np.radians(np.linspace(50.0, 80.0, 121))
    else:
        delta = _checks.increasing("flange_angle", flange_angle)
        _flange_angle(delta)
    ax = plots.axes_or_new(ax)
    lines = {}
    with matplotlib.rc_context(plots.STYLE):
        for i, m in enumerate(mu):
            (line,) = ax.plot(
                np.degrees(delta),
                nadal_limit(delta, float(m)),
                color=plots.COLORS[i % len(plots.COLORS)],
                label=f"$\\mu$ = {m:g}",
            )
            lines[f"friction {m:g}"] = line
        ax.set_xlabel("flange angle $\\vartheta_f$ (deg)")
        ax.set_ylabel("Nadal's limit $Y/Q$")
        ax.legend()
    return lines
