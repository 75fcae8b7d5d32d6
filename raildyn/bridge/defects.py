"""What a wheel meets on the running surface: a dipped joint, a flat on the wheel, roughness (ch. 3, 10).

Each gives r(x), how far the running surface lies below its line where the wheel stands (m, down
positive), and its slope dr/dx, for the wheel of :mod:`raildyn.bridge.impact`: a dipped joint as a V
of two angles, a flat worn round that comes back once a revolution, and any sampled roughness.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks

__all__ = ["MAX_DIP_ANGLE", "MAX_FLAT_DEPTH", "DippedJoint", "Roughness", "WheelFlat"]

#: The largest dip angle of one leg of a joint, rad: dipped joints measured on British Rail had total
#: angles of a few to some 20 mrad (Jenkins et al. 1974); 50 mrad a leg is past any joint in track.
MAX_DIP_ANGLE = 0.05
#: The deepest wheel flat, m: a flat 5 mm deep on a 0.46 m wheel is some 190 mm long, past any flat
#: a wheel could run with (railways withdraw wheels with flats of some 40-60 mm).
MAX_FLAT_DEPTH = 0.005


@dataclass(frozen=True)
class DippedJoint:
    """A joint whose rail ends have dipped: the running surface falls at α₁ into the joint, rises at α₂.

    r(x) is a V: from ``position − ramp`` it falls at α₁ to the depth α₁ · ramp at ``position``, then
    rises at α₂ back to the line. Its total angle 2α = α₁ + α₂ is the one of Jenkins et al. (1974).
    (:func:`raildyn.track.deterministic.dipped_joints` is the long-wave, periodic form of jointed rail
    for the vehicle's ride; this one is the short, sharp dip that sets off the impact.)

    Attributes
    ----------
    position : float
        The joint's x, m (any finite value).
    angles : (float, float)
        α₁ and α₂, rad, each in (0, 0.05] (:data:`MAX_DIP_ANGLE`).
    ramp : float
        The falling leg's length, m, in [0.05, 5]. Default 0.5 m.
    """

    position: float
    angles: tuple = (0.005, 0.005)
    ramp: float = 0.5

    def __post_init__(self):
        _checks.scalar("position", self.position)
        angles = _checks.array("angles", self.angles, shape=(2,))
        for name, value in zip(("angles[0]", "angles[1]"), angles, strict=True):
            _checks.scalar(name, value, low=0.0, low_open=True, high=MAX_DIP_ANGLE)
        object.__setattr__(self, "angles", (float(angles[0]), float(angles[1])))
        _checks.scalar("ramp", self.ramp, low=0.05, high=5.0)

    @property
    def total_angle(self) -> float:
        """2α = α₁ + α₂, rad."""
        return self.angles[0] + self.angles[1]

    @property
    def depth(self) -> float:
        """The dip's depth at the joint, m."""
        return self.angles[0] * self.ramp

    def profile(self, x) -> tuple[np.ndarray, np.ndarray]:
        """The dip below the rail's line and its slope along the track.

        Parameters
        ----------
        x : array_like
            Positions along the track, m; any shape, not empty.

        Returns
        -------
        (ndarray, ndarray)
            r_s (m, down positive) and dr_s/dx, each shaped like ``x``.
        """
        x = _checks.array("x", x, allow_empty=False)
        a1, a2 = self.angles
        s = x - self.position
        fall = (s > -self.ramp) & (s <= 0.0)
        rise = (s > 0.0) & (s < self.depth / a2)
        r = np.where(fall, self.depth + a1 * s, np.where(rise, self.depth - a2 * s, 0.0))
        return r, np.where(fall, a1, np.where(rise, -a2, 0.0))


@dataclass(frozen=True)
class WheelFlat:
    """A flat on the wheel, worn round: each revolution the wheel drops into it as into a dip.

    r = (d/2)(1 − cos 2πs/L) over a length L = √(16 R d) from each contact with the flat (s from its
    start), the shape and length of a *rounded* flat (Newton & Clark 1979, *J. Mech. Eng. Sci.* 21(4),
    287–297; the form most impact studies use): a new flat's sharp edges wear round within a few
    revolutions.

    Attributes
    ----------
    depth : float
        d, m, in (0, 0.005] (:data:`MAX_FLAT_DEPTH`).
    wheel_radius : float
        R, m, in [0.1, 1.5]. Default 0.46 m.
    first : float
        x at which the flat first meets the rail, m (any finite value). Default 0.
    """

    depth: float
    wheel_radius: float = 0.46
    first: float = 0.0

    def __post_init__(self):
        _checks.scalar("depth", self.depth, low=0.0, low_open=True, high=MAX_FLAT_DEPTH)
        _checks.plausible("wheel_radius", self.wheel_radius, "wheel_radius")
        _checks.scalar("first", self.first)

    @property
    def length(self) -> float:
        """L = √(16 R d), m."""
        return math.sqrt(16.0 * self.wheel_radius * self.depth)

    def profile(self, x) -> tuple[np.ndarray, np.ndarray]:
        """How far the wheel's centre drops, as a dip in the rail would make it, and its slope.

        Parameters
        ----------
        x : array_like
            The wheel's positions along the track, m; any shape, not empty.

        Returns
        -------
        (ndarray, ndarray)
            r_s (m, down positive) and dr_s/dx, each shaped like ``x``.
        """
        s = np.mod(_checks.array("x", x, allow_empty=False) - self.first, 2.0 * np.pi * self.wheel_radius)
        inside = s < self.length
        k = 2.0 * np.pi / self.length
        return (np.where(inside, 0.5 * self.depth * (1.0 - np.cos(k * s)), 0.0),
                np.where(inside, 0.5 * self.depth * k * np.sin(k * s), 0.0))  # fmt: skip


@dataclass(frozen=True, eq=False)
class Roughness:
    """A measured or sampled roughness of the running surface: r at evenly spaced x, interpolated linearly.

    Attributes
    ----------
    x : ndarray
        m, increasing, evenly spaced, at least 2 points.
    r : ndarray
        m (down positive), one per x, each within ±0.1 m.
    """

    x: np.ndarray
    r: np.ndarray

    def __post_init__(self):
        x = _checks.array("x", self.x, ndim=1)
        if x.size < 2 or not np.all(np.diff(x) > 0):
            raise ValueError(f"x must be increasing with at least 2 points, got {x.size} points")
        r = _checks.plausible_array("r", self.r, "irregularity", signed=True, shape=x.shape)
        object.__setattr__(self, "x", x)
        object.__setattr__(self, "r", r)

    def profile(self, x) -> tuple[np.ndarray, np.ndarray]:
        """The sampled roughness, interpolated, and its slope; zero outside the sampled stretch.

        Parameters
        ----------
        x : array_like
            Positions along the track, m; any shape, not empty.

        Returns
        -------
        (ndarray, ndarray)
            r_s (m, down positive) and dr_s/dx, each shaped like ``x``.
        """
        x = _checks.array("x", x, allow_empty=False)
        r = np.interp(x, self.x, self.r, left=0.0, right=0.0)
        i = np.clip(np.searchsorted(self.x, x) - 1, 0, self.x.size - 2)
        slope = (self.r[i + 1] - self.r[i]) / (self.x[i + 1] - self.x[i])
        return r, np.where((x >= self.x[0]) & (x <= self.x[-1]), slope, 0.0)
