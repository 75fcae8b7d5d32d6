"""The wheel–rail law of one wheelset, written once and compiled: the rails' forces from its motion.

Every caller evaluates these functions: the numpy path of :mod:`raildyn.wheelset.contact`
(:func:`~raildyn.wheelset.contact_forces`, :func:`~raildyn.wheelset.wheel_forces`, the right-hand
sides of :class:`~raildyn.wheelset.NonlinearLateral`) through the loops over arrays at the end, and
the compiled engine (:mod:`raildyn.wheelset._engine`) one wheelset at a time. The law itself is in
:mod:`raildyn.wheelset.contact`'s docstring of ``contact_forces``; here it is in code:

* each wheel's creepages are :func:`raildyn.contact.creepages.creepage_terms` with
  r = r₀ ± Δr(y)/2 and its tread angle, less the centred wheelset's spin ∓ sin ϑ_c/r₀;
* Kalker's linear forces F_x = −f₁₁γ_x, F_y = −f₂₂γ_y − f₂₃φ, M_z = f₂₃γ_y − f₃₃φ, scaled by
  :func:`raildyn.contact.saturation.saturation_scale` of √(F_x² + F_y²)/(μW/2);
* gravity through the contact-angle difference, −W Δϑ/2, the gravitational yaw stiffness
  W a ϑ₀ ψ, and the flange as a spring beyond the clearance.

The geometry (Δr, Δϑ and the tread angles at y) is the caller's: a cone (:func:`cone`), a profile
pair's tables (:func:`table`), or any Python function on the numpy path. The parameters of a
wheelset travel as a vector in the order of :data:`FIELDS`, from the place ``o`` of an array ``p``
(the engine's packed row, or :func:`parameters` at 0).
"""

from __future__ import annotations

import numba
import numpy as np

from raildyn._compiled import formula
from raildyn.contact.creepages import creepage_terms
from raildyn.contact.saturation import saturation_scale

# The law's parameters of a wheelset, in this order (the engine's packed row holds them so too).
FIELDS = ("a", "r0", "f11", "f22", "f23", "f33", "W", "eps", "theta0", "lam")
_A, _R0, _F11, _F22, _F23, _F33, _W, _EPS, _THETA0, _LAM = range(len(FIELDS))


def parameters(ws) -> np.ndarray:
    """The vector of :data:`FIELDS` of a :class:`~raildyn.wheelset.Wheelset`."""
    return np.array(
        [ws.half_gauge, ws.rolling_radius, ws.f11, ws.f22, ws.f23, ws.f33, ws.axle_load]
        + [ws.contact_angle_parameter, ws.contact_angle, ws.conicity],
        dtype=float,
    )


@formula
def cone(p, o, y):
    """Δr = 2λy and Δϑ = 2εy/a of the wheelset's cone (floats or arrays)."""
    return 2.0 * p[o + _LAM] * y, 2.0 * p[o + _EPS] * y / p[o + _A]


@formula
def tread(p, o, dd):
    """The tread angles ϑ₀ ± Δϑ/2 of a wheelset whose contact gives no tread angles of its own."""
    return p[o + _THETA0] + 0.5 * dd, p[o + _THETA0] - 0.5 * dd


@numba.njit(cache=True, error_model="numpy")
def table(x, f, y):
    """A tabulated f(y): linear between the points of (x, f), along the end intervals' slopes beyond."""
    below = (f[1] - f[0]) / (x[1] - x[0])
    above = (f[-1] - f[-2]) / (x[-1] - x[-2])
    return np.interp(y, x, f) + below * min(y - x[0], 0.0) + above * max(y - x[-1], 0.0)


@numba.njit(cache=True, error_model="numpy")
def table_many(x, f, y):
    """:func:`table` at each entry of the 1-D array y."""
    out = np.empty(y.size)
    for i in range(y.size):
        out[i] = table(x, f, y[i])
    return out


@numba.njit(cache=True, error_model="numpy")
def _creep(p, o, limit, xi_x, xi_y, spin):
    """One wheel's saturated creep forces F_x, F_y and moment M_z."""
    fx = -p[o + _F11] * xi_x
    fy = -p[o + _F22] * xi_y - p[o + _F23] * spin
    mz = p[o + _F23] * xi_y - p[o + _F33] * spin
    scale = saturation_scale(np.hypot(fx, fy) / limit)
    return scale * fx, scale * fy, scale * mz


@numba.njit(cache=True, error_model="numpy")
def wheels(p, o, friction, dr, theta_l, theta_r, centred_l, centred_r, psi, ydot, psidot, speed):
    """Both wheels' creepages and saturated forces: γ_x,L, γ_x,R, γ_y, (F_x, F_y, M_z) left, right."""
    r0 = p[o + _R0]
    xi_l, xi_r, xi_y, spin_l, spin_r = creepage_terms(
        speed, ydot, psi, psidot, r0 + 0.5 * dr, r0 - 0.5 * dr, r0, p[o + _A], theta_l, theta_r
    )
    # Less the centred wheelset's spins ∓ sin ϑ_c/r₀, whose forces cancel (contact_forces says why).
    spin_l += np.sin(centred_l) / r0
    spin_r -= np.sin(centred_r) / r0
    limit = friction * p[o + _W] / 2.0
    return xi_l, xi_r, xi_y, _creep(p, o, limit, xi_l, xi_y, spin_l), _creep(p, o, limit, xi_r, xi_y, spin_r)


@formula
def flange(y, clearance, stiffness):
    """The flange's lateral force on the wheelset, N: a spring beyond the clearance, pushing back."""
    return -stiffness * np.sign(y) * np.maximum(np.abs(y) - clearance, 0.0)


@numba.njit(cache=True, error_model="numpy")
def wheelset(
    p, o, friction, clearance, stiffness, dr, dd, theta_l, theta_r, centred_l, centred_r,
    y, psi, ydot, psidot, speed,
):  # fmt: skip
    """The rails' lateral force (N) and yaw moment (N·m) on the wheelset.

    The wheelset's parameters are p[o:o + 10]; μ, the flange clearance e and the flange stiffness
    k_f are the contact's; the geometry is at y (Δr, Δϑ, ϑ_L, ϑ_R) and at the centre (ϑ_c,L, ϑ_c,R).
    """
    _, _, _, left, right = wheels(
        p, o, friction, dr, theta_l, theta_r, centred_l, centred_r, psi, ydot, psidot, speed
    )
    W, a = p[o + _W], p[o + _A]
    lateral = left[1] + right[1] - W / 2.0 * dd + flange(y, clearance, stiffness)
    yaw = a * (right[0] - left[0]) + left[2] + right[2] + W * a * p[o + _THETA0] * psi
    return lateral, yaw


@numba.njit(cache=True, error_model="numpy")
def wheelset_many(
    p, friction, clearance, stiffness, dr, dd, theta_l, theta_r, centred_l, centred_r,
    y, psi, ydot, psidot, speed,
):  # fmt: skip
    """:func:`wheelset` at each entry of 1-D arrays of one size (the centred angles are two floats)."""
    lateral, yaw = np.empty(y.size), np.empty(y.size)
    for i in range(y.size):
        lateral[i], yaw[i] = wheelset(
            p, 0, friction, clearance, stiffness, dr[i], dd[i], theta_l[i], theta_r[i], centred_l, centred_r,
            y[i], psi[i], ydot[i], psidot[i], speed[i],
        )  # fmt: skip
    return lateral, yaw


@numba.njit(cache=True, error_model="numpy")
def wheels_many(p, friction, dr, theta_l, theta_r, centred_l, centred_r, psi, ydot, psidot, speed):
    """:func:`wheels` at each entry of 1-D arrays: rows γ_x,L, γ_x,R, γ_y, F_x,L, F_y,L, F_x,R, F_y,R."""
    out = np.empty((7, psi.size))
    for i in range(psi.size):
        xi_l, xi_r, xi_y, left, right = wheels(
            p, 0, friction, dr[i], theta_l[i], theta_r[i], centred_l, centred_r, psi[i], ydot[i], psidot[i],
            speed[i],
        )  # fmt: skip
        out[0, i], out[1, i], out[2, i] = xi_l, xi_r, xi_y
        out[3, i], out[4, i], out[5, i], out[6, i] = left[0], left[1], right[0], right[1]
    return out
