"""A curve with transitions (book chapter 8): the track's centre line, curvature and cant along it.

A :class:`Curve`: a straight, an entry transition (a clothoid, whose curvature grows linearly
with distance, under a linear cant ramp of the same length), a circular arc and the
mirror-image exit transition, with its curvature, cant, cant gradient, twist, heading and plan
coordinates as functions of the distance s along the centre line. Its radius, cant and rail
spacing are checked against the limits of :mod:`raildyn.track.cant`, in that module's
convention (small roll angles). The curve is left-handed: the curvature, the heading and y are
positive turning to the left. It lives with the track so that the models that run on it (the
nonlinear wheelset of :mod:`raildyn.wheelset`, the curving of :mod:`raildyn.curving`) read it
from below. SI units throughout: m, rad, m/s²; a cant gradient or a twist is a ratio, m per m.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, scalar
from raildyn._compiled import compiled_as
from raildyn.constants import GRAVITY
from raildyn.track.cant import (
    MAXIMUM_CANT,
    MINIMUM_RADIUS,
    STANDARD_RAIL_SPACING,
    TWIST_BASE,
    _rail_spacing,
)

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.special.fresnel

__all__ = ["Curve", "ramp"]

# The shortest transition the ramp divides by, m: a curve without transitions (L = 0) steps from the
# straight to the arc within a picometre, and no division by zero is made.
_SHORTEST_RAMP = 1.0e-12


def _ramp(s, start, end, transition):
    rise = np.minimum(s - start, end - s) / np.maximum(transition, _SHORTEST_RAMP)
    return np.maximum(np.minimum(rise, 1.0), 0.0)


@compiled_as(_ramp)
def ramp(s, start, end, transition):
    """The share of a curve's arc that its curvature and cant reach at distance s, in [0, 1].

    0 on the straights, rising linearly along the entry transition, 1 on the arc, falling
    along the exit: κ(s) = ramp/R and h_t(s) = ramp·h_t of :class:`Curve`. In the form that
    numpy evaluates on arrays and numba compiles for floats: the compiled engine of
    :mod:`raildyn.wheelset` calls it too (see ``raildyn._compiled``).

    Parameters
    ----------
    s : float or array_like
        Distance along the centre line, m, finite.
    start, end : float
        s at the start of the entry transition and at the end of the exit transition, m
        (finite, ``start`` ≤ ``end``; :meth:`Curve.ends`).
    transition : float
        L, the length of each transition, m, in [0, (end − start)/2].

    Returns
    -------
    float or ndarray
        The share, shaped like ``s``.

    Examples
    --------
    >>> [float(ramp(s, 50.0, 370.0, 60.0)) for s in (40.0, 80.0, 200.0, 340.0)]
    [0.0, 0.5, 1.0, 0.5]
    """
    s = _checks.array("s", s, allow_empty=False)
    start, end = scalar("start", start), scalar("end", end)
    if end < start:
        raise ValueError(f"start must not lie beyond end, got start = {start!r} m and end = {end!r} m")
    transition = scalar("transition", transition, low=0.0, high=0.5 * (end - start))
    out = _ramp(s, start, end, transition)
    return float(out) if out.ndim == 0 else out


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
        R, m (≥ :data:`~raildyn.track.cant.MINIMUM_RADIUS`). 600 m by default: a main-line curve of moderate
        radius.
    cant : float
        h_t, m, in [0, :data:`~raildyn.track.cant.MAXIMUM_CANT`]. 0.1 m by default (balance speed
        71 km/h on 600 m).
    transition_length : float
        L, m (≥ 0; 0 is an abrupt change of curvature and a step of cant). 60 m by default:
        a ramp of 1.67 mm/m, within :data:`~raildyn.track.cant.CANT_GRADIENT_LIMIT`.
    arc_length : float
        The circular arc's length, m (≥ 0). 200 m by default.
    straight : float
        The straight before the entry transition, m (≥ 0). 50 m by default.
    rail_spacing : float
        2a_r, m, in [0.5, 2.0]; the base of the cant (:data:`~raildyn.track.cant.STANDARD_RAIL_SPACING`).

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
        return self.ends()[3]

    def ends(self) -> tuple[float, float, float, float]:
        """The ends of the curve's pieces along the centre line.

        Returns
        -------
        tuple of float
            s₀, s₁, s₂, s₃, m: the starts of the entry transition, the arc and the exit
            transition, and the end of the exit transition.
        """
        s0 = self.straight
        s1 = s0 + self.transition_length
        s2 = s1 + self.arc_length
        return s0, s1, s2, s2 + self.transition_length

    def _share(self, s) -> np.ndarray:
        """:func:`ramp` along this curve at the distances s (checked), as an array."""
        s0, _, _, s3 = self.ends()
        return _ramp(_checks.array("s", s, allow_empty=False), s0, s3, self.transition_length)

    def _pieces(self, s):
        """The distances as an array, and the masks of the straight, entry, arc, exit and the track beyond."""
        s = _checks.array("s", s, allow_empty=False)
        s0, s1, s2, s3 = self.ends()
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
        return self._out(self._share(s) / self.radius, s)

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
        return self._out(self.cant * self._share(s), s)

    def unbalanced_acceleration(self, s, speed):
        """The unbalanced lateral acceleration a_q(s) = V² κ(s) − g h_t(s)/(2a_r) at distance s, m/s².

        :func:`~raildyn.track.cant.unbalanced_acceleration` along the curve, in that module's
        small-angle convention (g I/(2a_r) with I = 2a_r V² κ/g − h_t): zero on the straights,
        growing along the transitions.

        Parameters
        ----------
        s : float or array_like
            Distance along the centre line, m (any finite value).
        speed : float
            V, m/s, in [0, :data:`~raildyn.track.cant.MAXIMUM_SPEED`].

        Returns
        -------
        float or ndarray
            a_q(s), m/s², positive outwards, shaped like ``s``.

        Examples
        --------
        On the arc, the function's value for its radius and cant:

        >>> from raildyn.track.cant import unbalanced_acceleration
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
        :data:`~raildyn.track.cant.CANT_GRADIENT_LIMIT` (EN 13803).

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
            The base (a bogie's wheelbase), m (> 0); :data:`~raildyn.track.cant.TWIST_BASE` (3 m) by default.

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
        s0, s1, _, s3 = self.ends()
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
        from scipy.special import fresnel

        if self.transition_length == 0:
            return np.zeros_like(u), np.zeros_like(u)
        # √π √R √L, not √(πRL), which would overflow for R and L near 1e300.
        a = np.sqrt(np.pi) * np.sqrt(self.radius) * np.sqrt(self.transition_length)
        S, C = fresnel(u / a)
        return a * C, a * S

    def _plan(self, s) -> tuple[np.ndarray, np.ndarray]:
        s, before, entry, arc, exit_, beyond = self._pieces(s)
        s0, s1, s2, s3 = self.ends()
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
        ends = np.array(self.ends())
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
