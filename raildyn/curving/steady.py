"""Linear steady-state curving (book chapter 8) of any lateral model of raildyn.

A vehicle running steadily round a curve is at rest in axes that follow it: their
origin moves along the track's centre line at the speed V, turning at V/R, with x
along the track's tangent at the vehicle's centre. In those axes every suspension
element keeps its tangent-track law; the curve enters in two places only:

* at each wheelset, through :func:`raildyn.wheelset.curve_loads`: the track there
  is displaced by x²/(2R) and turned by x/R, the outer rail is longer by a/R per
  metre, and the wheelset turns at V/R;
* on every mass, through the unbalanced lateral acceleration a_q of the cant
  deficiency (:func:`raildyn.track.cant.unbalanced_acceleration`).

So the steady state of any linear model of the one protocol — a wheelset, a bogie,
a car, the three-piece freight car, the locomotive — is one linear solve,
K q = f (Garg & Dukkipati 1984, ch. 8; Wickens 2003, ch. 7; Elkins & Gostling 1977).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.contact.creepages import wheelset_creepages
from raildyn.linear_model import as_linear_system
from raildyn.track import MAXIMUM_CANT, MINIMUM_RADIUS, unbalanced_acceleration
from raildyn.wheelset import curve_loads, track_on_arc

__all__ = ["SteadyCurving", "steady_curving"]


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class SteadyCurving(Tabular):
    """A linear model's steady state in a curve to the left.

    Attributes
    ----------
    radius : float
        R, m (> 0).
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    cant : float
        h_t, height of the outer rail above the inner, m (≥ 0).
    unbalanced_acceleration : float
        a_q, m/s², in the plane of the track, outwards (negative: cant excess).
    labels : tuple of str
        The model's coordinates.
    displacement : ndarray, (n,)
        q in the axes that follow the vehicle (origin on the centre line at the
        vehicle's centre, x along the tangent there, y to the left, towards the
        curve's centre), m or rad.
    positions : ndarray, (k,)
        x of each wheelset (in the model's order), ahead of the vehicle's centre, m.
    offset : ndarray, (k,)
        Each wheelset's lateral displacement from the track's centre line where it
        runs, towards the outer rail, m.
    angle_of_attack : ndarray, (k,)
        Each wheelset's yaw from the local tangent, rad, positive when it points
        towards the outer rail (as a leading wheelset flanging on the outer rail does).
    longitudinal_creep_force : ndarray, (k,)
        On the outer wheel, forwards, N; the inner wheel's is equal and opposite.
    lateral_creep_force : ndarray, (k,)
        On the two wheels together, towards the outer rail, N.

    All arrays are finite; the scalars are checked as above.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("positions", "m"), ("offset", "m"), ("angle_of_attack", "rad"), ("longitudinal_creep_force", "N"),
        ("lateral_creep_force", "N"),
    )  # fmt: skip
    _scalars = (("radius", "m"), ("speed", "m/s"), ("cant", "m"), ("unbalanced_acceleration", "m/s²"))

    radius: float
    speed: float
    cant: float
    unbalanced_acceleration: float
    labels: tuple
    displacement: np.ndarray
    positions: np.ndarray
    offset: np.ndarray
    angle_of_attack: np.ndarray
    longitudinal_creep_force: np.ndarray
    lateral_creep_force: np.ndarray

    def __post_init__(self):
        _checks.positive("radius", self.radius)
        _checks.speed("speed", self.speed)
        _checks.nonnegative("cant", self.cant)
        _checks.scalar("unbalanced_acceleration", self.unbalanced_acceleration)
        labels = _checks.strings("labels", self.labels)
        _checks.array("displacement", self.displacement, shape=(len(labels),))
        k = _checks.array("positions", self.positions, ndim=1, allow_empty=False).shape[0]
        for name in ("offset", "angle_of_attack", "longitudinal_creep_force", "lateral_creep_force"):
            _checks.array(name, getattr(self, name), shape=(k,))

    def coordinate(self, label: str) -> float:
        """One coordinate of ``displacement``, m or rad.

        Parameters
        ----------
        label : str
            One of ``labels``.

        Returns
        -------
        float
        """
        return float(self.displacement[self.labels.index(_checks.choice("label", label, self.labels))])

    def plot(self, ax=None, *, artists: dict | None = None, exaggeration: float = 50.0) -> dict:
        """The wheelsets in plan, on the straightened track, their offset and yaw exaggerated.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (a new figure when None).
        artists : dict, optional
            What an earlier call returned: its artists are updated in place.
        exaggeration : float
            Factor on the offsets and angles of attack (> 0), so that millimetres and
            milliradians show at the scale of the vehicle.

        Returns
        -------
        dict
            ``rails``, ``axles`` (one line per wheelset), ``labels`` (one text per wheelset) and
            ``title``.
        """
        from raildyn.plots import COLORS, axes_or_new

        scale = _checks.positive("exaggeration", exaggeration)
        a = 0.75  # m: the rails drawn at ±a, the standard-gauge half-spacing of raildyn's Wheelset
        ends = []
        for x, y, alpha in zip(self.positions, self.offset, self.angle_of_attack, strict=True):
            # the axle across the track, turned by the exaggerated angle of attack: its outer (right)
            # end ahead when it points outwards
            dx = a * np.sin(scale * alpha)
            ends.append(([x - dx, x + dx], [-scale * y + a, -scale * y - a]))
        texts = [
            f"{1e3 * al:+.2f} mrad\n{1e3 * y:+.1f} mm"
            for y, al in zip(self.offset, self.angle_of_attack, strict=True)
        ]
        title = f"R = {self.radius:g} m, V = {3.6 * self.speed:.0f} km/h; inner rail at the top"
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            if len(artists.get("axles", ())) != len(ends):
                n = len(ends)
                raise ValueError(f"artists must come from a plot of {n} wheelsets, got {artists!r:.60}")
            for line, (xs, ys) in zip(artists["axles"], ends, strict=True):
                line.set_data(xs, ys)
            for text, s, (xs, _) in zip(artists["labels"], texts, ends, strict=True):
                text.set_text(s)
                text.set_x(np.mean(xs))
            if "title" in artists:  # a caller that titles the axes itself leaves it out
                artists["title"].set_text(title)
            return artists
        ax = axes_or_new(ax)
        span = np.array([self.positions.min() - 2.0, self.positions.max() + 2.0])
        rails = [ax.plot(span, [s * a, s * a], color="0.5", lw=2)[0] for s in (1, -1)]
        axles = [ax.plot(xs, ys, color=COLORS[0], lw=3, marker="o")[0] for xs, ys in ends]
        labels = [
            ax.text(np.mean(xs), 1.2 * a, s, ha="center", va="bottom", fontsize=8)
            for (xs, _), s in zip(ends, texts, strict=True)
        ]
        ax.set_xlabel("distance ahead of the vehicle's centre (m)")
        ax.set_ylabel(f"lateral (m); offset and yaw × {scale:g}")
        ax.set_ylim(-2.2 * a, 2.2 * a)
        return {"rails": rails, "axles": axles, "labels": labels, "title": ax.set_title(title)}


def steady_curving(model, speed, radius, cant=0.0) -> SteadyCurving:
    """The steady state of a linear lateral model in a curve to the left.

    Solves K q = f in the axes that follow the vehicle (described in
    :mod:`raildyn.curving.steady`), with f the wheel–rail loads of
    :func:`raildyn.wheelset.curve_loads` at every wheelset and −M r a_q, where r is 1
    on every lateral coordinate (label ending in " y") and a_q the unbalanced lateral
    acceleration. The creep forces are linear (Kalker's coefficients): they hold
    while the creepages stay well below saturation and no flange touches. The offsets
    grow as 1/R: on its cone of 0.15 the Manchester car's leading wheelsets reach a
    flangeway clearance of 7 mm near R = 1.4 km, the freight car on its 1:20 cone
    near 4 km; in sharper curves the flanges carry the difference.

    Parameters
    ----------
    model : LinearModel or LinearSystem
        A lateral model with wheelsets on the rails (:class:`~raildyn.wheelset.Wheelset`,
        :class:`~raildyn.vehicles.Bogie`, :class:`~raildyn.vehicles.LateralCar`, the freight car,
        the locomotive), each wheelset with its alignment input.
    speed : float
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    radius : float
        R, m (≥ :data:`~raildyn.track.cant.MINIMUM_RADIUS`, 50 m).
    cant : float
        h_t, m, in [0, :data:`~raildyn.track.cant.MAXIMUM_CANT`] (0.2 m).

    Returns
    -------
    SteadyCurving

    Examples
    --------
    A free wheelset with neither spin nor gravitational stiffness, at the balance
    speed, rolls at the pure-rolling offset r₀a/(λR) and square to the rails:

    >>> from raildyn.track import balance_speed
    >>> from raildyn.wheelset import Wheelset
    >>> ws = Wheelset(f23=0.0, f33=0.0, contact_angle=0.0, contact_angle_parameter=0.0).free()
    >>> state = steady_curving(ws, balance_speed(600.0, 0.1), 600.0, cant=0.1)
    >>> round(1e3 * float(state.offset[0]), 2), round(1e3 * float(state.angle_of_attack[0]), 6)
    (3.83, 0.0)
    """
    system = as_linear_system(model)
    if not system.wheelsets:
        raise ValueError(f"model must have wheelsets on the rails, got one with coordinates {system.labels}")
    V = _checks.speed("speed", speed)
    R = _checks.scalar("radius", radius, low=MINIMUM_RADIUS)
    D = _checks.scalar("cant", cant, low=0.0, high=MAXIMUM_CANT)
    a_q = unbalanced_acceleration(V, R, D)  # the small-angle g I/(2a_r) of the linear theory
    lateral = np.array([label.endswith(" y") for label in system.labels], dtype=float)
    try:
        x = system.wheelset_positions
    except ValueError as err:
        raise ValueError(f"model: {err}") from None
    f = -(system.M @ lateral) * a_q
    for (iy, ipsi, ws), xi in zip(system.wheelsets, x, strict=True):
        f[[iy, ipsi]] += curve_loads(ws, R, xi)
    q = np.linalg.solve(system.K, f)
    if not np.all(np.isfinite(q)) or not np.allclose(system.K @ q, f, rtol=1e-8, atol=1e-8 * np.abs(f).max()):
        raise ValueError("model: its stiffness matrix is singular, so it has no steady state in a curve")
    iy = np.array([w[0] for w in system.wheelsets])
    ipsi = np.array([w[1] for w in system.wheelsets])
    y_t, psi_t = track_on_arc(x, 1.0 / R)
    y = q[iy] - y_t  # from the local centre line, to the left
    psi = q[ipsi] - psi_t  # from the local tangent, anticlockwise
    fx, fy = np.empty(len(x)), np.empty(len(x))
    for k, (_, _, ws) in enumerate(system.wheelsets):
        r0, lam, a = ws.rolling_radius, ws.conicity, ws.half_gauge
        # Steady in the turning axes: ẏ = 0, ψ̇ = V/R. The spin of the contact-angle difference, first
        # order as in raildyn.wheelset.creep_terms (−2εy/(a r₀) over the two wheels), so that these are
        # the forces of the linear equations.
        c = wheelset_creepages(V, 0.0, psi[k], V / R, r0 + lam * y[k], r0 - lam * y[k], r0, a)
        spin = c.spin.sum() - 2 * ws.contact_angle_parameter * y[k] / (a * r0)
        fx[k] = -ws.f11 * c.longitudinal[1]  # the right wheel, outer in a left-hand curve
        fy[k] = ws.f22 * c.lateral.sum() + ws.f23 * spin  # −F_y: towards the outer rail
    return SteadyCurving(R, V, D, a_q, system.labels, q, x, -y, -psi, fx, fy)
