"""The time march of wheels on a discrete track, compiled with numba.

Newmark's average-acceleration rule (unconditionally stable, no numerical damping) on the track's
banded matrices and on the vehicle above (the wheels' unsprung masses and whatever rides on them, a
small linear block), both linear, joined by a Hertz spring under each wheel, which is not. The step's
effective stiffnesses are the same at every step, so each is factored (the block's inverted) once;
each step then solves once for the motion without the contact forces and adds the response to each
contact force, whose columns (one per rail unknown a wheel can stand on) are solved before the march.
What is left is one equation per wheel in the contact forces,

    F_i = C_H max(δ*_i − Σ_k A_ik F_k, 0)^{3/2},

each increasing in its own F_i and concave, which a Newton iteration kept inside its bracket solves
to round-off; the wheels' small coupling (through the rail between them and the vehicle above) is
met by sweeping over them until no force moves. :func:`raildyn.bridge.impact.wheel_on_track` checks
every input and documents the equations; nothing here checks anything.
"""

from __future__ import annotations

import numba
import numpy as np

from raildyn.bridge._band import band_factor, band_solve

__all__ = ["influence", "march"]


@numba.njit(cache=True)
def _matvec(ab, x, out):
    """out = A x for a symmetric A stored by diagonals."""
    p, n = ab.shape[0] - 1, ab.shape[1]
    for i in range(n):
        out[i] = ab[0, i] * x[i]
    for k in range(1, p + 1):
        for j in range(n - k):
            out[j + k] += ab[k, j] * x[j]
            out[j] += ab[k, j] * x[j + k]


@numba.njit(cache=True)
def influence(effective, columns):
    """Factor the effective stiffness in place and solve for a unit load at each of ``columns``."""
    band_factor(effective)
    n = effective.shape[1]
    out = np.zeros((columns.size, n))
    for c in range(columns.size):
        out[c, columns[c]] = 1.0
        band_solve(effective, out[c])
    return out


@numba.njit(cache=True)
def _contact(delta, c, hertz, guess):
    """The F ≥ 0 with F = C_H max(δ − cF, 0)^{3/2}; −1.0 if it is not finite."""
    if not (delta > 0.0):
        return 0.0 if delta <= 0.0 else -1.0
    lo, hi = 0.0, hertz * delta**1.5
    if not np.isfinite(hi):
        return -1.0
    f = min(max(guess, lo), hi)
    for _ in range(60):
        gap = delta - c * f
        r = f - hertz * max(gap, 0.0) ** 1.5
        if abs(r) <= 1e-12 * hi or hi - lo <= 1e-14 * hi:
            break
        if r > 0.0:
            hi = f
        else:
            lo = f
        slope = 1.0 + 1.5 * hertz * c * max(gap, 0.0) ** 0.5
        step = f - r / slope
        f = step if lo <= step <= hi else 0.5 * (lo + hi)
    return f if np.isfinite(f) else -1.0


@numba.njit(cache=True)
def _contacts(star, coupling, hertz, force):
    """Solve every wheel's contact equation together (sweeps of the one-wheel solve).

    Returns 0 when solved, 1 when a force is not finite, 2 when the sweeps do not settle."""
    n = star.size
    for _ in range(100):
        moved = 0.0
        for i in range(n):
            delta = star[i]
            for k in range(n):
                if k != i:
                    delta -= coupling[i, k] * force[k]
            f = _contact(delta, coupling[i, i], hertz[i], force[i])
            if f < 0.0:
                return 1
            moved = max(moved, abs(f - force[i]))
            force[i] = f
        if n == 1 or moved <= 1e-10 * (1.0 + np.max(np.abs(force))):
            return 0
    return 2


@numba.njit(cache=True)
def march(mass, damping, stiffness, factor, columns, column_of, dofs, weights, slopes, irregularity, slope_r,
          speed, block_mass, block_damping, block_stiffness, contact_dofs, static_loads, origin, hertz,
          dt, u, v, a, x, xd, xdd, force, record_every, pad_rows, sleeper_rows, pad_k, pad_c, ballast_k,
          ballast_c, out_force, out_wheel, out_rail, out_pad, out_ballast, out_energy, out_work,
          out_dissipated):  # fmt: skip
    """Advance the track (u, v, a), the vehicle block (x, xd, xdd: up positive, from the static state)
    and the contact forces over the steps.

    At step n wheel i stands on ``dofs[n, i]`` with shape ``weights[n, i]`` (slope weights ``slopes``)
    and meets r = ``irregularity[n, i]`` (dr/dx ``slope_r``); its down position is
    ``origin[i] − x[contact_dofs[i]]``. Records every ``record_every`` steps; the energy recorded is
    the system's total (kinetic, strain, the static loads' potential). Returns (steps done, status):
    status 0 done, 1 a non-finite contact force, 2 contact forces that would not settle.
    """
    n, nw = u.size, force.size
    steps = dofs.shape[0] - 1
    a0, a1 = 4.0 / (dt * dt), 2.0 / dt
    rhs, tmp, work_n = np.empty(n), np.empty(n), np.empty(n)
    g = np.empty((nw, n))
    star, coupling = np.empty(nw), np.empty((nw, nw))
    block_inverse = np.linalg.inv(block_stiffness + a0 * block_mass + a1 * block_damping)
    rail = np.empty(nw)
    power_prev = loss_prev = dissipated = work = 0.0
    rec = 0
    for step in range(steps + 1):
        if step > 0:
            # The track without the contact forces: M(a0 u + 4/dt v + a) + C(a1 u + v), solved.
            for i in range(n):
                tmp[i] = a0 * u[i] + 4.0 / dt * v[i] + a[i]
            _matvec(mass, tmp, rhs)
            for i in range(n):
                tmp[i] = a1 * u[i] + v[i]
            _matvec(damping, tmp, work_n)
            for i in range(n):
                rhs[i] += work_n[i]
            band_solve(factor, rhs)  # u*
            # Each wheel's response of the track to its unit force (down on the rail).
            for w in range(nw):
                for i in range(n):
                    g[w, i] = 0.0
                for k in range(4):
                    col = column_of[dofs[step, w, k]]
                    for i in range(n):
                        g[w, i] += weights[step, w, k] * columns[col, i]
            # The block without the contact forces (the static loads pull its wheels down).
            bx = block_mass @ (a0 * x + 4.0 / dt * xd + xdd) + block_damping @ (a1 * x + xd)
            for w in range(nw):
                bx[contact_dofs[w]] -= static_loads[w]
            x_star = block_inverse @ bx
            for i in range(nw):
                rail_star = 0.0
                for k in range(4):
                    rail_star += weights[step, i, k] * rhs[dofs[step, i, k]]
                star[i] = origin[i] - x_star[contact_dofs[i]] - rail_star - irregularity[step, i]
                for w in range(nw):
                    on_rail = 0.0
                    for k in range(4):
                        on_rail += weights[step, i, k] * g[w, dofs[step, i, k]]
                    # F_w lifts the block at its wheel (up) and presses the rail under it (down).
                    coupling[i, w] = on_rail + block_inverse[contact_dofs[i], contact_dofs[w]]
            status = _contacts(star, coupling, hertz, force)
            if status:
                return step, status
            for i in range(n):
                un = rhs[i]
                for w in range(nw):
                    un += g[w, i] * force[w]
                an = a0 * (un - u[i]) - 4.0 / dt * v[i] - a[i]
                v[i] += 0.5 * dt * (a[i] + an)
                a[i] = an
                u[i] = un
            xn = x_star.copy()
            for w in range(nw):
                xn += block_inverse[:, contact_dofs[w]] * force[w]
            an_b = a0 * (xn - x) - 4.0 / dt * xd - xdd
            xd += 0.5 * dt * (xdd + an_b)
            for i in range(xn.size):  # element by element: ARCHITECTURE.md, compiled kernels
                xdd[i] = an_b[i]
                x[i] = xn[i]
        # Power fed in by the rolling (the rail's slope and the irregularity passing under each wheel),
        # and the dampers' loss, integrated by the trapezoidal rule as Newmark's rule integrates them.
        power = 0.0
        for i in range(nw):
            rail_slope = 0.0
            rail[i] = 0.0
            for k in range(4):
                rail_slope += slopes[step, i, k] * u[dofs[step, i, k]]
                rail[i] += weights[step, i, k] * u[dofs[step, i, k]]
            power -= force[i] * speed * (rail_slope + slope_r[step, i])
        _matvec(damping, v, tmp)
        loss = xd @ (block_damping @ xd)
        for i in range(n):
            loss += v[i] * tmp[i]
        if step > 0:
            work += 0.5 * dt * (power + power_prev)
            dissipated += 0.5 * dt * (loss + loss_prev)
        power_prev, loss_prev = power, loss
        if step % record_every == 0:
            for i in range(nw):
                out_force[rec, i] = force[i]
                out_wheel[rec, i] = origin[i] - x[contact_dofs[i]]
                out_rail[rec, i] = rail[i]
            for j in range(pad_rows.size):
                r, s = pad_rows[j], sleeper_rows[j]
                out_pad[rec, j] = pad_k * (u[r] - u[s]) + pad_c * (v[r] - v[s])
                out_ballast[rec, j] = ballast_k * u[s] + ballast_c * v[s]
            # The energy: kinetic, strain (track, block, Hertz) and the potential of the static loads.
            _matvec(mass, v, tmp)
            energy = 0.5 * xd @ (block_mass @ xd) + 0.5 * x @ (block_stiffness @ x)
            for i in range(n):
                energy += 0.5 * v[i] * tmp[i]
            _matvec(stiffness, u, tmp)
            for i in range(n):
                energy += 0.5 * u[i] * tmp[i]
            for i in range(nw):
                energy += static_loads[i] * x[contact_dofs[i]]
                gap = origin[i] - x[contact_dofs[i]] - rail[i] - irregularity[step, i]
                if gap > 0.0:
                    energy += 0.4 * hertz[i] * gap**2.5
            out_energy[rec] = energy
            out_work[rec] = work
            out_dissipated[rec] = dissipated
            rec += 1
    return steps, 0
