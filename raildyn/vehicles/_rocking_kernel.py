"""The force law and the compiled time march of the rocking freight car (:mod:`raildyn.vehicles.rocking`).

The car is a set of rigid bodies (body, two bolsters, four wheelsets) joined by force *elements*, each
between a point of one body and a point of another (or of the ground: a rail under a wheel). A body
moves by up to four coordinates, its reference point's height z, pitch θ (front up), roll φ (left side
up) and sway y (left); a point at (x, a_y, a_z) from the reference point then stands, to second order
in the angles,

    Z = z + x θ + a_y φ − ½ a_z (θ² + φ²)      (height),
    Y = y − a_z φ − ½ a_y φ²                     (lateral),

so that a load carried by a point above or below the reference point adds its geometric stiffness
(the weight h above the roll axis lowers the roll stiffness by m g h) and the whole is conservative.
An element's deflection is δ = P_B − P_A along its direction, its force f ≥ 0 pushes A by +f and B by
−f, and (``kind``)

* 0, two-sided: f = P₀ + k δ + c δ̇ + F tanh(δ̇/v_ε) (a spring, a weight with k = 0, a friction wedge);
* 1, one-sided (contact): f = max(0, P₀ + k δ + c δ̇) while P₀ + k δ > 0, else 0 (separated), plus the
  same friction term; a gap g is P₀ = −k g.

P₀ is the static preload, so the coordinates are measured from the static equilibrium. Point B is the
weighted mean of two bodies' points (a side frame on its two wheelsets; else the second is the ground
with no weight), plus a rail's height where B stands on the ground under a wheel. The ground is the
last body, all of whose coordinates point at the state's extra last entry, held at 0. :func:`element_forces`
is the one law: the march calls it compiled, the checks and the static solution call it from Python.
Nothing here checks its input; :mod:`raildyn.vehicles.rocking` does.
"""

from __future__ import annotations

import numba
import numpy as np

from raildyn._compiled import formula
from raildyn.vehicles._rocking_coordinates import LABELS  # the 18 coordinates, in the arrays' order

__all__ = ["LABELS", "compiled_forces", "element_forces", "evaluate", "march"]


# Columns of the integer element table.
KIND, DIRECTION, BODY_A, BODY_B, BODY_B2, RAIL = range(6)
# Columns of the float element table.
XA, AYA, AZA, XB, AYB, AZB, WEIGHT_B, STIFFNESS, DAMPING, PRELOAD, FRICTION = range(11)


@formula
def _point(q, v, dofs, body, x, ay, az, direction):
    """Position, rate and the four derivatives (∂/∂z, ∂/∂θ, ∂/∂φ, ∂/∂y) of a point of ``body``.

    A coordinate a body lacks (and every coordinate of the ground) points at the state's last entry,
    which stays 0: no branch on the coordinates, which would cost more than the arithmetic.
    """
    iz, ith, iph, iy = dofs[body, 0], dofs[body, 1], dofs[body, 2], dofs[body, 3]
    z, th, ph, y = q[iz], q[ith], q[iph], q[iy]
    lateral = float(direction)
    vertical = 1.0 - lateral
    pos = vertical * (z + x * th + ay * ph - 0.5 * az * (th * th + ph * ph)) + lateral * (
        y - az * ph - 0.5 * ay * ph * ph
    )
    jz = vertical
    jth = vertical * (x - az * th)
    jph = vertical * (ay - az * ph) + lateral * (-az - ay * ph)
    jy = lateral
    rate = jz * v[iz] + jth * v[ith] + jph * v[iph] + jy * v[iy]
    return pos, rate, jz, jth, jph, jy


@formula
def _load(gen, dofs, body, scale, jz, jth, jph, jy):
    """Add scale × (jz, jθ, jφ, jy) to the generalized forces of ``body``'s coordinates (a missing one's
    share goes to the last entry, which is not a coordinate)."""
    gen[dofs[body, 0]] += scale * jz
    gen[dofs[body, 1]] += scale * jth
    gen[dofs[body, 2]] += scale * jph
    gen[dofs[body, 3]] += scale * jy


@formula
def element_forces(q, v, rail_z, rail_v, dofs, ei, ef, eps, forces, deflections, gen):
    """Every element's force (N) into ``forces``, its deflection (m) into ``deflections``, and the
    generalized forces they put on the coordinates (N or N·m) into ``gen`` (overwritten).

    ``q``, ``v`` and ``gen`` hold one entry more than there are coordinates: ``q`` and ``v`` end in 0 (the
    ground's and every missing coordinate's), ``gen``'s last entry is scratch. ``rail_z`` and ``rail_v``
    end in 0 too (a ground point on no rail).
    """
    gen[:] = 0.0
    for e in range(ei.shape[0]):
        d = ei[e, DIRECTION]
        a, b, b2, rail = ei[e, BODY_A], ei[e, BODY_B], ei[e, BODY_B2], ei[e, RAIL]
        w = ef[e, WEIGHT_B]
        pa, ra, az_, ath, aph, ay_ = _point(q, v, dofs, a, ef[e, XA], ef[e, AYA], ef[e, AZA], d)
        pb, rb, bz, bth, bph, by = _point(q, v, dofs, b, ef[e, XB], ef[e, AYB], ef[e, AZB], d)
        pc, rc, cz, cth, cph, cy = _point(q, v, dofs, b2, ef[e, XB], ef[e, AYB], ef[e, AZB], d)
        delta = w * pb + (1.0 - w) * pc + rail_z[rail] - pa
        rate = w * rb + (1.0 - w) * rc + rail_v[rail] - ra
        elastic = ef[e, PRELOAD] + ef[e, STIFFNESS] * delta
        f = elastic + ef[e, DAMPING] * rate
        if ei[e, KIND] == 1:
            f = max(f, 0.0) if elastic > 0.0 else 0.0
        f += ef[e, FRICTION] * np.tanh(rate / eps)
        forces[e] = f
        deflections[e] = delta
        _load(gen, dofs, a, f, az_, ath, aph, ay_)
        _load(gen, dofs, b, -f * w, bz, bth, bph, by)
        _load(gen, dofs, b2, -f * (1.0 - w), cz, cth, cph, cy)


@numba.njit(cache=True, error_model="numpy")
def compiled_forces(q, v, rail_z, rail_v, dofs, ei, ef, eps, forces, deflections, gen):
    """:func:`element_forces` compiled, for the Python callers that evaluate it many times (the statics)."""
    element_forces(q, v, rail_z, rail_v, dofs, ei, ef, eps, forces, deflections, gen)


@numba.njit(cache=True, error_model="numpy")
def _rails(t, speed, behind, rail_length, spacing, table, rail_z, rail_v):
    """The left and right rail heights (m) and rates (m/s) under each wheelset at time t."""
    n = table.shape[1] - 1
    for j in range(behind.size):  # rail_z[-1] and rail_v[-1] stay 0
        s = speed * t - behind[j]
        u = (s - rail_length * np.floor(s / rail_length)) / spacing
        i = min(int(u), n - 1)
        frac = u - i
        for side in range(2):
            rail_z[2 * j + side] = table[side, i] + frac * (table[side, i + 1] - table[side, i])
            rail_v[2 * j + side] = speed * (
                table[2 + side, i] + frac * (table[2 + side, i + 1] - table[2 + side, i])
            )


@numba.njit(cache=True, error_model="numpy")
def _acceleration(
    t,
    q,
    v,
    mass,
    dofs,
    ei,
    ef,
    eps,
    speed,
    behind,
    rail_length,
    spacing,
    table,
    rail_z,
    rail_v,
    forces,
    deflections,
    gen,
    out,
):
    _rails(t, speed, behind, rail_length, spacing, table, rail_z, rail_v)
    element_forces(q, v, rail_z, rail_v, dofs, ei, ef, eps, forces, deflections, gen)
    for i in range(mass.size):
        out[i] = gen[i] / mass[i]


@numba.njit(cache=True, error_model="numpy")
def march(
    mass,
    dofs,
    ei,
    ef,
    eps,
    speed,
    behind,
    rail_length,
    spacing,
    table,
    dt,
    steps,
    stride,
    tail,
    q0,
    v0,
    watched,
    roll_dof,
    hist_forces,
    hist_roll,
    hist_state,
    extremes,
    counts,
):
    """RK4 over ``steps`` steps of ``dt`` s at ``speed`` m/s from (q0, v0).

    Every ``stride`` steps the forces of the ``watched`` elements go to ``hist_forces``, the roll to
    ``hist_roll`` and, if ``hist_state`` has a row for each sample, the coordinates and their rates to it
    (n_out, 2n). From step ``tail`` on, ``extremes`` (2, n_watched) keeps each watched force's least and
    greatest value and the roll's least and greatest (its last column pair), and ``counts`` the steps
    in which each watched force is zero (``counts[:n_watched]``), in which one of the wheels (watched 0-7)
    is, one of the plate edges (8-11) is, and one of the side bearers (12-15) is loaded (the last three).
    Returns −1, or the first step whose state is not finite.

    The state arrays hold one entry more than the n coordinates, held at 0 (:func:`element_forces`).
    """
    n = q0.size
    q, v = np.zeros(n + 1), np.zeros(n + 1)
    for i in range(n):  # element by element: ARCHITECTURE.md, compiled kernels
        q[i] = q0[i]
        v[i] = v0[i]
    nw = watched.size
    rail_z, rail_v = np.zeros(2 * behind.size + 1), np.zeros(2 * behind.size + 1)
    forces, deflections, gen = np.zeros(ei.shape[0]), np.zeros(ei.shape[0]), np.zeros(n + 1)
    kq, kv = np.zeros((4, n + 1)), np.zeros((4, n + 1))  # RK4's four stages of q̇ and v̇
    qs, vs = np.zeros(n + 1), np.zeros(n + 1)
    extremes[0, :] = np.inf
    extremes[1, :] = -np.inf
    counts[:] = 0
    out = 0
    for step in range(steps + 1):
        t = step * dt
        _acceleration(t, q, v, mass, dofs, ei, ef, eps, speed, behind, rail_length, spacing, table, rail_z,
                      rail_v, forces, deflections, gen, kv[0])  # fmt: skip
        finite = True
        for i in range(n):
            if not (np.isfinite(q[i]) and np.isfinite(v[i]) and np.isfinite(kv[0, i])):
                finite = False
        if not finite:
            return step
        if step % stride == 0:
            for k in range(nw):
                hist_forces[out, k] = forces[watched[k]]
            hist_roll[out] = q[roll_dof]
            if hist_state.shape[0] > out:
                for i in range(n):
                    hist_state[out, i] = q[i]
                    hist_state[out, n + i] = v[i]
            out += 1
        if step >= tail:
            wheel, plate, bearer = False, False, False
            for k in range(nw):
                f = forces[watched[k]]
                extremes[0, k] = min(extremes[0, k], f)
                extremes[1, k] = max(extremes[1, k], f)
                if f <= 0.0:
                    counts[k] += 1
                    if k < 8:
                        wheel = True
                    elif k < 12:
                        plate = True
                elif k >= 12:
                    bearer = True
            extremes[0, nw] = min(extremes[0, nw], q[roll_dof])
            extremes[1, nw] = max(extremes[1, nw], q[roll_dof])
            counts[nw] += wheel
            counts[nw + 1] += plate
            counts[nw + 2] += bearer
        if step == steps:
            break
        # RK4 on (q, v): k_q = v, k_v = a(t, q, v); stages 2-4 from the one before, at ½, ½ and 1 step.
        for i in range(n):
            kq[0, i] = v[i]
        for stage in range(1, 4):
            c = 0.5 if stage < 3 else 1.0
            for i in range(n):
                qs[i] = q[i] + c * dt * kq[stage - 1, i]
                vs[i] = v[i] + c * dt * kv[stage - 1, i]
            _acceleration(t + c * dt, qs, vs, mass, dofs, ei, ef, eps, speed, behind, rail_length, spacing,
                          table, rail_z, rail_v, forces, deflections, gen, kv[stage])  # fmt: skip
            for i in range(n):
                kq[stage, i] = vs[i]
        for i in range(n):
            q[i] += dt / 6.0 * (kq[0, i] + 2.0 * kq[1, i] + 2.0 * kq[2, i] + kq[3, i])
            v[i] += dt / 6.0 * (kv[0, i] + 2.0 * kv[1, i] + 2.0 * kv[2, i] + kv[3, i])
    return -1


def evaluate(car, q, v, rail_z, rail_v):
    """(generalized forces (18,), element forces, element deflections) of a
    :class:`~raildyn.vehicles.rocking.RockingFreightCar` in state (q, v) on rails (rail_z, rail_v), by the
    law called from numpy."""
    mass, dofs, ei, ef, _ = car._tables()
    element, deflection, gen = np.zeros(len(ei)), np.zeros(len(ei)), np.zeros(19)
    compiled_forces(
        np.append(q, 0.0),
        np.append(v, 0.0),
        np.append(rail_z, 0.0),
        np.append(rail_v, 0.0),
        dofs,
        ei,
        ef,
        car.velocity_scale,
        element,
        deflection,
        gen,
    )
    return gen[:18], element, deflection
