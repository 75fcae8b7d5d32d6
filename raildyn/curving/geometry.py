"""Curve geometry (book chapter 8): cant, cant deficiency, balance speed, and curves with transitions.

* The cant quantities of a curve of radius R and cant h_t on a track whose rail-centre
  spacing is G: the equilibrium cant (:func:`equilibrium_cant`), the cant deficiency
  (:func:`cant_deficiency`), the unbalanced lateral acceleration in the track plane
  (:func:`unbalanced_acceleration`), the balance speed (:func:`balance_speed`) and the
  speed that runs at a given cant deficiency (:func:`speed_for_deficiency`).
* A :class:`Curve`: a straight, an entry transition (a clothoid, whose curvature grows
  linearly with distance, under a linear cant ramp of the same length), a circular arc
  and the mirror-image exit transition, with its curvature, cant, cant gradient, twist,
  heading and plan coordinates as functions of the distance s along the centre line.

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

from dataclasses import dataclass, replace

import numpy as np
from scipy.special import fresnel

from raildyn import _checks, constants
from raildyn._checks import nonnegative, scalar
from raildyn.constants import GRAVITY

__all__ = [
    "CANT_GRADIENT_LIMIT",
    "MAXIMUM_CANT",
    "MAXIMUM_SPEED",
    "MINIMUM_RADIUS",
    "STANDARD_RAIL_SPACING",
    "TWIST_BASE",
    "Curve",
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


# ---------------------------------------------------------------------------
# A curve with transitions


@dataclass(frozen=True)
class Curve:
    """A left-hand curve: straight, clothoid entry with a linear cant ramp, circular arc, mirror exit.

    Along the centre line, from s = 0: a straight of length ``straight``; the entry
    transition of length L, over which the curvature grows linearly from 0 to 1/R (a
    clothoid, the curve of Garg & Dukkipati 1984, ch. 8, and of EN 13803) and the cant
    from 0 to h_t; the arc of length ``arc_length`` at curvature 1/R and cant h_t; the exit
    transition, the entry's mirror image; and beyond it straight track on the new
    heading. Before s = 0 the straight continues backwards.

    Attributes
    ----------
    radius : float
        R, m (≥ :data:`MINIMUM_RADIUS`). 600 m by default: a main-line curve of moderate
        radius.
    cant : float
        h_t, m, in [0, :data:`MAXIMUM_CANT`]. 0.1 m by default (balance speed 71 km/h on 600 m).
    transition_length : float
        L, m (≥ 0; 0 is an abrupt change of curvature and a step of cant). 60 m by default:
        a ramp of 1.67 mm/m, within :data:`CANT_GRADIENT_LIMIT`.
    arc_length : float
        The circular arc's length, m (≥ 0). 200 m by default.
    straight : float
        The straight before the entry transition, m (≥ 0). 50 m by default.
    rail_spacing : float
        2a_r, m, in [0.5, 2.0]; the base of the cant (:data:`STANDARD_RAIL_SPACING`).

    Examples
    --------
    >>> c = Curve(radius=600.0, cant=0.1, transition_length=60.0, arc_length=200.0, straight=50.0)
    >>> c.length
    370.0
    >>> round(c.heading(c.length), 4)  # the deflection (L + arc)/R, rad
    0.4333
    """

    radius: float = 600.0
    cant: float = 0.1
    transition_length: float = 60.0
    arc_length: float = 200.0
    straight: float = 50.0
    rail_spacing: float = STANDARD_RAIL_SPACING

    def __post_init__(self):
        object.__setattr__(self, "radius", scalar("radius", self.radius, low=MINIMUM_RADIUS))
        object.__setattr__(self, "cant", scalar("cant", self.cant, low=0.0, high=MAXIMUM_CANT))
        object.__setattr__(
            self, "transition_length", nonnegative("transition_length", self.transition_length)
        )
        object.__setattr__(self, "arc_length", nonnegative("arc_length", self.arc_length))
        object.__setattr__(self, "straight", nonnegative("straight", self.straight))
        object.__setattr__(self, "rail_spacing", _rail_spacing(self.rail_spacing))

    def replace(self, **changes) -> Curve:
        """A copy with some fields changed (and checked again).

        Parameters
        ----------
        **changes
            Field names and their new values.

        Returns
        -------
        Curve
            The changed copy.
        """
        return replace(self, **changes)

    # ----------------------------------------------------------------- the segments

    @property
    def length(self) -> float:
        """The distance from s = 0 to the end of the exit transition, m."""
        return self._ends()[3]

    def _ends(self) -> tuple[float, float, float, float]:
        """s at the starts of the entry transition, the arc and the exit transition, and at the end, m."""
        s0 = self.straight
        s1 = s0 + self.transition_length
        s2 = s1 + self.arc_length
        return s0, s1, s2, s2 + self.transition_length

    def _pieces(self, s):
        """The distances as an array, and the masks of the straight, entry, arc, exit and the track beyond."""
        s = _checks.array("s", s, allow_empty=False)
        s0, s1, s2, s3 = self._ends()
        entry = (s > s0) & (s <= s1)
        arc = (s > s1) & (s <= s2)
        exit_ = (s > s2) & (s <= s3)
        return s, (s <= s0), entry, arc, exit_, (s > s3)

    def _out(self, value: np.ndarray, s):
        return float(value) if np.ndim(s) == 0 else value

    # ----------------------------------------------------------------- curvature and cant

    def curvature(self, s):
        """The curvature of the centre line at distance s, 1/m (positive to the left).

        κ = 0 on the straights, (s − s₀)/(R L) on the entry clothoid, 1/R on the arc and
        the mirror image on the exit.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value; before 0 and after the end
            the track is straight).

        Returns
        -------
        float or ndarray
            κ(s), 1/m, shaped like ``s``.
        """
        s, _, entry, arc, exit_, _ = self._pieces(s)
        s0, _, _, s3 = self._ends()
        R, L = self.radius, self.transition_length
        k = np.zeros_like(s)
        k[entry] = (s[entry] - s0) / (R * L)
        k[arc] = 1.0 / R
        k[exit_] = (s3 - s[exit_]) / (R * L)
        return self._out(k, s)

    def cant_at(self, s):
        """The cant h_t(s) at distance s, m (``cant`` itself is the arc's cant, a field).

        h_t(s) = 0 on the straights, h_t (s − s₀)/L on the entry ramp, h_t on the arc, and the
        mirror image on the exit: the linear ramp over the length of the clothoid.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).

        Returns
        -------
        float or ndarray
            h_t(s), m, shaped like ``s``.
        """
        s, _, entry, arc, exit_, _ = self._pieces(s)
        s0, _, _, s3 = self._ends()
        D, L = self.cant, self.transition_length
        out = np.zeros_like(s)
        out[entry] = D * (s[entry] - s0) / L
        out[arc] = D
        out[exit_] = D * (s3 - s[exit_]) / L
        return self._out(out, s)

    def unbalanced_acceleration(self, s, speed):
        """The unbalanced lateral acceleration a_q(s) = V² κ(s) − g h_t(s)/(2a_r) at distance s, m/s².

        :func:`unbalanced_acceleration` along the curve, in the module's small-angle convention
        (g I/(2a_r) with I = 2a_r V² κ/g − h_t): zero on the straights, growing along the transitions.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).
        speed : float
            V, m/s, in [0, :data:`MAXIMUM_SPEED`].

        Returns
        -------
        float or ndarray
            a_q(s), m/s², positive outwards, shaped like ``s``.

        Examples
        --------
        On the arc, the function's value for its radius and cant:

        >>> c, V = Curve(radius=600.0, cant=0.1), 120 / 3.6
        >>> bool(np.isclose(c.unbalanced_acceleration(150.0, V), unbalanced_acceleration(V, 600.0, 0.1)))
        True
        """
        V = _checks.speed("speed", speed, low_open=False)
        return V * V * self.curvature(s) - GRAVITY * self.cant_at(s) / self.rail_spacing

    def cant_gradient(self, s):
        """The cant gradient dD/ds at distance s, m/m (× 1000 for mm/m).

        h_t/L on the entry ramp, −h_t/L on the exit, 0 elsewhere. With no transition
        (L = 0) the cant steps and the gradient is 0 everywhere but at the step: use
        :meth:`twist` over a base, which stays finite. Compare with
        :data:`CANT_GRADIENT_LIMIT` (EN 13803).

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).

        Returns
        -------
        float or ndarray
            dD/ds, m/m, shaped like ``s``.
        """
        s, _, entry, _, exit_, _ = self._pieces(s)
        out = np.zeros_like(s)
        if self.transition_length > 0:
            out[entry] = self.cant / self.transition_length
            out[exit_] = -self.cant / self.transition_length
        return self._out(out, s)

    def twist(self, s, base=TWIST_BASE):
        """The track twist over a base: (D(s) − D(s − base)) / base, m/m (× 1000 for mm/m).

        The change of cross-level between a vehicle's leading axle at s and its trailing
        axle a wheelbase behind, per metre of base: the twist of EN 13848-5 (on a 3 m base)
        that unloads a wheel of a stiff bogie (Garg & Dukkipati 1984, ch. 8). On a linear
        ramp longer than the base it equals the cant gradient; with L = 0 it is h_t/base
        for a base length past the step.

        Parameters
        ----------
        s : float or array_like
            Distance of the leading axle along the centre line, m (any finite value).
        base : float
            The base (a bogie's wheelbase), m (> 0); :data:`TWIST_BASE` (3 m) by default.

        Returns
        -------
        float or ndarray
            The twist, m/m, shaped like ``s``; positive while the cant rises.
        """
        b = _checks.positive("base", base)
        s_arr = _checks.array("s", s, allow_empty=False)
        lead = np.asarray(self.cant_at(s_arr))
        trail = np.asarray(self.cant_at(s_arr - b))
        return self._out((lead - trail) / b, s)

    # ----------------------------------------------------------------- heading and plan

    def heading(self, s):
        """The heading of the centre line at distance s, rad (from the first straight, positive to the left).

        θ = ∫κ ds: 0 on the first straight, (s − s₀)²/(2 R L) on the entry clothoid (L/(2R)
        at its end), L/(2R) + (s − s₁)/R on the arc, and (L + arc)/R beyond the exit.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).

        Returns
        -------
        float or ndarray
            θ(s), rad, shaped like ``s``.
        """
        s, _, entry, arc, exit_, beyond = self._pieces(s)
        s0, s1, _, s3 = self._ends()
        R, L = self.radius, self.transition_length
        total = (L + self.arc_length) / R
        theta = np.zeros_like(s)
        theta[entry] = (s[entry] - s0) ** 2 / (2 * R * L)
        theta[arc] = L / (2 * R) + (s[arc] - s1) / R
        theta[exit_] = total - (s3 - s[exit_]) ** 2 / (2 * R * L)
        theta[beyond] = total
        return self._out(theta, s)

    def _clothoid(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """x, y of the clothoid κ = u/(RL) from its straight end (heading 0) at distance u, m.

        x = a C(u/a), y = a S(u/a), a = √(π R L), with Fresnel's integrals
        C(z) = ∫₀^z cos(πt²/2) dt and S(z) = ∫₀^z sin(πt²/2) dt.
        """
        if self.transition_length == 0:
            return np.zeros_like(u), np.zeros_like(u)
        # √π √R √L, not √(πRL), which would overflow for R and L near 1e300.
        a = np.sqrt(np.pi) * np.sqrt(self.radius) * np.sqrt(self.transition_length)
        S, C = fresnel(u / a)
        return a * C, a * S

    def _plan(self, s) -> tuple[np.ndarray, np.ndarray]:
        s, before, entry, arc, exit_, beyond = self._pieces(s)
        s0, s1, s2, s3 = self._ends()
        R, L = self.radius, self.transition_length
        x, y = np.empty_like(s), np.empty_like(s)
        # the first straight
        x[before], y[before] = s[before], 0.0
        # the entry clothoid, from (s0, 0) at heading 0
        cx, cy = self._clothoid(s[entry] - s0)
        x[entry], y[entry] = s0 + cx, cy
        # the arc, from P1 at heading θ1: P1 + 2R sin(w/2R) (cos, sin)(θ1 + w/2R)
        cL, sL = self._clothoid(np.array(L))
        x1, y1, th1 = s0 + float(cL), float(sL), L / (2 * R)

        def on_arc(w):
            chord = 2 * R * np.sin(w / (2 * R))
            return x1 + chord * np.cos(th1 + w / (2 * R)), y1 + chord * np.sin(th1 + w / (2 * R))

        x[arc], y[arc] = on_arc(s[arc] - s1)
        x2, y2 = on_arc(np.array(self.arc_length))
        # the exit clothoid, written back from its end E (heading θE, curvature 0) over w = s3 − s:
        # P = E − (cos θE C_w + sin θE S_w, sin θE C_w − cos θE S_w)
        thE = (L + self.arc_length) / R
        cE, sE = np.cos(thE), np.sin(thE)
        xE = float(x2) + cE * float(cL) + sE * float(sL)
        yE = float(y2) + sE * float(cL) - cE * float(sL)
        cw, sw = self._clothoid(s3 - s[exit_])
        x[exit_], y[exit_] = xE - (cE * cw + sE * sw), yE - (sE * cw - cE * sw)
        # the straight beyond, on the heading θE
        x[beyond], y[beyond] = xE + (s[beyond] - s3) * cE, yE + (s[beyond] - s3) * sE
        return x, y

    def x(self, s):
        """The plan coordinate x (along the first straight) of the centre line at distance s, m.

        x = ∫cos θ ds: the clothoids through Fresnel's integrals (``scipy.special.fresnel``),
        x = a C(u/a) with a = √(π R L); the arc in closed form.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).

        Returns
        -------
        float or ndarray
            x(s), m, shaped like ``s``.
        """
        return self._out(self._plan(s)[0], s)

    def y(self, s):
        """The plan coordinate y (to the left of the first straight) of the centre line at distance s, m.

        y = ∫sin θ ds: the clothoids through Fresnel's integrals, y = a S(u/a) with
        a = √(π R L); the arc in closed form.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).

        Returns
        -------
        float or ndarray
            y(s), m, shaped like ``s``.
        """
        return self._out(self._plan(s)[1], s)

    # ----------------------------------------------------------------- picture

    def plot(self, ax=None, *, view: str = "plan") -> dict:
        """Draw the curve: its plan, or its curvature or its cant against the distance.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        view : str
            ``"plan"`` (y against x, equal scales: the centre line, and the ends of the
            transitions marked), ``"curvature"`` (κ, 1/km, against s) or ``"cant"`` (h_t, mm,
            against s).

        Returns
        -------
        dict
            The artists: ``line`` (the curve) and ``ends`` (markers at the four segment ends).
        """
        import matplotlib

        from raildyn import plots

        view = _checks.choice("view", view, ("plan", "curvature", "cant"))
        ax = plots.axes_or_new(ax)
        ends = np.array(self._ends())
        margin = max(0.1 * self.length, 10.0)
        s = np.unique(np.concatenate([np.linspace(-margin, self.length + margin, 801), ends]))
        with matplotlib.rc_context(plots.STYLE):
            if view == "plan":
                (line,) = ax.plot(self.x(s), self.y(s), color=plots.COLORS[0], label="centre line")
                (marks,) = ax.plot(
                    self.x(ends), self.y(ends), "o", color=plots.COLORS[1], label="segment ends"
                )
                ax.set_aspect("equal", adjustable="datalim")
                ax.set_xlabel("$x$ (m)")
                ax.set_ylabel("$y$ (m)")
            elif view == "curvature":
                (line,) = ax.plot(s, 1e3 * self.curvature(s), color=plots.COLORS[0], label="curvature")
                (marks,) = ax.plot(ends, 1e3 * self.curvature(ends), "o", color=plots.COLORS[1])
                ax.set_xlabel("distance $s$ (m)")
                ax.set_ylabel("curvature $\\kappa$ (1/km)")
            else:
                (line,) = ax.plot(s, 1e3 * self.cant_at(s), color=plots.COLORS[0], label="cant")
                (marks,) = ax.plot(ends, 1e3 * self.cant_at(ends), "o", color=plots.COLORS[1])
                ax.set_xlabel("distance $s$ (m)")
                ax.set_ylabel("cant $h_t$ (mm)")
        return {"line": line, "ends": marks}
