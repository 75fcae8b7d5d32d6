"""The compiled engine of the nonlinear lateral models: their right-hand side in numba, run in batches.

:class:`raildyn.wheelset.NonlinearWheelset` and :class:`raildyn.wheelset.NonlinearLateral` (the
bogie, the car and the vehicles of chapter 8 on tangent track or on a
:class:`raildyn.track.curve.Curve`) evaluate their right-hand side with numpy, some 30–60 µs a
call, most of it numpy's per-call cost on arrays of four wheelsets. Here the same equations are
compiled: :func:`pack` writes a model at one speed into one row of floats, and :func:`lateral_rhs`
evaluates M q̈ = −C_s q̇ − K_s q + Σ F_contact (− m a_q on a curve) from that row in about a
microsecond. It is the right-hand side that :mod:`raildyn.stability.nonlinear` hands the compiled
runner, :func:`raildyn.integrators.runner.dormand_prince_batch`, which advances many rows (speeds,
parameter sets) at once.

The wheel–rail forces are those of :func:`raildyn.wheelset.contact_forces`, term for term: each
wheel's creepages of :func:`raildyn.contact.creepages.wheelset_creepages` with r = r₀ ± Δr(y)/2 and its
tread angle ϑ(y), Kalker's linear forces scaled by :func:`raildyn.contact.saturation.saturation_factor`,
gravity through Δϑ(y), and the flange spring beyond the clearance; Δr, Δϑ and the tread angles
from the cone or from the tables of :func:`raildyn.wheelset.profile_contact`. A model this engine
cannot hold (nonlinear suspension elements, whose force laws are Python functions, or contact
functions other than a cone or a table) is reported by :func:`pack` raising :class:`NotCompiled`,
and its callers take scipy's path. The tests hold this engine to the numpy right-hand side and to
scipy's integration of it.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from raildyn.constants import GRAVITY
from raildyn.integrators.runner import RHS_SIGNATURE

# The row of one model at one speed: a header of fixed places, then the arrays at the offsets it gives.
_N, _NW, _SPEED, _CURVED, _START = 0, 1, 2, 3, 4
_CURVE = 5  # s₀, s₁, s₂, s₃ (the ends of the pieces), R, L, h_t, rail spacing: places 5–12
_FRICTION, _CLEARANCE, _FLANGE = 13, 14, 15
_DR, _DR_SIZE, _DD, _DD_SIZE = 16, 17, 18, 19  # table offsets and sizes; offset −1: the cone
_MK, _MC, _MINV, _WHEELSETS, _LATERAL = 20, 21, 22, 23, 24  # offsets of M⁻¹K_s, M⁻¹C_s, M⁻¹, …
_K, _MASS = 25, 26  # offsets of K_s and of the lateral mass vector (the forces at rest on an arc)
_TL, _TL_SIZE, _TR, _TR_SIZE = 27, 28, 29, 30  # the tread angles' tables; offset −1: ϑ₀ ± Δϑ/2
_HEADER = 31
# One wheelset's fields, in this order, from its offset.
_FIELDS = ("iy", "ipsi", "x", "a", "r0", "f11", "f22", "f23", "f33", "W", "eps", "theta0", "lam")
_WS = len(_FIELDS)


class NotCompiled(Exception):
    """The model holds something the engine cannot compile: it is run on scipy's path instead."""


def _table(contact, name):
    """(x, f) of a contact table, or None for the cone; NotCompiled for any other function."""
    from raildyn.wheelset import ContactTable

    fn = getattr(contact, name)
    if fn is None:
        return None
    if type(fn) is not ContactTable:
        raise NotCompiled(f"contact {name} is a Python function, not a profile table")
    return fn.x, fn.f


def _tread_tables(contact):
    """The (x, f) tables of ϑ_L and ϑ_R, or (None, None) without tread angles; NotCompiled for a function."""
    from raildyn.wheelset import ContactTable, ContactTables

    fn = contact.tread_angles
    if fn is None:
        return None, None
    if (
        type(fn) is not ContactTables
        or len(fn.tables) != 2
        or any(type(t) is not ContactTable for t in fn.tables)
    ):
        raise NotCompiled("contact tread_angles is a Python function, not two profile tables")
    return tuple((t.x, t.f) for t in fn.tables)


def _parts(model):
    """M, K_s, C_s, the wheelsets [(iy, iψ, x, Wheelset)], the lateral mass vector, contact, curve, start."""
    from raildyn.wheelset import NonlinearLateral, NonlinearWheelset

    if type(model) is NonlinearWheelset:
        ws = model.wheelset
        return (
            np.diag([ws.mass, ws.yaw_inertia]),
            np.diag([ws.lateral_stiffness, ws.yaw_stiffness]),
            np.diag([ws.lateral_damping, ws.yaw_damping]),
            [(0, 1, 0.0, ws)],
            np.array([ws.mass, 0.0]),
            model.contact,
            None,
            0.0,
        )
    if type(model) is not NonlinearLateral:
        raise NotCompiled(f"{type(model).__name__} is not a model the engine knows")
    if model.elements:
        raise NotCompiled("nonlinear suspension elements have force laws in Python")
    positions = model._positions if model._positions is not None else np.zeros(len(model.system.wheelsets))
    wheelsets = [
        (iy, ipsi, float(x), ws) for (iy, ipsi, ws), x in zip(model.system.wheelsets, positions, strict=True)
    ]
    return (
        model.system.M,
        model._K_suspension,
        model._C_suspension,
        wheelsets,
        model._lateral_mass,
        model.contact,
        model.curve,
        model.start,
    )


def pack(model) -> np.ndarray:
    """The row of floats that :func:`lateral_rhs` reads: ``model`` (already checked) at its speed.

    Raises
    ------
    NotCompiled
        If the model holds nonlinear suspension elements or contact functions other than tables.
    """
    M, K, C, wheelsets, lateral_mass, contact, curve, start = _parts(model)
    dr, dd = _table(contact, "rolling_radius_difference"), _table(contact, "contact_angle_difference")
    tl, tr = _tread_tables(contact)
    n = M.shape[0]
    M_inv = np.linalg.inv(M)
    pieces = [(M_inv @ K).ravel(), (M_inv @ C).ravel(), M_inv.ravel()]
    rows = []
    for iy, ipsi, x, ws in wheelsets:
        rows.append(
            [iy, ipsi, x, ws.half_gauge, ws.rolling_radius, ws.f11, ws.f22, ws.f23, ws.f33, ws.axle_load]
            + [ws.contact_angle_parameter, ws.contact_angle, ws.conicity]
        )
    pieces += [np.array(rows, dtype=float).ravel(), M_inv @ lateral_mass, np.ravel(K), lateral_mass]
    header = np.zeros(_HEADER)
    header[[_N, _NW, _SPEED, _START]] = n, len(wheelsets), model.speed, start
    header[[_FRICTION, _CLEARANCE, _FLANGE]] = (
        contact.friction,
        contact.flange_clearance,
        contact.flange_stiffness,
    )
    if curve is not None:
        header[_CURVED] = 1.0
        header[_CURVE : _CURVE + 8] = (*curve._ends(), curve.radius, curve.transition_length, curve.cant,
                                       curve.rail_spacing)  # fmt: skip
    offset = _HEADER
    for place, piece in zip((_MK, _MC, _MINV, _WHEELSETS, _LATERAL, _K, _MASS), pieces, strict=True):
        header[place] = offset
        offset += piece.size
    for place, table in ((_DR, dr), (_DD, dd), (_TL, tl), (_TR, tr)):
        header[place] = -1.0
        if table is not None:
            header[place], header[place + 1] = offset, table[0].size
            pieces.append(np.concatenate(table))
            offset += 2 * table[0].size
    return np.concatenate([header, *pieces])


def batch(rows) -> np.ndarray:
    """Rows of different lengths as one C array, each padded with zeros to the longest."""
    out = np.zeros((len(rows), max(r.size for r in rows)))
    for i, r in enumerate(rows):
        out[i, : r.size] = r
    return out


# ---------------------------------------------------------------------------
# The compiled equations


@numba.njit(cache=True, error_model="numpy")
def _interp(row, offset, size, y):
    """A contact table at y: linear between its points, along its end slopes beyond (as ``ContactTable``)."""
    o = int(offset)
    m = int(size)
    x0, x1 = row[o], row[o + m - 1]
    f = o + m
    if y <= x0:
        return row[f] + (row[f + 1] - row[f]) / (row[o + 1] - x0) * (y - x0)
    if y >= x1:
        return row[f + m - 1] + (row[f + m - 1] - row[f + m - 2]) / (x1 - row[o + m - 2]) * (y - x1)
    lo, hi = 0, m - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if row[o + mid] <= y:
            lo = mid
        else:
            hi = mid
    xa, xb = row[o + lo], row[o + lo + 1]
    return row[f + lo] + (row[f + lo + 1] - row[f + lo]) * (y - xa) / (xb - xa)


@numba.njit(cache=True, error_model="numpy")
def _wheel(f11, f22, f23, f33, limit, xi_x, xi_y, spin):
    """One wheel's saturated creep forces F_x, F_y and moment M_z (as ``raildyn.wheelset.contact_forces``).

    Kalker's linear forces scaled by Shen–Hedrick–Elkins at the limit μW/2 (``saturation_factor``).
    """
    fx = -f11 * xi_x
    fy = -f22 * xi_y - f23 * spin
    mz = f23 * xi_y - f33 * spin
    u = math.hypot(fx, fy) / limit
    scale = 1.0
    if u > 0.0:
        v = min(u, 3.0)
        scale = (v - v * v / 3.0 + v * v * v / 27.0) / u
    return scale * fx, scale * fy, scale * mz


@numba.njit(cache=True, error_model="numpy")
def wheel_rail(row, w, y, psi, ydot, psidot, speed):
    """Lateral force (N) and yaw moment (N·m) of the rails on wheelset ``w`` of a packed row."""
    k = int(row[_WHEELSETS]) + _WS * w
    a, r0, f11, f22, f23, f33 = row[k + 3], row[k + 4], row[k + 5], row[k + 6], row[k + 7], row[k + 8]
    W, eps, theta0, lam = row[k + 9], row[k + 10], row[k + 11], row[k + 12]
    dr = 2.0 * lam * y if row[_DR] < 0.0 else _interp(row, row[_DR], row[_DR_SIZE], y)
    dd = 2.0 * eps * y / a if row[_DD] < 0.0 else _interp(row, row[_DD], row[_DD_SIZE], y)
    # The tread angles at y and at the centre (whose spins, cancelling, contact_forces takes out).
    if row[_TL] < 0.0:
        dd0 = 0.0 if row[_DD] < 0.0 else _interp(row, row[_DD], row[_DD_SIZE], 0.0)
        theta_l, theta_r = theta0 + 0.5 * dd, theta0 - 0.5 * dd
        centred_l, centred_r = theta0 + 0.5 * dd0, theta0 - 0.5 * dd0
    else:
        theta_l = _interp(row, row[_TL], row[_TL_SIZE], y)
        theta_r = _interp(row, row[_TR], row[_TR_SIZE], y)
        centred_l = _interp(row, row[_TL], row[_TL_SIZE], 0.0)
        centred_r = _interp(row, row[_TR], row[_TR_SIZE], 0.0)
    # Each wheel's creepages, as wheelset_creepages with r = r₀ ± Δr/2 and the tread angles.
    yaw = a * psidot / speed
    xi_y = ydot / speed - psi
    spin = psidot / speed
    limit = row[_FRICTION] * W / 2.0
    spin_l = spin * math.cos(theta_l) - math.sin(theta_l) / r0 + math.sin(centred_l) / r0
    spin_r = spin * math.cos(theta_r) + math.sin(theta_r) / r0 - math.sin(centred_r) / r0
    fx_l, fy_l, mz_l = _wheel(f11, f22, f23, f33, limit, (r0 - (r0 + 0.5 * dr)) / r0 - yaw, xi_y, spin_l)
    fx_r, fy_r, mz_r = _wheel(f11, f22, f23, f33, limit, (r0 - (r0 - 0.5 * dr)) / r0 + yaw, xi_y, spin_r)
    flange = 0.0
    excess = abs(y) - row[_CLEARANCE]
    if excess > 0.0:
        flange = -row[_FLANGE] * excess * (1.0 if y > 0.0 else -1.0)
    lateral = fy_l + fy_r - W / 2.0 * dd + flange
    yaw_moment = a * (fx_r - fx_l) + mz_l + mz_r + W * a * theta0 * psi
    return lateral, yaw_moment


@numba.njit(cache=True, error_model="numpy")
def _ramp(row, s):
    """The share of the arc's curvature and cant at s along the packed curve, in [0, 1].

    0 on the straights, rising linearly along the entry transition, 1 on the arc and falling along
    the exit: κ = share/R (:meth:`raildyn.track.curve.Curve.curvature`) and h_t = share·h_t of
    the arc (:meth:`raildyn.track.curve.Curve.cant_at`).
    """
    s0, s1, s2, s3, L = row[_CURVE], row[_CURVE + 1], row[_CURVE + 2], row[_CURVE + 3], row[_CURVE + 5]
    if s <= s0 or s > s3:
        return 0.0
    if s <= s1:
        return (s - s0) / L
    if s <= s2:
        return 1.0
    return (s3 - s) / L


@numba.njit(RHS_SIGNATURE, cache=True, error_model="numpy")
def lateral_rhs(t, state, member, data, out):
    """d/dt [q; q̇] of the packed model in row ``member`` of ``data`` (the equations of ``rhs``)."""
    row = data[member]
    n, nw, V = int(row[_N]), int(row[_NW]), row[_SPEED]
    mk, mc, minv = int(row[_MK]), int(row[_MC]), int(row[_MINV])
    for i in range(n):
        out[i] = state[n + i]
        acc = 0.0
        for j in range(n):
            acc -= row[mk + i * n + j] * state[j] + row[mc + i * n + j] * state[n + j]
        out[n + i] = acc
    curved = row[_CURVED] > 0.0
    kappa = 0.0
    s_c = 0.0
    if curved:
        s_c = row[_START] + V * t
        share = _ramp(row, s_c)
        kappa = share / row[_CURVE + 4]
        a_q = V * V * kappa - GRAVITY * share * row[_CURVE + 6] / row[_CURVE + 7]
        lat = int(row[_LATERAL])
        for i in range(n):
            out[n + i] -= row[lat + i] * a_q
    base = int(row[_WHEELSETS])
    for w in range(nw):
        k = base + _WS * w
        iy, ipsi = int(row[k]), int(row[k + 1])
        y, psi, psidot = state[iy], state[ipsi], state[n + ipsi]
        if curved:
            x = row[k + 2]
            y -= 0.5 * x * x * _ramp(row, s_c + x / 3.0) / row[_CURVE + 4]
            psi -= x * kappa
            psidot += V * kappa
        fy, mz = wheel_rail(row, w, y, psi, state[n + iy], psidot, V)
        for i in range(n):
            out[n + i] += row[minv + i * n + iy] * fy + row[minv + i * n + ipsi] * mz


@numba.njit(cache=True, error_model="numpy")
def _arc_forces(row, q, V, kappa, a_q, out):
    """The generalized forces at rest on an arc into ``out`` (as ``NonlinearLateral.arc_forces``)."""
    n, k_s, mass = int(row[_N]), int(row[_K]), int(row[_MASS])
    for i in range(n):
        acc = -row[mass + i] * a_q
        for j in range(n):
            acc -= row[k_s + i * n + j] * q[j]
        out[i] = acc
    base = int(row[_WHEELSETS])
    for w in range(int(row[_NW])):
        k = base + _WS * w
        iy, ipsi, x = int(row[k]), int(row[k + 1]), row[k + 2]
        fy, mz = wheel_rail(row, w, q[iy] - 0.5 * x * x * kappa, q[ipsi] - x * kappa, 0.0, V * kappa, V)
        out[iy] += fy
        out[ipsi] += mz


@numba.njit(cache=True, error_model="numpy")
def _arc_jacobian(row, q, V, kappa, a_q, J):
    """∂F/∂q of :func:`_arc_forces` into ``J``: −K_s, and each wheelset's 2 × 2 contact block by forward
    differences of 1e-7 m (rad), as ``NonlinearLateral.arc_jacobian``."""
    n, k_s = int(row[_N]), int(row[_K])
    h = 1.0e-7
    for i in range(n):
        for j in range(n):
            J[i, j] = -row[k_s + i * n + j]
    base = int(row[_WHEELSETS])
    for w in range(int(row[_NW])):
        k = base + _WS * w
        iy, ipsi, x = int(row[k]), int(row[k + 1]), row[k + 2]
        y, psi, rate = q[iy] - 0.5 * x * x * kappa, q[ipsi] - x * kappa, V * kappa
        fy, mz = wheel_rail(row, w, y, psi, 0.0, rate, V)
        fy_y, mz_y = wheel_rail(row, w, y + h, psi, 0.0, rate, V)
        fy_p, mz_p = wheel_rail(row, w, y, psi + h, 0.0, rate, V)
        J[iy, iy] += (fy_y - fy) / h
        J[ipsi, iy] += (mz_y - mz) / h
        J[iy, ipsi] += (fy_p - fy) / h
        J[ipsi, ipsi] += (mz_p - mz) / h


@numba.njit(cache=True, error_model="numpy")
def _merit(r):
    total = 0.0
    for i in range(r.size):
        total += r[i] * r[i]
    return total


@numba.njit(cache=True, error_model="numpy")
def _max_abs(r):
    """max |r|, inf where an entry is not a number (a residual that is nowhere near converged)."""
    out = 0.0
    for i in range(r.size):
        if math.isnan(r[i]):
            return np.inf
        out = max(out, abs(r[i]))
    return out


@numba.njit(cache=True, error_model="numpy")
def _solve_small(J, r, step):
    """step = −J⁻¹ r by Gaussian elimination with partial pivoting, J overwritten; False if singular.

    A few dozen unknowns at most: elimination in place costs less than a call to LAPACK and its
    copies, at every Newton step of every point of a map.
    """
    n = r.size
    for i in range(n):
        step[i] = -r[i]
    for c in range(n):
        pivot, big = c, abs(J[c, c])
        for i in range(c + 1, n):
            if abs(J[i, c]) > big:
                pivot, big = i, abs(J[i, c])
        if not big > 1e-300:  # zero or not a number
            return False
        if pivot != c:
            for j in range(n):
                J[c, j], J[pivot, j] = J[pivot, j], J[c, j]
            step[c], step[pivot] = step[pivot], step[c]
        for i in range(c + 1, n):
            f = J[i, c] / J[c, c]
            if f != 0.0:
                for j in range(c, n):
                    J[i, j] -= f * J[c, j]
                step[i] -= f * step[c]
    for i in range(n - 1, -1, -1):
        acc = step[i]
        for j in range(i + 1, n):
            acc -= J[i, j] * step[j]
        step[i] = acc / J[i, i]
    for i in range(n):
        if not math.isfinite(step[i]):
            return False
    return True


@numba.njit(cache=True, error_model="numpy")
def arc_newton(row, q, V, kappa, a_q, tolerance, steps, done):
    """Newton's method on each column of ``q`` (n, P), in place, towards the rest states on arcs.

    Column p solves ``_arc_forces`` = 0 at V[p], κ[p], a_q[p]: at most ``steps`` Newton steps,
    each halved up to eleven times until the sum of squared residuals falls (the line search of
    :func:`raildyn.curving.quasi_static._newton`, column by column); a column stops where no step
    improves it or its Jacobian is singular. ``done[p]`` is set where every residual is within
    ``tolerance`` (N).
    """
    n, P = q.shape
    x, trial, r, r_trial, step = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    J = np.empty((n, n))
    for p in range(P):
        for i in range(n):
            x[i] = q[i, p]
        _arc_forces(row, x, V[p], kappa[p], a_q[p], r)
        for _ in range(steps):
            if not _max_abs(r) > tolerance:
                break
            _arc_jacobian(row, x, V[p], kappa[p], a_q[p], J)
            if not _solve_small(J, r, step):  # singular: the other searches take this point over
                break
            merit = _merit(r)
            alpha = 1.0
            better = False
            for _ in range(12):
                for i in range(n):
                    trial[i] = x[i] + alpha * step[i]
                _arc_forces(row, trial, V[p], kappa[p], a_q[p], r_trial)
                if _merit(r_trial) < merit:
                    better = True
                    break
                alpha *= 0.5
            if not better:
                break
            for i in range(n):
                x[i] = trial[i]
                r[i] = r_trial[i]
        for i in range(n):
            q[i, p] = x[i]
        done[p] = _max_abs(r) <= tolerance
