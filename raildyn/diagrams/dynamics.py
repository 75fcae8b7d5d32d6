"""Chapter 1's schematics: the linear single-degree-of-freedom oscillator (book Fig. 1.3) and the degrees of
freedom of a constrained rigid body in general and in planar motion (book Figs 1.1 and 1.2).

* :func:`oscillator_model` — mass m on a spring k and a damper c, the force F(t), the coordinate x,
  drawn from a :class:`raildyn.vibration.SDOF` (its values written beside the symbols);
* :func:`rigid_body_freedoms` — a rigid body held at a point that may not move along y: five
  coordinates in general motion, two (x and the rotation about z) in planar motion.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.diagrams import _draw as d
from raildyn.vibration import SDOF

__all__ = ["oscillator_model", "rigid_body_freedoms"]


def oscillator_model(sdof: SDOF, *, ax=None) -> dict:
    """Draw the linear SDOF model: mass, spring, damper, force and coordinate (book Fig. 1.3).

    The mass stands on a spring k and a damper c side by side, on the ground; F(t) acts
    on it along x, and x measures its displacement from equilibrium, so that the picture is the
    free-body diagram of m ẍ + c ẋ + k x = F(t) (book eq. 1.3). The labels carry the
    model's values; the block's size grows as the cube root of the mass relative to 1000 kg,
    between half and twice its size (a heavier body looks heavier), and a damper of c = 0 is
    drawn dashed.

    Parameters
    ----------
    sdof : raildyn.vibration.SDOF
        The oscillator: mass (kg), damping (N·s/m), stiffness (N/m).
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        The artists: ``mass`` (Polygon), ``spring``, ``damper`` (Line2D), ``force``, ``x``
        (arrows), ``texts`` (list of Text).

    Examples
    --------
    >>> from raildyn.vibration import SDOF
    >>> art = oscillator_model(SDOF(1000.0, 2000.0, 4e5))
    >>> sorted(art)
    ['damper', 'force', 'ground', 'mass', 'spring', 'texts', 'x']
    """
    _checks.instance("sdof", sdof, SDOF, "raildyn.vibration.SDOF")
    ax = d.start(ax)
    size = float(np.clip((sdof.mass / 1000.0) ** (1 / 3), 0.5, 2.0))
    width, height, legs = 1.2 * size, 0.6 * size, 1.0
    with d.style():
        art = {"ground": d.ground(ax, -0.9 * width, 0.9 * width, 0.0, 0.08)}
        art["mass"] = d.block(ax, d.rectangle_xy((0.0, legs + height / 2), width, height))
        art["spring"] = d.spring(ax, (-0.25 * width, 0.0), (-0.25 * width, legs), 0.22)
        art["damper"] = d.dashpot(ax, (0.25 * width, legs), (0.25 * width, 0.0), 0.22)
        if sdof.damping == 0:
            art["damper"].set_linestyle("--")
        top = legs + height
        art["force"] = d.arrow(ax, (0.0, top), (0.0, top + 0.5), color=d.FORCE)
        xs = 0.7 * width
        art["x"] = d.arrow(ax, (xs, legs + height / 2), (xs, legs + height / 2 + 0.45))
        ax.plot([xs - 0.1, xs + 0.1], [legs + height / 2] * 2, color=d.COORDINATE, lw=0.8)
        art["texts"] = [
            d.label(ax, (0.0, legs + height / 2), f"$m$ = {sdof.mass:.4g} kg"),
            d.label(ax, (-0.25 * width - 0.2, legs / 2), f"$k$ = {d.si(sdof.stiffness, 'N/m')}", ha="right"),
            d.label(ax, (0.25 * width + 0.2, legs / 2), f"$c$ = {d.si(sdof.damping, 'N·s/m')}", ha="left"),
            d.label(ax, (0.12, top + 0.4), "$F(t)$", color=d.FORCE, ha="left"),
            d.label(ax, (xs + 0.1, legs + height / 2 + 0.35), "$x(t)$", color=d.COORDINATE, ha="left"),
            d.label(
                ax,
                (0.0, -0.3),
                rf"$\omega_n$ = {sdof.natural_frequency:.3g} rad/s,  "
                rf"$\xi$ = {sdof.damping_ratio:.3g}",
                size=8,
            ),
        ]
        d.finish(ax)
    return art


def _box(origin, size, depth_axis) -> list[np.ndarray]:
    """The visible faces of a box in cabinet projection: front, top, side (each (4, 2))."""
    (x0, z0), (w, h, dep) = origin, size
    e = depth_axis * dep
    front = np.array([[x0, z0], [x0 + w, z0], [x0 + w, z0 + h], [x0, z0 + h]])
    top = np.array([front[3], front[2], front[2] + e, front[3] + e])
    side = np.array([front[1], front[1] + e, front[2] + e, front[2]])
    return [front, top, side]


def rigid_body_freedoms(planar: bool = False, *, ax=None) -> dict:
    """Draw a rigid body held at a point that cannot move along y, and its degrees of freedom.

    General motion (book Fig. 1.1, ``planar=False``): the attachment slides between two
    guides normal to y, so of the six coordinates of a free body one is lost: two
    translations, x and z, and three rotations θ_x, θ_y, θ_z about the axes remain (N = 6 − 1,
    book eq. 1.1). Planar motion (book Fig. 1.2, ``planar=True``): the body also stays in the
    x–y plane, its attachment sliding along a guide on x, so x and θ_z remain. The axes are
    drawn in cabinet projection (y receding at 45°).

    Parameters
    ----------
    planar : bool
        False for general motion (five degrees of freedom), True for planar (two).
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``body`` (list of Polygon), ``guide`` (list of artists), ``freedoms`` (dict of coordinate
        name to its arrow), ``texts`` (list of Text).

    Examples
    --------
    >>> art = rigid_body_freedoms(planar=True)
    >>> sorted(art["freedoms"])
    ['theta_z', 'x']
    """
    planar = _checks.flag("planar", planar)
    ax = d.start(ax)
    receding = 0.5 * np.array([np.cos(np.pi / 4), np.sin(np.pi / 4)])  # y drawn into the page
    texts, freedoms = [], {}
    with d.style():
        if planar:
            # the x-y plane seen from above: x right, y up, z out of the page
            body = [d.block(ax, d.rectangle_xy((0.9, 0.9), 1.2, 0.6, np.radians(25.0)))]
            pin = np.array([0.35, 0.55])
            link = ax.plot([pin[0], 0.9], [0.0, 0.9], **d.LINE)[0]
            guide = d.ground(ax, -0.6, 2.2, -0.12, 0.08) + [link]
            guide.append(d.block(ax, d.rectangle_xy((pin[0], 0.0), 0.3, 0.2), fill="white", z=3))
            freedoms["x"] = d.arrow(ax, (pin[0] - 0.6, 0.3), (pin[0] + 0.1, 0.3))
            freedoms["theta_z"] = d.rotation(ax, (0.9, 0.9), 0.55, np.radians(60), np.radians(110))[1]
            texts += [
                d.label(ax, (pin[0] - 0.25, 0.4), "$x$", color=d.COORDINATE),
                d.label(ax, (0.25, 1.45), r"$\theta_z$", color=d.COORDINATE),
            ]
            axes_origin = np.array([-0.5, 1.3])
            names = (("$x$", np.array([0.45, 0.0])), ("$y$", np.array([0.0, 0.45])))
            texts.append(d.label(ax, (0.8, -0.45), "planar motion: 2 degrees of freedom ($x$, $\\theta_z$)"))
        else:
            faces = _box((0.2, 0.9), (1.4, 0.7, 1.0), receding)
            body = [
                d.block(ax, f, fill=shade) for f, shade in zip(faces, ("0.88", "0.95", "0.8"), strict=True)
            ]
            pin = np.array([0.9, 0.0])
            link = ax.plot([pin[0], 0.9], [pin[1], 0.9], **d.LINE)[0]
            # two guide plates normal to y, either side of the attachment: y is held
            guide = [link]
            for s in (-0.25, 0.25):
                plate = (
                    np.array([[-0.3, -0.35], [0.3, -0.35], [0.3, 0.35], [-0.3, 0.35]]) + pin + s * receding
                )
                guide.append(d.block(ax, plate, fill="0.97", z=0.5))
            guide.append(ax.plot(*pin, "o", color="black", ms=4)[0])
            centre = np.array([0.9, 1.25]) + 0.5 * receding
            freedoms["x"] = d.arrow(ax, (1.9, 1.05), (2.5, 1.05))
            freedoms["z"] = d.arrow(ax, (-0.15, 1.3), (-0.15, 1.9))
            freedoms["theta_x"] = d.rotation(ax, (2.75, 1.05), 0.18, np.radians(-60), np.radians(280))[1]
            tip = centre + 2.3 * receding
            freedoms["theta_y"] = d.rotation(ax, tip, 0.18, np.radians(-60), np.radians(280))[1]
            freedoms["theta_z"] = d.rotation(ax, (0.75, 2.45), 0.3, np.radians(200), np.radians(250))[1]
            ax.plot(*np.column_stack([centre, tip]), color=d.DIMENSION, lw=0.6, ls=":")
            texts += [
                d.label(ax, (2.25, 1.17), "$x$", color=d.COORDINATE),
                d.label(ax, (-0.3, 1.8), "$z$", color=d.COORDINATE),
                d.label(ax, (3.05, 1.05), r"$\theta_x$", color=d.COORDINATE),
                d.label(ax, tip + (0.35, 0.1), r"$\theta_y$", color=d.COORDINATE),
                d.label(ax, (1.2, 2.6), r"$\theta_z$", color=d.COORDINATE),
                d.label(ax, pin + (0.45, -0.35), "$y$ held", color=d.DIMENSION, size=8),
                d.label(
                    ax,
                    (1.3, -0.8),
                    "general motion: 5 degrees of freedom "
                    r"($x$, $z$, $\theta_x$, $\theta_y$, $\theta_z$)",
                ),
            ]
            axes_origin = np.array([-0.6, 0.0])
            names = (("$x$", np.array([0.45, 0.0])), ("$y$", 0.9 * receding), ("$z$", np.array([0.0, 0.45])))
        for name, direction in names:
            d.arrow(ax, axes_origin, axes_origin + direction, color="black", lw=0.8)
            texts.append(d.label(ax, axes_origin + 1.25 * direction, name, size=8))
        d.finish(ax)
    return {"body": body, "guide": guide, "freedoms": freedoms, "texts": texts}
