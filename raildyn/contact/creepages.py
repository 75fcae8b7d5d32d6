"""The creepages of a wheelset's two wheels from its motion and its contact geometry.

:func:`wheelset_creepages` returns :class:`WheelsetCreepages` (longitudinal, lateral and spin of each
wheel, sign convention of :mod:`raildyn.contact.kalker`); the creep laws take them as input.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._compiled import compiled_as

__all__ = [
    "WheelsetCreepages",
    "creepage_terms",
    "wheelset_creepages",
]


@dataclass(frozen=True)
class WheelsetCreepages:
    """Creepages at the two contacts of a wheelset; index 0 is the left wheel, 1 the right.

    Attributes
    ----------
    longitudinal : ndarray, shape (2, ...)
        γ_x at the left and right contacts.
    lateral : ndarray, shape (2, ...)
        γ_y (the same at both wheels in this kinematic form).
    spin : ndarray, shape (2, ...)
        φ (1/m).

    The three arrays are finite and of one shape (2, ...).
    """

    longitudinal: np.ndarray
    lateral: np.ndarray
    spin: np.ndarray

    def __post_init__(self):
        _checks.fields(self)
        shape = np.shape(self.longitudinal)
        for name in ("longitudinal", "lateral", "spin"):
            value = np.asarray(getattr(self, name), dtype=float)
            if value.ndim == 0 or value.shape[0] != 2 or value.shape != shape:
                raise ValueError(
                    f"{name} must have the shape (2, ...) of longitudinal (left, right), "
                    f"{shape}, got shape {value.shape}"
                )
            object.__setattr__(self, name, value)


def _unchecked_creepages(longitudinal, lateral, spin) -> WheelsetCreepages:
    """A :class:`WheelsetCreepages` built without its check, for the unchecked path (a right-hand side)."""
    out = object.__new__(WheelsetCreepages)
    object.__setattr__(out, "longitudinal", longitudinal)
    object.__setattr__(out, "lateral", lateral)
    object.__setattr__(out, "spin", spin)
    return out


def wheelset_creepages(
    speed,
    lateral_velocity,
    yaw_angle,
    yaw_rate,
    rolling_radius_left,
    rolling_radius_right,
    nominal_radius,
    half_gauge,
    contact_angle_left=0.0,
    contact_angle_right=0.0,
    *,
    check: bool = True,
) -> WheelsetCreepages:
    """Creepages of a wheelset on straight track (Garg & Dukkipati 1984, ch. 4–5).

    The wheelset runs at ``speed`` V and turns about its axle at Ω = V/r₀, the angular
    speed of its nominal rolling radius; y is positive to the left, the yaw ψ positive
    anticlockwise seen from above, the contact angles ϑ positive when the contact moves
    towards the flange. Each creepage is a slip velocity of the contact point divided by
    V, so all three share the one radius that sets Ω, the nominal r₀: the rolling radius
    r_L or r_R enters only through the rim's speed Ω r in γ_x, and the spin is the angular
    velocity about the contact normal, ψ̇ cos ϑ ∓ Ω sin ϑ, over V. With a the half
    distance between the contacts,

        γ_x,L = (r₀ − r_L)/r₀ − a ψ̇/V,            γ_x,R = (r₀ − r_R)/r₀ + a ψ̇/V,
        γ_y   = ẏ/V − ψ,
        φ_L = ψ̇ cos ϑ_L / V − sin ϑ_L / r₀,     φ_R = ψ̇ cos ϑ_R / V + sin ϑ_R / r₀

    (Kalker 1967; :func:`raildyn.derivations.contact.creepages` derives them from the
    velocities of the contact points). The cos ϑ matters at a steep contact: on a flange
    at 70° the yaw rate gives only a third of the spin it gives on the tread.

    Parameters
    ----------
    speed : float
        V (m/s), in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    lateral_velocity, yaw_angle, yaw_rate : float or array_like
        ẏ (m/s), ψ (rad), ψ̇ (rad/s).
    rolling_radius_left, rolling_radius_right : float or array_like
        r_L, r_R at the current contacts (m), each in [0.1, 1.5]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius"),
        e.g. r₀ ± Δr(y)/2.
    nominal_radius : float
        r₀ (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
    half_gauge : float
        a (m), half the lateral distance between the contact points, in [0.15, 1.1]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "half_gauge").
    contact_angle_left, contact_angle_right : float or array_like
        ϑ_L, ϑ_R (rad), within ±π/2.
    check : bool
        Check the input and the result (default). A caller that has checked it already, such as
        the right-hand side of :class:`raildyn.wheelset.NonlinearLateral` evaluated
        thousands of times a run, passes False: bad input then gives bad numbers.

    Returns
    -------
    WheelsetCreepages
        γ_x, γ_y, φ at the left (index 0) and right (index 1) contacts.

    Examples
    --------
    A coned wheelset shifted 3 mm to the left, λ = 1/20:

    >>> c = wheelset_creepages(40.0, 0.0, 0.0, 0.0, 0.46 + 1.5e-4, 0.46 - 1.5e-4, 0.46, 0.75)
    >>> np.round(c.longitudinal * 1e4, 4).tolist()
    [-3.2609, 3.2609]
    """
    if check is False:
        return _unchecked_creepages(*_wheelset_creepages(
            speed, lateral_velocity, yaw_angle, yaw_rate, rolling_radius_left, rolling_radius_right,
            nominal_radius, half_gauge, contact_angle_left, contact_angle_right,
        ))  # fmt: skip
    _checks.flag("check", check)
    v = _checks.speed("speed", speed)
    r0 = _checks.plausible("nominal_radius", nominal_radius, "wheel_radius")
    l_half = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    y_dot = _checks.array("lateral_velocity", lateral_velocity, allow_empty=False)
    psi = _checks.array("yaw_angle", yaw_angle, allow_empty=False)
    psi_dot = _checks.array("yaw_rate", yaw_rate, allow_empty=False)
    r_l = _checks.plausible_array(
        "rolling_radius_left", rolling_radius_left, "wheel_radius", allow_empty=False
    )
    r_r = _checks.plausible_array(
        "rolling_radius_right", rolling_radius_right, "wheel_radius", allow_empty=False
    )
    d_l = _checks.array("contact_angle_left", contact_angle_left, allow_empty=False)
    d_r = _checks.array("contact_angle_right", contact_angle_right, allow_empty=False)
    for name, angle in (("contact_angle_left", d_l), ("contact_angle_right", d_r)):
        if np.abs(angle).max(initial=0.0) > np.pi / 2:
            raise ValueError(f"{name} must be within ±π/2 rad (an angle in degrees?), got {angle!r:.80}")
    return WheelsetCreepages(*_wheelset_creepages(v, y_dot, psi, psi_dot, r_l, r_r, r0, l_half, d_l, d_r))


def _terms(
    speed, lateral_velocity, yaw_angle, yaw_rate, rolling_radius_left, rolling_radius_right, nominal_radius,
    half_gauge, contact_angle_left, contact_angle_right,
):  # fmt: skip
    r0 = nominal_radius
    yaw, spin = half_gauge * yaw_rate / speed, yaw_rate / speed
    return (
        (r0 - rolling_radius_left) / r0 - yaw,
        (r0 - rolling_radius_right) / r0 + yaw,
        lateral_velocity / speed - yaw_angle,
        spin * np.cos(contact_angle_left) - np.sin(contact_angle_left) / r0,
        spin * np.cos(contact_angle_right) + np.sin(contact_angle_right) / r0,
    )


@compiled_as(_terms)
def creepage_terms(
    speed, lateral_velocity, yaw_angle, yaw_rate, rolling_radius_left, rolling_radius_right, nominal_radius,
    half_gauge, contact_angle_left, contact_angle_right,
):  # fmt: skip
    """The five creepages of :func:`wheelset_creepages` as a tuple of numbers, for a force law to combine.

    The same formulas, in the form that numpy evaluates on arrays and numba compiles for floats:
    the nonlinear contact of :mod:`raildyn.wheelset` (its numpy path and its compiled engine)
    builds its creep forces on them (see ``raildyn._compiled``).

    Parameters
    ----------
    speed, lateral_velocity, yaw_angle, yaw_rate, rolling_radius_left, rolling_radius_right
        As for :func:`wheelset_creepages` (m/s, m/s, rad, rad/s, m, m); arrays broadcast.
    nominal_radius, half_gauge, contact_angle_left, contact_angle_right
        As for :func:`wheelset_creepages` (m, m, rad, rad).

    Returns
    -------
    tuple of float or ndarray
        γ_x,L, γ_x,R, γ_y, φ_L, φ_R (φ in 1/m).

    Examples
    --------
    >>> [round(float(g) * 1e4, 4) for g in creepage_terms(40.0, 0.0, 0.0, 0.0, 0.46015, 0.45985, 0.46,
    ...                                                   0.75, 0.0, 0.0)[:2]]
    [-3.2609, 3.2609]
    """
    c = wheelset_creepages(
        speed, lateral_velocity, yaw_angle, yaw_rate, rolling_radius_left, rolling_radius_right,
        nominal_radius, half_gauge, contact_angle_left, contact_angle_right,
    )  # fmt: skip
    return c.longitudinal[0], c.longitudinal[1], c.lateral[0], c.spin[0], c.spin[1]


def _wheelset_creepages(v, y_dot, psi, psi_dot, r_l, r_r, r0, l_half, d_l, d_r):
    """γ_x, γ_y, φ of :func:`wheelset_creepages`, each of shape (2, ...), from checked arrays."""
    parts = _terms(v, y_dot, psi, psi_dot, r_l, r_r, r0, l_half, d_l, d_r)
    # Broadcast only when the shapes differ: the nonlinear wheelset calls this at every evaluation
    # of its right-hand side, with arrays of one shape.
    if len({np.shape(p) for p in parts}) > 1:
        parts = np.broadcast_arrays(*parts)
    xi_l, xi_r, eta, phi_l, phi_r = parts
    return np.array((xi_l, xi_r)), np.array((eta, eta)), np.array((phi_l, phi_r))
