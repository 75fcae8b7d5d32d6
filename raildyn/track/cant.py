"""The cant of a curve (book chapter 8): cant deficiency, balance speed, the limits of curve geometry.

* The cant quantities of a curve of radius R and cant h_t on a track whose rail-centre
  spacing is G: the equilibrium cant (:func:`equilibrium_cant`), the cant deficiency
  (:func:`cant_deficiency`), the unbalanced lateral acceleration in the track plane
  (:func:`unbalanced_acceleration`), the balance speed (:func:`balance_speed`) and the
  speed that runs at a given cant deficiency (:func:`speed_for_deficiency`).
* The limits of curve geometry that every curve of raildyn is checked against, each defined
  here once: the smallest radius (:data:`MINIMUM_RADIUS`), the largest cant
  (:data:`MAXIMUM_CANT`), the cant gradient and twist base of the standards. The curve itself,
  with its transitions, is :class:`raildyn.track.curve.Curve`.

**One convention, the railway engineer's.** The cant quantities are linear in the cant:
the track's roll angle θ_t is taken small (sin θ_t ≈ tan θ_t ≈ θ_t = h_t/(2a_r)), which is how the
design standards state them (EN 13803 writes the equilibrium cant of standard-gauge
track as 11.8 V²/R, mm with V in km/h and R in m: 2a_r = 1500 mm) and how Garg & Dukkipati
(1984, ch. 8) use them. In this convention the balance speed has zero cant deficiency
and zero unbalanced acceleration exactly. :func:`unbalanced_acceleration` gives the
exact in-plane form V²/R cos θ_t − g sin θ_t on request (``exact=True``); the two differ by
less than g θ_t³/2 + |a| θ_t²/2 (below 0.2 % of g at the largest cant allowed here).

The curves are left-handed: the curvature, the heading and y are positive turning to the
left (x forward, y to the left, as in :mod:`raildyn.wheelset`); a right-hand curve is the
mirror image, y → −y. SI units throughout: m, m/s, rad, m/s²; a cant gradient or a twist
is a ratio, m per m (multiply by 1000 for mm/m).
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks, constants
from raildyn._checks import scalar
from raildyn.constants import GRAVITY

__all__ = [
    "CANT_GRADIENT_LIMIT",
    "MAXIMUM_CANT",
    "MAXIMUM_SPEED",
    "MINIMUM_RADIUS",
    "STANDARD_RAIL_SPACING",
    "TWIST_BASE",
    "balance_speed",
    "cant_deficiency",
    "equilibrium_cant",
    "speed_for_deficiency",
    "unbalanced_acceleration",
]

STANDARD_RAIL_SPACING = constants.STANDARD_RAIL_SPACING
"""2a_r = 1.5 m (:data:`raildyn.constants.STANDARD_RAIL_SPACING`), named here too for the curving
functions that state the cant over it."""

MINIMUM_RADIUS = 50.0
"""The smallest radius accepted, m. Main lines curve far more gently (a few hundred metres
and up); 50 m is already depot and industrial track. Below it a bogie's geometric angle of
attack (about the semi-wheelbase over R: 25 mrad for 1.25 m on 50 m) and the gauge widening
such curves need leave the small-angle curving theory of chapter 8 that these curves feed."""

MAXIMUM_CANT = 0.2
"""The largest cant accepted, m: a hard bound a little above the 180 mm that EN 13803 allows
as the design cant of ballasted standard-gauge track, so that every main-line design cant
passes. At 0.2 m on 2a_r = 1.5 m the roll angle is 0.134 rad and 1 − cos θ_t < 0.9 %, so the
small-angle convention of this module stays within a per cent of the exact trigonometry."""

MAXIMUM_SPEED = constants.MAXIMUM_SPEED
"""The largest speed accepted, m/s (720 km/h): the package's one speed limit,
:data:`raildyn.constants.MAXIMUM_SPEED`, named here too for the curving functions that state it."""

CANT_GRADIENT_LIMIT = 2.25e-3
"""A limiting cant gradient dD/ds of a linear cant ramp, m/m (2.25 mm/m), the value EN 13803
gives for plain line: a steeper ramp twists a vehicle's wheelbase more and unloads its
leading outer wheel, the low-speed danger of wheel climb. Not enforced: a :class:`Curve`
reports its gradient and twist, and the caller compares."""

TWIST_BASE = 3.0
"""The base of the twist, m: the 3 m over which EN 13848-5 measures track twist, about the
wheelbase of a passenger bogie (2.5 m to 3 m)."""


# ---------------------------------------------------------------------------
# Input


def _values(name: str, value, *, low: float, low_open: bool = False, high: float | None = None) -> np.ndarray:
    """``value`` as a non-empty finite array within [low, high], checked by :mod:`raildyn._checks`."""
    arr = _checks.array(name, value, low=low, low_open=low_open, allow_empty=False)
    if high is not None:
        scalar(name, arr.max(), low=low, low_open=low_open, high=high)
    return arr


def _radius(value) -> np.ndarray:
    return _values("radius", value, low=MINIMUM_RADIUS)


def _cant(value) -> np.ndarray:
    return _values("cant", value, low=0.0, high=MAXIMUM_CANT)


def _speed(value) -> np.ndarray:
    return _values("speed", value, low=0.0, high=MAXIMUM_SPEED)


def _rail_spacing(value) -> float:
    # From about 0.65 m (600 mm narrow gauge) to about 1.75 m (1676 mm broad gauge), with a margin.
    return scalar("rail_spacing", value, low=0.5, high=2.0)


def _result(value: np.ndarray, *inputs):
    """A float when every input was a single number, else the array."""
    if all(np.ndim(x) == 0 for x in inputs):
        return float(value)
    return value


# ---------------------------------------------------------------------------
# Cant, cant deficiency, balance speed


def equilibrium_cant(speed, radius, rail_spacing=STANDARD_RAIL_SPACING):
    """The cant at which a vehicle at ``speed`` feels no lateral acceleration in the track plane, m.

    h_eq = 2a_r V²/(g R) (Garg & Dukkipati 1984, ch. 8; EN 13803's 11.8 V²/R in mm with V in
    km/h), in the small-angle convention of this module.

    Parameters
    ----------
    speed : float or array_like
        V, m/s, in [0, :data:`MAXIMUM_SPEED`].
    radius : float or array_like
        R, m (≥ :data:`MINIMUM_RADIUS`); broadcast against ``speed``.
    rail_spacing : float
        2a_r, m, in [0.5, 2.0]; :data:`STANDARD_RAIL_SPACING` (1.5 m) by default.

    Returns
    -------
    float or ndarray
        h_eq, m (a float for single numbers).

    Examples
    --------
    >>> round(equilibrium_cant(160 / 3.6, 1500.0) * 1000, 1)  # 160 km/h on R = 1500 m, mm
    201.4
    """
    V = _speed(speed)
    R = _radius(radius)
    G = _rail_spacing(rail_spacing)
    _checks.broadcast(speed=V, radius=R)
    return _result(G * V**2 / (GRAVITY * R), speed, radius)


def cant_deficiency(speed, radius, cant, rail_spacing=STANDARD_RAIL_SPACING):
    """The cant deficiency I = h_eq − h_t, m: positive short of equilibrium, negative a cant excess.

    I = 2a_r V²/(g R) − h_t (Garg & Dukkipati 1984, ch. 8; EN 13803), in the small-angle convention.

    Parameters
    ----------
    speed : float or array_like
        V, m/s, in [0, :data:`MAXIMUM_SPEED`].
    radius : float or array_like
        R, m (≥ :data:`MINIMUM_RADIUS`).
    cant : float or array_like
        h_t, the height of the outer rail over the inner, m, in [0, :data:`MAXIMUM_CANT`].
    rail_spacing : float
        2a_r, m, in [0.5, 2.0].

    Returns
    -------
    float or ndarray
        I, m (a negative I is a cant excess of −I). The arguments broadcast together.

    Examples
    --------
    >>> round(cant_deficiency(120 / 3.6, 600.0, 0.1) * 1000, 1)  # 120 km/h, R = 600 m, h_t = 100 mm
    183.3
    """
    D = _cant(cant)
    _checks.broadcast(speed=speed, radius=radius, cant=D)
    deficiency = np.asarray(equilibrium_cant(speed, radius, rail_spacing)) - D
    return _result(deficiency, speed, radius, cant)


def unbalanced_acceleration(speed, radius, cant, rail_spacing=STANDARD_RAIL_SPACING, *, exact=False):
    """The lateral acceleration left unbalanced in the plane of the track, m/s², positive outwards.

    The module's small-angle form (the default): a_q = g I/(2a_r), with I the cant deficiency,
    zero at the balance speed. With ``exact=True`` the exact in-plane component,
    a_q = V²/R cos θ_t − g sin θ_t with sin θ_t = h_t/(2a_r) (Garg & Dukkipati 1984, ch. 8). In closed
    form exact = (g I/(2a_r)) cos θ_t − g sin θ_t (1 − cos θ_t), so the two differ by at most
    (|a_q| + g sin θ_t)(1 − cos θ_t) ≈ (|a_q| + g θ_t) θ_t²/2.

    Parameters
    ----------
    speed : float or array_like
        V, m/s, in [0, :data:`MAXIMUM_SPEED`].
    radius : float or array_like
        R, m (≥ :data:`MINIMUM_RADIUS`).
    cant : float or array_like
        h_t, m, in [0, :data:`MAXIMUM_CANT`].
    rail_spacing : float
        2a_r, m, in [0.5, 2.0].
    exact : bool
        False (the module's convention) for g I/(2a_r), True for V²/R cos θ_t − g sin θ_t.

    Returns
    -------
    float or ndarray
        a_q, m/s² (negative: a cant excess pushes the vehicle inwards).

    Examples
    --------
    >>> round(unbalanced_acceleration(120 / 3.6, 600.0, 0.1), 3)
    1.198
    >>> round(unbalanced_acceleration(120 / 3.6, 600.0, 0.1, exact=True), 3)
    1.194
    """
    exact = _checks.flag("exact", exact)
    G = _rail_spacing(rail_spacing)
    I = np.asarray(cant_deficiency(speed, radius, cant, G))  # noqa: E741 — the book's I
    if not exact:
        return _result(GRAVITY * I / G, speed, radius, cant)
    V = np.asarray(speed, dtype=float)
    R = np.asarray(radius, dtype=float)
    sin_phi = np.asarray(cant, dtype=float) / G
    cos_phi = np.sqrt(1.0 - sin_phi**2)
    return _result(V**2 / R * cos_phi - GRAVITY * sin_phi, speed, radius, cant)


def balance_speed(radius, cant, rail_spacing=STANDARD_RAIL_SPACING):
    """The speed at which the cant balances the centripetal acceleration, m/s.

    V_b = √(g R h_t/(2a_r)) (Garg & Dukkipati 1984, ch. 8): the small-angle form of √(g R tan θ_t),
    the speed at which :func:`cant_deficiency` and :func:`unbalanced_acceleration` are zero.

    Parameters
    ----------
    radius : float or array_like
        R, m (≥ :data:`MINIMUM_RADIUS`).
    cant : float or array_like
        h_t, m, in [0, :data:`MAXIMUM_CANT`] (no cant: a balance speed of 0).
    rail_spacing : float
        2a_r, m, in [0.5, 2.0].

    Returns
    -------
    float or ndarray
        V_b, m/s.

    Examples
    --------
    >>> round(balance_speed(600.0, 0.1) * 3.6, 1)  # km/h
    71.3
    """
    R = _radius(radius)
    D = _cant(cant)
    G = _rail_spacing(rail_spacing)
    _checks.broadcast(radius=R, cant=D)
    return _result(np.sqrt(GRAVITY * R * D / G), radius, cant)


def speed_for_deficiency(radius, cant, deficiency, rail_spacing=STANDARD_RAIL_SPACING):
    """The speed that runs a curve at a given cant deficiency, m/s.

    V = √(g R (h_t + I)/(2a_r)), the inverse of :func:`cant_deficiency` (Garg & Dukkipati 1984,
    ch. 8): the highest speed a permitted deficiency allows, or with I = 0 the balance speed.

    Parameters
    ----------
    radius : float or array_like
        R, m (≥ :data:`MINIMUM_RADIUS`).
    cant : float or array_like
        h_t, m, in [0, :data:`MAXIMUM_CANT`].
    deficiency : float or array_like
        I, m, with h_t + I ≥ 0 (a cant excess −I at most the cant itself: I = −h_t is standing still).
    rail_spacing : float
        2a_r, m, in [0.5, 2.0].

    Returns
    -------
    float or ndarray
        V, m/s.

    Examples
    --------
    >>> round(speed_for_deficiency(600.0, 0.1, 0.15) * 3.6, 1)  # 150 mm deficiency, km/h
    112.7
    """
    R = _radius(radius)
    D = _cant(cant)
    G = _rail_spacing(rail_spacing)
    I = _checks.array("deficiency", deficiency, allow_empty=False)  # noqa: E741 — the book's I
    _checks.broadcast(radius=R, cant=D, deficiency=I)
    total = D + I
    if np.any(total < 0):
        worst = np.broadcast_to(I, total.shape)[total < 0].flat[0]
        raise ValueError(
            f"deficiency must be >= -cant (a cant excess no larger than the cant: I = -D is a speed of 0), "
            f"got deficiency {worst!r} with cant {np.max(D)!r}"
        )
    return _result(np.sqrt(GRAVITY * R * total / G), radius, cant, deficiency)
