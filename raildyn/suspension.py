"""Suspension force laws for the vehicle models (chapter 3, the building blocks of a model).

Each law gives the force an element carries for a relative displacement δ (m)
or relative velocity v (m/s) across it, positive in the sense of δ (a spring
pushed by δ > 0 answers with a positive force). All are vectorized: arrays of
any shape broadcast against each other, and parameters may be arrays too.

* linear spring          F = k δ + F₀
* viscous damper         F = c v
* Coulomb friction       F = F_f sgn v, or the smooth F = F_f tanh(v/v_ε)
* clearance, bump stop   F = k δ + k_s (|δ| − g)₊ sgn δ

The smooth friction law replaces the jump of sgn v at v = 0 by a slope F_f/v_ε,
so that an ODE solver need not stop at each stick–slip change; it misses the
ideal law by F_f(1 − tanh(|v|/v_ε)) < 2F_f e^{−2|v|/v_ε} (:func:`friction_error_bound`),
below 0.5 % of F_f once |v| > 3v_ε, and it cannot represent true sticking
(a body held by friction creeps at a speed of order v_ε·F/F_f). The
three-piece freight truck's friction wedges are Coulomb dampers of this kind,
with F_f = μN growing with the load N on the wedge (Garg & Dukkipati 1984,
ch. 3).
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

__all__ = [
    "spring_force",
    "damper_force",
    "coulomb_friction",
    "friction_error_bound",
    "clearance_force",
]


def _field(name: str, value, *, low=None) -> np.ndarray:
    return _checks.array(name, value, low=low)


def spring_force(deflection, stiffness, preload=0.0) -> np.ndarray:
    """Linear spring: F = k δ + F₀ (N).

    Parameters
    ----------
    deflection : array_like
        δ, m.
    stiffness : array_like
        k >= 0, N/m.
    preload : array_like
        F₀, N (the static load the spring already carries).

    Examples
    --------
    >>> spring_force([0.0, 0.01], 1.0e6).tolist()
    [0.0, 10000.0]
    """
    d = _field("deflection", deflection)
    k = _field("stiffness", stiffness, low=0.0)
    f0 = _field("preload", preload)
    return np.asarray(k * d + f0)


def damper_force(velocity, damping) -> np.ndarray:
    """Viscous damper: F = c v (N), v in m/s, c >= 0 in N·s/m.

    Examples
    --------
    >>> damper_force([-0.1, 0.2], 2.0e4).tolist()
    [-2000.0, 4000.0]
    """
    v = _field("velocity", velocity)
    c = _field("damping", damping, low=0.0)
    return np.asarray(c * v)


def coulomb_friction(velocity, friction_force, *, velocity_scale=None) -> np.ndarray:
    """Coulomb friction F = F_f sgn v, or its smooth regularization F_f tanh(v/v_ε) (N).

    Parameters
    ----------
    velocity : array_like
        Sliding velocity v, m/s.
    friction_force : array_like
        F_f >= 0, N (μN for a friction wedge under normal load N).
    velocity_scale : float or array_like, optional
        v_ε > 0, m/s. Without it the ideal law is returned (F = 0 at v = 0
        exactly); with it, the smooth law, whose error is bounded by
        :func:`friction_error_bound`.

    Examples
    --------
    >>> coulomb_friction([-1.0, 0.0, 1.0], 500.0).tolist()
    [-500.0, 0.0, 500.0]
    >>> round(float(coulomb_friction(0.03, 500.0, velocity_scale=0.01)), 3)
    497.527
    """
    v = _field("velocity", velocity)
    f = _field("friction_force", friction_force, low=0.0)
    if velocity_scale is None:
        return np.asarray(f * np.sign(v))
    eps = _checks.array("velocity_scale", velocity_scale, low=0.0, low_open=True)
    return np.asarray(f * np.tanh(v / eps))


def friction_error_bound(velocity, friction_force, velocity_scale) -> np.ndarray:
    """Bound on |F_smooth − F_ideal| away from v = 0: 2 F_f e^{−2|v|/v_ε} (N).

    1 − tanh u = 2/(e^{2u} + 1) < 2e^{−2u} for u > 0, so the bound holds at every
    v ≠ 0; at v = 0 the two laws agree (both 0).
    """
    v = _field("velocity", velocity)
    f = _field("friction_force", friction_force, low=0.0)
    eps = _checks.array("velocity_scale", velocity_scale, low=0.0, low_open=True)
    return np.asarray(2.0 * f * np.exp(-2.0 * np.abs(v) / eps))


def clearance_force(deflection, clearance, stop_stiffness, stiffness=0.0) -> np.ndarray:
    """A spring (or nothing) inside a clearance, and a bump stop beyond it.

    F = k δ + k_s (|δ| − g)₊ sgn δ (N): a free gap (k = 0) such as the lateral
    clearance between an axle box and its guide, or a suspension spring whose
    travel is limited by a rubber bump stop after g. F is continuous and odd in
    δ; its slope jumps from k to k + k_s at |δ| = g.

    Parameters
    ----------
    deflection : array_like
        δ, m.
    clearance : array_like
        g >= 0, free travel each way, m.
    stop_stiffness : array_like
        k_s >= 0, N/m.
    stiffness : array_like
        k >= 0, the spring acting inside and beyond the gap, N/m (default 0).

    Examples
    --------
    >>> clearance_force([-0.02, 0.005, 0.02], clearance=0.01, stop_stiffness=1.0e6).tolist()
    [-10000.0, 0.0, 10000.0]
    """
    d = _field("deflection", deflection)
    g = _field("clearance", clearance, low=0.0)
    ks = _field("stop_stiffness", stop_stiffness, low=0.0)
    k = _field("stiffness", stiffness, low=0.0)
    return np.asarray(k * d + ks * np.maximum(np.abs(d) - g, 0.0) * np.sign(d))
