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
  W a ϑ₀ ψ, and the flange as a spring beyond the clearance;
* on a two-point contact (:func:`flange`), the flange as a second contact of its own: its normal
  force N_f = H/sin ϑ_f (H the spring's lateral force), its creepages at its own radius and angle,
  its creep forces with Kalker's coefficients scaled to its load and saturated at μN_f, and the
  vertical load V_f = H/tan ϑ_f + F_y,f sin ϑ_f it takes off its wheel's tread, whose creep forces and
  gravitational force then act with the load that is left.

Kalker's coefficients follow the Hertz patch of each contact's own normal load N: c ∝ N^(1/3), so
f₁₁, f₂₂ ∝ c² ∝ N^(2/3), f₂₃ ∝ N and f₃₃ ∝ N^(4/3) (Garg & Dukkipati 1984, ch. 4; Kalker 1967), from
the wheelset's coefficients at W/2. The flange's patch has the curvatures of the gauge corner, not the
tread's; that difference is left out (the flange's creep forces are saturated in any case, at the
large creepages of its larger radius and its spin).

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


# The contact's parameters, in this order (the engine's header holds them so too): μ, the flangeway
# clearance e, the flange stiffness k_f, 1 for a two-point contact (0: the flange a spring alone), the
# flange angle ϑ_f and the flange contact's radius above the tape circle's, r_f − r₀.
CONTACT_FIELDS = ("friction", "flange_clearance", "flange_stiffness", "two_point", "flange_angle",
                  "flange_radius_excess")  # fmt: skip
_MU, _E, _KF, _TWO, _ANGLE, _EXCESS = range(len(CONTACT_FIELDS))


def contact_parameters(contact) -> np.ndarray:
    """The vector of :data:`CONTACT_FIELDS` of a :class:`~raildyn.wheelset.WheelRailContact`."""
    return np.array([float(getattr(contact, name)) for name in CONTACT_FIELDS])


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
def place(x, y):
    """The interval i of the increasing x that y falls in (an end one beyond x), and y's fraction of it."""
    i = min(max(np.searchsorted(x, y) - 1, 0), x.size - 2)
    return i, (y - x[i]) / (x[i + 1] - x[i])


@numba.njit(cache=True, error_model="numpy")
def at_place(f, i, fraction):
    """The tabulated f at a :func:`place`: linear in its interval (and along an end one beyond the table)."""
    return f[i] + fraction * (f[i + 1] - f[i])


@numba.njit(cache=True, error_model="numpy")
def table(x, f, y):
    """A tabulated f(y): linear between the points of (x, f), along the end intervals' slopes beyond."""
    i, fraction = place(x, y)
    return at_place(f, i, fraction)


@numba.njit(cache=True, error_model="numpy")
def table_many(x, f, y):
    """:func:`table` at each entry of the 1-D array y."""
    out = np.empty(y.size)
    for i in range(y.size):
        out[i] = table(x, f, y[i])
    return out


@numba.njit(cache=True, error_model="numpy")
def _creep(p, o, limit, load, xi_x, xi_y, spin):
    """One contact's saturated creep forces F_x, F_y and moment M_z; ``load`` its normal load over W/2."""
    if limit <= 0.0:  # a contact that bears nothing (a tread lifted by its flange) carries no creep force
        return 0.0, 0.0, 0.0
    c = 1.0 if load == 1.0 else np.cbrt(load)  # the Hertz patch's size against the wheelset's at W/2
    c2 = c * c
    fx = -p[o + _F11] * c2 * xi_x
    fy = -p[o + _F22] * c2 * xi_y - p[o + _F23] * c2 * c * spin
    mz = p[o + _F23] * c2 * c * xi_y - p[o + _F33] * c2 * c2 * spin
    scale = saturation_scale(np.hypot(fx, fy) / limit)
    return scale * fx, scale * fy, scale * mz


@numba.njit(cache=True, error_model="numpy")
def wheels(
    p, o, friction, load_l, load_r, dr, theta_l, theta_r, centred_l, centred_r, psi, ydot, psidot, speed
):
    """Both treads' creepages and saturated forces: γ_x,L, γ_x,R, γ_y, (F_x, F_y, M_z) left, right.

    ``load_l`` and ``load_r`` are the treads' normal loads over W/2 (1 but where a flange bears part).
    """
    r0 = p[o + _R0]
    xi_l, xi_r, xi_y, spin_l, spin_r = creepage_terms(
        speed, ydot, psi, psidot, r0 + 0.5 * dr, r0 - 0.5 * dr, r0, p[o + _A], theta_l, theta_r
    )
    # Less the centred wheelset's spins ∓ sin ϑ_c/r₀, whose forces cancel (contact_forces says why).
    spin_l += np.sin(centred_l) / r0
    spin_r -= np.sin(centred_r) / r0
    limit = friction * p[o + _W] / 2.0
    left = _creep(p, o, limit * load_l, load_l, xi_l, xi_y, spin_l)
    return xi_l, xi_r, xi_y, left, _creep(p, o, limit * load_r, load_r, xi_r, xi_y, spin_r)


@formula
def flange(y, clearance, stiffness):
    """The flange's lateral force on the wheelset, N: a spring beyond the clearance, pushing back."""
    return -stiffness * np.sign(y) * np.maximum(np.abs(y) - clearance, 0.0)


@numba.njit(cache=True, error_model="numpy")
def flange_contact(p, o, c, y, psi, ydot, psidot, speed):
    """The flange's contact on the wheelset: lateral force H + F_y,f cos ϑ_f (N), the vertical load V_f it
    bears (N), its creep forces F_x,f, F_y,f (N), its yaw moment (N·m) and its creepages γ_x,f, γ_y.

    Off the flange all are 0; on a spring flange (c[_TWO] = 0) the lateral force is the spring's H,
    V_f = |H|/tan ϑ_f its normal force's vertical part, and it has no creep forces.
    """
    h = flange(y, c[_E], c[_KF])
    if h == 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    angle = c[_ANGLE]
    vertical = abs(h) / np.tan(angle)
    if c[_TWO] == 0.0:
        return h, vertical, 0.0, 0.0, 0.0, 0.0, 0.0
    side = 1.0 if y > 0.0 else -1.0  # the left flange (y > 0) or the right
    r0, a = p[o + _R0], p[o + _A]
    rf = r0 + c[_EXCESS]
    xi_l, xi_r, xi_y, spin_l, spin_r = creepage_terms(speed, ydot, psi, psidot, rf, rf, r0, a, angle, angle)
    xi_x, spin = (xi_l, spin_l) if side > 0.0 else (xi_r, spin_r)
    normal = abs(h) / np.sin(angle)
    fx, fy, mz = _creep(p, o, c[_MU] * normal, normal / (0.5 * p[o + _W]), xi_x, xi_y, spin)
    # F_y,f acts in the flange's contact plane: cos ϑ_f of it across the track, sin ϑ_f of it upwards
    # on the left flange (downwards on the right, its mirror image).
    vertical += side * fy * np.sin(angle)
    return h + fy * np.cos(angle), vertical, fx, fy, -side * a * fx + mz, xi_x, xi_y


@numba.njit(cache=True, error_model="numpy")
def _tread_loads(p, o, c, y, vertical):
    """The treads' normal loads over W/2, left and right, and the load (N) the flange takes off its tread."""
    if c[_TWO] == 0.0 or vertical == 0.0:
        return 1.0, 1.0, 0.0
    half = 0.5 * p[o + _W]
    lost = min(vertical, half)  # beyond W/2 the tread has lifted: the wheel climbs its flange
    if y > 0.0:
        return 1.0 - lost / half, 1.0, lost
    return 1.0, 1.0 - lost / half, lost


@numba.njit(cache=True, error_model="numpy")
def wheelset(p, o, c, dr, dd, theta_l, theta_r, centred_l, centred_r, y, psi, ydot, psidot, speed):
    """The rails' lateral force (N) and yaw moment (N·m) on the wheelset.

    The wheelset's parameters are p[o:o + 10], the contact's c (:data:`CONTACT_FIELDS`); the geometry is
    at y (Δr, Δϑ, ϑ_L, ϑ_R) and at the centre (ϑ_c,L, ϑ_c,R).
    """
    f_lateral, f_vertical, _, _, f_yaw, _, _ = flange_contact(p, o, c, y, psi, ydot, psidot, speed)
    load_l, load_r, lost = _tread_loads(p, o, c, y, f_vertical)
    _, _, _, left, right = wheels(
        p, o, c[_MU], load_l, load_r, dr, theta_l, theta_r, centred_l, centred_r, psi, ydot, psidot, speed
    )
    W, a = p[o + _W], p[o + _A]
    # The treads' normal forces −Q_L ϑ_L + Q_R ϑ_R: −W Δϑ/2, and back the unloaded tread's share.
    relief = lost * theta_l if y > 0.0 else -lost * theta_r
    lateral = left[1] + right[1] - W / 2.0 * dd + f_lateral + relief
    yaw = a * (right[0] - left[0]) + left[2] + right[2] + W * a * p[o + _THETA0] * psi + f_yaw
    return lateral, yaw


@numba.njit(cache=True, error_model="numpy")
def wheelset_many(p, c, dr, dd, theta_l, theta_r, centred_l, centred_r, y, psi, ydot, psidot, speed):
    """:func:`wheelset` at each entry of 1-D arrays of one size (the centred angles are two floats)."""
    lateral, yaw = np.empty(y.size), np.empty(y.size)
    for i in range(y.size):
        lateral[i], yaw[i] = wheelset(
            p, 0, c, dr[i], dd[i], theta_l[i], theta_r[i], centred_l, centred_r, y[i], psi[i], ydot[i],
            psidot[i], speed[i],
        )  # fmt: skip
    return lateral, yaw


@numba.njit(cache=True, error_model="numpy")
def wheels_many(p, c, dr, theta_l, theta_r, centred_l, centred_r, y, psi, ydot, psidot, speed):
    """Each wheel's forces at each entry of 1-D arrays, rows by wheel [left, right]: F_x of its contacts
    (0, 1), its tread's F_y (2, 3), its flange's lateral force (4, 5) and vertical load (6, 7), and the
    wear number Tγ of its contacts (8, 9)."""
    out = np.zeros((10, psi.size))
    for i in range(psi.size):
        motion = (psi[i], ydot[i], psidot[i], speed[i])
        f_lat, f_vert, f_x, f_y, _, f_xi_x, f_xi_y = flange_contact(p, 0, c, y[i], *motion)
        load_l, load_r, _ = _tread_loads(p, 0, c, y[i], f_vert)
        xi_l, xi_r, xi_y, left, right = wheels(
            p, 0, c[_MU], load_l, load_r, dr[i], theta_l[i], theta_r[i], centred_l, centred_r, *motion
        )
        k = 0 if y[i] > 0.0 else 1  # the wheel whose flange may touch
        out[0, i], out[1, i], out[2, i], out[3, i] = left[0], right[0], left[1], right[1]
        out[0 + k, i] += f_x
        out[4 + k, i], out[6 + k, i] = f_lat, f_vert
        out[8, i] = abs(left[0] * xi_l) + abs(left[1] * xi_y)
        out[9, i] = abs(right[0] * xi_r) + abs(right[1] * xi_y)
        out[8 + k, i] += abs(f_x * f_xi_x) + abs(f_y * f_xi_y)
    return out
