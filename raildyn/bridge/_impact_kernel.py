"""The time march of a wheel on a discrete track, compiled with numba.

Newmark's average-acceleration rule (unconditionally stable, no numerical damping) on the track's
banded matrices and on the wheel with its sprung mass, both linear, joined by the Hertz spring,
which is not. The step's effective stiffness is the same at every step, so it is factored once;
each step then solves once for the track's motion without the contact force and adds the response
to the contact force, whose columns (one per unknown the wheel can stand on) are solved once before
the march. What is left is one equation in the contact force F,

    F = C_H max(δ* − c F, 0)^{3/2},

increasing on one side and concave on the other, which a Newton iteration kept inside its bracket
solves to round-off. :func:`raildyn.bridge.impact.wheel_on_track` checks every input and documents
the equations; nothing here checks anything.
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
def march(mass, damping, stiffness, factor, columns, column_of, dofs, weights, slopes, irregularity, slope_r,
          speed, wheel_mass, sprung_mass, primary_k, primary_c, wheel_force, sprung_force, hertz, force0, dt,
          u, v, a, z, zd, zdd, record_every, pad_rows, sleeper_rows, pad_k, pad_c, ballast_k, ballast_c,
          out_force, out_wheel, out_rail, out_pad, out_ballast, out_energy, out_work,
          out_dissipated):  # fmt: skip
    """Advance the track (u, v, a) and the wheel and sprung mass (z, zd, zdd: 2 each) over the steps.

    Step n+1 puts the contact at ``dofs[n+1]`` with shape ``weights[n+1]`` (slope weights ``slopes``),
    meets the irregularity r = ``irregularity[n+1]`` (slope dr/dx ``slope_r``). Records every
    ``record_every`` steps; the energy recorded is the system's total (kinetic, strain and the
    constant loads' potential). Returns (steps done, status): status 0 done, 1 a non-finite contact force.
    """
    n = u.size
    steps = dofs.shape[0] - 1
    a0, a1 = 4.0 / (dt * dt), 2.0 / dt
    rhs = np.empty(n)
    tmp = np.empty(n)
    g = np.empty(n)
    # The wheel's 2 × 2 effective stiffness: [wheel, sprung].
    kww = wheel_mass * a0 + primary_k + primary_c * a1
    kss = sprung_mass * a0 + primary_k + primary_c * a1
    kws = -(primary_k + primary_c * a1)
    det = kww * kss - kws * kws
    force = force0
    power_prev = 0.0
    loss_prev = 0.0
    dissipated = 0.0
    work = 0.0
    rec = 0
    for step in range(steps + 1):
        if step > 0:
            # The track without the contact force: rhs = M(a0 u + 4/dt v + a) + C(a1 u + v).
            for i in range(n):
                tmp[i] = a0 * u[i] + 4.0 / dt * v[i] + a[i]
            _matvec(mass, tmp, rhs)
            for i in range(n):
                tmp[i] = a1 * u[i] + v[i]
            _matvec(damping, tmp, g)
            for i in range(n):
                rhs[i] += g[i]
            band_solve(factor, rhs)  # rhs is now u*
            # The response to a unit contact force (down on the rail): g = Σ w_k G[col(dof_k)].
            for i in range(n):
                g[i] = 0.0
            for k in range(4):
                col = column_of[dofs[step, k]]
                w = weights[step, k]
                for i in range(n):
                    g[i] += w * columns[col, i]
            rail_star, rail_unit = 0.0, 0.0
            for k in range(4):
                rail_star += weights[step, k] * rhs[dofs[step, k]]
                rail_unit += weights[step, k] * g[dofs[step, k]]
            # The wheel without the contact force, and its response to F (F pushes the wheel up).
            bw = wheel_force + wheel_mass * (a0 * z[0] + 4.0 / dt * zd[0] + zdd[0])
            bw += primary_c * (a1 * (z[0] - z[1]) + (zd[0] - zd[1]))
            bs = sprung_force + sprung_mass * (a0 * z[1] + 4.0 / dt * zd[1] + zdd[1])
            bs -= primary_c * (a1 * (z[0] - z[1]) + (zd[0] - zd[1]))
            zw_star = (kss * bw - kws * bs) / det
            zs_star = (kww * bs - kws * bw) / det
            zw_unit, zs_unit = -kss / det, kws / det
            force = _contact(zw_star - rail_star - irregularity[step], rail_unit - zw_unit, hertz, force)
            if force < 0.0:
                return step, 1
            for i in range(n):
                un = rhs[i] + g[i] * force
                an = a0 * (un - u[i]) - 4.0 / dt * v[i] - a[i]
                v[i] += 0.5 * dt * (a[i] + an)
                a[i] = an
                u[i] = un
            for j, (star, unit) in enumerate(((zw_star, zw_unit), (zs_star, zs_unit))):
                zn = star + unit * force
                an = a0 * (zn - z[j]) - 4.0 / dt * zd[j] - zdd[j]
                zd[j] += 0.5 * dt * (zdd[j] + an)
                zdd[j] = an
                z[j] = zn
        # Power fed in by the rolling (the rail's slope and the irregularity passing under the wheel),
        # and the dampers' loss, integrated by the trapezoidal rule as Newmark's rule integrates them.
        rail_slope = 0.0
        for k in range(4):
            rail_slope += slopes[step, k] * u[dofs[step, k]]
        power = -force * speed * (rail_slope + slope_r[step])
        _matvec(damping, v, tmp)
        loss = primary_c * (zd[0] - zd[1]) ** 2
        for i in range(n):
            loss += v[i] * tmp[i]
        if step > 0:
            work += 0.5 * dt * (power + power_prev)
            dissipated += 0.5 * dt * (loss + loss_prev)
        power_prev, loss_prev = power, loss
        if step % record_every == 0:
            rail = 0.0
            for k in range(4):
                rail += weights[step, k] * u[dofs[step, k]]
            out_force[rec] = force
            out_wheel[rec] = z[0]
            out_rail[rec] = rail
            for j in range(pad_rows.size):
                r, s = pad_rows[j], sleeper_rows[j]
                out_pad[rec, j] = pad_k * (u[r] - u[s]) + pad_c * (v[r] - v[s])
                out_ballast[rec, j] = ballast_k * u[s] + ballast_c * v[s]
            # The energy: kinetic, strain (track, primary, Hertz) and the potential of the constant loads.
            _matvec(mass, v, tmp)
            energy = 0.5 * wheel_mass * zd[0] ** 2 + 0.5 * sprung_mass * zd[1] ** 2
            for i in range(n):
                energy += 0.5 * v[i] * tmp[i]
            _matvec(stiffness, u, tmp)
            for i in range(n):
                energy += 0.5 * u[i] * tmp[i]
            energy += 0.5 * primary_k * (z[0] - z[1]) ** 2 - wheel_force * z[0] - sprung_force * z[1]
            gap = z[0] - rail - irregularity[step]
            if gap > 0.0:
                energy += 0.4 * hertz * gap**2.5
            out_energy[rec] = energy
            out_work[rec] = work
            out_dissipated[rec] = dissipated
            rec += 1
    return steps, 0
