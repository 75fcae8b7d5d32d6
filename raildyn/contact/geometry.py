"""The rigid contact geometry of a wheelset on straight track: contact points, Δr(y), contact angles.

Coordinates (SI, m) in the plane of the wheelset axle, one profile per side:
``u`` runs across the rail and is positive towards the track centre (the
flange side of the wheel, the gauge side of the rail). A wheel profile
(:class:`WheelProfile`) gives its rolling radius r(u) (the tape circle is u = 0,
radius r₀); a rail profile (:class:`RailProfile`) gives the height z(u) of the head
(the crown at u = 0, z = 0), already tilted by the rail inclination. The named
profiles (conical, S1002, 60E1) are in :mod:`raildyn.contact.profiles`.

For a lateral shift y of the wheelset (positive to the left) the left wheel's
point u_w sits above the left rail's point u_r = u_w − y − d, where d is the
offset of the tape circle from the rail centre line in the centred position.
The contact is where the vertical gap between the two surfaces is least; the
right side is the mirror image with −y. The wheelset rolls so that both wheels
touch (first order in the roll angle; optional). A yawed wheelset shows each
rail its wheel's contact trace line instead of its profile
(:mod:`raildyn.contact.trace_line`): the same search then gives the contact points
of the yawed wheelset, and their lead or lag ahead of the axle.

:func:`contact_geometry` returns :class:`ContactGeometry`; :func:`rolling_radius_difference`,
:func:`contact_angles` and :func:`equivalent_conicity` are its parts a chapter needs alone.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.contact.conicity import kinematic_conicity
from raildyn.contact.trace_line import _RADIUS_MAX, MAX_YAW, trace_line

__all__ = [
    "ContactGeometry",
    "RailProfile",
    "WheelProfile",
    "contact_angles",
    "contact_geometry",
    "equivalent_conicity",
    "rolling_radius_difference",
]


_CANT_MAX = 0.1  # rail inclination (slope); in track 1:20 to 1:40, or upright


def _grid(name: str, value, *, uniform: bool = False) -> np.ndarray:
    """A 1-D finite array of at least two strictly increasing positions (m); ``uniform``: equally spaced."""
    u = _checks.increasing(name, value)
    if u.size < 2:
        raise ValueError(f"{name} must hold at least two positions, got {u.size}")
    steps = np.diff(u)
    if uniform and np.ptp(steps) > 1e-6 * steps.mean():
        raise ValueError(
            f"{name} must be uniformly spaced (the contact search steps along it), "
            f"got steps from {steps.min():.6g} to {steps.max():.6g} m"
        )
    return u


@dataclass(frozen=True)
class WheelProfile:
    """A wheel profile sampled on a fine lateral grid.

    Attributes
    ----------
    name : str
        What the profile is, for labels.
    lateral : ndarray
        u (m), strictly increasing (at least two samples), positive towards the flange.
    radius : ndarray
        Rolling radius r(u) (m), one per ``lateral``, each in (0, 2] m (the largest railway
        wheels have a radius of about 1.1 m).
    nominal_radius : float
        r₀ = r(0) (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
    """

    name: str
    lateral: np.ndarray
    radius: np.ndarray
    nominal_radius: float

    def __post_init__(self):
        _checks.instance("name", self.name, str)
        u = _grid("lateral", self.lateral)
        r = _checks.array("radius", self.radius, shape=(u.size,), low=0.0, low_open=True)
        if r.max() > _RADIUS_MAX:
            raise ValueError(f"radius must be <= {_RADIUS_MAX} m (a railway wheel), got {r.max()!r}")
        r0 = _checks.plausible("nominal_radius", self.nominal_radius, "wheel_radius")
        object.__setattr__(self, "lateral", u)
        object.__setattr__(self, "radius", r)
        object.__setattr__(self, "nominal_radius", r0)

    def radius_at(self, u):
        """Rolling radius r(u) by linear interpolation.

        Parameters
        ----------
        u : float or array_like
            Lateral position on the wheel, m, positive towards the flange, within the
            profile (``lateral[0]`` to ``lateral[-1]``).

        Returns
        -------
        float or ndarray
            r, m.

        Examples
        --------
        >>> from raildyn.contact.profiles import conical_wheel
        >>> round(float(conical_wheel(1 / 20).radius_at(3e-3)), 6)  # r₀ + λu
        0.46015
        """
        u = _checks.array("u", u)
        if u.size and (u.min() < self.lateral[0] or u.max() > self.lateral[-1]):
            raise ValueError(
                f"u must lie within the profile, [{self.lateral[0]:.6g}, {self.lateral[-1]:.6g}] m, "
                f"got {u.min() if u.min() < self.lateral[0] else u.max()!r}"
            )
        return np.interp(u, self.lateral, self.radius)


@dataclass(frozen=True)
class RailProfile:
    """A rail head profile, tilted by its inclination, sampled on a fine lateral grid.

    Attributes
    ----------
    name : str
        What the profile is, for labels.
    lateral : ndarray
        u (m), strictly increasing and uniformly spaced (the contact search steps along it),
        positive towards the track centre (gauge side).
    height : ndarray
        z(u) (m), one per ``lateral``, 0 at the crown (the highest point; all zeros is a flat head).
    inclination : float
        Rail cant (rad), e.g. atan(1/40), in [0, atan(1/10)] (in track 1:20 to 1:40, or upright).
    gauge_face : float
        u of the gauge face 14 mm below the top (m), used to place the rails: on the gauge
        side of the profile, 0 < u ≤ ``lateral[-1]``.
    """

    name: str
    lateral: np.ndarray
    height: np.ndarray
    inclination: float
    gauge_face: float

    def __post_init__(self):
        _checks.instance("name", self.name, str)
        u = _grid("lateral", self.lateral, uniform=True)
        z = _checks.array("height", self.height, shape=(u.size,))
        if abs(z.max()) > 1e-6:
            raise ValueError(
                f"height must be 0 at the crown (its highest point), got a maximum of {z.max()!r} m"
            )
        cant = _checks.scalar("inclination", self.inclination, low=0.0, high=float(np.arctan(_CANT_MAX)))
        face = _checks.scalar("gauge_face", self.gauge_face, low=0.0, high=float(u[-1]), low_open=True)
        object.__setattr__(self, "lateral", u)
        object.__setattr__(self, "height", z)
        object.__setattr__(self, "inclination", cant)
        object.__setattr__(self, "gauge_face", face)


@dataclass(frozen=True)
class ContactGeometry(Tabular):
    """Rigid contact points of a wheelset against its lateral shift y (arrays over y).

    Every field but ``shift`` stacks the left and the right contact: shape (2, n).

    Attributes
    ----------
    shift : ndarray
        y (m), positive to the left.
    wheel_position : ndarray, shape (2, n)
        u of the contact point on each wheel (m, positive towards the flange).
    rail_position : ndarray, shape (2, n)
        u of the contact point on each rail (m, positive towards the gauge side).
    rolling_radius : ndarray, shape (2, n)
        r_L, r_R (m).
    contact_angle : ndarray, shape (2, n)
        ϑ_L, ϑ_R (rad) in the track frame, positive when the contact normal leans towards the
        track centre.
    roll : ndarray, shape (n,)
        Roll angle φ of the wheelset (rad), positive when the left wheel rises; zeros when the
        roll is left out.
    lead : ndarray, shape (2, n), optional
        How far each contact point lies ahead of the axle (m, forwards); zeros (the default) for
        a wheelset square to the track.
    yaw : float, optional
        The wheelset's yaw ψ (rad, turning to the left), in [−0.03, 0.03]; 0 by default.

    Every number is finite; n ≥ 1.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("shift", "m"), ("wheel_position", "m"), ("rail_position", "m"), ("rolling_radius", "m"),
        ("contact_angle", "rad"), ("roll", "rad"), ("lead", "m"),
    )  # fmt: skip
    _scalars = (("yaw", "rad"),)
    _by_row = ("wheel_position", "rail_position", "rolling_radius", "contact_angle", "lead")

    shift: np.ndarray
    wheel_position: np.ndarray
    rail_position: np.ndarray
    rolling_radius: np.ndarray
    contact_angle: np.ndarray
    roll: np.ndarray
    lead: np.ndarray | None = None
    yaw: float = 0.0

    def __post_init__(self):
        if self.lead is None:
            object.__setattr__(self, "lead", np.zeros((2, *np.shape(self.shift))))
        _checks.fields(self)
        _checks.scalar("yaw", self.yaw, low=-MAX_YAW, high=MAX_YAW)
        n = np.shape(self.shift)
        if len(n) != 1 or n[0] == 0:
            raise ValueError(f"shift must be a non-empty 1-D array, got shape {n}")
        for name in ("wheel_position", "rail_position", "rolling_radius", "contact_angle", "roll", "lead"):
            want = n if name == "roll" else (2, *n)
            if np.shape(getattr(self, name)) != want:
                raise ValueError(
                    f"shift and {name} must have shapes {n} and {want}, got {name} of shape "
                    f"{np.shape(getattr(self, name))}"
                )
        for f in fields(self):
            if f.name != "yaw":
                object.__setattr__(self, f.name, np.asarray(getattr(self, f.name), dtype=float))

    @property
    def rolling_radius_difference(self) -> np.ndarray:
        """Δr(y) = r_L − r_R (m)."""
        return self.rolling_radius[0] - self.rolling_radius[1]

    @property
    def contact_angle_difference(self) -> np.ndarray:
        """ϑ_L − ϑ_R (rad)."""
        return self.contact_angle[0] - self.contact_angle[1]

    def equivalent_conicity(self, amplitudes) -> np.ndarray:
        """EN 15302's equivalent conicity λ_e(ŷ) of this table of Δr(y).

        The kinematic method of :func:`~raildyn.contact.conicity.kinematic_conicity` on the
        table sorted by shift.

        Parameters
        ----------
        amplitudes : float or array_like
            ŷ (m), > 0, within the reach of this table (its shifts must hold both turning
            points of the motion: ±ŷ for a symmetric pair).

        Returns
        -------
        ndarray
            λ_e for each amplitude (dimensionless).
        """
        order = np.argsort(self.shift)  # the table in the order of its shifts, whatever order they came in
        return kinematic_conicity(self.shift[order], self.rolling_radius_difference[order], amplitudes)

    def _line(self, ax, artists, key, x, y, label, color, xlabel, ylabel):
        from raildyn import plots

        return plots.movable_line(
            ax, artists, key, x, y, label=label, color=color, xlabel=xlabel, ylabel=ylabel
        )

    def plot_rolling_radius_difference(self, ax=None, *, label=None, color=None, artists=None) -> dict:
        """Draw Δr(y) in mm against the shift y in mm; or move a line drawn before.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        label : str, optional
            Legend label.
        color : color, optional
            Line colour.
        artists : dict, optional
            The dict a previous call returned (same shifts): its line takes this table.

        Returns
        -------
        dict
            ``{"rolling_radius_difference": line}``.
        """
        return self._line(
            ax, artists, "rolling_radius_difference", 1e3 * self.shift, 1e3 * self.rolling_radius_difference,
            label, color, "lateral shift y (mm)", "Δr = r_L − r_R (mm)",
        )  # fmt: skip

    def plot_contact_angle(self, ax=None, *, label=None, color=None, artists=None) -> dict:
        """Draw the left wheel's contact angle ϑ_L in degrees against the shift y in mm.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        label : str, optional
            Legend label.
        color : color, optional
            Line colour.
        artists : dict, optional
            The dict a previous call returned (same shifts): its line takes this table.

        Returns
        -------
        dict
            ``{"contact_angle": line}``.
        """
        return self._line(
            ax, artists, "contact_angle", 1e3 * self.shift, np.degrees(self.contact_angle[0]),
            label, color, "lateral shift y (mm)", "left contact angle ϑ_L (deg)",
        )  # fmt: skip

    def plot_equivalent_conicity(self, amplitudes, ax=None, *, label=None, color=None, artists=None) -> dict:
        """Draw EN 15302's λ_e(ŷ) (:meth:`equivalent_conicity`) against the amplitude ŷ in mm.

        Parameters
        ----------
        amplitudes : float or array_like
            ŷ (m), > 0, within the reach of this table.
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        label : str, optional
            Legend label.
        color : color, optional
            Line colour.
        artists : dict, optional
            The dict a previous call returned (same amplitudes): its line takes this table.

        Returns
        -------
        dict
            ``{"equivalent_conicity": line}``.
        """
        amp = _amplitudes(amplitudes)
        return self._line(
            ax, artists, "equivalent_conicity", 1e3 * amp, self.equivalent_conicity(amp),
            label, color, "amplitude ŷ (mm)", "equivalent conicity λ_e",
        )  # fmt: skip


def _offset(rail: RailProfile, gauge: float, tape_distance: float) -> float:
    """d: tape circle minus rail centre line, lateral, in the centred position (m)."""
    rail_centre = gauge / 2 + rail.gauge_face
    return tape_distance / 2 - rail_centre


def _gap(wheel: WheelProfile, rail: RailProfile, shifts: np.ndarray, offset: float):
    """Vertical gap wheel − rail over the rail grid for each shift (left side), and the wheel's u there."""
    u_w = rail.lateral[None, :] + shifts[:, None] + offset
    inside = (u_w >= wheel.lateral[0]) & (u_w <= wheel.lateral[-1])
    # Wheel surface height relative to the tape circle: a larger radius reaches lower.
    z_w = wheel.nominal_radius - np.interp(u_w, wheel.lateral, wheel.radius)
    return np.where(inside, z_w - rail.height[None, :], np.inf), u_w


def _off_rail(gap: np.ndarray) -> np.ndarray:
    """For each row (shift), whether its least gap fails to lie strictly inside both profiles.

    A least gap at an end of the rail's profile, or next to where the wheel's profile ends, or no
    overlap at all, means that the wheel hangs beyond the rail head: off the rail.
    """
    i = np.argmin(gap, axis=1)
    j = np.clip(i, 1, gap.shape[1] - 2)
    rows = np.arange(gap.shape[0])
    inside = np.isfinite(gap[rows, j - 1]) & np.isfinite(gap[rows, j]) & np.isfinite(gap[rows, j + 1])
    return (i != j) | ~inside


def _on_rails(wheel, rail, y, offset, name, gap_l, gap_r) -> None:
    """Refuse shifts that put a wheel off its rail, blaming ``name`` (or the track if even y = 0 does)."""
    off = _off_rail(gap_l) | _off_rail(gap_r)
    if not off.any():
        return
    if _off_rail(_gap(wheel, rail, np.zeros(1), offset)[0])[0]:
        raise ValueError(
            "gauge and tape_distance put the wheels off the rails even in the centred position: the tape "
            f"circle lies {1e3 * offset:.4g} mm from the rail's centre line, and the contact would fall at "
            f"an edge of the {wheel.name!r} wheel or the {rail.name!r} rail profile"
        )
    bad = y[off][np.argmin(np.abs(y[off]))]
    raise ValueError(
        f"{name} must keep both wheels on their rails: a lateral shift y = {bad:.6g} m puts the contact "
        f"at an edge of the {wheel.name!r} wheel or the {rail.name!r} rail profile (off the rail head)"
    )


def _contact_on(gap: np.ndarray, wheel: WheelProfile, rail: RailProfile, shifts: np.ndarray, offset: float):
    """Contact at the least gap of each row, refined by a parabola through its neighbours."""
    u_r = rail.lateral
    i = np.clip(np.argmin(gap, axis=1), 1, u_r.size - 2)
    rows = np.arange(shifts.size)
    g0, g1, g2 = gap[rows, i - 1], gap[rows, i], gap[rows, i + 1]
    curv = g0 - 2 * g1 + g2
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = np.where(np.isfinite(curv) & (curv > 0), 0.5 * (g0 - g2) / curv, 0.0)
    frac = np.clip(frac, -0.5, 0.5)
    step = u_r[1] - u_r[0]
    ur = u_r[i] + frac * step
    uw = ur + shifts + offset
    slope = np.interp(ur, 0.5 * (u_r[1:] + u_r[:-1]), np.diff(rail.height) / step)
    return uw, ur, np.interp(uw, wheel.lateral, wheel.radius), -np.arctan(slope)


_ROLL_ITERATIONS = 8  # the fixed point contracts by about 2|u_w|/T ≈ 0.05 per step: 0.05⁸ ≈ 4e-11 of φ


def contact_geometry(
    wheel: WheelProfile, rail: RailProfile, shifts, *, gauge=1.435, tape_distance=1.5, roll: bool = True,
    yaw=0.0,
) -> ContactGeometry:  # fmt: skip
    """Contact points, rolling radii and contact angles of a wheelset for each lateral shift.

    Each wheel touches its rail where the vertical gap is least. With
    ``roll=True`` the wheelset also rolls by the angle φ that lets both wheels
    touch at once: raising the left wheel by e_L(φ) and the right by e_R(φ)
    needs φ = (e_L − e_R)/T (T the tape-circle distance), solved by fixed-point
    iteration with the roll applied to first order (each wheel point rises by
    φ times its lateral distance from the wheelset centre). With
    ``roll=False`` each wheel is lowered on to its rail on its own; a cone then
    gives Δr = 2λy exactly. The shift y is that of the wheels at rail level: a
    rolled wheelset's axle centre sits r₀φ further to the right.

    Parameters
    ----------
    wheel : WheelProfile
        The wheel profile, the same on both sides (mirror images).
    rail : RailProfile
        The rail profile, the same on both sides.
    shifts : float or array_like
        Lateral shifts y (m), positive to the left, 1-D, at least one. Each must keep both
        wheels on their rails: a shift that puts a contact at an edge of the wheel's or
        the rail's profile (a wheel off the rail head) is refused with that reason.
    gauge : float, keyword
        Track gauge, between the gauge points 14 mm below the top (m), > 0; 1.435.
    tape_distance : float, keyword
        Distance between the tape circles of the wheelset (m), > 0; 1.5 for standard gauge.
        With ``gauge`` it must put the centred wheelset's wheels on the rails.
    roll : bool, keyword
        Include the wheelset roll angle (default True).
    yaw : float, keyword
        The wheelset's yaw ψ (rad, turning to the left), in [−0.03, 0.03]: each wheel touches along
        its contact trace line (:mod:`raildyn.contact.trace_line`). Its effect on Δr and the angles
        is of second order in ψ; the lead of each contact point is of first order.

    Returns
    -------
    ContactGeometry
        Contact points, radii and angles over the shifts; ``.plot_*`` methods draw them.

    Examples
    --------
    A cone without roll gives Δr = 2λy exactly:

    >>> from raildyn.contact.profiles import conical_wheel, uic60_rail
    >>> g = contact_geometry(conical_wheel(1 / 20), uic60_rail(1 / 40), [0.0, 2e-3], roll=False)
    >>> np.round(g.rolling_radius_difference * 1e3, 6).tolist()  # mm
    [0.0, 0.2]
    """
    y = np.atleast_1d(_checks.array("shifts", shifts, allow_empty=False))
    if y.ndim != 1:
        raise ValueError(f"shifts must be a number or a 1-D array, got shape {y.shape}")
    return _geometry(wheel, rail, y, "shifts", gauge=gauge, tape_distance=tape_distance, roll=roll, yaw=yaw)


def _geometry(wheel, rail, y, name, *, gauge=1.435, tape_distance=1.5, roll=True, yaw=0.0) -> ContactGeometry:
    """:func:`contact_geometry` for checked shifts ``y``; a wheel off its rail is blamed on ``name``."""
    _checks.instance("wheel", wheel, WheelProfile)
    _checks.instance("rail", rail, RailProfile)
    g = _checks.positive("gauge", gauge)
    t = _checks.positive("tape_distance", tape_distance)
    roll = _checks.flag("roll", roll)
    u_e, r_e, lead = trace_line(wheel.lateral, wheel.radius, yaw, t)
    # The rail sees the wheel's trace line; at ψ = 0 it is the profile itself.
    profile = wheel if yaw == 0.0 else WheelProfile(wheel.name, u_e, r_e, wheel.nominal_radius)
    d = _offset(rail, g, t)
    gap_l, u_l = _gap(profile, rail, y, d)
    gap_r, u_r = _gap(profile, rail, -y, d)
    _on_rails(profile, rail, y, d, name, gap_l, gap_r)
    phi = np.zeros_like(y)
    if roll:
        # A roll φ (left side up) lifts a left-wheel point at u_w by φ(T/2 − u_w) and lowers a
        # right-wheel point by φ(T/2 − u_w); the T/2 parts are the rigid tilt of the axle.
        for _ in range(_ROLL_ITERATIONS):
            e_l = -np.min(gap_l - phi[:, None] * u_l, axis=1)
            e_r = -np.min(gap_r + phi[:, None] * u_r, axis=1)
            phi = (e_l - e_r) / t
    gap_l, gap_r = gap_l - phi[:, None] * u_l, gap_r + phi[:, None] * u_r
    _on_rails(profile, rail, y, d, name, gap_l, gap_r)  # the roll may carry a contact to an edge
    left = _contact_on(gap_l, profile, rail, y, d)
    right = _contact_on(gap_r, profile, rail, -y, d)
    wheel_pos, rail_pos, radius, angle = (np.stack([lv, rv]) for lv, rv in zip(left, right, strict=True))
    if yaw != 0.0:
        # Back from the trace line to the wheel's own profile: its point u and its radius there.
        wheel_pos = np.interp(wheel_pos, u_e, wheel.lateral)
        radius = np.interp(wheel_pos, wheel.lateral, wheel.radius)
    # The lead: ahead of the axle on the left wheel for ψ > 0, behind it on the right.
    ahead = np.interp(wheel_pos, wheel.lateral, lead) * np.array([[1.0], [-1.0]])
    return ContactGeometry(y, wheel_pos, rail_pos, radius, angle, phi, ahead, float(yaw))


def rolling_radius_difference(wheel: WheelProfile, rail: RailProfile, shifts, **kwargs) -> np.ndarray:
    """Rolling-radius difference Δr(y) = r_L − r_R for each lateral shift y.

    Parameters
    ----------
    wheel : WheelProfile
        The wheel profile (both sides).
    rail : RailProfile
        The rail profile (both sides).
    shifts : float or array_like
        y (m), positive to the left.
    **kwargs
        ``gauge``, ``tape_distance``, ``roll`` as :func:`contact_geometry`.

    Returns
    -------
    ndarray
        Δr, m.
    """
    return contact_geometry(wheel, rail, shifts, **kwargs).rolling_radius_difference


def contact_angles(wheel: WheelProfile, rail: RailProfile, shifts, **kwargs) -> np.ndarray:
    """Contact angles ϑ_L, ϑ_R for each lateral shift y.

    Parameters
    ----------
    wheel : WheelProfile
        The wheel profile (both sides).
    rail : RailProfile
        The rail profile (both sides).
    shifts : float or array_like
        y (m), positive to the left.
    **kwargs
        ``gauge``, ``tape_distance``, ``roll`` as :func:`contact_geometry`.

    Returns
    -------
    ndarray, shape (2, n)
        ϑ_L, ϑ_R, rad.
    """
    return contact_geometry(wheel, rail, shifts, **kwargs).contact_angle


def equivalent_conicity(wheel: WheelProfile, rail: RailProfile, amplitudes, **kwargs) -> np.ndarray:
    """Equivalent conicity λ_e(ŷ) of a wheel and rail profile pair, as EN 15302 defines it.

    The rolling-radius difference Δr(y) of the pair (:func:`contact_geometry`, on 801 shifts
    over ±max(ŷ)) goes to EN 15302's kinematic method
    (:func:`~raildyn.contact.conicity.kinematic_conicity`): the wavelength of the wheelset's
    kinematic motion of amplitude ŷ on this Δr, compared with Klingel's
    L = 2π√(r₀ e₀/λ_e) of a cone. For the first-harmonic value of the same table, pass its
    shifts and Δr to :func:`~raildyn.contact.conicity.harmonic_conicity`.

    Parameters
    ----------
    wheel : WheelProfile
        The wheel profile (both sides).
    rail : RailProfile
        The rail profile (both sides).
    amplitudes : float or array_like
        ŷ (m), > 0, 1-D; the wheelset must stay on the rails over ±max(ŷ).
    **kwargs
        ``gauge``, ``tape_distance``, ``roll`` as :func:`contact_geometry`.

    Returns
    -------
    ndarray
        λ_e for each amplitude (dimensionless).

    Examples
    --------
    >>> from raildyn.contact.profiles import conical_wheel, uic60_rail
    >>> round(float(equivalent_conicity(conical_wheel(1 / 20), uic60_rail(1 / 40), 3e-3, roll=False)[0]), 9)
    0.05
    """
    amp = _amplitudes(amplitudes)
    table_y = np.linspace(-amp.max(), amp.max(), 801)
    dr = _geometry(wheel, rail, table_y, "amplitudes", **kwargs).rolling_radius_difference
    # The two wheels are mirror images: Δr is odd in y. Taking its odd part removes the rounding of
    # the contact search, so that the motion is centred on y = 0 and reaches exactly ±ŷ.
    dr = 0.5 * (dr - dr[::-1])
    return kinematic_conicity(table_y, dr, amp)


def _amplitudes(amplitudes) -> np.ndarray:
    """Amplitudes A (m) as a non-empty 1-D array, each > 0."""
    amp = np.atleast_1d(_checks.array("amplitudes", amplitudes, low=0.0, low_open=True, allow_empty=False))
    if amp.ndim != 1:
        raise ValueError(f"amplitudes must be a number or a 1-D array, got shape {amp.shape}")
    return amp
