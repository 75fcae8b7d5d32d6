"""The train's coupler chain (chapter 9) and the bridge under its moving load (chapter 10).

* :func:`coupler_chain` — the front vehicles of a :class:`raildyn.train.Consist` as boxes to scale,
  joined by the draft gear (a spring) and the coupler's slack e of a :class:`raildyn.train.DraftGear`;
* :func:`beam_load` — a :class:`raildyn.bridge.SimplySupportedBeam` of span L with a load (a force, or
  a sprung mass) at x = Vt, bent under it; it returns a :class:`BeamLoad` whose ``update(position)``
  moves the load and the deflected shape in place.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.bridge import SimplySupportedBeam
from raildyn.diagrams import _draw as d
from raildyn.train import Consist, DraftGear

__all__ = ["BeamLoad", "beam_load", "coupler_chain"]

_MAX_DRAWN = 50  # vehicles: more is a grey band, not a picture
_SLACK_SCALE = 40.0  # the slack as drawn, times its length (25 mm would be invisible beside 16 m cars)


def _subscript(k: int) -> str:
    """A mathtext subscript: ``1`` or ``{12}``."""
    return str(k) if k < 10 else f"{{{k}}}"


def coupler_chain(consist: Consist, gear: DraftGear | None = None, *, vehicles: int = 3, ax=None) -> dict:
    """Draw the front vehicles of a consist as boxes joined by draft gear springs with slack e.

    Each vehicle is a box of its ``length`` (to scale) on two trucks ``truck_centres`` apart;
    locomotives are drawn darker. Between vehicles i and i + 1 the coupler is a draft gear
    spring in series with the slack e (``gear.slack``), drawn 40 times its length; the
    train runs to the right (front vehicle, index 0, on the right). The coordinate x_i of each
    vehicle and the extension Δx_i = x_i − x_{i+1} − (L_i + L_{i+1})/2 of each coupler are those of
    chapter 9's equations (notation page).

    Parameters
    ----------
    consist : raildyn.train.Consist
        The train.
    gear : raildyn.train.DraftGear, optional
        The draft gear of every coupler; ``DraftGear()`` if None.
    vehicles : int
        How many vehicles to draw from the front, in [1, 50] (fewer if the consist is shorter).
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    dict
        ``boxes`` (Polygons, front first), ``springs`` (Line2D, one per coupler drawn), ``slack``
        (list of (arrow, Text) per coupler), ``texts`` (list of Text).

    Examples
    --------
    >>> from raildyn.train import make_consist
    >>> art = coupler_chain(make_consist("1 SD40-2 + 3 loaded hopper"), vehicles=3)
    >>> len(art["boxes"]), len(art["springs"])
    (3, 2)
    """
    _checks.instance("consist", consist, Consist, "raildyn.train.Consist")
    gear = (
        DraftGear() if gear is None else _checks.instance("gear", gear, DraftGear, "raildyn.train.DraftGear")
    )
    n = min(_checks.integer("vehicles", vehicles, low=1, high=_MAX_DRAWN), len(consist))
    slack = gear.slack * _SLACK_SCALE
    gap = 3.1 + slack  # the coupler as drawn: rods, the draft gear spring and the slack
    height, floor, r = 3.0, 1.1, 0.46
    ax = d.start(ax, (9.0, 2.4))
    art = {"boxes": [], "springs": [], "slack": []}
    texts = []
    with d.style():
        front = 0.0
        for i in range(n):
            length = float(consist.length[i])
            rear = front - length
            fill = "0.7" if consist.locomotive[i] else d.FILL
            art["boxes"].append(
                d.block(
                    ax, d.rectangle_xy(((front + rear) / 2, floor + height / 2), length, height), fill=fill
                )
            )
            centre = (front + rear) / 2
            for truck in (-0.5, 0.5):
                xt = centre + truck * float(consist.truck_centres[i])
                d.block(ax, d.rectangle_xy((xt, floor - 0.25), 2.6, 0.3), fill="0.8")
                for xw in (xt - 0.9, xt + 0.9):
                    d.block(ax, d.wheel_xy((xw, r), r), z=2)
            d.arrow(ax, (centre, floor + height + 0.3), (centre + 3.0, floor + height + 0.3))
            ax.plot(
                [centre, centre], [floor + height + 0.05, floor + height + 0.55], color=d.COORDINATE, lw=0.8
            )
            texts.append(
                d.label(
                    ax,
                    (centre - 0.3, floor + height + 0.12),
                    f"$x_{_subscript(i)}$",
                    color=d.COORDINATE,
                    ha="right",
                    va="bottom",
                )
            )
            name = consist.vehicles[i].name
            texts.append(
                d.label(ax, (centre, floor + height / 2), name if len(name) < 24 else name[:22] + "…", size=7)
            )
            if i + 1 < n:
                z = floor + 0.6
                ax.plot([rear, rear - 0.3], [z, z], **d.LINE)
                art["springs"].append(d.spring(ax, (rear - 0.3, z), (rear - 2.3, z), 0.6, coils=4))
                knuckle = rear - 2.3
                ax.plot([knuckle, knuckle], [z - 0.4, z + 0.4], **d.LINE)
                ax.plot([knuckle - slack, knuckle - slack], [z - 0.4, z + 0.4], **d.LINE)
                ax.plot([knuckle - slack, rear - gap], [z, z], **d.LINE)
                arrow, t = d.dimension(ax, (knuckle - slack, z + 0.7), (knuckle, z + 0.7), "$e$", size=8)
                art["slack"].append((arrow, t))
                texts.append(t)
                texts.append(
                    d.label(ax, (rear - gap / 2, -0.35), f"$\\Delta x_{_subscript(i)}$", size=8, va="top")
                )
            front = rear - gap
        ax.plot([front + gap - 2.0, 2.0], [0.0, 0.0], color="black", lw=1.0)
        d.arrow(ax, (0.5, floor + height + 0.3), (4.0, floor + height + 0.3), color=d.FORCE)
        texts.append(d.label(ax, (4.3, floor + height + 0.3), "$V$", color=d.FORCE, ha="left"))
        if n >= 2:  # below the Δx labels, whatever the figure's size: 14 points under their top
            note = f"slack $e$ = {1e3 * gear.slack:.3g} mm, drawn × {_SLACK_SCALE:g}"
            texts.append(d.note(ax, (front / 2, -0.35), note, points=14))
        art["texts"] = texts
        d.finish(ax)
    return art


def _static_shape(x: np.ndarray, span: float, at: float) -> np.ndarray:
    """The static deflection of a simply supported beam under a unit point load at ``at``, over P L³/(48 EI).

    w(x) = P b x (L² − b² − x²)/(6 L EI) for x ≤ a, b = L − a (and its mirror for x > a).
    """
    a, b = at, span - at
    left = b * x * (span**2 - b**2 - x**2)
    right = a * (span - x) * (span**2 - a**2 - (span - x) ** 2)
    w = np.where(x <= at, left, right)
    return w / (6 * span) / (span**3 / 48)


class BeamLoad:
    """A simply supported beam and its moving load, drawn; :meth:`update` moves the load in place.

    Made by :func:`beam_load`, which documents the drawing; a widget following the load across
    the span calls :meth:`update` with each new position, and the same artists move.

    Parameters
    ----------
    beam : raildyn.bridge.SimplySupportedBeam
        The beam: ``span`` L, m.
    position : float
        Where the load stands, x = Vt, m, in [0, L].
    sprung : bool
        False: a force P; True: a sprung mass (a body M_v on a spring k_v and damper c_v over a
        wheel m_w), as in chapter 10's vehicle–bridge model.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Attributes
    ----------
    ax : matplotlib.axes.Axes
    artists : dict
        ``beam`` (Line2D, the deflected axis), ``load`` (the force's arrow, or the sprung mass's
        ``body`` Polygon, ``wheel`` Polygon, ``spring``, ``damper`` Line2D), ``x`` (the arrow from the
        left support to the load), ``texts`` (dict).
    """

    def __init__(self, beam: SimplySupportedBeam, position: float = 0.0, *, sprung: bool = False, ax=None):
        self._beam = _checks.instance("beam", beam, SimplySupportedBeam, "raildyn.bridge.SimplySupportedBeam")
        self._sprung = _checks.flag("sprung", sprung)
        at = self._position(position)
        span = beam.span
        self._x = np.linspace(0.0, span, 101)
        self._sag = span / 14  # the drawn deflection of a load at midspan
        self._unit = span / 20  # the size of supports and loads
        u = self._unit
        self.ax = ax = d.start(ax, (6.5, 3.0))
        with d.style():
            art = {}
            (art["beam"],) = ax.plot([], [], color="black", lw=2.2, solid_capstyle="butt", zorder=2)
            ax.plot([0.0, span], [0.0, 0.0], color=d.DIMENSION, lw=0.5, ls=":")
            for xs, roller in ((0.0, False), (span, True)):
                tri = np.array([(xs, 0.0), (xs - 0.5 * u, -0.8 * u), (xs + 0.5 * u, -0.8 * u)])
                d.block(ax, tri, fill=d.FILL)
                base = -0.8 * u
                if roller:
                    for dx in (-0.25 * u, 0.25 * u):
                        d.block(ax, d.wheel_xy((xs + dx, base - 0.15 * u), 0.15 * u, 20), fill="white")
                    base -= 0.3 * u
                d.ground(ax, xs - 0.8 * u, xs + 0.8 * u, base, 0.25 * u)
            texts = {}
            if self._sprung:
                art["load"] = {
                    "wheel": d.block(ax, np.zeros((3, 2)), fill="0.7", z=3),
                    "body": d.block(ax, np.zeros((4, 2)), z=3),
                    "spring": d.spring(ax, (0, 0), (0, 1), 0.3 * u, coils=3),
                    "damper": d.dashpot(ax, (0, 0), (0, 1), 0.3 * u),
                }
                texts["load"] = d.label(ax, (0.0, 0.0), "$M_v$")
                texts["suspension"] = d.label(ax, (0.0, 0.0), "$k_v$, $c_v$", size=8, ha="left")
                texts["wheel"] = d.label(ax, (0.0, 0.0), "$m_w$", size=8, ha="left")
            else:
                art["load"] = d.arrow(ax, (0.0, 0.0), (0.0, 1.0), color=d.FORCE, lw=1.4)
                texts["load"] = d.label(ax, (0.0, 0.0), "$P$", color=d.FORCE, ha="left")
            art["x"] = d.arrow(ax, (0.0, 0.0), (0.0, 0.0))
            texts["x"] = d.label(ax, (0.0, 0.0), "$x = Vt$", color=d.COORDINATE, size=8)
            _, texts["L"] = d.dimension(ax, (0.0, -2.2 * u), (span, -2.2 * u), "$L$", side=-1.0)
            d.arrow(ax, (span - 3 * u, 4.6 * u), (span, 4.6 * u), color=d.FORCE)
            texts["V"] = d.label(ax, (span - 3.3 * u, 4.6 * u), "$V$", color=d.FORCE, ha="right")
            art["texts"] = texts
            self.artists = art
            self._place(at)
            ax.set_xlim(-1.5 * u, span + 1.5 * u)
            ax.set_ylim(-3.2 * u, 6.0 * u)
            ax.set_aspect("equal", adjustable="box")
            ax.set_axis_off()

    def _position(self, position) -> float:
        return _checks.scalar("position", position, low=0.0, high=self._beam.span)

    @property
    def points(self) -> np.ndarray:
        """x of the drawn beam's 101 points, m, from 0 to L: where :meth:`update` takes a deflection."""
        return self._x.copy()

    def _place(self, at: float, drawn: np.ndarray | None = None) -> None:
        art, u, span = self.artists, self._unit, self._beam.span
        w = -self._sag * _static_shape(self._x, span, at) if drawn is None else -drawn
        art["beam"].set_data(self._x, w)
        top = float(np.interp(at, self._x, w))  # where the load meets the bent beam
        texts = art["texts"]
        if self._sprung:
            load, r = art["load"], 0.45 * u
            load["wheel"].set_xy(d.wheel_xy((at, top + r), r, 30))
            low, high = top + 2 * r, top + 2 * r + 1.6 * u
            load["body"].set_xy(d.rectangle_xy((at, high + 0.5 * u), 2.2 * u, 1.0 * u))
            load["spring"].set_data(*d.spring_xy((at - 0.4 * u, low), (at - 0.4 * u, high), 0.3 * u, 3).T)
            load["damper"].set_data(*d.dashpot_xy((at + 0.4 * u, high), (at + 0.4 * u, low), 0.3 * u).T)
            texts["load"].set_position((at, high + 0.5 * u))
            texts["suspension"].set_position((at + 0.75 * u, (low + high) / 2))
            texts["wheel"].set_position((at + 0.55 * u, top + r))
            marker = high + 1.4 * u
        else:
            art["load"].set_positions((at, top + 2.5 * u), (at, top))
            texts["load"].set_position((at + 0.2 * u, top + 2.0 * u))
            marker = top + 2.9 * u
        art["x"].set_positions((0.0, marker), (at, marker))
        art["x"].set_visible(at > 0.0)
        texts["x"].set_position((at / 2, marker + 0.35 * u))

    def update(self, position: float, deflection=None) -> dict:
        """Move the load to ``position`` and bend the beam under it: the same artists, moved.

        Parameters
        ----------
        position : float
            Where the load stands, x = Vt, m, in [0, L].
        deflection : array_like, (101,), optional
            The beam's deflection as drawn at :attr:`points`, m, downwards (a model's deflection
            times the exaggeration its picture states), each within L/4. None: the static shape
            under the load, scaled so that a load at midspan sags L/14.

        Returns
        -------
        dict
            The artists (``artists``), moved.
        """
        at = self._position(position)
        if deflection is not None:
            deflection = _checks.array("deflection", deflection, shape=self._x.shape)
            if np.abs(deflection).max() > self._beam.span / 4:
                raise ValueError(
                    f"deflection must be drawn within L/4 = {self._beam.span / 4:.4g} m, "
                    f"got a largest |w| of {np.abs(deflection).max():.4g} m"
                )
        self._place(at, deflection)
        return self.artists


def beam_load(beam: SimplySupportedBeam, position: float = 0.0, *, sprung: bool = False, ax=None) -> BeamLoad:
    """Draw a simply supported beam of span L with its moving load at x = Vt; ``update`` moves the load.

    The beam (``beam.span`` L, to scale) rests on a pin at x = 0 and a roller at x = L; the load
    stands at ``position`` = Vt and travels to the right at the speed V. The beam is drawn bent
    in its static shape under the load (the point-load deflection of a simply supported beam,
    scaled so that a load at midspan sags L/14 in the picture), so that the bend follows the load
    as it crosses. The load is a force P, or with ``sprung`` a sprung mass (body M_v on k_v and c_v
    over a wheel m_w), the moving oscillator of chapter 10.

    Parameters
    ----------
    beam : raildyn.bridge.SimplySupportedBeam
        The beam: ``span`` L, m.
    position : float
        Where the load stands, x = Vt, m, in [0, L].
    sprung : bool
        False: a force P; True: a sprung mass.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.

    Returns
    -------
    BeamLoad
        Its ``artists`` (a dict) and ``update(position)``, which moves them in place.

    Examples
    --------
    >>> from raildyn.bridge import SimplySupportedBeam
    >>> drawn = beam_load(SimplySupportedBeam(), position=5.0)
    >>> x, w = drawn.update(10.0)["beam"].get_data()
    >>> bool(w.argmin() == 50)  # the deepest point is under the load at midspan
    True
    """
    return BeamLoad(beam, position, sprung=sprung, ax=ax)
