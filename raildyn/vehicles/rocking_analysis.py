"""The rocking freight car's linearisation, and the car at rest under a steady roll load: its balance and
the loads at which a centre plate lifts on one edge and a wheel off its rail. The ``linearized``,
``static_roll``, ``plate_lift_moment`` and ``wheel_lift_acceleration`` methods of
:class:`~raildyn.vehicles.rocking.RockingFreightCar` call these.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY
from raildyn.errors import SolverError
from raildyn.linear_model import SystemMatrices
from raildyn.vehicles._rocking_coordinates import LABELS

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.optimize,
# raildyn.vehicles._rocking_kernel

__all__ = ["StaticRoll"]


@dataclass(frozen=True, eq=False)
class StaticRoll:
    """The car at rest under a roll moment on its body
    (:meth:`~raildyn.vehicles.rocking.RockingFreightCar.static_roll`).

    Attributes
    ----------
    roll_moment : float
        N·m, left side up positive.
    lateral_acceleration : float
        m/s², towards the right positive.
    q : ndarray, (18,)
        The coordinates (``LABELS``), m and rad, from the unloaded equilibrium.
    wheel_loads : ndarray, (4, 2)
        Each wheelset's left and right wheel load, N, ≥ 0.
    elastic_wheel_loads : ndarray, (4, 2)
        The same as the track's spring would give it, P₀ + k δ, N: negative by the amount the rail
        would have to pull once a wheel has lifted (a measure of how far past lift-off).
    plate_loads : ndarray, (2, 2)
        Each truck's centre-plate edge loads, left and right, N, ≥ 0.
    bearer_loads : ndarray, (2, 2)
        Each truck's side-bearer loads, left and right, N, ≥ 0.
    """

    roll_moment: float
    lateral_acceleration: float
    q: np.ndarray
    wheel_loads: np.ndarray
    elastic_wheel_loads: np.ndarray
    plate_loads: np.ndarray
    bearer_loads: np.ndarray

    def __post_init__(self):
        object.__setattr__(self, "roll_moment", _checks.scalar("roll_moment", self.roll_moment))
        object.__setattr__(
            self, "lateral_acceleration", _checks.scalar("lateral_acceleration", self.lateral_acceleration)
        )
        object.__setattr__(self, "q", _checks.array("q", self.q, shape=(18,)))
        for name, shape in (("wheel_loads", (4, 2)), ("plate_loads", (2, 2)), ("bearer_loads", (2, 2))):
            object.__setattr__(self, name, _checks.array(name, getattr(self, name), shape=shape, low=0.0))
        object.__setattr__(
            self,
            "elastic_wheel_loads",
            _checks.array("elastic_wheel_loads", self.elastic_wheel_loads, shape=(4, 2)),
        )

    @property
    def body_roll(self) -> float:
        """The body's roll, rad."""
        return float(self.q[2])


def static_roll(car, roll_moment: float = 0.0, lateral_acceleration: float = 0.0, start=None) -> StaticRoll:
    """:meth:`~raildyn.vehicles.rocking.RockingFreightCar.static_roll` (see there); ``start``, a
    :class:`StaticRoll` of the same car under a share s of the same kind of load, starts the
    continuation there (at s) instead of at rest."""

    from raildyn.vehicles import _rocking_kernel as kernel

    limit = car.weight * car.half_rail_spacing
    M = _checks.scalar("roll_moment", roll_moment, low=-limit, high=limit)
    a_y = _checks.scalar("lateral_acceleration", lateral_acceleration, low=-GRAVITY, high=GRAVITY)
    free = car.replace(car=car.car.replace(wedge_friction=0.0))
    # the load on the coordinates: the moment on the body's roll, and each part's m a_y to the right
    # at its centre of gravity (a wheelset's r₀ above its reference point at the rail, where the rail
    # holds it: a roll moment m a_y r₀ on it)
    mass = car._tables()[0]
    load = np.zeros(18)
    load[2] = M
    load[[3, 6, 9]] = -a_y * mass[[3, 6, 9]]
    load[11::2] = a_y * car.wheelset_mass * car.wheel_radius
    v0 = np.zeros(18)
    q = np.zeros(18)
    done, step = 0.0, 0.125
    if start is not None:
        given = start.roll_moment if M != 0 else start.lateral_acceleration
        wanted = M if M != 0 else a_y
        if wanted != 0 and 0 <= given / wanted <= 1:
            q, done, step = start.q, given / wanted, 1.0
    floor = 1 / 1024 if start is None else (1.0 - done) / 4  # a warm start gives up sooner
    tol = 1e-8 * car.weight
    while done < 1.0:
        share = min(1.0, done + step)
        solved = _balance(free, q, share * load, tol)
        if solved is None:
            if step < floor:
                raise SolverError(
                    f"no static balance at {share:.4g} of the roll moment {M:.6g} N·m and the lateral "
                    f"acceleration {a_y:.6g} m/s²: the car (or its body, off its plates) overturns"
                )
            step /= 2
            continue
        q, done = solved, share
    _, element = free.forces(q, v0)
    mass, _, _, ef, _ = car._tables()
    # a contact's elastic force P₀ + k δ, which goes negative once it has separated
    elastic = (
        ef[:16, kernel.PRELOAD]
        + ef[:16, kernel.STIFFNESS] * kernel.evaluate(free, q, v0, np.zeros(8), np.zeros(8))[2][:16]
    )
    return StaticRoll(
        M,
        a_y,
        q,
        element[:8].reshape(4, 2),
        elastic[:8].reshape(4, 2),
        element[8:12].reshape(2, 2),
        element[12:16].reshape(2, 2),
    )


def threshold(car, event: str) -> float:
    """The least load at which ``event`` happens or no balance exists, by bisection to 1e-7 of its range:
    "wheel_lift" (a lateral acceleration, m/s², at which a wheel's elastic load reaches 0) or "plate_lift"
    (a roll moment on the body, N·m, at which a plate edge's load does)."""
    if event == "wheel_lift":
        kind, limit = "lateral_acceleration", GRAVITY

        def holds(s):
            return s.elastic_wheel_loads.min() > 0
    else:
        kind, limit = "roll_moment", car.weight * car.half_rail_spacing

        def holds(s):
            return s.plate_loads.min() > 0

    last = [None]  # the balance at the highest load known to hold: the next try starts from it

    def ok(x):
        try:
            state = static_roll(car, **{kind: x}, start=last[0])
        except SolverError:
            return False
        if holds(state):
            last[0] = state
            return True
        return False

    low, high = 0.0, limit
    while high - low > 1e-7 * limit:
        mid = 0.5 * (low + high)
        low, high = (mid, high) if ok(mid) else (low, mid)
    return 0.5 * (low + high)


def _balance(free, q, load, tol: float):
    """The coordinates that balance the generalized ``load`` (N, N·m), from the guess q, or None."""
    import scipy.optimize

    from raildyn.vehicles import _rocking_kernel as kernel

    m = load[2] if load[2] != 0 else -load[3]
    _, dofs, ei, ef, _ = free._tables()
    x1, v1, rails = np.zeros(19), np.zeros(19), np.zeros(9)
    element, deflection, gen = np.zeros(len(ei)), np.zeros(len(ei)), np.zeros(19)

    def residual(x):  # the law of RockingFreightCar.forces, its tables built once
        x1[:18] = x
        kernel.compiled_forces(
            x1, v1, rails, rails, dofs, ei, ef, free.velocity_scale, element, deflection, gen
        )
        return gen[:18] + load

    def jacobian(x):
        J = np.empty((18, 18))
        for i in range(18):
            h = np.zeros(18)
            h[i] = 1e-7
            J[:, i] = (residual(x + h) - residual(x - h)) / 2e-7
        return J

    if np.abs(residual(q)).max() < tol:
        return q
    # From the last balance; else (the body snapping over from its plate's edge onto a side bearer,
    # with no balance between) from the body turned through the bearers' gap.
    snapped = q.copy()
    snapped[2] += np.sign(m) * 1.5 * free.side_bearer_gap / free.side_bearer_spacing
    for guess in (q, snapped):
        sol = scipy.optimize.root(residual, guess, jac=jacobian, method="hybr")
        if np.abs(residual(sol.x)).max() < tol:
            return sol.x
    return None


def linearize(car, engaged: bool) -> SystemMatrices:
    """:meth:`~raildyn.vehicles.rocking.RockingFreightCar.linearized` (see there): K = Σ k g gᵀ + Σ P₀ ∇²δ,
    C = Σ (c + F/v_ε) g gᵀ."""
    from raildyn.vehicles import _rocking_kernel as kernel

    mass, dofs, ei, ef, _ = car._tables()
    n = mass.size
    K, C = np.zeros((n, n)), np.zeros((n, n))
    GK, GC = np.zeros((n, 8)), np.zeros((n, 8))
    for e in range(len(ei)):
        kind, direction, A, B, B2, rail = ei[e]
        P0, k = ef[e, kernel.PRELOAD], ef[e, kernel.STIFFNESS]
        if kind == 1 and P0 <= 0 and not engaged:
            continue
        w = ef[e, kernel.WEIGHT_B]
        g, H = np.zeros(n), np.zeros((n, n))
        for body, x, ay, az, sign in (
            (A, *ef[e, 0:3], -1.0),
            (B, *ef[e, 3:6], w),
            (B2, *ef[e, 3:6], 1 - w),
        ):
            if body == 7:  # the ground
                continue
            iz, ith, iph, iy = (i if i < 18 else -1 for i in dofs[body])
            if direction == 0:
                for i, value in ((iz, 1.0), (ith, x), (iph, ay)):
                    if i >= 0:
                        g[i] += sign * value
                for i in (ith, iph):
                    if i >= 0:
                        H[i, i] += sign * -az
            else:
                for i, value in ((iy, 1.0), (iph, -az)):
                    if i >= 0:
                        g[i] += sign * value
                if iph >= 0:
                    H[iph, iph] += sign * -ay
        K += k * np.outer(g, g) + (P0 if kind == 0 or P0 > 0 else 0.0) * H
        c = ef[e, kernel.DAMPING] + ef[e, kernel.FRICTION] / car.velocity_scale
        C += c * np.outer(g, g)
        if rail < 8:  # δ = rail − Z_A: a rail rising by w pushes A with k w + c ẇ
            GK[:, rail] = -k * g
            GC[:, rail] = -ef[e, kernel.DAMPING] * g
    return SystemMatrices(np.diag(mass), C, K, GK, GC, LABELS, 1.0)
