"""Bogies, cars and the three-piece freight truck (chapters 6 to 8), drawn to scale from their models.

* :func:`bogie_plan` — a :class:`raildyn.vehicles.Bogie` from above: two wheelsets 2b apart in a
  frame, the primary springs (lateral k_y, longitudinal ones whose couple is k_ψ);
* :func:`car_side` — a :class:`raildyn.vehicles.VerticalCar` from the side: body, two bogies 2l
  apart, secondary and primary springs and dampers, the coordinates z_c, θ_c;
* :func:`car_plan` — a :class:`raildyn.vehicles.LateralCar` from above: the body yawed by ψ on its two bogies;
* :func:`truck_schematic` — a :class:`raildyn.vehicles.ThreePieceTruck`: a side frame from the side
  (bolster on its spring nest between two friction wedges) and the truck from above (side frames,
  bolster, wheelsets: the parallelogram that warps).

Lengths along and across the track are the model's (b, l, a, d, r₀); the heights of frames and bodies,
which the lateral and vertical models do not hold, are drawn at fixed, typical sizes.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.diagrams import _draw as d
from raildyn.vehicles import Bogie, LateralCar, ThreePieceTruck, VerticalCar

__all__ = ["BogiePlan", "bogie_plan", "car_plan", "car_side", "truck_schematic"]

_MAX_EXAGGERATION = 1.0e4

WHEEL_RADIUS = 0.46
"""Radius (m) of the wheels in :func:`car_side`, whose model (a vertical car) holds none."""


def _rails(ax, x0: float, x1: float, a: float) -> list:
    lines = []
    for side in (-1.0, 1.0):
        for edge in (-0.036, 0.036):
            lines += ax.plot([x0, x1], [side * a + edge] * 2, color="0.45", lw=0.7)
    lines += ax.plot([x0, x1], [0.0, 0.0], color=d.DIMENSION, lw=0.6, ls="-.")
    return lines


def _wheelset_plan(ax, centre, a: float, r0: float, yaw: float = 0.0) -> list:
    """An axle and its two wheels from above, centred at ``centre``, turned by ``yaw``."""
    centre = np.asarray(centre, float)
    parts = [d.block(ax, d.rectangle_xy(centre, 0.14, 2 * a + 0.4, yaw), z=1.5)]
    for side in (-1.0, 1.0):
        hub = d.rotate([centre + (0.0, side * a)], yaw, centre)[0]
        parts.append(d.block(ax, d.rectangle_xy(hub, 2 * r0, 0.13, yaw), z=2))
    return parts


class BogiePlan:
    """A two-axle bogie drawn in plan on its track, which :meth:`update` moves in place.

    :func:`bogie_plan` documents the drawing and draws it at rest. The frame and each wheelset move
    with their own lateral displacement y and yaw ψ (the coordinates of the bogie's lateral model,
    :class:`raildyn.vehicles.Bogie`), and the springs between them stretch to follow: an animation of
    the hunting bogie calls :meth:`update` with each new state, and the same artists move.

    Parameters
    ----------
    bogie : raildyn.vehicles.Bogie
        The bogie: ``semi_wheelbase`` b (m) and its ``wheelset`` (a, r₀ in m).
    exaggerate : float
        Factor in [1, 10⁴] on the drawn displacements and yaws, which the picture states.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Attributes
    ----------
    ax : matplotlib.axes.Axes
    artists : dict
        As :func:`bogie_plan` returns them.

    Examples
    --------
    >>> from raildyn.vehicles import Bogie
    >>> plan = BogiePlan(Bogie(), exaggerate=10.0)
    >>> plan.update((0.001, 0.0), ((0.004, 0.002), (-0.002, 0.001))) is plan.artists
    True
    """

    def __init__(self, bogie: Bogie, *, exaggerate: float = 1.0, ax=None):
        self._bogie = _checks.instance("bogie", bogie, Bogie, "raildyn.vehicles.Bogie")
        self._exaggerate = _checks.scalar("exaggerate", exaggerate, low=1.0, high=_MAX_EXAGGERATION)
        ws = bogie.wheelset
        a, r0, b = ws.half_gauge, ws.rolling_radius, bogie.semi_wheelbase
        self._box = box = a + 0.2  # the axle boxes, just outside the wheels
        self._side = side = box + 0.3  # the frame's side members
        reach = b + r0 + 0.9
        self.ax = ax = d.start(ax)
        with d.style():
            art = {"rails": _rails(ax, -reach, reach, a)}
            art["wheelsets"] = [_wheelset_plan(ax, (x, 0.0), a, r0) for x in (b, -b)]
            frame = [d.block(ax, np.zeros((4, 2)), fill="0.8", z=1) for _ in range(4)]
            frame.append(d.block(ax, np.zeros((4, 2)), fill="white", z=1.2))
            art["frame"] = frame
            art["boxes"] = [d.block(ax, np.zeros((4, 2)), fill="0.7", z=2.5) for _ in range(4)]
            art["brackets"] = [ax.plot([], [], **d.LINE)[0] for _ in range(4)]
            art["lateral_springs"] = [ax.plot([], [], **d.LINE)[0] for _ in range(4)]
            art["longitudinal_springs"] = [ax.plot([], [], **d.LINE)[0] for _ in range(4)]
            gap = (box + 0.08 + side - 0.07) / 2  # between the axle box and the frame's side member
            texts = [
                d.label(ax, (b + 0.14, gap), "$k_y$", ha="left", size=7),
                d.label(ax, (b - 0.33, gap), r"$k_\psi$", size=7),
            ]
            _, t = d.dimension(ax, (0.0, -side - 0.35), (b, -side - 0.35), "$b$", side=-1.0)
            texts.append(t)
            _, t = d.dimension(ax, (-b, -side - 0.35), (0.0, -side - 0.35), "$b$", side=-1.0)
            texts.append(t)
            _, t = d.dimension(ax, (-reach + 0.25, 0.0), (-reach + 0.25, a), "$a$")
            texts.append(t)
            d.arrow(ax, (reach - 0.6, side + 0.35), (reach, side + 0.35), color=d.FORCE)
            texts.append(d.label(ax, (reach - 0.65, side + 0.35), "$V$", color=d.FORCE, ha="right"))
            if self._exaggerate != 1.0:
                texts.append(
                    d.label(
                        ax,
                        (0.0, side + 0.35),
                        f"$y$ and $\\psi$ drawn × {self._exaggerate:g}",
                        size=7,
                        color=d.DIMENSION,
                    )
                )
            art["texts"] = texts
            self.artists = art
            self._place(np.zeros(2), np.zeros((2, 2)))
            d.finish(ax)

    def _drawn(self, frame, wheelsets) -> tuple[np.ndarray, np.ndarray]:
        """The drawn (y, ψ) of the frame and of the two wheelsets, checked and exaggerated."""
        frame = _checks.array("frame", frame, shape=(2,))
        wheelsets = _checks.array("wheelsets", wheelsets, shape=(2, 2))
        limit_y, limit_psi = 0.25 * self._bogie.wheelset.half_gauge, np.pi / 12
        for name, value in (("frame", frame), ("wheelsets", wheelsets)):
            drawn = np.reshape(value, (-1, 2)) * self._exaggerate
            if np.abs(drawn[:, 0]).max() > limit_y or np.abs(drawn[:, 1]).max() > limit_psi:
                raise ValueError(
                    f"{name} must be drawn within |y| × exaggerate ≤ {limit_y:.4g} m and "
                    f"|ψ| × exaggerate ≤ {limit_psi:.4g} rad, got {value.tolist()} with "
                    f"exaggerate = {self._exaggerate!r}"
                )
        return frame * self._exaggerate, wheelsets * self._exaggerate

    def _place(self, frame: np.ndarray, wheelsets: np.ndarray) -> None:
        art, b = self.artists, self._bogie.semi_wheelbase
        ws = self._bogie.wheelset
        a, r0, box, side = ws.half_gauge, ws.rolling_radius, self._box, self._side

        def on_frame(points):  # frame coordinates → track: turned by ψ about the centre, shifted by y
            return d.rotate(points, frame[1]) + (0.0, frame[0])

        shapes = [d.rectangle_xy((0.0, s * side), 2 * b + 0.9, 0.14) for s in (-1.0, 1.0)]
        shapes += [d.rectangle_xy((x, 0.0), 0.16, 2 * side) for x in (-0.3, 0.3)]
        shapes.append(d.arc_xy((0.0, 0.0), 0.2, 0.0, 2 * np.pi))
        for patch, shape in zip(art["frame"], shapes, strict=True):
            patch.set_xy(on_frame(shape))
        k = 0
        for x, (y_w, psi_w), parts in zip((b, -b), wheelsets, art["wheelsets"], strict=True):
            centre = np.array([x, y_w])

            def on_wheelset(points, centre=centre, psi_w=psi_w):
                return d.rotate(np.asarray(points, float) + (0.0, centre[1]), psi_w, centre)

            parts[0].set_xy(on_wheelset(d.rectangle_xy((x, 0.0), 0.14, 2 * a + 0.4)))
            for s, wheel in zip((-1.0, 1.0), parts[1:], strict=True):
                wheel.set_xy(on_wheelset(d.rectangle_xy((x, s * a), 2 * r0, 0.13)))
            for s in (-1.0, 1.0):
                art["boxes"][k].set_xy(on_wheelset(d.rectangle_xy((x, s * box), 0.2, 0.16)))
                bracket = x - np.sign(x) * 0.55
                ends = on_frame([(bracket, s * box), (bracket, s * (side - 0.07))])
                art["brackets"][k].set_data(ends[:, 0], ends[:, 1])
                p0 = on_wheelset([(x, s * (box + 0.08))])[0]
                p1 = on_frame([(x, s * (side - 0.07))])[0]
                art["lateral_springs"][k].set_data(*d.spring_xy(p0, p1, 0.1, 3).T)
                p0 = on_wheelset([(x - np.sign(x) * 0.1, s * box)])[0]
                art["longitudinal_springs"][k].set_data(*d.spring_xy(p0, ends[0], 0.1, 3).T)
                k += 1

    def update(self, frame, wheelsets) -> dict:
        """Move the drawn frame and wheelsets: the same artists, moved (no new artist, no new figure).

        Parameters
        ----------
        frame : array_like, (2,)
            The frame's lateral displacement y (m, positive to the left) and yaw ψ (rad, positive
            turning to the left); as drawn, times ``exaggerate``, within a/4 and π/12.
        wheelsets : array_like, (2, 2)
            (y, ψ) of the wheelset at x = +b, then of the one at x = −b, as ``frame``.

        Returns
        -------
        dict
            The artists (``artists``), moved.
        """
        self._place(*self._drawn(frame, wheelsets))
        return self.artists


def bogie_plan(bogie: Bogie, *, ax=None) -> dict:
    """Draw a two-axle bogie from above: wheelsets at ±b in a frame, the primary springs, to scale.

    The track's rails at ±a (``bogie.wheelset.half_gauge``) carry two wheelsets (wheels 2r₀ long)
    at x = ±b (``bogie.semi_wheelbase``); at each axle box a lateral spring k_y and a longitudinal
    spring tie the wheelset to the frame. The longitudinal springs, either side of the centre line,
    resist the wheelset's yaw relative to the frame as a couple: the yaw stiffness k_ψ (the
    :class:`~raildyn.wheelset.Wheelset`'s ``yaw_stiffness``). The body rests on the centre pivot;
    the red arrow is the direction of travel. The bogie stands centred; :class:`BogiePlan` draws
    the same picture and moves it.

    Parameters
    ----------
    bogie : raildyn.vehicles.Bogie
        The bogie: ``semi_wheelbase`` b (m) and its ``wheelset`` (a, r₀ in m).
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``wheelsets`` (two lists of Polygons, x = +b first), ``frame`` and ``boxes`` (lists of
        Polygons), ``lateral_springs``, ``longitudinal_springs``, ``brackets`` (lists of Line2D),
        ``texts`` (list of Text), ``rails``.

    Examples
    --------
    >>> from raildyn.vehicles import Bogie
    >>> art = bogie_plan(Bogie())
    >>> len(art["lateral_springs"]), len(art["longitudinal_springs"])
    (4, 4)
    """
    return BogiePlan(bogie, ax=ax).artists


def car_side(car: VerticalCar, *, ax=None) -> dict:
    """Draw a car from the side: body on two bogies, secondary and primary springs and dampers, l, b, z, θ.

    To scale along the car: the bogie centres at x = ±l (``car.semi_bogie_spacing``), each bogie's
    wheels at ±b about its centre (``car.semi_wheelbase``), on wheels of radius 0.46 m
    (``WHEEL_RADIUS``). Each wheelset carries its bogie frame on the primary spring k_p and
    damper c_p, each bogie the body on the secondary k_s and c_s (the model's
    ``primary_stiffness``, ``primary_damping``, ``secondary_stiffness``, ``secondary_damping``). The
    body's coordinates are its bounce z_c and pitch θ_c, each bogie's z_b and θ_b (as in notebook
    06; θ > 0 raises the front, on the right, as in :mod:`raildyn.vehicles.vertical`); heights are
    drawn at fixed sizes.

    Parameters
    ----------
    car : raildyn.vehicles.VerticalCar
        The car.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``body`` (Polygon), ``bogies`` (two Polygons, x = +l first), ``wheels`` (four Polygons),
        ``primary``, ``secondary`` (lists of (spring, damper) Line2D pairs), ``texts`` (list of Text).

    Examples
    --------
    >>> from raildyn.vehicles import VerticalCar
    >>> art = car_side(VerticalCar())
    >>> len(art["wheels"]), len(art["secondary"])
    (4, 2)
    """
    _checks.instance("car", car, VerticalCar, "raildyn.vehicles.VerticalCar")
    l, b, r = car.semi_bogie_spacing, car.semi_wheelbase, WHEEL_RADIUS
    frame_z, frame_h = r + 0.9, 0.35  # the bogie frame's centre and depth, m
    body_z, body_h = frame_z + 1.4, 2.6  # the body's underside and depth
    half = l + b + 1.5  # the body's half length
    ax = d.start(ax, (9.0, 3.2))
    with d.style():
        art = {"rail": d.ground(ax, -half - 0.5, half + 0.5, 0.0, 0.25)}
        art["body"] = d.block(ax, d.rectangle_xy((0.0, body_z + body_h / 2), 2 * half, body_h))
        art["bogies"], art["wheels"], art["primary"], art["secondary"] = [], [], [], []
        for xc in (l, -l):
            art["bogies"].append(d.block(ax, d.rectangle_xy((xc, frame_z), 2 * b + 1.4, frame_h), fill="0.8"))
            top = frame_z + frame_h / 2
            art["secondary"].append(
                (
                    d.spring(ax, (xc - 0.35, top), (xc - 0.35, body_z), 0.3, coils=4),
                    d.dashpot(ax, (xc + 0.35, body_z), (xc + 0.35, top), 0.3),
                )
            )
            for xw in (xc + b, xc - b):
                art["wheels"].append(d.block(ax, d.wheel_xy((xw, r), r), z=2))
                ax.plot(xw, r, "o", color="black", ms=2.5, zorder=3)
                low = frame_z - frame_h / 2
                art["primary"].append(
                    (
                        d.spring(ax, (xw - 0.3, r), (xw - 0.3, low), 0.25, coils=3),
                        d.dashpot(ax, (xw + 0.3, low), (xw + 0.3, r), 0.25),
                    )
                )
                ax.plot([xw - 0.3, xw + 0.3], [r, r], **d.LINE)
        texts = [
            d.label(ax, (l + 0.75, (frame_z + frame_h / 2 + body_z) / 2), "$k_s$, $c_s$", ha="left", size=8),
            d.label(ax, (l + b + 0.55, (r + frame_z - frame_h / 2) / 2), "$k_p$, $c_p$", ha="left", size=8),
        ]
        centre = np.array([0.0, body_z + body_h / 2])
        d.arrow(ax, centre, centre + (0.0, 1.6))
        texts.append(
            d.label(
                ax, centre + (0.3, body_h / 2 + 0.15), "$z_c$", color=d.COORDINATE, ha="left", va="bottom"
            )
        )
        d.rotation(ax, centre, 0.8, np.radians(110), np.radians(130))  # θ_c > 0 raises the front
        texts.append(d.label(ax, centre + (-1.1, 0.75), r"$\theta_c$", color=d.COORDINATE, ha="right"))
        ax.plot(*centre, "o", color=d.COORDINATE, ms=3, zorder=6)
        for xc, tag in ((l, "1"), (-l, "2")):
            texts.append(
                d.label(
                    ax,
                    (xc - b - 0.9, frame_z),
                    f"$z_{{b{tag}}}$, $\\theta_{{b{tag}}}$",
                    size=7,
                    color=d.COORDINATE,
                    ha="right",
                )
            )
        _, t = d.dimension(ax, (0.0, -0.7), (l, -0.7), "$l$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (-l, -0.7), (0.0, -0.7), "$l$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (l, -0.7), (l + b, -0.7), "$b$", side=-1.0)
        texts.append(t)
        ax.plot([0.0, 0.0], [-0.9, body_z + body_h + 0.3], color=d.DIMENSION, lw=0.6, ls="-.")
        for x in (l, -l, l + b):
            ax.plot([x, x], [-0.9, 0.0], color=d.DIMENSION, lw=0.5)
        d.arrow(ax, (half - 1.5, body_z + body_h + 0.5), (half, body_z + body_h + 0.5), color=d.FORCE)
        texts.append(d.label(ax, (half - 1.7, body_z + body_h + 0.5), "$V$", color=d.FORCE, ha="right"))
        art["texts"] = texts
        d.finish(ax)
    return art


def car_plan(car: LateralCar, psi: float = 0.0, *, exaggerate: float = 1.0, ax=None) -> dict:
    """Draw a car from above: the body, yawed by ψ, on two bogies 2l apart, each with two wheelsets 2b apart.

    To scale: bogie centres at x = ±l (``car.semi_bogie_spacing``), wheelsets at ±b about them
    (``car.bogie.semi_wheelbase``) on rails ±a apart (``car.wheelset.half_gauge``), the body 2(l + b
    + 1.5 m) long and 2(a + 0.65 m) wide, turned by ψ (times ``exaggerate``) about its centre. A
    curved arrow at the body's front shows ψ's positive sense (to the left) whatever its value.

    Parameters
    ----------
    car : raildyn.vehicles.LateralCar
        The car.
    psi : float
        The body's yaw angle, rad, positive turning to the left; drawn (times ``exaggerate``)
        within ±π/12.
    exaggerate : float
        Factor in [1, 10⁴] on the drawn ψ.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``body`` (Polygon), ``bogies`` (two Polygons, x = +l first), ``wheelsets`` (four lists of
        Polygons), ``texts`` (list of Text).

    Examples
    --------
    >>> from raildyn.vehicles import LateralCar
    >>> art = car_plan(LateralCar(), psi=0.01)
    >>> len(art["wheelsets"])
    4
    """
    _checks.instance("car", car, LateralCar, "raildyn.vehicles.LateralCar")
    psi = _checks.scalar("psi", psi)
    exaggerate = _checks.scalar("exaggerate", exaggerate, low=1.0, high=1.0e4)
    yaw = psi * exaggerate
    if abs(yaw) > np.pi / 12:
        raise ValueError(
            f"psi must be drawn within ±π/12: |psi| × exaggerate ≤ {np.pi / 12:.4g} rad, "
            f"got psi = {psi!r} with exaggerate = {exaggerate!r}"
        )
    l, b = car.semi_bogie_spacing, car.bogie.semi_wheelbase
    a, r0 = car.wheelset.half_gauge, car.wheelset.rolling_radius
    half, width = l + b + 1.5, 2 * (a + 0.65)
    ax = d.start(ax, (9.0, 2.6))
    with d.style():
        art = {"rails": _rails(ax, -half - 1.0, half + 1.0, a)}
        art["bogies"] = [
            d.block(ax, d.rectangle_xy((x, 0.0), 2 * b + 0.9, 2 * a + 0.5), fill="0.8", z=1) for x in (l, -l)
        ]
        art["wheelsets"] = [_wheelset_plan(ax, (x, 0.0), a, r0) for x in (l + b, l - b, -l + b, -l - b)]
        body = d.block(ax, d.rectangle_xy((0.0, 0.0), 2 * half, width, yaw), fill="none", z=3)
        body.set_linewidth(1.2)
        art["body"] = body
        axis = d.rotate([(-half - 0.5, 0.0), (half + 0.5, 0.0)], yaw)
        ax.plot(axis[:, 0], axis[:, 1], color=d.COORDINATE, lw=0.7, ls="--", zorder=4)
        texts = []
        d.rotation(ax, (0.0, 0.0), half - 1.0, np.radians(-4), np.radians(8))
        texts.append(
            d.label(ax, d.rotate([(half - 0.4, 0.0)], np.radians(5))[0], r"$\psi$", color=d.COORDINATE)
        )
        for x in (l, -l):
            ax.plot(x, 0.0, "o", color="black", ms=3, zorder=5)
        _, t = d.dimension(ax, (0.0, -width / 2 - 0.5), (l, -width / 2 - 0.5), "$l$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (-l, -width / 2 - 0.5), (0.0, -width / 2 - 0.5), "$l$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (l, -width / 2 - 0.5), (l + b, -width / 2 - 0.5), "$b$", side=-1.0)
        texts.append(t)
        d.arrow(ax, (half - 1.5, width / 2 + 1.2), (half + 0.5, width / 2 + 1.2), color=d.FORCE)
        texts.append(d.label(ax, (half - 1.7, width / 2 + 1.2), "$V$", color=d.FORCE, ha="right"))
        if exaggerate != 1.0:
            texts.append(
                d.label(
                    ax, (0.0, width / 2 + 0.6), f"$\\psi$ drawn × {exaggerate:g}", size=7, color=d.DIMENSION
                )
            )
        art["texts"] = texts
        d.finish(ax)
    return art


def truck_schematic(truck: ThreePieceTruck, *, ax=None) -> dict:
    """Draw a three-piece freight truck: a side frame from the side, and the whole truck from above.

    Above, to scale along the truck: a side frame, its pedestals on the wheels' bearing adapters at
    ±b (``truck.semi_wheelbase``), wheels of radius r₀ (``truck.wheelset.rolling_radius``); in its
    window the bolster's end rests on the spring nest between two friction wedges. Below, the
    truck from above: the side frames d either side of the centre line (``truck.side_frame_spacing``),
    the bolster across them, the two wheelsets on rails ±a apart: the parallelogram that shears
    (warps) by ψ_b − ψ_f, resisted by the wedges (k_w).

    Parameters
    ----------
    truck : raildyn.vehicles.ThreePieceTruck
        The truck.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``side_frame`` (Polygon, elevation), ``bolster`` (Polygon, elevation), ``wedges`` (two
        Polygons), ``nest`` (list of Line2D springs), ``wheels`` (two Polygons, elevation),
        ``plan`` (dict: ``side_frames`` (two Polygons), ``bolster``, ``wheelsets``), ``texts``.

    Examples
    --------
    >>> from raildyn.vehicles import ThreePieceTruck
    >>> art = truck_schematic(ThreePieceTruck())
    >>> len(art["wedges"]), len(art["plan"]["side_frames"])
    (2, 2)
    """
    _checks.instance("truck", truck, ThreePieceTruck, "raildyn.vehicles.ThreePieceTruck")
    b, dd = truck.semi_wheelbase, truck.side_frame_spacing
    a, r0 = truck.wheelset.half_gauge, truck.wheelset.rolling_radius
    ax = d.start(ax)
    texts = []
    with d.style():
        # -- elevation: the side frame (a truss with a window for the bolster) on two wheels
        art = {"rail": d.ground(ax, -b - r0 - 0.4, b + r0 + 0.4, 0.0, 0.06)}
        art["wheels"] = [d.block(ax, d.wheel_xy((x, r0), r0), z=1) for x in (b, -b)]
        for x in (b, -b):
            ax.plot(x, r0, "o", color="black", ms=2.5, zorder=3)
        top, bottom, window = r0 + 0.32, r0 - 0.05, 0.33  # the frame's top and bottom chords, window half
        outline = [
            (-b - 0.18, r0 + 0.05), (-b - 0.18, top), (b + 0.18, top), (b + 0.18, r0 + 0.05),
            (b - 0.12, r0 + 0.05), (window + 0.05, bottom - 0.1), (-window - 0.05, bottom - 0.1),
            (-b + 0.12, r0 + 0.05),
        ]  # fmt: skip
        art["side_frame"] = d.block(ax, np.array(outline), fill="0.8", z=2)
        win = d.rectangle_xy((0.0, (bottom + top) / 2 - 0.02), 2 * window, top - bottom - 0.1)
        d.block(ax, win, fill="white", z=2.1)
        seat = bottom
        bolster_low = seat + 0.16
        art["nest"] = [d.spring(ax, (x, seat), (x, bolster_low), 0.08, coils=3) for x in (-0.12, 0.0, 0.12)]
        for line in art["nest"]:
            line.set_zorder(2.3)
        art["bolster"] = d.block(
            ax, d.rectangle_xy((0.0, bolster_low + 0.12), 2 * (window - 0.09), 0.24), z=2.4
        )
        wedges = []
        for s in (-1.0, 1.0):
            x0 = s * window
            tri = np.array([(x0, bolster_low), (x0, bolster_low + 0.22), (x0 - s * 0.09, bolster_low + 0.22)])
            wedges.append(d.block(ax, tri, fill="0.6", z=2.5))
        art["wedges"] = wedges
        # The labels stand above the wheels and the frame, each with a leader to what it names.
        above = max(top, 2 * r0) + 0.14
        for start, end in (((window - 0.03, bolster_low + 0.18), (window + 0.25, above - 0.04)),
                           ((-b / 2, top), (-b / 2, above - 0.04))):  # fmt: skip
            ax.plot(*zip(start, end, strict=True), color=d.DIMENSION, lw=0.5, zorder=4)
        texts += [
            d.label(ax, (-b / 2, above), "side frame", size=7, color=d.DIMENSION, va="bottom"),
            d.label(ax, (0.0, bolster_low + 0.12), "bolster", size=6),
            d.label(ax, (window + 0.25, above), "wedge", size=7, color=d.DIMENSION, va="bottom"),
        ]
        _, t = d.dimension(ax, (0.0, -0.15), (b, -0.15), "$b$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (-b, -0.15), (0.0, -0.15), "$b$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (-b - r0 - 0.2, 0.0), (-b - r0 - 0.2, r0), "$r_0$")
        texts.append(t)
        # -- plan, below: side frames at ±d, bolster, wheelsets, rails at ±a
        y0 = -0.5 - dd - 0.4  # the plan's centre line
        plan = {"rails": []}
        for s in (-1.0, 1.0):
            for edge in (-0.036, 0.036):
                plan["rails"] += ax.plot(
                    [-b - r0 - 0.4, b + r0 + 0.4], [y0 + s * a + edge] * 2, color="0.45", lw=0.7
                )
        plan["wheelsets"] = [_wheelset_plan(ax, (x, y0), a, r0) for x in (b, -b)]
        plan["side_frames"] = [
            d.block(ax, d.rectangle_xy((0.0, y0 + s * dd), 2 * b + 0.36, 0.12), fill="0.8", z=3)
            for s in (-1.0, 1.0)
        ]
        plan["bolster"] = d.block(ax, d.rectangle_xy((0.0, y0), 0.3, 2 * dd + 0.3), fill="0.7", z=3.5)
        for s in (-1.0, 1.0):
            for x in (-0.2, 0.2):
                tri = np.array(
                    [
                        (x, y0 + s * (dd - 0.07)),
                        (x, y0 + s * (dd + 0.07)),
                        (x - np.sign(x) * 0.08, y0 + s * dd),
                    ]
                )
                d.block(ax, tri, fill="0.6", z=3.6)
        art["plan"] = plan
        ax.plot([-b - r0 - 0.4, b + r0 + 0.4], [y0, y0], color=d.DIMENSION, lw=0.6, ls="-.")
        _, t = d.dimension(ax, (b + r0 + 0.25, y0), (b + r0 + 0.25, y0 + dd), "$d$", side=-1.0)
        texts.append(t)
        _, t = d.dimension(ax, (-b - r0 - 0.25, y0), (-b - r0 - 0.25, y0 + a), "$a$")
        texts.append(t)
        texts.append(
            d.label(ax, (0.3, y0 + dd + 0.2), r"$y_f$, $\psi_f$", size=7, ha="left", color=d.COORDINATE)
        )
        texts.append(d.label(ax, (0.25, y0 + 0.12), r"$\psi_b$", size=7, ha="left", color=d.COORDINATE))
        texts.append(d.label(ax, (-0.3, y0 + dd + 0.2), "$k_w$", size=7, ha="right"))
        art["texts"] = texts
        d.finish(ax)
    return art
