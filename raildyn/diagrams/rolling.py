"""The wheelset on the rails (chapters 4 and 5), drawn from a :class:`raildyn.wheelset.Wheelset`: in section,
with its coned treads, and in plan, moving with its lateral displacement y and yaw ψ (the hunting wheelset).

Coordinates as in :mod:`raildyn.wheelset`: x forward, y to the left, z up, ψ positive turning to the
left. The section is seen from behind, looking in the direction of travel, so the left rail is on the
left of the picture; the plan is seen from above, x to the right and y up the page.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.diagrams import _draw as d
from raildyn.wheelset import Wheelset

__all__ = ["WheelsetPlan", "wheelset_plan", "wheelset_section"]

_MAX_EXAGGERATION = 1.0e4
# The wheel's profile in section, m: from the contact point, the tread runs 70 mm outwards and 50 mm
# inwards to the flange root; the flange is 30 mm deep and 30 mm thick; the rim 100 mm deep.
_TREAD_OUT, _TREAD_IN, _FLANGE_DEPTH, _FLANGE_WIDTH, _RIM = 0.07, 0.05, 0.03, 0.03, 0.10


def _wheelset(name: str, ws) -> Wheelset:
    return _checks.instance(name, ws, Wheelset, "raildyn.wheelset.Wheelset")


def _exaggeration(value) -> float:
    return _checks.scalar("exaggerate", value, low=1.0, high=_MAX_EXAGGERATION)


def _drawn_shift(ws: Wheelset, y, exaggerate: float) -> float:
    """The lateral shift as drawn, y times the exaggeration, refused past a quarter of a."""
    y = _checks.scalar("y", y)
    if abs(y * exaggerate) > 0.25 * ws.half_gauge:
        raise ValueError(
            f"y must be drawn within a quarter of the half gauge a = {ws.half_gauge} m: "
            f"|y| × exaggerate ≤ {0.25 * ws.half_gauge:.4g} m, got y = {y!r} with exaggerate = {exaggerate!r}"
        )
    return y * exaggerate


def _wheel_profile(a: float, r0: float, cone: float, side: float) -> np.ndarray:
    """One wheel's section (n, 2) in the wheelset's frame (origin at the axle's centre, up positive).

    ``side`` is −1 for the left wheel (left of the picture), +1 for the right; the tread's radius grows
    towards the flange, ``cone`` per metre.
    """
    c = side * a  # the contact point of the centred wheelset

    def tread(u_in):  # u_in: distance from the contact point towards the track's centre
        return -(r0 + cone * u_in)

    inward = -side  # the direction towards the track's centre
    rim = -(r0 - _RIM)
    flange = _TREAD_IN + _FLANGE_WIDTH
    # (distance inwards from the contact point, height): the lower half of the wheel, from the web's
    # outer side at the hub, round the tread and the flange, to the web's inner side at the hub
    lower = [
        (-0.01, -0.12), (-0.01, rim), (-_TREAD_OUT, rim), (-_TREAD_OUT, tread(-_TREAD_OUT)),
        (0.0, tread(0.0)), (_TREAD_IN, tread(_TREAD_IN)),
        (_TREAD_IN + 0.4 * _FLANGE_WIDTH, tread(_TREAD_IN) - _FLANGE_DEPTH),
        (flange, tread(_TREAD_IN) - 0.5 * _FLANGE_DEPTH), (flange, rim), (0.02, rim), (0.02, -0.12),
    ]  # fmt: skip
    half = np.array(lower)
    outline = np.vstack([half, half[::-1] * (1.0, -1.0)])  # the upper half mirrors the lower
    points = np.column_stack([c + inward * outline[:, 0], outline[:, 1]])
    return points


def _rail_xy(u: float) -> np.ndarray:
    """A rail's section (n, 2) with the crown of its head at (u, 0): head, web, foot (UIC 60 proportions)."""
    right = np.array(
        [
            (0.02, 0.004),
            (0.036, 0.0),
            (0.036, -0.04),
            (0.009, -0.05),
            (0.009, -0.14),
            (0.075, -0.158),
            (0.075, -0.172),
        ]
    )
    left = right[::-1] * (-1.0, 1.0)
    return np.vstack([[(0.0, 0.005)], right, left]) + (u, 0.0)


def wheelset_section(ws: Wheelset, y: float = 0.0, *, exaggerate: float = 1.0, ax=None) -> dict:
    """Draw a wheelset on its rails in section, to scale: coned treads, r₀, a, λ and the shift y.

    The rails' crowns sit at ±a (``ws.half_gauge``) from the track's centre line; the wheels of
    rolling radius r₀ (``ws.rolling_radius``) are cones of conicity λ (``ws.conicity``), their radius
    growing towards the flange. Shifted by y to the left, the wheelset rolls on r₀ + λy on the left
    and r₀ − λy on the right, so it rolls by λy/a about the track's axis (a cone on knife-edge
    rails, book chapter 5): the picture moves it and tilts it by as much. The contact points stay
    on the rails' crowns. Lateral shifts and conicity of a real wheelset are small: ``exaggerate``
    multiplies both as drawn (y by it, the cone's slope by it) and says so in the picture.

    Parameters
    ----------
    ws : raildyn.wheelset.Wheelset
        The wheelset: ``half_gauge`` a (m), ``rolling_radius`` r₀ (m), ``conicity`` λ.
    y : float
        Lateral displacement of the wheelset, m, positive to the left; drawn within a quarter of a.
    exaggerate : float
        Factor in [1, 10⁴] on the drawn shift and the drawn cone slope.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``wheels`` (two Polygons, left and right), ``axle`` (Polygon), ``rails`` (two Polygons),
        ``contacts`` (Line2D whose data are the two contact points, m), ``centre_line`` (Line2D of the
        wheelset's centre line), ``texts`` (list of Text).

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> art = wheelset_section(Wheelset(), y=0.004, exaggerate=5.0)
    >>> art["contacts"].get_xdata()
    array([-0.75,  0.75])
    """
    ws = _wheelset("ws", ws)
    exaggerate = _exaggeration(exaggerate)
    shift = _drawn_shift(ws, y, exaggerate)
    a, r0 = ws.half_gauge, ws.rolling_radius
    cone = min(ws.conicity * exaggerate, 0.5)
    roll = -cone * shift / a  # picture angle: the left end rises when the wheelset moves left
    ax = d.start(ax)

    def placed(points):
        return d.rotate(points, roll) + (-shift, r0)

    with d.style():
        art = {"rails": [d.block(ax, _rail_xy(side * a), fill="0.7") for side in (-1.0, 1.0)]}
        sleeper = d.rectangle_xy((0.0, -0.172 - 0.09), 2 * a + 1.0, 0.18)
        art["sleeper"] = d.block(ax, sleeper, fill="0.95", z=0.5)
        axle = d.rectangle_xy((0.0, 0.0), 2 * a + 0.24, 0.16)
        art["axle"] = d.block(ax, placed(axle), z=1.5)
        art["wheels"] = [d.block(ax, placed(_wheel_profile(a, r0, cone, s)), z=2) for s in (-1.0, 1.0)]
        (art["contacts"],) = ax.plot([-a, a], [0.0, 0.0], "o", color=d.FORCE, ms=4, zorder=6)
        top = r0 + 0.35
        ax.plot([0.0, 0.0], [-0.4, top], color=d.DIMENSION, lw=0.6, ls="-.")
        centre = placed(np.array([[0.0, -r0 - 0.05], [0.0, 0.35]]))
        (art["centre_line"],) = ax.plot(centre[:, 0], centre[:, 1], color=d.COORDINATE, lw=0.7, ls="-.")
        texts = []
        _, t = d.dimension(ax, (0.0, -0.4), (a, -0.4), "$a$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (-a, -0.4), (0.0, -0.4), "$a$", side=-1.0)
        texts.append(t)
        hub = placed(np.array([[a + 0.2, 0.0]]))[0]
        _, t = d.dimension(ax, (a + 0.2, 0.0), (a + 0.2, hub[1]), "$r_0$", side=-1.0)
        texts.append(t)
        ax.plot([a, a + 0.25], [0.0, 0.0], color=d.DIMENSION, lw=0.5)
        ax.plot([hub[0] - 0.1, a + 0.25], [hub[1], hub[1]], color=d.DIMENSION, lw=0.5)
        if shift != 0.0:
            d.arrow(ax, (0.0, top - 0.05), (-shift, top - 0.05))
        texts.append(d.label(ax, (-shift / 2, top + 0.03), "$y$", color=d.COORDINATE))
        tread = placed(np.array([[a - _TREAD_IN / 2 - 0.01, -r0 - 0.01]]))[0]
        texts.append(d.label(ax, tread + (-0.12, -0.07), r"$\lambda$", ha="right"))
        ax.plot([tread[0] - 0.11, tread[0]], [tread[1] - 0.065, tread[1]], color=d.DIMENSION, lw=0.5)
        texts.append(d.label(ax, (-a - 0.12, r0 + 0.2), "L", size=8, color=d.DIMENSION))
        texts.append(d.label(ax, (a + 0.12, r0 + 0.2), "R", size=8, color=d.DIMENSION))
        if exaggerate != 1.0:  # below the dimension labels of a, whatever the figure's size
            texts.append(d.note(ax, (0.0, -0.4), f"$y$ and $\\lambda$ drawn × {exaggerate:g}", points=16))
        art["texts"] = texts
        d.finish(ax)
    return art


class WheelsetPlan:
    """A wheelset drawn in plan on its track, which :meth:`update` moves in place (y, ψ).

    Made by :func:`wheelset_plan`, which documents the drawing; a widget showing the hunting
    wheelset calls :meth:`update` with each new (y, ψ), and the same artists move.

    Parameters
    ----------
    ws : raildyn.wheelset.Wheelset
        The wheelset: ``half_gauge`` a (m), ``rolling_radius`` r₀ (m).
    y : float
        Lateral displacement, m, positive to the left; drawn (times ``exaggerate``) within a quarter of a.
    psi : float
        Yaw angle ψ, rad, positive turning to the left; drawn (times ``exaggerate``) within ±π/6.
    exaggerate : float
        Factor in [1, 10⁴] on the drawn y and ψ.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Attributes
    ----------
    ax : matplotlib.axes.Axes
    artists : dict
        ``wheels`` (two Polygons), ``axle`` (Polygon), ``heading`` (Line2D, the wheelset's rolling
        direction), ``reference`` (Line2D, the track's direction through the wheelset's centre),
        ``y`` (the y arrow), ``psi`` (Line2D arc) and ``psi_head`` (its arrow), ``texts``
        (dict: ``y``, ``psi``, ``V``, ``a``), ``rails`` (list of Line2D).
    """

    def __init__(self, ws: Wheelset, y: float = 0.0, psi: float = 0.0, *, exaggerate: float = 1.0, ax=None):
        self._ws = _wheelset("ws", ws)
        self._exaggerate = _exaggeration(exaggerate)
        shift, yaw = self._drawn(y, psi)
        a, r0 = ws.half_gauge, ws.rolling_radius
        self._reach = 2.4 * r0 + 0.6
        self.ax = ax = d.start(ax)
        with d.style():
            rails = []
            for side in (-1.0, 1.0):
                for edge in (-0.036, 0.036):
                    rails += ax.plot([-self._reach, self._reach], [side * a + edge] * 2, **d.LINE)
            ax.plot([-self._reach, self._reach], [0.0, 0.0], color=d.DIMENSION, lw=0.6, ls="-.")
            art = {"rails": rails, "axle": d.block(ax, np.zeros((4, 2)), z=1.5)}
            art["wheels"] = [d.block(ax, np.zeros((4, 2)), z=2) for _ in range(2)]
            (art["heading"],) = ax.plot([], [], color=d.COORDINATE, lw=0.7, ls="--")
            (art["reference"],) = ax.plot([], [], color=d.DIMENSION, lw=0.6, ls=":")
            art["y"] = d.arrow(ax, (0.0, 0.0), (0.0, 0.0))
            (art["psi"],) = ax.plot([], [], color=d.COORDINATE, lw=1.1)
            art["psi_head"] = d.arrow(ax, (0.0, 0.0), (0.0, 0.0))
            texts = {
                "y": d.label(ax, (0.0, 0.0), "$y$", color=d.COORDINATE, ha="left"),
                "psi": d.label(ax, (0.0, 0.0), r"$\psi$", color=d.COORDINATE, ha="left"),
            }
            d.arrow(ax, (self._reach - 0.5, a + 0.35), (self._reach, a + 0.35), color=d.FORCE)
            texts["V"] = d.label(ax, (self._reach - 0.55, a + 0.35), "$V$", color=d.FORCE, ha="right")
            _, texts["a"] = d.dimension(ax, (-self._reach + 0.2, 0.0), (-self._reach + 0.2, a), "$a$")
            if self._exaggerate != 1.0:
                d.label(
                    ax,
                    (0.0, -a - 0.3),
                    f"$y$ and $\\psi$ drawn × {self._exaggerate:g}",
                    size=7,
                    color=d.DIMENSION,
                )
            art["texts"] = texts
            self.artists = art
            self._place(shift, yaw)
            ax.set_ylim(-a - 0.45, a + 0.5)
            ax.set_xlim(-self._reach - 0.1, self._reach + 0.1)
            ax.set_aspect("equal", adjustable="box")
            ax.set_axis_off()

    def _drawn(self, y, psi) -> tuple[float, float]:
        shift = _drawn_shift(self._ws, y, self._exaggerate)
        psi = _checks.scalar("psi", psi)
        if abs(psi * self._exaggerate) > np.pi / 6:
            raise ValueError(
                f"psi must be drawn within ±π/6: |psi| × exaggerate ≤ {np.pi / 6:.4g} rad, "
                f"got psi = {psi!r} with exaggerate = {self._exaggerate!r}"
            )
        return shift, psi * self._exaggerate

    def _place(self, shift: float, yaw: float) -> None:
        a, r0 = self._ws.half_gauge, self._ws.rolling_radius
        art, centre = self.artists, np.array([0.0, shift])
        art["axle"].set_xy(d.rectangle_xy(centre, 0.14, 2 * a + 0.3, yaw))
        for side, wheel in zip((-1.0, 1.0), art["wheels"], strict=True):
            hub = d.rotate([centre + (0.0, side * a)], yaw, centre)[0]
            wheel.set_xy(d.rectangle_xy(hub, 2 * r0, 0.13, yaw))
        heading = d.rotate([centre + (-0.1, 0.0), centre + (2.0 * r0 + 0.5, 0.0)], yaw, centre)
        art["heading"].set_data(heading[:, 0], heading[:, 1])
        art["reference"].set_data([0.0, 2.0 * r0 + 0.5], [shift, shift])
        x_y = 1.3 * r0 + 0.25  # the y arrow stands behind the wheel
        art["y"].set_positions((-x_y, 0.0), (-x_y, shift))
        art["y"].set_visible(abs(shift) > 1e-9)
        art["texts"]["y"].set_position((-x_y + 0.06, shift / 2))
        arc = d.arc_xy(centre, 2.0 * r0 + 0.3, 0.0, yaw)
        art["psi"].set_data(arc[:-3, 0], arc[:-3, 1])
        art["psi_head"].set_positions(tuple(arc[-4]), tuple(arc[-1]))
        art["psi_head"].set_visible(abs(yaw) > 1e-9)
        art["texts"]["psi"].set_position(tuple(arc[len(arc) // 2] + (0.06, 0.0)))

    def update(self, y: float, psi: float) -> dict:
        """Move the drawn wheelset to (y, ψ): the same artists, moved (no new artist, no new figure).

        Parameters
        ----------
        y : float
            Lateral displacement, m, positive to the left (as drawn, times ``exaggerate``, within a/4).
        psi : float
            Yaw angle, rad, positive turning to the left (as drawn, times ``exaggerate``, within ±π/6).

        Returns
        -------
        dict
            The artists (``artists``), moved.
        """
        self._place(*self._drawn(y, psi))
        return self.artists


def wheelset_plan(ws: Wheelset, y: float = 0.0, psi: float = 0.0, *, exaggerate: float = 1.0, ax=None):
    """Draw a wheelset in plan on its track, displaced by y and yawed by ψ; it moves with ``update``.

    Seen from above: the two rails at ±a (``ws.half_gauge``), the track's centre line, the axle
    and the wheels (2r₀ long, ``ws.rolling_radius``) turned by ψ about the wheelset's centre,
    which stands y to the left of the centre line; the dashed line is the wheelset's rolling
    direction, the arc from the track's direction to it is ψ, and the red arrow the direction of
    travel at the speed V. Hunting amplitudes are millimetres and milliradians: ``exaggerate``
    multiplies both as drawn (a widget might pass 20) and the picture says so.

    Parameters
    ----------
    ws : raildyn.wheelset.Wheelset
        The wheelset: ``half_gauge`` a (m), ``rolling_radius`` r₀ (m).
    y : float
        Lateral displacement, m, positive to the left; drawn (times ``exaggerate``) within a quarter of a.
    psi : float
        Yaw angle ψ, rad, positive turning to the left; drawn (times ``exaggerate``) within ±π/6.
    exaggerate : float
        Factor in [1, 10⁴] on the drawn y and ψ.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    WheelsetPlan
        Its ``artists`` (a dict) and ``update(y, psi)``, which moves them in place.

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> plan = wheelset_plan(Wheelset(), y=0.003, psi=0.002, exaggerate=20.0)
    >>> moved = plan.update(-0.003, 0.0)
    >>> moved is plan.artists
    True
    """
    return WheelsetPlan(ws, y, psi, exaggerate=exaggerate, ax=ax)
