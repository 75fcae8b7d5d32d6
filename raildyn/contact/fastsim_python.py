"""FASTSIM in numpy and in plain Python: the twins the compiled :func:`~raildyn.contact.fastsim.fastsim`
is held to.

``_fastsim_numpy`` is the same march as the compiled kernel in numpy (a Python loop over the cells
of a strip, numpy over all strips of all states), the version before the kernel: the tests hold
the kernel to it and the chapter 4 benchmark times the kernel against it. :func:`fastsim_reference`
is the same algorithm cell by cell in plain Python, for one state: the independent implementation
the tests hold both to. Both check their input and prepare each state as
:mod:`raildyn.contact.fastsim` does.
"""

from __future__ import annotations

import math

import numpy as np

from raildyn import _checks
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact.fastsim import _CELLS_MAX, FastsimResult, _prepare, _result, _within_sliding
from raildyn.contact.kalker import _ratio

__all__ = ["fastsim_reference"]


def _fastsim_numpy(
    longitudinal,
    lateral,
    spin,
    normal_load,
    friction,
    a,
    b,
    shear_modulus=STEEL_SHEAR_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
    *,
    n_x: int = 20,
    n_y: int = 20,
    fields: bool = True,
) -> FastsimResult:
    """:func:`~raildyn.contact.fastsim.fastsim` with the march in numpy: the version before the compiled
    kernel, kept as reference.

    All strips of all states step together, a Python loop over the n_x cells of a strip.
    The tests hold the kernel to it and the chapter 4 benchmark times the kernel against it.
    """
    state = _prepare(
        longitudinal,
        lateral,
        spin,
        normal_load,
        friction,
        a,
        b,
        shear_modulus,
        poisson_ratio,
        n_x,
        n_y,
        fields,
    )
    xi, eta, phi, a, b, l1, l2, l3 = (
        state.xi,
        state.eta,
        state.phi,
        state.a,
        state.b,
        state.l1,
        state.l2,
        state.l3,
    )
    eta_y, pz_grid, n_x, n_y, fields = state.eta_y, state.shape, state.n_x, state.n_y, state.fields
    e = (..., None)  # add the strip axis
    y = b[e] * eta_y  # S + (n_y,)
    half = a[e] * state.root  # a(y), half-length of each strip
    dx = 2.0 * half / n_x
    dy = 2.0 * b[e] / n_y
    bound_scale = state.limit[e]
    # Traction rates of the adhesion solution: ∂p_x/∂x = γ_x/L₁ − φy/L₃, ∂p_y/∂x = γ_y/L₂ + φx/L₃.
    rate_x = (xi / l1)[e] - (phi / l3)[e] * y
    rate_y = (eta / l2)[e]
    spin_y = (phi / l3)[e]
    px = np.zeros_like(half)
    py = np.zeros_like(half)
    fx = np.zeros_like(half)
    fy = np.zeros_like(half)
    mz = np.zeros_like(half)
    if fields:
        shape = half.shape + (n_x,)
        out = {k: np.empty(shape) for k in ("x", "px", "py", "sx", "sy")}
        stick = np.empty(shape, dtype=bool)
    cell = dx * dy
    for k in range(n_x):
        x = half - (k + 0.5) * dx
        step = 0.5 * dx if k == 0 else dx
        # Exact increment of the adhesion traction from x + step to x (marching against x):
        # ∫ φx/L₃ dx over the step is φ/L₃ · step · (x + step/2).
        tx = px - rate_x * step
        ty = py - rate_y * step - spin_y * step * (x + 0.5 * step)
        bound = bound_scale * pz_grid[:, k]  # the pressure shape depends on (strip, cell) only
        magnitude = np.hypot(tx, ty)
        factor = np.divide(bound, magnitude, out=np.ones_like(magnitude), where=magnitude > bound)
        px, py = tx * factor, ty * factor
        fx += px * cell
        fy += py * cell
        mz += (x * py - y * px) * cell
        if fields:
            out["x"][..., k] = x
            out["px"][..., k] = px
            out["py"][..., k] = py
            # Slip: the part of the rigid-slip rate the springs could not take up, in creepage units.
            out["sx"][..., k] = l1[e] * (tx - px) / step
            out["sy"][..., k] = l2[e] * (ty - py) / step
            stick[..., k] = factor >= 1.0
    fx_t, fy_t, mz_t = fx.sum(-1), fy.sum(-1), mz.sum(-1)
    if not fields:
        return _result(state, fx_t, fy_t, mz_t)
    return _result(state, fx_t, fy_t, mz_t, x=out["x"], px=out["px"], py=out["py"], slip_x=out["sx"],
                   slip_y=out["sy"], adhesion=stick)  # fmt: skip


def fastsim_reference(
    longitudinal, lateral, spin, normal_load, friction, a, b, l1, l2, l3, n_x=20, n_y=20
) -> FastsimResult:
    """The same algorithm as :func:`~raildyn.contact.fastsim.fastsim` written cell by cell in plain Python,
    for one state.

    It exists as the independent, straightforward implementation that the tests
    and the chapter 4 benchmark compare the compiled one with; it takes the
    flexibilities directly. Its input is checked as that of :func:`~raildyn.contact.fastsim.fastsim`, and huge
    creepages are scaled down in the same way.

    Parameters
    ----------
    longitudinal, lateral : float
        γ_x, γ_y.
    spin : float
        φ (1/m).
    normal_load : float
        N (N), in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float
        μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    a, b : float
        Semi-axes (m), > 0, with 0.1 ≤ a/b ≤ 10 as for :func:`~raildyn.contact.fastsim.fastsim`.
    l1, l2, l3 : float
        Flexibilities (m/Pa), > 0, e.g. from :func:`~raildyn.contact.fastsim.flexibilities`.
    n_x, n_y : int
        Cells per strip and strips, 2 to 1000.

    Returns
    -------
    FastsimResult
        Fx, Fy (N) and Mz (N m) only.

    Examples
    --------
    >>> from raildyn.contact.fastsim import fastsim, flexibilities
    >>> f = flexibilities(6e-3, 4e-3)
    >>> ref = fastsim_reference(1e-3, 0.0, 0.0, 1e5, 0.3, 6e-3, 4e-3, f.l1, f.l2, f.l3)
    >>> bool(abs(ref.fx - fastsim(1e-3, 0.0, 0.0, 1e5, 0.3, 6e-3, 4e-3).fx) < 1e-6)
    True
    """
    longitudinal, lateral, spin = (
        _checks.scalar(k, v)
        for k, v in (("longitudinal", longitudinal), ("lateral", lateral), ("spin", spin))
    )
    normal_load, friction, a, b, l1, l2, l3 = (
        _checks.positive(k, v)
        for k, v in (("normal_load", normal_load), ("friction", friction), ("a", a), ("b", b),
                     ("l1", l1), ("l2", l2), ("l3", l3))
    )  # fmt: skip
    n_x = _checks.integer("n_x", n_x, low=2, high=_CELLS_MAX)
    n_y = _checks.integer("n_y", n_y, low=2, high=_CELLS_MAX)
    _ratio(a, b)  # the domain of fastsim, whose flexibilities come from Kalker's table
    dy = 2.0 * b / n_y
    total = 0.0  # the grid integral of the parabolic pressure shape, normalised as in fastsim
    for j in range(n_y):
        yr = (j + 0.5) / n_y * 2.0 - 1.0
        for k in range(n_x):
            xr = math.sqrt(1.0 - yr * yr) * (1.0 - (k + 0.5) * 2.0 / n_x)
            total += max(0.0, 1.0 - xr * xr - yr * yr) * 2.0 * math.sqrt(1.0 - yr * yr) / n_x * 2.0 / n_y
    p0 = normal_load / (a * b * total)
    scaled = _within_sliding(longitudinal, lateral, spin, a, b, l1, l2, l3, friction * p0)
    longitudinal, lateral, spin = (float(v) for v in scaled)
    fx = fy = mz = 0.0
    for j in range(n_y):
        yr = (j + 0.5) / n_y * 2.0 - 1.0
        y = b * yr
        half = a * math.sqrt(1.0 - yr * yr)
        dx = 2.0 * half / n_x
        px = py = 0.0
        x_prev = half
        for k in range(n_x):
            x = half - (k + 0.5) * dx
            step = x_prev - x
            tx = px - (longitudinal / l1 - spin * y / l3) * step
            ty = py - lateral / l2 * step - spin / l3 * 0.5 * (x_prev * x_prev - x * x)
            bound = friction * p0 * max(0.0, 1.0 - (x / a) ** 2 - yr * yr)
            mag = math.hypot(tx, ty)
            if mag > bound:
                px, py = tx * bound / mag, ty * bound / mag
            else:
                px, py = tx, ty
            fx += px * dx * dy
            fy += py * dx * dy
            mz += (x * py - y * px) * dx * dy
            x_prev = x
    return FastsimResult(fx, fy, mz, normal_load=normal_load, friction=friction, a=a, b=b)
