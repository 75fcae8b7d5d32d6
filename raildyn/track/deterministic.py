"""Deterministic track irregularities along distance: dipped rail joints, an isolated bump, sinusoids.

Each function takes distances ``x`` (m) and returns the irregularity (m) or, with
``derivative=1`` or ``2``, its slope (m/m) or curvature (1/m) along the track; a
vehicle at speed V sees the rates dz/dt = V·dz/dx and d²z/dt² = V²·d²z/dx², which
each function returns when given ``speed=V``.

Jointed rail (Garg & Dukkipati 1984, ch. 3): rails of length L (11.9 m, the
39-ft North American rail) whose ends are pushed down at each joint. Each joint
is a cusp of depth h_j and half-length ℓ_j,

    z(s) = −h_j (1 − |s|/ℓ_j)²  for |s| < ℓ_j,   0 elsewhere,

s being the signed distance to the nearest joint. z and its slope are continuous away
from the joint, where the slope jumps by 4h_j/ℓ_j (the cusp) — the kick that a
wheel receives on each joint; the curvature jumps at |s| = ℓ_j. With ℓ_j = L/2 the
whole rail sags between joints. On the two rails the joints are either *in
phase* (opposite each other: a bounce and pitch input) or *staggered* by L/2
(a roll input, the source of rock-and-roll of freight cars).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.constants import MAXIMUM_SPEED

__all__ = [
    "RAIL_LENGTH",
    "JointedTrack",
    "dipped_joints",
    "jointed_track",
    "bump",
    "sinusoid",
    "passing_frequency",
    "passing_speed",
    "harmonic_amplitudes",
]

RAIL_LENGTH = 11.9  # m; the 39-ft rail of North American jointed track (Garg & Dukkipati 1984, ch. 3)
# m/s: the speed a rate in time may be asked at: the package's one speed limit.
_ARRANGEMENTS = ("staggered", "in_phase")


def _rail_length(value) -> float:
    """L, m, in [1, 150] (``PLAUSIBLE_RANGES["rail_length"]``)."""
    return _checks.plausible("rail_length", value, "rail_length")


def _along(name: str, value, high=None) -> float:
    """A length along the track, m, in [1 mm, 1 km] (``PLAUSIBLE_RANGES["track_length"]``), at most
    ``high``."""
    return _checks.plausible(name, value, "track_length", high=high)


def _size(name: str, value, *, signed: bool = False) -> float:
    """A dip's depth in [0, 0.1] m, or a height or amplitude within ±0.1 m (``signed``)."""
    return _checks.plausible(name, value, "irregularity", signed=signed)


def _derivative(value) -> int:
    return _checks.integer("derivative", value, low=0, high=2)


def _vehicle_speed(speed) -> float:
    """A vehicle speed for a view in time, 0 < V <= MAXIMUM_SPEED (200 m/s)."""
    return _checks.speed("speed", speed)


def _speed(speed) -> float | None:
    """The speed a rate in time is asked at, or None (derivatives along x)."""
    return None if speed is None else _vehicle_speed(speed)


def _in_time(values: np.ndarray, order: int, speed: float | None) -> np.ndarray:
    """Derivatives along x turned into rates in time at speed V: d^k z/dt^k = V^k d^k z/dx^k."""
    return values if speed is None else speed**order * values


def dipped_joints(
    x,
    depth: float,
    half_width: float,
    *,
    rail_length: float = RAIL_LENGTH,
    offset: float = 0.0,
    derivative=0,
    speed=None,
) -> np.ndarray:
    """Vertical profile of one jointed rail with cusp-shaped dipped joints at x = offset + jL.

    Parameters
    ----------
    x : array_like
        Distance along the track, m; any shape, not empty.
    depth : float
        h_j, depth of the dip at each joint, m, in [0, 0.1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "irregularity").
    half_width : float
        ℓ_j, half the length of track each dip spans, m, in [0.001, L/2]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "track_length").
    rail_length : float
        L, distance between joints, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "rail_length"; default 11.9).
    offset : float
        Position of one joint, m (any real).
    derivative : {0, 1, 2}
        Return z (m), dz/dx or d²z/dx² (1/m). At a joint itself the slope is
        taken as the mean of its two one-sided values (0); the curvature returned
        is the regular part, without the Dirac term of the slope jump 4h_j/ℓ_j.
    speed : float, optional
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]: return the rates met
        in time instead, dz/dt = V dz/dx (m/s)
        or d²z/dt² = V² d²z/dx² (m/s²).

    Returns
    -------
    ndarray, same shape as ``x``
        z (m) or the derivative asked for.

    Examples
    --------
    >>> dipped_joints([0.0, 1.0, 5.95], depth=0.01, half_width=2.0).round(6).tolist()
    [-0.01, -0.0025, 0.0]
    """
    x = _checks.array("x", x, allow_empty=False)
    delta = _size("depth", depth)
    L = _rail_length(rail_length)
    a = _along("half_width", half_width, high=L / 2)
    offset = _checks.scalar("offset", offset)
    order = _derivative(derivative)
    speed = _speed(speed)
    xi = np.mod(x - offset + 0.5 * L, L) - 0.5 * L  # signed distance to the nearest joint
    u = np.abs(xi) / a
    inside = u < 1.0
    if order == 0:
        z = np.where(inside, -delta * (1.0 - u) ** 2, 0.0)
    elif order == 1:
        z = np.where(inside, 2.0 * delta * (1.0 - u) * np.sign(xi) / a, 0.0)
    else:
        z = np.where(inside, -2.0 * delta / a**2, 0.0)
    return _in_time(z, order, speed)


@dataclass(frozen=True)
class JointedTrack(Tabular):
    """Vertical profiles of the two rails of jointed track (or their derivatives).

    Attributes
    ----------
    x : ndarray
        Distance, m; any shape, not empty.
    left, right : ndarray
        Rail profiles, m (or their derivatives), of the shape of ``x``.
    arrangement : str
        "staggered" or "in_phase".
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("x", "m"), ("left", "m"), ("right", "m"))

    x: np.ndarray
    left: np.ndarray
    right: np.ndarray
    arrangement: str

    def __post_init__(self):
        x = _checks.array("x", self.x, allow_empty=False)
        object.__setattr__(self, "x", x)
        for name in ("left", "right"):
            profile = _checks.array(name, getattr(self, name))
            if profile.shape != x.shape:
                raise ValueError(f"{name} must have the shape of x, {x.shape}, got {profile.shape}")
            object.__setattr__(self, name, profile)
        _checks.choice("arrangement", self.arrangement, _ARRANGEMENTS)

    @property
    def vertical(self) -> np.ndarray:
        """Centreline profile (left + right)/2: the bounce input."""
        return 0.5 * (self.left + self.right)

    @property
    def cross_level(self) -> np.ndarray:
        """Cross-level left − right: the roll input (zero for joints in phase)."""
        return self.left - self.right

    def plot(self, ax=None, *, artists=None) -> dict:
        """Draw both rails and the cross-level in mm against distance; or move artists drawn before.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        artists : dict, optional
            The dict a previous call returned: its lines take this track's
            profiles (``set_ydata``, same ``x``) instead of drawing new ones.

        Returns
        -------
        dict
            The lines ``left``, ``right`` and ``cross_level``.
        """
        profiles = {"left": self.left, "right": self.right, "cross_level": self.cross_level}
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict returned by an earlier plot, or None")
            if set(artists) != set(profiles):
                raise ValueError(
                    f"artists must hold the lines {sorted(profiles)}, got keys {sorted(artists)}"
                )
            for name, values in profiles.items():
                artists[name].set_ydata(1e3 * values)
            return artists
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        styles = {
            "left": {"color": plots.COLORS[0], "label": "left rail"},
            "right": {"color": plots.COLORS[1], "ls": "--", "label": "right rail"},
            "cross_level": {"color": plots.COLORS[2], "ls": ":", "lw": 1.2, "label": "cross-level"},
        }
        drawn = {}
        with matplotlib.rc_context(plots.STYLE):
            for name, values in profiles.items():
                (drawn[name],) = ax.plot(self.x, 1e3 * values, **styles[name])
            ax.set_xlabel("distance $x$ (m)")
            ax.set_ylabel("profile (mm)")
        return drawn


def jointed_track(
    x,
    depth: float,
    half_width: float,
    *,
    rail_length: float = RAIL_LENGTH,
    arrangement: str = "staggered",
    derivative=0,
    speed=None,
) -> JointedTrack:
    """Both rails of jointed track: joints in phase, or staggered by half a rail length.

    The left rail has a joint at x = 0; the right one at x = 0 (``"in_phase"``)
    or x = L/2 (``"staggered"``).

    Parameters
    ----------
    x : array_like
        Distance along the track, m; any shape, not empty.
    depth : float
        h_j, depth of each dip, m, in [0, 0.1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "irregularity").
    half_width : float
        ℓ_j, half the length of track each dip spans, m, in [0.001, L/2]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "track_length").
    rail_length : float
        L, m, in [1, 150] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "rail_length"; default 11.9).
    arrangement : {"staggered", "in_phase"}
        Joints of the right rail half a rail length along, or opposite those of the left.
    derivative : {0, 1, 2}
        Profiles (m), slopes or curvatures (1/m), as for :func:`dipped_joints`.
    speed : float, optional
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]: rates in time instead, as for
        :func:`dipped_joints`.

    Returns
    -------
    JointedTrack
        Both rails; ``.plot(ax)`` draws them with the cross-level.

    Examples
    --------
    >>> t = jointed_track([0.0, 5.95], 0.01, 2.0, arrangement="staggered")
    >>> t.cross_level.round(6).tolist()
    [-0.01, 0.01]
    """
    _checks.choice("arrangement", arrangement, _ARRANGEMENTS)
    L = _rail_length(rail_length)
    left = dipped_joints(x, depth, half_width, rail_length=L, derivative=derivative, speed=speed)
    shift = 0.5 * L if arrangement == "staggered" else 0.0
    right = dipped_joints(
        x, depth, half_width, rail_length=L, offset=shift, derivative=derivative, speed=speed
    )
    return JointedTrack(np.asarray(x, dtype=float), left, right, arrangement)


def bump(x, height: float, length: float, *, position: float = 0.0, derivative=0, speed=None) -> np.ndarray:
    """An isolated bump (height > 0) or dip (height < 0) of 1 − cos shape.

    z = (h/2)(1 − cos(2π(x − x₀)/ℓ)) for x₀ <= x <= x₀ + ℓ, and 0 elsewhere: z and its
    slope are continuous everywhere, the curvature jumps by ±2π²h/ℓ² at both ends.

    Parameters
    ----------
    x : array_like
        Distance, m; any shape, not empty.
    height : float
        h, m, of either sign, within ±0.1 (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "irregularity").
    length : float
        ℓ, m, in [0.001, 1000] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "track_length").
    position : float
        x₀, start of the bump, m (any real).
    derivative : {0, 1, 2}
        z (m), dz/dx or d²z/dx² (1/m).
    speed : float, optional
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]: return the rates met in
        time instead, dz/dt = V dz/dx
        (m/s) or d²z/dt² = V² d²z/dx² (m/s²). The largest dz/dt is πhV/ℓ.

    Returns
    -------
    ndarray, same shape as ``x``
        z (m) or the derivative asked for.

    Examples
    --------
    >>> bump([0.0, 0.5, 1.0], height=0.02, length=1.0).round(6).tolist()
    [0.0, 0.02, 0.0]
    >>> round(float(bump(0.25, 0.02, 1.0, derivative=1, speed=10.0)), 6)  # π h V/ℓ
    0.628319
    """
    x = _checks.array("x", x, allow_empty=False)
    h = _size("height", height, signed=True)
    ell = _along("length", length)
    x0 = _checks.scalar("position", position)
    order = _derivative(derivative)
    speed = _speed(speed)
    k = 2.0 * np.pi / ell
    s = x - x0
    inside = (s >= 0.0) & (s <= ell)
    if order == 0:
        z = np.where(inside, 0.5 * h * (1.0 - np.cos(k * s)), 0.0)
    elif order == 1:
        z = np.where(inside, 0.5 * h * k * np.sin(k * s), 0.0)
    else:
        z = np.where(inside, 0.5 * h * k**2 * np.cos(k * s), 0.0)
    return _in_time(z, order, speed)


def sinusoid(
    x, amplitude: float, wavelength: float, *, phase: float = 0.0, derivative=0, speed=None
) -> np.ndarray:
    """A sinusoidal profile or alignment z = A sin(2πx/λ + φ), or its derivatives.

    Parameters
    ----------
    x : array_like
        Distance, m; any shape, not empty.
    amplitude : float
        A, m, of either sign, within ±0.1 (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "irregularity").
    wavelength : float
        L_w, m, in [0.001, 1000] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "track_length").
    phase : float
        φ, rad (any real).
    derivative : {0, 1, 2}
        z (m), dz/dx or d²z/dx² (1/m).
    speed : float, optional
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]: return the rates met in
        time instead (m/s, m/s²).

    Returns
    -------
    ndarray, same shape as ``x``
        z (m) or the derivative asked for.

    Examples
    --------
    >>> float(sinusoid(0.0, 0.005, 20.0, derivative=1))  # A·2π/λ
    0.0015707963267948967
    """
    x = _checks.array("x", x, allow_empty=False)
    A = _size("amplitude", amplitude, signed=True)
    lam = _along("wavelength", wavelength)
    phi = _checks.scalar("phase", phase)
    order = _derivative(derivative)
    speed = _speed(speed)
    k = 2.0 * np.pi / lam
    arg = k * x + phi
    z = (A * np.sin(arg), A * k * np.cos(arg), -A * k**2 * np.sin(arg))[order]
    return _in_time(z, order, speed)


def passing_frequency(speed: float, rail_length: float = RAIL_LENGTH) -> float:
    """Frequency f = V/L at which the joints of one rail pass an axle.

    Also the frequency at which any feature repeating every L metres (a
    wavelength L) is met.

    Parameters
    ----------
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    rail_length : float
        L, m, the rail length or any wavelength, in [0.001, 1000]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "track_length";
        default 11.9).

    Returns
    -------
    float
        f, Hz.

    Examples
    --------
    >>> round(passing_frequency(119.0 / 3.6), 4)  # 119 km/h over 11.9 m rails
    2.7778
    """
    return _vehicle_speed(speed) / _along("rail_length", rail_length)


def passing_speed(frequency: float, rail_length: float = RAIL_LENGTH, *, harmonic: int = 1) -> float:
    """Speed V = fL/n at which harmonic n of a rail-length periodic input is met at frequency f.

    The inverse of :func:`passing_frequency`: harmonic n has the wavelength L/n
    and is met at nV/L, so a mode of frequency f is excited in resonance at
    V = fL/n (for staggered joints the cross-level holds the odd harmonics).

    Parameters
    ----------
    frequency : float
        f, Hz, > 0.
    rail_length : float
        L, m, the rail length or any wavelength, in [0.001, 1000]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "track_length";
        default 11.9).
    harmonic : int
        n >= 1.

    Returns
    -------
    float
        V, m/s, at most :data:`~raildyn.constants.MAXIMUM_SPEED` (a frequency no train could
        meet that fast is refused).

    Examples
    --------
    >>> round(passing_speed(0.9, harmonic=3) * 3.6, 2)  # km/h
    12.85
    """
    f = _checks.positive("frequency", frequency)
    L = _along("rail_length", rail_length)
    n = _checks.integer("harmonic", harmonic, low=1)
    V = f * L / n
    if not V <= MAXIMUM_SPEED:
        raise ValueError(
            f"frequency = {frequency!r} Hz would be met at V = fL/n = {V:.4g} m/s, above the "
            f"{MAXIMUM_SPEED:g} m/s of raildyn.constants.MAXIMUM_SPEED: no train meets it (a frequency "
            f"in rad/s, or rail_length = {rail_length!r} m in millimetres?)"
        )
    return V


def harmonic_amplitudes(one_period, count: int) -> np.ndarray:
    """Amplitudes of the first ``count`` harmonics of a periodic profile (same unit as the profile).

    ``one_period`` samples exactly one period uniformly, without repeating its
    first point. Harmonic n has the wavelength L/n, so an axle at speed V meets it
    at the frequency nV/L (see :func:`passing_frequency`). The amplitude of
    harmonic n is 2|Xₙ|/N from the discrete Fourier transform of the N samples.

    Parameters
    ----------
    one_period : array_like, shape (N,)
        The profile over one period, uniformly sampled, N >= 3 (one harmonic needs three points).
    count : int
        Harmonics wanted, 1 <= count <= (N − 1)/2.

    Returns
    -------
    ndarray, shape (count,)
        Amplitudes of harmonics 1 … count, in the unit of the profile.

    Examples
    --------
    >>> x = np.arange(64) / 64
    >>> np.round(harmonic_amplitudes(3 * np.cos(2 * np.pi * x) + np.sin(6 * np.pi * x), 3), 12).tolist()
    [3.0, 0.0, 1.0]
    """
    samples = _checks.array("one_period", one_period, ndim=1)
    if samples.size < 3:
        raise ValueError(
            f"one_period must hold at least 3 samples (N >= 3 for one harmonic), got {samples.size}"
        )
    count = _checks.integer("count", count, low=1, high=(samples.size - 1) // 2)
    return 2.0 * np.abs(np.fft.rfft(samples))[1 : count + 1] / samples.size
