"""The compiled engine of the nonlinear lateral models: their right-hand side in numba, run in batches.

:class:`raildyn.wheelset.NonlinearLateral` (the wheelset, the bogie, the car and the vehicles of
chapter 8, on tangent track or on a :class:`raildyn.track.curve.Curve`) evaluates its right-hand side
with numpy in some 30–60 µs a call, most of it numpy's per-call cost on arrays of four wheelsets.
Here the same equations run compiled: :func:`pack` writes a model at one speed into one row of
floats, and :func:`lateral_rhs` evaluates M q̈ = −C_s q̇ − K_s q + Σ F_contact (− m a_q on a curve)
from that row in about a microsecond. The model hands both to :mod:`raildyn.stability`
(:meth:`~raildyn.wheelset.NonlinearLateral.compiled_rhs`), whose runs go to the compiled runner,
:func:`raildyn.integrators.runner.dormand_prince_batch`, many rows (speeds, parameter sets) at once.
:func:`arc_forces` and :func:`arc_jacobian` are the forces at rest on arcs, a batch of states at a
time, that :meth:`~raildyn.wheelset.NonlinearLateral.arc_forces` returns for a model the engine holds.

The wheel–rail forces are :mod:`raildyn.wheelset._law`'s, the one law the numpy path calls too, with
the geometry of a cone or of a profile pair's tables, and the curve's share of its arc is
:func:`raildyn.track.curve.ramp`. A model says itself whether the engine holds it
(:attr:`~raildyn.wheelset.NonlinearLateral.compiled_reason`): nonlinear suspension elements, whose
force laws are Python functions, and contact functions other than a cone or tables run on numpy.
"""

from __future__ import annotations

import numba
import numpy as np

from raildyn.constants import GRAVITY
from raildyn.integrators.runner import RHS_SIGNATURE
from raildyn.track.curve import ramp
from raildyn.wheelset import _law

# The row of one model at one speed: a header of fixed places, then the arrays at the offsets it gives.
_N, _NW, _SPEED, _CURVED, _START = 0, 1, 2, 3, 4
_CURVE = 5  # s₀, s₁, s₂, s₃ (the ends of the pieces), R, L, h_t, rail spacing: places 5–12
_CONTACT = 13  # the contact's parameters (raildyn.wheelset._law.CONTACT_FIELDS): places 13–18
_DR, _DR_SIZE, _DD, _DD_SIZE = 19, 20, 21, 22  # table offsets and sizes; offset −1: the cone
_MK, _MC, _MINV, _WHEELSETS, _LATERAL = 23, 24, 25, 26, 27  # offsets of M⁻¹K_s, M⁻¹C_s, M⁻¹, …
_K, _MASS = 28, 29  # offsets of K_s and of the lateral mass vector (the forces at rest on an arc)
_TL, _TL_SIZE, _TR, _TR_SIZE = 30, 31, 32, 33  # the tread angles' tables; offset −1: ϑ₀ ± Δϑ/2
_SHARED, _CENTRED = 34, 35  # 1 if the four tables share their shifts; the tables' ϑ_L(0), ϑ_R(0): 35, 36
_HEADER = 37
_N_CONTACT = len(_law.CONTACT_FIELDS)
# One wheelset: its coordinates' places iy and iψ, its place x along the vehicle, then the law's
# parameters (raildyn.wheelset._law.FIELDS).
_PLACES = 3
_WS = _PLACES + len(_law.FIELDS)


def pack(model, speed=None) -> np.ndarray:
    """The row of floats that :func:`lateral_rhs` reads: ``model``, which the engine holds, at ``speed``.

    ``speed`` is V (m/s, already checked) for a run; None (a 0 in the row) for the forces on arcs,
    which take their speeds per state.
    """
    contact, curve = model.contact, model.curve
    tables = [_table(contact.rolling_radius_difference), _table(contact.contact_angle_difference)]
    tables += list(
        (None, None) if contact.tread_angles is None else (_table(t) for t in contact.tread_angles.tables)
    )
    M = model.system.M
    n = M.shape[0]
    M_inv = np.linalg.inv(M)
    positions = model._positions if model._positions is not None else np.zeros(len(model.system.wheelsets))
    rows = [
        [iy, ipsi, float(x), *_law.parameters(ws)]
        for (iy, ipsi, ws), x in zip(model.system.wheelsets, positions, strict=True)
    ]
    pieces = [(M_inv @ model._K_suspension).ravel(), (M_inv @ model._C_suspension).ravel(), M_inv.ravel()]
    pieces += [np.array(rows, dtype=float).ravel(), M_inv @ model._lateral_mass]
    pieces += [np.ravel(model._K_suspension), model._lateral_mass]
    header = np.zeros(_HEADER)
    header[[_N, _NW, _SPEED, _START]] = n, len(rows), 0.0 if speed is None else speed, model.start
    header[_CONTACT : _CONTACT + len(_law.CONTACT_FIELDS)] = _law.contact_parameters(contact)
    if curve is not None:
        header[_CURVED] = 1.0
        header[_CURVE : _CURVE + 8] = (*curve.ends(), curve.radius, curve.transition_length, curve.cant,
                                       curve.rail_spacing)  # fmt: skip
    offset = _HEADER
    for place, piece in zip((_MK, _MC, _MINV, _WHEELSETS, _LATERAL, _K, _MASS), pieces, strict=True):
        header[place] = offset
        offset += piece.size
    for place, table in zip((_DR, _DD, _TL, _TR), tables, strict=True):
        header[place] = -1.0
        if table is not None:
            header[place], header[place + 1] = offset, table[0].size
            pieces.append(np.concatenate(table))
            offset += 2 * table[0].size
    if all(t is not None and np.array_equal(t[0], tables[0][0]) for t in tables):
        header[_SHARED] = 1.0  # one search of the shifts serves all four (profile_contact's tables)
    if contact.tread_angles is not None:
        header[_CENTRED : _CENTRED + 2] = contact.tread_angles(0.0)
    return np.concatenate([header, *pieces])


def _table(fn):
    """(x, f) of a contact table, None for the cone (the model has checked that it is one or the other)."""
    return None if fn is None else (fn.x, fn.f)


def batch(rows) -> np.ndarray:
    """Rows of different lengths as one C array, each padded with zeros to the longest."""
    out = np.zeros((len(rows), max(r.size for r in rows)))
    for i, r in enumerate(rows):
        out[i, : r.size] = r
    return out


# ---------------------------------------------------------------------------
# The compiled equations


@numba.njit(cache=True, error_model="numpy")
def _at(row, place, y):
    """A packed contact table at y."""
    o, m = int(row[place]), int(row[place + 1])
    return _law.table(row[o : o + m], row[o + m : o + 2 * m], y)


@numba.njit(cache=True, error_model="numpy")
def wheel_rail(row, w, y, psi, ydot, psidot, speed):
    """Lateral force (N) and yaw moment (N·m) of the rails on wheelset ``w`` of a packed row."""
    o = int(row[_WHEELSETS]) + _WS * w + _PLACES  # the wheelset's parameters in the row
    if row[_SHARED] > 0.0:
        return _on_tables(row, o, y, psi, ydot, psidot, speed)
    dr, dd = _law.cone(row, o, y)
    if row[_DR] >= 0.0:
        dr = _at(row, _DR, y)
    if row[_DD] >= 0.0:
        dd = _at(row, _DD, y)
    # The tread angles at y and at the centre (whose spins, cancelling, the law takes out).
    if row[_TL] < 0.0:
        dd0 = 0.0 if row[_DD] < 0.0 else _at(row, _DD, 0.0)
        theta_l, theta_r = _law.tread(row, o, dd)
        centred_l, centred_r = _law.tread(row, o, dd0)
    else:
        theta_l, theta_r = _at(row, _TL, y), _at(row, _TR, y)
        centred_l, centred_r = row[_CENTRED], row[_CENTRED + 1]
    c = row[_CONTACT : _CONTACT + _N_CONTACT]
    return _law.wheelset(
        row, o, c, dr, dd, theta_l, theta_r, centred_l, centred_r, y, psi, ydot, psidot, speed
    )


@numba.njit(cache=True, error_model="numpy")
def _on_tables(row, o, y, psi, ydot, psidot, speed):
    """:func:`wheel_rail` on four tables over one set of shifts: y placed once among them."""
    o_dr, m = int(row[_DR]), int(row[_DR_SIZE])
    i, fraction = _law.place(row[o_dr : o_dr + m], y)
    dr = _law.at_place(row[o_dr + m : o_dr + 2 * m], i, fraction)
    dd = _law.at_place(row[int(row[_DD]) + m : int(row[_DD]) + 2 * m], i, fraction)
    theta_l = _law.at_place(row[int(row[_TL]) + m : int(row[_TL]) + 2 * m], i, fraction)
    theta_r = _law.at_place(row[int(row[_TR]) + m : int(row[_TR]) + 2 * m], i, fraction)
    c = row[_CONTACT : _CONTACT + _N_CONTACT]
    return _law.wheelset(row, o, c, dr, dd, theta_l, theta_r, row[_CENTRED], row[_CENTRED + 1], y, psi, ydot,
                         psidot, speed)  # fmt: skip


@numba.njit(cache=True, error_model="numpy")
def _share(row, s):
    """The share of the arc's curvature and cant at s along the packed curve."""
    return ramp(s, row[_CURVE], row[_CURVE + 3], row[_CURVE + 5])


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
        share = _share(row, s_c)
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
            y -= 0.5 * x * x * _share(row, s_c + x / 3.0) / row[_CURVE + 4]
            psi -= x * kappa
            psidot += V * kappa
        fy, mz = wheel_rail(row, w, y, psi, state[n + iy], psidot, V)
        for i in range(n):
            out[n + i] += row[minv + i * n + iy] * fy + row[minv + i * n + ipsi] * mz


@numba.njit(RHS_SIGNATURE, cache=True, error_model="numpy")
def stacked_lateral_rhs(t, y, member, data, out):
    """``lateral_rhs`` on each column of a stacked state, integrated as one system (the shooting's finite
    differences, which must share one sequence of steps). The last row of ``data`` lays the stack out:
    [n, the data row of column 0, of column 1, ...]. Defined here, not built around the kernel where it is
    used, so that numba can cache it: a function that closes over a kernel is compiled in every process.
    """
    layout = data.shape[0] - 1
    n = int(data[layout, 0])
    for c in range(y.size // n):
        lateral_rhs(t, y[c * n : (c + 1) * n], int(data[layout, 1 + c]), data, out[c * n : (c + 1) * n])


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
def arc_forces(row, q, V, kappa, a_q, out):
    """:func:`_arc_forces` of each column of q (n, P) at V[p], κ[p], a_q[p], into ``out`` (n, P)."""
    for p in range(q.shape[1]):
        _arc_forces(row, q[:, p], V[p], kappa[p], a_q[p], out[:, p])  # views, no copies


@numba.njit(cache=True, error_model="numpy")
def arc_jacobian(row, q, V, kappa, a_q, J):
    """:func:`_arc_jacobian` of each column of q (n, P), into ``J`` (P, n, n)."""
    for p in range(q.shape[1]):
        _arc_jacobian(row, q[:, p], V[p], kappa[p], a_q[p], J[p])
