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
from raildyn.errors import SolverError

__all__ = ["march"]


def _matvec(ab, x):
    """A x for a symmetric A stored by diagonals (numpy, along a last axis)."""
    out = ab[0] * x
    for k in range(1, ab.shape[0]):
        out[..., k:] += ab[k, :-k] * x[..., :-k]
        out[..., :-k] += ab[k, :-k] * x[..., k:]
    return out


def march(track, block, profile, x0, V, standing, t, u0, origin, out):
    """The same equations as first-order ODEs, integrated by scipy's RK45; fills ``out`` as the march does.

    ``block`` is the :class:`raildyn.bridge.wheels.WheelBlock` above the rail, ``profile(seen)`` gives
    (r_s, dr_s/dx) at the wheels' positions (k, w), ``u0`` and ``origin`` the static state.
    """
    from scipy.integrate import solve_ivp
    from scipy.linalg import cho_solve_banded, cholesky_banded

    mats = track.matrices
    n, nb = mats.size, block.mass.shape[0]
    factor = cholesky_banded(mats.mass, lower=True)
    block_mass_inverse = np.linalg.inv(block.mass)
    c, loads, hertz = block.contact_dofs, block.static_loads, block.hertz_constants
    h = track.sleeper_spacing / track.elements_per_bay
    phi = 12.0 * track.rail_flexural_rigidity / (track.rail_shear_stiffness * h * h)
    last = track.elements_per_bay * track.bays - 1

    def point(time):
        """Each wheel's four unknowns, weights and slope weights, and its r_s and dr_s/dx: (k, w, …)."""
        time = np.atleast_1d(time)
        seen = x0 + V * time[:, None] - block.offsets[None, :]
        where = np.broadcast_to(x0 - block.offsets, seen.shape) if standing else seen
        element = np.minimum((where / h).astype(int), last)
        nw, dnw = (np.moveaxis(a, 0, -1) for a in _shape(where / h - element, h, phi)[:2])
        a, b = mats.deflection[element], mats.deflection[element + 1]
        r, slope = profile(seen)
        return np.stack([a, a + 1, b, b + 1], axis=-1), nw, (0.0 * dnw if standing else dnw), r, slope

    def rhs(time, y):
        dofs, nw, _, r, _ = point(time)
        u, v, x, xd = y[:n], y[n : 2 * n], y[2 * n : 2 * n + nb], y[2 * n + nb :]
        rail = np.einsum("wk,wk->w", nw[0], u[dofs[0]])
        force = hertz * np.maximum(origin - x[c] - rail - r[0], 0.0) ** 1.5
        load = -_matvec(mats.damping, v) - _matvec(mats.stiffness, u)
        np.add.at(load, dofs[0], nw[0] * force[:, None])
        on_block = -block.damping @ xd - block.stiffness @ x
        on_block[c] += force - loads
        return np.concatenate([v, cho_solve_banded((factor, True), load), xd, block_mass_inverse @ on_block])

    y0 = np.concatenate([u0, np.zeros(n), np.zeros(2 * nb)])
    sol = solve_ivp(rhs, (0.0, t[-1]), y0, method="RK45", t_eval=t, rtol=1e-8, atol=1e-12)
    if not sol.success:
        raise SolverError(f"scipy's RK45 failed: {sol.message}", time=float(sol.t[-1]))
    y = sol.y.T
    dofs, nw, dnw, r, slope_r = point(t)
    u, v = y[:, :n], y[:, n : 2 * n]
    x, xd = y[:, 2 * n : 2 * n + nb], y[:, 2 * n + nb :]
    at = u[np.arange(t.size)[:, None, None], dofs]
    rail = np.sum(nw * at, axis=-1)
    gap = origin - x[:, c] - rail - r
    force = hertz * np.maximum(gap, 0.0) ** 1.5
    out["force"][:], out["wheel"][:], out["rail"][:] = force, origin - x[:, c], rail
    under = mats.deflection[mats.sleeper_nodes]
    out["pad"][:] = track.pad_stiffness * (u[:, under] - u[:, mats.sleepers]) + track.pad_damping * (
        v[:, under] - v[:, mats.sleepers]
    )
    out["ballast"][:] = (
        track.ballast_stiffness * u[:, mats.sleepers] + track.ballast_damping * v[:, mats.sleepers]
    )

    def quadratic(a, m):
        return np.einsum("ki,ij,kj->k", a, m, a)

    out["energy"][:] = (
        0.5 * np.sum(v * _matvec(mats.mass, v), axis=1) + 0.5 * np.sum(u * _matvec(mats.stiffness, u), axis=1)
        + 0.5 * quadratic(xd, block.mass) + 0.5 * quadratic(x, block.stiffness)
        + x[:, c] @ loads + 0.4 * np.sum(hertz * np.maximum(gap, 0.0) ** 2.5, axis=1)
    )  # fmt: skip
    loss = np.sum(v * _matvec(mats.damping, v), axis=1) + quadratic(xd, block.damping)
    power = -V * np.sum(force * (np.sum(dnw * at, axis=-1) + slope_r), axis=1)
    dt = np.diff(t)
    out["work"][1:] = np.cumsum(0.5 * dt * (power[1:] + power[:-1]))
    out["dissipated"][1:] = np.cumsum(0.5 * dt * (loss[1:] + loss[:-1]))
