"""The nonlinear wheel–rail contact of one wheelset (book chapters 4, 5 and 8).

* :class:`~raildyn.wheelset.WheelRailContact`: the geometry Δr(y), Δϑ(y) and the tread angles
  (a cone by default), the saturation of the creep forces at the friction limit, and the flange
  as a stiff spring beyond the flangeway clearance;
* :func:`~raildyn.wheelset.profile_contact`: that contact for a real wheel and rail profile
  pair, its geometry in tables (:class:`~raildyn.wheelset.ContactTable`,
  :class:`~raildyn.wheelset.ContactTables`) that the compiled engine of
  :mod:`raildyn.stability` reads too;
* the rails' forces: on the wheelset (:func:`~raildyn.wheelset.contact_forces`), on each wheel
  (:func:`~raildyn.wheelset.wheel_forces`), and the tread contact angles
  (:func:`~raildyn.wheelset.tread_contact_angles`).

Coordinates: y to the left, ψ turning to the left. SI units throughout.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, scalar
from raildyn.wheelset.linear import Wheelset

# Imported where used, to keep this module's import cheap (tests/test_imports.py): raildyn.wheelset._law

__all__ = [
    "ContactTable",
    "ContactTables",
    "WheelForces",
    "WheelRailContact",
    "contact_forces",
    "profile_contact",
    "tread_contact_angles",
    "wheel_forces",
]


# rad: the S1002 wheel's flange flank, a straight line of slope 2.747477419 (EN 13715, section E; the
# coefficients in raildyn.contact.profiles), 70.0°.
_S1002_FLANK = float(np.arctan(2.747477419))


@dataclass(frozen=True)
class WheelRailContact:
    """Nonlinear wheel–rail contact of one wheelset: geometry, saturation and flange.

    Attributes
    ----------
    friction : float
        Coefficient of friction μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction": dry
        rail steel reaches about
        0.6; 30 would be a percentage); the creep force of a wheel saturates at μ W/2.
    flange_clearance : float
        Flangeway clearance e, m, in (0, 0.05]: the flange touches the rail beyond
        |y| = e (5 to 15 mm on standard-gauge track).
    flange_stiffness : float
        Lateral stiffness of the rail under flange contact k_f, N/m (≥ 0). Defaults
        e = 9.1 mm and k_f = 14.6 MN/m as in Cooperrider's truck model
        (Cooperrider 1972, as used by Jensen & True 1997).
    rolling_radius_difference : callable or None
        Δr(y) = r_L − r_R, m, vectorised over y: an array of y's shape, within ±0.1 m
        (twice a flange height is about 60 mm). None: the cone 2λy of the wheelset.
    contact_angle_difference : callable or None
        ϑ_L(y) − ϑ_R(y), rad, vectorised over y, within ±π/2 (each contact angle lies in
        [0, π/2)). None: the linear 2εy/a of the wheelset.
    tread_angles : callable or None
        [ϑ_L(y), ϑ_R(y)], the two tread contacts' angles, rad, vectorised: an array of shape
        ``(2, *y.shape)``, each within ±π/2. Each wheel spins about its contact normal by
        sin ϑ/r₀ (:func:`contact_forces`), and its normal force, tilted by ϑ, enters its lateral
        force Y (:func:`raildyn.curving.quasi_static.quasi_static_curving`). None: ϑ₀ ± Δϑ(y)/2
        of the wheelset (:func:`tread_contact_angles`; ϑ₀ ± εy/a on a cone).
    flange_angle : float
        ϑ_f, the largest contact angle of the flange on its rail, rad, in (0, π/2): the angle of
        Nadal's and Weinstock's limits of Y/Q (:mod:`raildyn.curving.climb`). Default 70°, the
        flank of the S1002 wheel (EN 13715); :func:`profile_contact` reads it from the pair.
    two_point : bool
        False (the default): the flange is the lateral spring of Cooperrider's model and nothing
        more. True: it is a second contact beside the tread, with its normal force |H|/sin ϑ_f
        (H the spring's force), the creepages of its own radius and angle, its own saturated creep
        forces, and the vertical load it takes off its wheel's tread (see
        :func:`contact_forces`); :func:`profile_contact` gives a profile pair so.
    flange_radius_excess : float
        r_f − r₀, m, in [0, 0.05]: how much larger the wheel's radius is at the flange contact
        than at its tape circle (its longitudinal creepage on a two-point contact). Default 0
        (the spring flange has none); :func:`profile_contact` reads it from the pair.

    Each callable is tried once, at y = −e, 0 and e, and what it returns checked.
    """

    friction: float = 0.3
    flange_clearance: float = 9.1e-3
    flange_stiffness: float = 14.6e6
    rolling_radius_difference: Callable | None = None
    contact_angle_difference: Callable | None = None
    tread_angles: Callable | None = None
    flange_angle: float = _S1002_FLANK
    two_point: bool = False
    flange_radius_excess: float = 0.0

    def __post_init__(self):
        _checks.friction("friction", self.friction)
        _checks.flag("two_point", self.two_point)
        scalar("flange_radius_excess", self.flange_radius_excess, low=0.0, high=0.05)
        scalar("flange_angle", self.flange_angle, low=0.0, high=np.pi / 2, low_open=True, high_open=True)
        scalar("flange_clearance", self.flange_clearance, low=0.0, low_open=True, high=0.05)
        nonnegative("flange_stiffness", self.flange_stiffness)
        y = np.array([-1.0, 0.0, 1.0]) * self.flange_clearance
        for name, bound in (("rolling_radius_difference", 0.1), ("contact_angle_difference", np.pi / 2)):
            fn = getattr(self, name)
            if fn is not None:
                out = _checks.returned(name, _checks.function(name, fn)(y), shape=(3,), at=f"y = {y} m")
                if np.abs(out).max() > bound:
                    raise ValueError(
                        f"{name} must return values within ±{bound:.4g}, returned {out} at y = {y} m"
                    )
        if self.tread_angles is not None:
            fn = _checks.function("tread_angles", self.tread_angles)
            out = _checks.returned("tread_angles", fn(y), shape=(2, 3), at=f"y = {y} m")
            if np.abs(out).max() > np.pi / 2:
                raise ValueError(f"tread_angles must return angles within ±π/2, returned {out} at y = {y} m")


_PROFILE_STEP = 2.5e-4  # m, the lateral step of the contact tables
_BEYOND = 0.02  # m: the tables' last points lie this far beyond the clearance (and go on at that slope)


def profile_contact(
    wheel, rail, *, friction=0.3, flange_stiffness=14.6e6, gauge=1.435, tape_distance=1.5
) -> WheelRailContact:
    """The nonlinear contact of a wheel and rail profile pair: tread tables and the flange.

    The rigid contact of chapter 4 (:func:`raildyn.contact.geometry.contact_geometry`, with
    the wheelset's roll) is followed outwards from the centre in steps of 0.25 mm until a
    contact angle passes 40°: there the contact jumps from the tread to the flange, and that
    shift is the flangeway clearance e (:func:`raildyn.contact.profile_files.check_pair`, which
    also refuses a pair that cannot run). Inside it, the rolling-radius and contact-angle
    differences Δr(y) and Δϑ(y) and the two tread angles ϑ_L(y), ϑ_R(y) are tabulated and
    interpolated linearly; beyond it the tread keeps its contact, while the flange touches
    too, pressed by the rail's lateral stiffness ``flange_stiffness``: a two-point contact,
    tread and flange at once (Garg & Dukkipati 1984, ch. 4 and 8), each with its own normal
    load, creepages and creep forces (``two_point``). The flange angle of the contact is
    the steepest contact angle the pair reaches on its flange within those 20 mm, and its radius
    excess the flange contact's r − r₀ where the contact first jumps. Beyond e the flanging
    wheel's rail gives way under its flange, so that wheel's tread contact stays where it was: the
    tables hold the angles at their values at ±e, and Δr changes only by the other wheel's
    rolling on along its tread (the tangent of its contact angle per metre of shift). The
    geometry of a pair is tabulated once and kept (the last 16 pairs, each with its gauge and
    tape distance), so that asking again, with another friction or flange stiffness, is free.

    Parameters
    ----------
    wheel : raildyn.contact.profiles.WheelProfile
    rail : raildyn.contact.profiles.RailProfile
    friction : float
        μ, > 0.
    flange_stiffness : float
        k_f, the lateral stiffness of the rail under flange contact, N/m (≥ 0).
    gauge, tape_distance : float
        m, as for :func:`raildyn.contact.geometry.contact_geometry`.

    Returns
    -------
    WheelRailContact

    Raises
    ------
    ValueError
        As :func:`raildyn.contact.profile_files.check_pair`, naming both profiles (their files),
        the gauge and the tape distance: no flange contact within 20 mm of the centre (a pair
        with no flange, such as a cone, or a gauge too wide), or wheels that stand on their
        flanges when centred, or off the rails.

    Examples
    --------
    The S1002 wheel on UIC 60 rail inclined at 1:40 flanges 6.5 to 6.75 mm off centre:

    >>> from raildyn.contact.profiles import s1002_wheel, uic60_rail
    >>> contact = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    >>> round(1e3 * contact.flange_clearance, 2)
    6.5
    """
    from raildyn.contact.geometry import RailProfile, WheelProfile

    _checks.instance("wheel", wheel, WheelProfile)
    _checks.instance("rail", rail, RailProfile)
    key = _pair_key(
        wheel, rail, _checks.positive("gauge", gauge), _checks.positive("tape_distance", tape_distance)
    )
    if key not in _PAIRS:
        if len(_PAIRS) >= _PAIRS_KEPT:
            _PAIRS.pop(next(iter(_PAIRS)))  # the oldest pair goes
        _PAIRS[key] = _pair_geometry(wheel, rail, gauge, tape_distance)
    return WheelRailContact(
        friction=friction, flange_stiffness=flange_stiffness, two_point=True, **_PAIRS[key]
    )


# The geometry of the last few profile pairs, tabulated once each (a widget or a family of runs asks again).
_PAIRS: dict = {}
_PAIRS_KEPT = 16


def _pair_key(wheel, rail, gauge: float, tape_distance: float) -> str:
    """A digest of everything the pair's tables depend on: both profiles, the gauge and the tape distance."""
    digest = hashlib.sha1()
    for profile in (wheel, rail):
        digest.update(
            repr({k: v for k, v in vars(profile).items() if not isinstance(v, np.ndarray)}).encode()
        )
        for v in vars(profile).values():
            if isinstance(v, np.ndarray):
                digest.update(v.tobytes())
    digest.update(np.array([gauge, tape_distance]).tobytes())
    return digest.hexdigest()


def _pair_geometry(wheel, rail, gauge: float, tape_distance: float) -> dict:
    """The geometry fields of :func:`profile_contact`'s :class:`WheelRailContact` for a profile pair."""
    from raildyn.contact.geometry import contact_geometry
    from raildyn.contact.profile_files import check_pair

    # The pair's checks and its clearance e, found by the one scan outwards from the centre.
    clearance = check_pair(wheel, rail, gauge=gauge, tape_distance=tape_distance)
    y = np.arange(0.0, 0.02 + _PROFILE_STEP / 2, _PROFILE_STEP)
    left = contact_geometry(wheel, rail, y, gauge=gauge, tape_distance=tape_distance)
    right = contact_geometry(wheel, rail, -y, gauge=gauge, tape_distance=tape_distance)
    last = int(np.searchsorted(y, clearance + 1e-12)) - 1  # the last shift on the treads: e
    shifts = np.concatenate([-y[last:0:-1], y[: last + 1]])
    angles = [
        np.concatenate([right.contact_angle[k, last:0:-1], left.contact_angle[k, : last + 1]]) for k in (0, 1)
    ]
    dr = np.concatenate(
        [right.rolling_radius_difference[last:0:-1], left.rolling_radius_difference[: last + 1]]
    )
    dd = np.concatenate(
        [right.contact_angle_difference[last:0:-1], left.contact_angle_difference[: last + 1]]
    )
    # Beyond the clearance the flanging wheel's rail gives way under its flange: that wheel's tread contact
    # stays where it was, and only the other wheel rolls on along its tread, its radius falling as the
    # tangent of its contact angle. The angles keep their values at ±e.
    shifts = np.concatenate([[shifts[0] - _BEYOND], shifts, [shifts[-1] + _BEYOND]])
    angles = [np.concatenate([[v[0]], v, [v[-1]]]) for v in angles]
    dd = np.concatenate([[dd[0]], dd, [dd[-1]]])
    ends = [dr[0] - np.tan(angles[0][0]) * _BEYOND, dr[-1] + np.tan(angles[1][-1]) * _BEYOND]
    dr = np.concatenate([[ends[0]], dr, [ends[1]]])
    # The flange's own angle: the steepest contact of either wheel on its flange; its radius: where the
    # contact first jumps to it (the two wheels are mirror images: the left one's).
    flange_angle = max(left.contact_angle[0].max(), right.contact_angle[1].max())
    excess = left.rolling_radius[0, last + 1] - wheel.nominal_radius
    return dict(
        flange_angle=float(flange_angle),
        flange_radius_excess=float(excess),
        flange_clearance=float(y[last]),
        rolling_radius_difference=ContactTable(shifts, dr),
        contact_angle_difference=ContactTable(shifts, dd),
        tread_angles=ContactTables(ContactTable(shifts, angles[0]), ContactTable(shifts, angles[1])),
    )


class ContactTable:
    """f(y) by linear interpolation in a table, continued along the slope of its end intervals.

    How :func:`profile_contact` holds a profile pair's Δr(y), Δϑ(y) and tread angles, so that
    the compiled engine of :mod:`raildyn.stability` can read the table (``x``, ``f``) and run the
    same interpolation; any other callable runs on scipy's path.

    Parameters
    ----------
    x : array_like, (n,)
        The lateral shifts y of the table, m, finite and strictly increasing, at least two.
    f : array_like, (n,)
        The values at ``x`` (m for a rolling-radius difference, rad for an angle), finite.

    Attributes
    ----------
    x, f : ndarray, (n,)
        The table, as given.
    slopes : tuple of float
        The slopes of the first and the last interval (per m), which continue the table
        beyond its ends.

    Examples
    --------
    >>> table = ContactTable([0.0, 1e-3, 2e-3], [0.0, 1e-4, 3e-4])
    >>> np.round(table([5e-4, 3e-3]), 6).tolist()
    [5e-05, 0.0005]
    """

    def __init__(self, x, f):
        x = _checks.increasing("x", x)
        if x.size < 2:
            raise ValueError(f"x must hold at least two shifts, got {x.size}")
        f = _checks.array("f", f, shape=x.shape)
        self.x, self.f = x, f
        self.slopes = ((f[1] - f[0]) / (x[1] - x[0]), (f[-1] - f[-2]) / (x[-1] - x[-2]))

    def __call__(self, y):
        from raildyn.wheelset import _law

        y = np.asarray(y, dtype=float)
        return _law.table_many(self.x, self.f, np.ravel(y)).reshape(y.shape)  # the engine's table, compiled


class ContactTables:
    """Tables side by side, [f₀(y), f₁(y), …]: an array of shape ``(k, *y.shape)``.

    How :func:`profile_contact` holds the two tread angles [ϑ_L(y), ϑ_R(y)] (rad), in a form the
    compiled engine of :mod:`raildyn.stability` reads.

    Parameters
    ----------
    *tables : ContactTable
        At least one.

    Attributes
    ----------
    tables : tuple of ContactTable

    Examples
    --------
    >>> left = ContactTable([-1e-3, 1e-3], [0.04, 0.06])
    >>> right = ContactTable([-1e-3, 1e-3], [0.06, 0.04])
    >>> ContactTables(left, right)(0.0).tolist()
    [0.05, 0.05]
    """

    def __init__(self, *tables):
        if not tables:
            raise ValueError("tables must hold at least one ContactTable, got none")
        for table in tables:
            _checks.instance("tables", table, ContactTable)
        self.tables = tables

    def __call__(self, y):
        return np.stack([table(y) for table in self.tables])


def contact_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed):
    """Lateral force (N) and yaw moment (N·m) of the rails on a wheelset, nonlinear; arrays broadcast.

    Each wheel has the creepages of :func:`raildyn.contact.creepages.wheelset_creepages` with
    r_L,R = r₀ ± Δr(y)/2 and its own tread contact angle ϑ_L(y), ϑ_R(y)
    (:func:`tread_contact_angles`): γ_x = ∓(aψ̇/V + Δr/(2r₀)), γ_y = ẏ/V − ψ and the spin
    φ = ψ̇ cos ϑ/V ∓ sin ϑ/r₀ on the left/right wheel. Kalker's linear forces of each wheel,
    F_x = −f₁₁γ_x, F_y = −f₂₂γ_y − f₂₃φ and M_z = f₂₃γ_y − f₃₃φ, are scaled together by the
    saturation of Shen, Hedrick and Elkins (:func:`raildyn.contact.saturation.saturation_factor`)
    of that wheel's resultant √(F_x² + F_y²) at μ W/2, as
    :func:`raildyn.contact.saturation.shen_hedrick_elkins` scales them. Gravity acts through the
    contact-angle difference, and the flange as a spring beyond the clearance.

    One simplification: the spins ∓ sin ϑ_c/r₀ of the centred wheelset (ϑ_c its tread angles at
    y = 0, ϑ₀ on a cone) are taken out of each wheel's spin. Their forces ±f₂₃ sin ϑ_c/r₀ are
    equal and opposite and leave the wheelset's equations, as in the linear model; kept in each
    wheel, they would take up part of its adhesion at rest (39 % of μW/2 on the default cone of
    0.15, under 8 % on a tread of 2°) and the saturation's slope there would soften every creep
    force about the centre. Left out, the nonlinear wheelset linearises about the centre to
    exactly the forces of :func:`creep_terms`, and its Hopf point is the linear critical speed.

    Parameters
    ----------
    ws : Wheelset
    contact : WheelRailContact
    y, psi, ydot, psidot : float or ndarray
        Lateral displacement (m), yaw (rad) and their rates (m/s, rad/s): finite, of
        either sign, shapes that broadcast together.
    speed : float or ndarray
        V, m/s, each in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (the creepages divide by
        it), of a shape that broadcasts with the motion.

    Returns
    -------
    lateral : ndarray
        N.
    yaw : ndarray
        N·m.
    """
    return _contact_forces(ws, contact, *_motion(ws, contact, y, psi, ydot, psidot, speed))


def _motion(ws, contact, y, psi, ydot, psidot, speed) -> list:
    """The checked [y, ψ, ẏ, ψ̇, V] of :func:`contact_forces` and :func:`wheel_forces`, broadcast."""
    _checks.instance("ws", ws, Wheelset)
    _checks.instance("contact", contact, WheelRailContact)
    names = (*_MOTION, "speed")
    motion = [_checks.array(name, v) for name, v in zip(_MOTION, (y, psi, ydot, psidot), strict=True)]
    motion.append(_checks.plausible_array("speed", speed, "speed", low_open=True))
    _checks.broadcast(**dict(zip(names, motion, strict=True)))
    return list(np.broadcast_arrays(*motion))


_MOTION = ("y", "psi", "ydot", "psidot")


def tread_contact_angles(ws: Wheelset, contact: WheelRailContact, y) -> np.ndarray:
    """The contact angles ϑ_L(y), ϑ_R(y) of a wheelset's two treads, rad.

    The contact's ``tread_angles`` where it has them (a profile pair,
    :func:`profile_contact`); else ϑ₀ ± Δϑ(y)/2 with Δϑ(y) the contact's
    ``contact_angle_difference`` or, on a cone, the linear 2εy/a of the wheelset.

    Parameters
    ----------
    ws : Wheelset
    contact : WheelRailContact
    y : float or array_like
        Lateral displacement of the wheelset relative to the rails, m, finite.

    Returns
    -------
    ndarray, shape (2, *y.shape)
        [ϑ_L, ϑ_R], rad.

    Examples
    --------
    >>> ws = Wheelset(contact_angle=0.05, contact_angle_parameter=0.1)
    >>> np.round(tread_contact_angles(ws, WheelRailContact(), 3e-3), 4).tolist()
    [0.0504, 0.0496]
    """
    _checks.instance("ws", ws, Wheelset)
    _checks.instance("contact", contact, WheelRailContact)
    return np.stack(_angles(ws, contact, _checks.array("y", y))[:2])


def _angles(ws: Wheelset, contact: WheelRailContact, y):
    """ϑ_L(y), ϑ_R(y) and Δϑ(y) of :func:`tread_contact_angles`, unchecked."""
    from raildyn.wheelset import _law

    p = _law.parameters(ws)
    y = np.asarray(y, dtype=float)
    dd = (
        _law.cone(p, 0, y)[1]
        if contact.contact_angle_difference is None
        else contact.contact_angle_difference(y)
    )
    if contact.tread_angles is None:
        return (*_law.tread(p, 0, dd), dd)
    left, right = contact.tread_angles(y)
    return left, right, dd


def _geometry(ws: Wheelset, contact: WheelRailContact, y):
    """The law's parameters and geometry at y: p, Δr, Δϑ, ϑ_L, ϑ_R and the centred ϑ_c,L, ϑ_c,R."""
    from raildyn.wheelset import _law

    p = _law.parameters(ws)
    dr = (
        _law.cone(p, 0, np.asarray(y, dtype=float))[0]
        if contact.rolling_radius_difference is None
        else contact.rolling_radius_difference(y)
    )
    theta_l, theta_r, dd = _angles(ws, contact, y)
    centred_l, centred_r = (float(v) for v in _angles(ws, contact, 0.0)[:2])
    return p, dr, dd, theta_l, theta_r, centred_l, centred_r


def _flat(*arrays):
    """The arrays broadcast together, each as a writable contiguous 1-D float copy, and their common shape."""
    shape = np.broadcast_shapes(*(np.shape(a) for a in arrays))
    flat = [np.array(np.broadcast_to(a, shape), dtype=float).ravel() for a in arrays]
    return flat, shape


def _contact_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed):
    """:func:`contact_forces` without the checks, for the right-hand sides (called at every step)."""
    from raildyn.wheelset import _law

    p, dr, dd, theta_l, theta_r, centred_l, centred_r = _geometry(ws, contact, y)
    (dr, dd, theta_l, theta_r, y, psi, ydot, psidot, speed), shape = _flat(
        dr, dd, theta_l, theta_r, y, psi, ydot, psidot, speed
    )
    lateral, yaw = _law.wheelset_many(
        p,
        _law.contact_parameters(contact),
        dr,
        dd,
        theta_l,
        theta_r,
        centred_l,
        centred_r,
        y,
        psi,
        ydot,
        psidot,
        speed,
    )
    return lateral.reshape(shape), yaw.reshape(shape)


@dataclass(frozen=True)
class WheelForces:
    """The rails' forces on the two wheels of a wheelset; index 0 is the left wheel, 1 the right.

    Attributes
    ----------
    longitudinal : ndarray, shape (2, ...)
        Saturated longitudinal creep force on each wheel, N (forwards): its tread's and, on a
        two-point contact, its flange's.
    lateral : ndarray, shape (2, ...)
        Saturated lateral creep force of each wheel's tread, N (to the left).
    flange : ndarray, shape (2, ...)
        Lateral force of the flange contact on each wheel, N (to the left; 0 off the flange): its
        normal force's and, on a two-point contact, its creep force's.
    wear_number : ndarray, shape (2, ...)
        Tγ = |T_x γ_x| + |T_y γ_y| of each wheel's contacts, N (J/m): the creep forces' work per
        metre rolled, the wear index of Pearce & Sherratt (1991).
    flange_vertical : ndarray, shape (2, ...)
        The vertical load the flange contact of each wheel bears, N (0 off the flange): of its normal
        force |H|/tan ϑ_f and, on a two-point contact, of its creep force; the tread bears the rest.

    All finite, of one shape (2, ...); the wear number ≥ 0.
    """

    longitudinal: np.ndarray
    lateral: np.ndarray
    flange: np.ndarray
    wear_number: np.ndarray
    flange_vertical: np.ndarray

    def __post_init__(self):
        shape = np.shape(self.longitudinal)
        for name in ("longitudinal", "lateral", "flange", "wear_number", "flange_vertical"):
            value = _checks.array(name, getattr(self, name), low=0.0 if name == "wear_number" else None)
            if value.ndim == 0 or value.shape[0] != 2 or value.shape != shape:
                raise ValueError(
                    f"{name} must have the shape (2, ...) of longitudinal, {shape}, got {value.shape}"
                )
            object.__setattr__(self, name, value)


def wheel_forces(ws: Wheelset, contact: WheelRailContact, y, psi, ydot, psidot, speed) -> WheelForces:
    """The rails' creep and flange forces on each wheel of a wheelset, nonlinear; arrays broadcast.

    The same forces as :func:`contact_forces`, wheel by wheel: each wheel's creep forces
    −f γ scaled by the saturation factor, and the flange contact on the wheel whose flange
    touches (the left one for y > e).

    Parameters
    ----------
    ws : Wheelset
    contact : WheelRailContact
    y, psi, ydot, psidot, speed : float or ndarray
        As for :func:`contact_forces`.

    Returns
    -------
    WheelForces

    Examples
    --------
    A wheelset 12 mm to the left, past the 9.1 mm flangeway clearance, leans on its left flange:

    >>> f = wheel_forces(Wheelset(), WheelRailContact(), 0.012, 0.0, 0.0, 0.0, 30.0)
    >>> round(float(f.flange[0]) / 1e3, 1), float(f.flange[1])
    (-42.3, 0.0)
    """
    from raildyn.wheelset import _law

    y, psi, ydot, psidot, speed = _motion(ws, contact, y, psi, ydot, psidot, speed)
    p, dr, _, theta_l, theta_r, centred_l, centred_r = _geometry(ws, contact, y)
    (dr, theta_l, theta_r, y, psi, ydot, psidot, speed), shape = _flat(
        dr, theta_l, theta_r, y, psi, ydot, psidot, speed
    )
    rows = _law.wheels_many(
        p, _law.contact_parameters(contact), dr, theta_l, theta_r, centred_l, centred_r, y, psi, ydot, psidot,
        speed,
    ).reshape((5, 2, *shape))  # fmt: skip
    return WheelForces(*rows[:2], rows[2], rows[4], rows[3])
