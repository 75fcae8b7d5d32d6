"""The wheel on the discrete track by scipy's RK45: the reference for the compiled march's answer and speed.

The same equations as :func:`raildyn.bridge.impact.wheel_on_track` states, written as first-order
ODEs (the track's accelerations by a banded Cholesky solve with its mass) and handed to
``scipy.integrate.solve_ivp``. The rail's shortest elements set RK45's step (a few tenths of a
microsecond, where the compiled implicit march takes 10 µs), which is why it is the reference and
not the way. Nothing here checks its arguments; the caller has.
"""

from __future__ import annotations

import numpy as np

from raildyn.bridge.sleepers import _shape
from raildyn.constants import GRAVITY
from raildyn.errors import SolverError

__all__ = ["march"]


def _matvec(ab, x):
    """A x for a symmetric A stored by diagonals (numpy, along a last axis)."""
    out = ab[0] * x
    for k in range(1, ab.shape[0]):
        out[..., k:] += ab[k, :-k] * x[..., :-k]
        out[..., :-k] += ab[k, :-k] * x[..., k:]
    return out


def march(track, profile, x0, V, standing, t, wheel, hertz, u0, z0, out):
    """The same equations as first-order ODEs, integrated by scipy's RK45; fills ``out`` as the march does."""
    from scipy.integrate import solve_ivp
    from scipy.linalg import cho_solve_banded, cholesky_banded

    mats = track.matrices
    n = mats.size
    factor = cholesky_banded(mats.mass, lower=True)
    ms = wheel.sprung_mass if wheel.sprung_mass > 0.0 else 1.0
    k1, c1 = (wheel.primary_stiffness, wheel.primary_damping) if wheel.sprung_mass > 0.0 else (0.0, 0.0)
    Ws = wheel.sprung_mass * GRAVITY
    Ww = wheel.static_load - Ws

    h = track.sleeper_spacing / track.elements_per_bay
    phi = 12.0 * track.rail_flexural_rigidity / (track.rail_shear_stiffness * h * h)
    last = track.elements_per_bay * track.bays - 1

    def point(time):
        """The contact's four unknowns, their weights and slope weights, and r and dr/dx, at each time."""
        time = np.atleast_1d(time)
        x = np.full_like(time, x0) if standing else x0 + V * time
        element = np.minimum((x / h).astype(int), last)
        nw, dnw = (a.T for a in _shape(x / h - element, h, phi)[:2])
        a, b = mats.deflection[element], mats.deflection[element + 1]
        r, slope = profile(x0 + V * time)
        return np.stack([a, a + 1, b, b + 1], axis=1), nw, (0.0 * dnw if standing else dnw), r, slope

    def rhs(time, y):
        dofs, nw, _, r, _ = point(time)
        u, v = y[:n], y[n : 2 * n]
        force = hertz * max(y[2 * n] - nw[0] @ u[dofs[0]] - r[0], 0.0) ** 1.5
        load = -_matvec(mats.damping, v) - _matvec(mats.stiffness, u)
        load[dofs[0]] += nw[0] * force
        zw, zs, vw, vs = y[2 * n :]
        primary = k1 * (zs - zw) + c1 * (vs - vw)
        aw = (Ww - force + primary) / wheel.unsprung_mass
        return np.concatenate([v, cho_solve_banded((factor, True), load), [vw, vs, aw, (Ws - primary) / ms]])

    y0 = np.concatenate([u0, np.zeros(n), z0, np.zeros(2)])
    sol = solve_ivp(rhs, (0.0, t[-1]), y0, method="RK45", t_eval=t, rtol=1e-8, atol=1e-12)
    if not sol.success:
        raise SolverError(f"scipy's RK45 failed: {sol.message}", time=float(sol.t[-1]))
    y = sol.y.T
    dofs, nw, dnw, r, slope_r = point(t)
    u, v = y[:, :n], y[:, n : 2 * n]
    at = np.take_along_axis(u, dofs, axis=1)
    rail = np.sum(nw * at, axis=1)
    force = hertz * np.maximum(y[:, 2 * n] - rail - r, 0.0) ** 1.5
    out["force"][:], out["wheel"][:], out["rail"][:] = force, y[:, 2 * n], rail
    under = mats.deflection[mats.sleeper_nodes]
    out["pad"][:] = track.pad_stiffness * (u[:, under] - u[:, mats.sleepers]) + track.pad_damping * (
        v[:, under] - v[:, mats.sleepers]
    )
    out["ballast"][:] = (
        track.ballast_stiffness * u[:, mats.sleepers] + track.ballast_damping * v[:, mats.sleepers]
    )
    zw, zs, vw, vs = y[:, 2 * n :].T
    gap = np.maximum(zw - rail - r, 0.0)
    out["energy"][:] = (
        0.5 * np.sum(v * _matvec(mats.mass, v), axis=1) + 0.5 * np.sum(u * _matvec(mats.stiffness, u), axis=1)
        + 0.5 * wheel.unsprung_mass * vw**2 + 0.5 * ms * vs**2 + 0.5 * k1 * (zw - zs) ** 2 - Ww * zw - Ws * zs
        + 0.4 * hertz * gap**2.5
    )  # fmt: skip
    loss = np.sum(v * _matvec(mats.damping, v), axis=1) + c1 * (vw - vs) ** 2
    power = -force * V * (np.sum(dnw * at, axis=1) + slope_r)
    dt = np.diff(t)
    out["work"][1:] = np.cumsum(0.5 * dt * (power[1:] + power[:-1]))
    out["dissipated"][1:] = np.cumsum(0.5 * dt * (loss[1:] + loss[:-1]))
