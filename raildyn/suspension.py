"""Suspension force laws for the vehicle models (chapter 3, the building blocks of a model).

Each law gives the force an element carries for a deflection u (m, the relative
displacement across it) or relative velocity v = u̇ (m/s), positive in the sense of u
(a spring pushed by u > 0 answers with a positive force). All are vectorized: arrays of
any shape broadcast against each other, and parameters may be arrays too. Every
input is finite and non-empty; arrays whose shapes do not broadcast are refused,
naming the one that does not fit.

* linear spring          F = k u + F₀
* viscous damper         F = c v
* Coulomb friction       F = F_f sgn v, or the smooth F = F_f tanh(v/v_ε)
* clearance, bump stop   F = k u + k_s (|u| − e)₊ sgn u

The smooth friction law replaces the jump of sgn v at v = 0 by a slope F_f/v_ε,
so that an ODE solver need not stop at each stick–slip change; it misses the
ideal law by F_f(1 − tanh(|v|/v_ε)) < 2F_f e^{−2|v|/v_ε} (:func:`friction_error_bound`),
below 0.5 % of F_f once |v| > 3v_ε, and it cannot represent true sticking
(a body held by friction creeps at a speed of order v_ε·F/F_f). Its slope
dF/dv (:func:`coulomb_friction_slope`) is the tangent an implicit integrator
needs, and :class:`FrictionDamper` puts the law and its tangent in the
``f(t, x, v)`` and ``jacobian(t, x, v)`` form of :mod:`raildyn.integrators`. The
three-piece freight truck's friction wedges are Coulomb dampers of this kind,
with F_f = μN growing with the load N on the wedge (Garg & Dukkipati 1984,
ch. 3); a mass on a spring k under such friction loses 4F_f/k of amplitude a
cycle (:func:`friction_amplitude_loss`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.integrators import ForceJacobian

__all__ = [
    "FrictionDamper",
    "clearance_force",
    "coulomb_friction",
    "coulomb_friction_slope",
    "damper_force",
    "friction_amplitude_loss",
    "friction_error_bound",
    "spring_force",
]


def _field(name: str, value, *, low=None, low_open=False) -> np.ndarray:
    """A finite, non-empty array of the law's input ``name``, >= ``low`` (> with ``low_open``)."""
    return _checks.array(name, value, low=low, low_open=low_open, allow_empty=False)


def _force(law, **inputs) -> np.ndarray:
    """The force ``law()`` computes from the checked ``inputs``, refused if it overflows.

    Finite inputs of absurd size (a deflection of 1e300 m against a stiffness of 1e6 N/m) give a
    force beyond double precision: a ValueError names the inputs, never a silent inf or NaN.
    """
    with np.errstate(over="ignore", invalid="ignore"):
        force = np.asarray(law())
    if not np.isfinite(force).all():
        names = ", ".join(inputs)
        largest = ", ".join(f"{k} = {np.abs(v).max():.3g}" for k, v in inputs.items())
        raise ValueError(
            f"the force overflows: {names} are too large together for double precision ({largest})"
        )
    return force


def spring_force(deflection, stiffness, preload=0.0) -> np.ndarray:
    """Linear spring: F = k u + F₀ (N).

    Parameters
    ----------
    deflection : array_like
        u, m.
    stiffness : array_like
        k >= 0, N/m.
    preload : array_like
        F₀, N (the static load the spring already carries).

    Returns
    -------
    ndarray
        F, N, broadcast over the arguments.

    Examples
    --------
    >>> spring_force([0.0, 0.01], 1.0e6).tolist()
    [0.0, 10000.0]
    """
    d = _field("deflection", deflection)
    k = _field("stiffness", stiffness, low=0.0)
    f0 = _field("preload", preload)
    _checks.broadcast(deflection=d, stiffness=k, preload=f0)
    return _force(lambda: k * d + f0, deflection=d, stiffness=k, preload=f0)


def damper_force(velocity, damping) -> np.ndarray:
    """Viscous damper: F = c v (N).

    Parameters
    ----------
    velocity : array_like
        v, m/s.
    damping : array_like
        c >= 0, N·s/m.

    Returns
    -------
    ndarray
        F, N, broadcast over the arguments.

    Examples
    --------
    >>> damper_force([-0.1, 0.2], 2.0e4).tolist()
    [-2000.0, 4000.0]
    """
    v = _field("velocity", velocity)
    c = _field("damping", damping, low=0.0)
    _checks.broadcast(velocity=v, damping=c)
    return _force(lambda: c * v, velocity=v, damping=c)


def coulomb_friction(velocity, friction_force, *, velocity_scale=None) -> np.ndarray:
    """Coulomb friction F = F_f sgn v, or its smooth regularization F_f tanh(v/v_ε) (N).

    Parameters
    ----------
    velocity : array_like
        Sliding velocity v, m/s.
    friction_force : array_like
        F_f >= 0, N (μN for a friction wedge under normal load N).
    velocity_scale : float or array_like, optional
        v_ε, m/s, in [1e-6, 1] (a smoothing of the sign of v, far below the sliding speeds). Without it the
        ideal law is returned (F = 0 at v = 0
        exactly); with it, the smooth law, whose error is bounded by
        :func:`friction_error_bound`.

    Returns
    -------
    ndarray
        F, N, broadcast over the arguments.

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
        _checks.broadcast(velocity=v, friction_force=f)
        return np.asarray(f * np.sign(v))
    eps = _checks.smoothing_speed("velocity_scale", velocity_scale)
    _checks.broadcast(velocity=v, friction_force=f, velocity_scale=eps)
    return np.asarray(f * np.tanh(v / eps))


def coulomb_friction_slope(velocity, friction_force, *, velocity_scale) -> np.ndarray:
    """dF/dv of the smooth friction law F = F_f tanh(v/v_ε): (F_f/v_ε) sech²(v/v_ε) (N·s/m).

    The tangent an implicit integrator needs (:func:`raildyn.integrators.newmark_newton`,
    :func:`raildyn.integrators.stiff`): near v = 0 the law is a viscous damper of
    F_f/v_ε, far from it the slope vanishes as 4(F_f/v_ε)e^{−2|v|/v_ε}. The ideal
    law has no slope at v = 0, so ``velocity_scale`` is required.

    Parameters
    ----------
    velocity : array_like
        Sliding velocity v, m/s.
    friction_force : array_like
        F_f >= 0, N.
    velocity_scale : float or array_like
        v_ε, m/s, in [1e-6, 1] (a smoothing of the sign of v, far below the sliding speeds).

    Returns
    -------
    ndarray
        dF/dv >= 0, N·s/m, broadcast over the arguments.

    Examples
    --------
    >>> coulomb_friction_slope([0.0, 1.0], 1.0e4, velocity_scale=1.0e-3).tolist()  # F_f/v_ε at v = 0
    [10000000.0, 0.0]
    """
    v = _field("velocity", velocity)
    f = _field("friction_force", friction_force, low=0.0)
    eps = _checks.smoothing_speed("velocity_scale", velocity_scale)
    _checks.broadcast(velocity=v, friction_force=f, velocity_scale=eps)
    # sech² u = 4e^{−2|u|}/(1 + e^{−2|u|})²: no overflow however large |u|.
    decay = np.exp(-2.0 * np.abs(v / eps))
    return np.asarray(f / eps * 4.0 * decay / (1.0 + decay) ** 2)


def friction_error_bound(velocity, friction_force, velocity_scale) -> np.ndarray:
    """Bound on |F_smooth − F_ideal| away from v = 0: 2 F_f e^{−2|v|/v_ε} (N).

    1 − tanh u = 2/(e^{2u} + 1) < 2e^{−2u} for u > 0, so the bound holds at every
    v ≠ 0; at v = 0 the two laws agree (both 0).

    Parameters
    ----------
    velocity : array_like
        Sliding velocity v, m/s.
    friction_force : array_like
        F_f >= 0, N.
    velocity_scale : float or array_like
        v_ε, m/s, in [1e-6, 1] (a smoothing of the sign of v, far below the sliding speeds).

    Returns
    -------
    ndarray
        The bound, N, broadcast over the arguments.

    Examples
    --------
    >>> round(float(friction_error_bound(0.03, 500.0, 0.01)), 3)  # the smooth law gives 497.527 N
    2.479
    """
    v = _field("velocity", velocity)
    f = _field("friction_force", friction_force, low=0.0)
    eps = _checks.smoothing_speed("velocity_scale", velocity_scale)
    _checks.broadcast(velocity=v, friction_force=f, velocity_scale=eps)
    return np.asarray(2.0 * f * np.exp(-2.0 * np.abs(v) / eps))


def friction_amplitude_loss(friction_force, stiffness) -> np.ndarray:
    """Amplitude lost per cycle by a mass on a spring under Coulomb friction: 4 F_f / k (m).

    Each half cycle the friction works against the motion over the whole swing, so
    the amplitude falls by 2F_f/k each half cycle, linearly rather than
    geometrically, until the spring force at a turning point, k x, no longer exceeds
    F_f and the mass sticks {Den Hartog 1956}.

    Parameters
    ----------
    friction_force : array_like
        F_f >= 0, N.
    stiffness : array_like
        k > 0, N/m.

    Returns
    -------
    ndarray
        The loss of amplitude per cycle, m.

    Examples
    --------
    >>> float(friction_amplitude_loss(1.0e4, 5.0e6))  # a loaded wedge-damped spring nest: 8 mm a cycle
    0.008
    """
    f = _field("friction_force", friction_force, low=0.0)
    k = _field("stiffness", stiffness, low=0.0, low_open=True)
    _checks.broadcast(friction_force=f, stiffness=k)
    return _force(lambda: 4.0 * f / k, friction_force=f, stiffness=k)


def clearance_force(deflection, clearance, stop_stiffness, stiffness=0.0) -> np.ndarray:
    """A spring (or nothing) inside a clearance, and a bump stop beyond it.

    F = k u + k_s (|u| − e)₊ sgn u (N): a free gap (k = 0) such as the lateral
    clearance between an axle box and its guide, or a suspension spring whose
    travel is limited by a rubber bump stop after e. F is continuous and odd in
    u; its slope jumps from k to k + k_s at |u| = e.

    Parameters
    ----------
    deflection : array_like
        u, m.
    clearance : array_like
        e >= 0, free travel each way, m.
    stop_stiffness : array_like
        k_s >= 0, N/m.
    stiffness : array_like
        k >= 0, the spring acting inside and beyond the gap, N/m (default 0).

    Returns
    -------
    ndarray
        F, N, broadcast over the arguments.

    Examples
    --------
    >>> clearance_force([-0.02, 0.005, 0.02], clearance=0.01, stop_stiffness=1.0e6).tolist()
    [-10000.0, 0.0, 10000.0]
    """
    d = _field("deflection", deflection)
    g = _field("clearance", clearance, low=0.0)
    ks = _field("stop_stiffness", stop_stiffness, low=0.0)
    k = _field("stiffness", stiffness, low=0.0)
    _checks.broadcast(deflection=d, clearance=g, stop_stiffness=ks, stiffness=k)
    return _force(
        lambda: k * d + ks * np.maximum(np.abs(d) - g, 0.0) * np.sign(d),
        deflection=d,
        clearance=g,
        stop_stiffness=ks,
        stiffness=k,
    )


@dataclass(frozen=True)
class FrictionDamper:
    """Smooth Coulomb dampers between each coordinate and a fixed frame, ready for the integrators.

    The load they put on the coordinates is f = −F_f tanh(v/v_ε) (N), the smooth
    law of :func:`coulomb_friction` resisting the motion, and its tangent is
    ∂f/∂x = 0, ∂f/∂v = −diag(dF/dv) (:func:`coulomb_friction_slope`): the
    ``force(t, x, v)`` and ``jacobian(t, x, v)`` of
    :func:`raildyn.integrators.newmark_newton` and :func:`raildyn.integrators.stiff`.

    Parameters
    ----------
    friction_force : float or array_like, shape (n,)
        F_f >= 0, N: one for every coordinate, or one value for all.
    velocity_scale : float or array_like, shape (n,)
        v_ε, m/s, in [1e-6, 1] (a smoothing of the sign of v, far below the sliding speeds).

    Examples
    --------
    >>> damper = FrictionDamper(friction_force=1.0e4, velocity_scale=1.0e-3)
    >>> damper.force(0.0, np.zeros(1), np.array([0.1])).round(3).tolist()
    [-10000.0]
    >>> damper.jacobian(0.0, np.zeros(1), np.zeros(1)).wrt_velocity.tolist()
    [[-10000000.0]]
    """

    friction_force: float | np.ndarray
    velocity_scale: float | np.ndarray

    def __post_init__(self):
        f = _field("friction_force", self.friction_force, low=0.0)
        eps = _checks.smoothing_speed("velocity_scale", self.velocity_scale)
        for name, value in (("friction_force", f), ("velocity_scale", eps)):
            if value.ndim > 1:
                raise ValueError(f"{name} must be a number or a vector (n,), got shape {value.shape}")
            object.__setattr__(self, name, float(value) if value.ndim == 0 else value)

    def _velocity(self, t, x, v) -> np.ndarray:
        """The checked velocities; t and x, unused by the law, are checked too (finite, x like v)."""
        _checks.scalar("t", t)
        v = _checks.array("v", np.atleast_1d(_checks.array("v", v)), ndim=1, allow_empty=False)
        x = _checks.array("x", np.atleast_1d(_checks.array("x", x)), ndim=1)
        if x.shape != v.shape:
            raise ValueError(f"x must have the shape of v, {v.shape}, got {x.shape}")
        for name in ("friction_force", "velocity_scale"):
            size = np.size(getattr(self, name))
            if size > 1 and size != v.size:
                raise ValueError(f"v must have {size} entries, one per {name}, got {v.size}")
        return v

    def force(self, t, x, v) -> np.ndarray:
        """The friction load on the coordinates, −F_f tanh(v/v_ε).

        Parameters
        ----------
        t : float
            Time, s, finite (unused: the law does not change in time).
        x : array_like, shape (n,)
            Displacements, m, finite, shaped like ``v`` (unused).
        v : array_like, shape (n,)
            Velocities, m/s.

        Returns
        -------
        ndarray, shape (n,)
            f, N.
        """
        return -coulomb_friction(
            self._velocity(t, x, v), self.friction_force, velocity_scale=self.velocity_scale
        )

    def jacobian(self, t, x, v) -> ForceJacobian:
        """The tangent of :meth:`force`: ∂f/∂x = 0, ∂f/∂v = −diag((F_f/v_ε) sech²(v/v_ε)).

        Parameters
        ----------
        t : float
            Time, s, finite (unused).
        x : array_like, shape (n,)
            Displacements, m, finite, shaped like ``v`` (unused).
        v : array_like, shape (n,)
            Velocities, m/s.

        Returns
        -------
        ForceJacobian
            ∂f/∂x in N/m and ∂f/∂v in N·s/m, each (n, n).
        """
        v = self._velocity(t, x, v)
        slope = coulomb_friction_slope(v, self.friction_force, velocity_scale=self.velocity_scale)
        return ForceJacobian(np.zeros((v.size, v.size)), -np.diag(np.broadcast_to(slope, v.shape)))
