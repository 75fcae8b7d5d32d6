"""Chapter 4's creepages derived: the slip of each contact point from the velocities of the wheelset;
and the contact trace line of a yawed wheel (:func:`trace_line`).

A wheelset runs at the speed V, moves sideways at ẏ, is yawed by ψ at the rate ψ̇ and spins about
its axle at Ω = V/r₀. The velocity of the wheel's material at each contact point, v_c + ω × r_P,
divided by V, is the creepage there (the rail is at rest): its component along the wheel's rolling
direction is γ_x, across it γ_y, and the angular velocity along the contact normal, tilted by the
contact angle ϑ, gives the spin φ (Kalker 1967; Garg & Dukkipati 1984, ch. 4). Linearised in the
small quantities, these are the creepages of :func:`raildyn.contact.creepages.wheelset_creepages`; the tests
hold the two together.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
import sympy

from raildyn import _checks
from raildyn.derivations._core import Step

__all__ = ["CreepageDerivation", "TraceLineDerivation", "creepages", "trace_line"]

_ARGUMENTS = (
    "speed",
    "lateral_velocity",
    "yaw_angle",
    "yaw_rate",
    "rolling_radius_left",
    "rolling_radius_right",
    "nominal_radius",
    "half_gauge",
    "contact_angle_left",
    "contact_angle_right",
)


@dataclass(frozen=True, eq=False)  # sympy matrices: compared by identity
class CreepageDerivation:
    """The creepages of a wheelset's two contacts, derived symbolically, first order in small quantities.

    Attributes
    ----------
    longitudinal, lateral, spin : sympy.Matrix, shape (2, 1)
        γ_x, γ_y (dimensionless) and φ (1/m) at the left and the right contact.
    symbols : tuple of sympy.Symbol
        V, ẏ, ψ, ψ̇, r_L, r_R, r₀, a, ϑ_L, ϑ_R: the arguments of
        :func:`raildyn.contact.creepages.wheelset_creepages`, in its order (m/s, m/s, rad, rad/s, m, m, m, m,
        rad, rad). Every free symbol of the three matrices is among them.
    steps : tuple of Step
        The derivation, step by step, for a notebook to show.
    """

    longitudinal: sympy.Matrix
    lateral: sympy.Matrix
    spin: sympy.Matrix
    symbols: tuple
    steps: tuple = ()

    def __post_init__(self):
        if not isinstance(self.symbols, tuple) or len(self.symbols) != len(_ARGUMENTS):
            raise TypeError(
                f"symbols must be a tuple of {len(_ARGUMENTS)} sympy Symbols ({', '.join(_ARGUMENTS)}), "
                f"got {self.symbols!r:.80}"
            )
        for i, s in enumerate(self.symbols):
            _checks.instance(f"symbols[{i}]", s, sympy.Symbol)
        for name in ("longitudinal", "lateral", "spin"):
            value = getattr(self, name)
            if not isinstance(value, sympy.MatrixBase) or value.shape != (2, 1):
                raise ValueError(f"{name} must be a sympy Matrix of shape (2, 1), got {value!r:.80}")
            extra = value.free_symbols - set(self.symbols)
            if extra:
                raise ValueError(f"{name} holds symbols that symbols does not list: {extra}")
        if not isinstance(self.steps, tuple):
            raise TypeError(f"steps must be a tuple of Step, got {self.steps!r:.80}")
        for i, step in enumerate(self.steps):
            _checks.instance(f"steps[{i}]", step, Step)

    @functools.cached_property
    def _function(self):
        return sympy.lambdify(
            list(self.symbols), [self.longitudinal, self.lateral, self.spin], modules="numpy"
        )

    def numeric(
        self,
        speed,
        lateral_velocity,
        yaw_angle,
        yaw_rate,
        rolling_radius_left,
        rolling_radius_right,
        nominal_radius,
        half_gauge,
        contact_angle_left=0.0,
        contact_angle_right=0.0,
    ):
        """The derived creepages evaluated, for the arguments of ``raildyn.contact.wheelset_creepages``.

        Parameters
        ----------
        speed : float
            V (m/s), in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`].
        lateral_velocity, yaw_angle, yaw_rate : float
            ẏ (m/s), ψ (rad), ψ̇ (rad/s).
        rolling_radius_left, rolling_radius_right, nominal_radius : float
            r_L, r_R, r₀ (m), each in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
        half_gauge : float
            a (m), half the distance between the contact points, in [0.15, 1.1]
            (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
            "half_gauge").
        contact_angle_left, contact_angle_right : float
            ϑ_L, ϑ_R (rad), in [−π/2, π/2].

        Returns
        -------
        raildyn.contact.WheelsetCreepages
            γ_x, γ_y, φ at the left (index 0) and right (index 1) contacts.
        """
        from raildyn.contact import WheelsetCreepages

        values = (
            _checks.speed("speed", speed),
            _checks.scalar("lateral_velocity", lateral_velocity),
            _checks.scalar("yaw_angle", yaw_angle),
            _checks.scalar("yaw_rate", yaw_rate),
            _checks.plausible("rolling_radius_left", rolling_radius_left, "wheel_radius"),
            _checks.plausible("rolling_radius_right", rolling_radius_right, "wheel_radius"),
            _checks.plausible("nominal_radius", nominal_radius, "wheel_radius"),
            _checks.plausible("half_gauge", half_gauge, "half_gauge"),
            _checks.scalar("contact_angle_left", contact_angle_left, low=-np.pi / 2, high=np.pi / 2),
            _checks.scalar("contact_angle_right", contact_angle_right, low=-np.pi / 2, high=np.pi / 2),
        )
        with np.errstate(over="ignore", invalid="ignore"):
            gx, gy, phi = (np.asarray(m, dtype=float).reshape(2) for m in self._function(*values))
        for name, value in (("longitudinal", gx), ("lateral", gy), ("spin", phi)):
            if not np.all(np.isfinite(value)):
                raise ValueError(
                    f"the {name} creepage overflows for these arguments (speed {values[0]!r} m/s against "
                    f"rates {values[1]!r} m/s, {values[3]!r} rad/s): give rates and a speed of sensible size"
                )
        return WheelsetCreepages(gx, gy, phi)


@functools.cache
def creepages() -> CreepageDerivation:
    """The creepages of a wheelset's contacts from the velocities of the contact points (book ch. 4).

    Track axes x forward, y left, z up; the wheelset's centre moves at (V, ẏ, 0), its axle is turned
    by ψ, and it turns at ω = Ω e_y' + ψ̇ e_z with Ω = V/r₀ and e_y' the axle's direction. The
    contact points lie at ±a along the axle and r_L, r_R below it. The slip velocity of each is
    v_P = v_c + ω × r_P; along the rolling direction e_x' and the axle e_y', divided by V, it gives
    γ_x and γ_y. The contact normal of each wheel is tilted towards the track centre by ϑ,
    n_L = −sin ϑ_L e_y' + cos ϑ_L e_z, n_R = sin ϑ_R e_y' + cos ϑ_R e_z, and φ = ω·n/V. To first
    order in ψ, ẏ/V, aψ̇/V and ϑ (Kalker 1967; Garg & Dukkipati 1984, ch. 4):

        γ_x,L = (r₀ − r_L)/r₀ − aψ̇/V,  γ_x,R = (r₀ − r_R)/r₀ + aψ̇/V,  γ_y = ẏ/V − ψ,
        φ_L = ψ̇/V − ϑ_L/r₀,  φ_R = ψ̇/V + ϑ_R/r₀.

    :func:`raildyn.contact.creepages.wheelset_creepages` writes the spin's second term as sin ϑ/r (the
    book's form), which differs from ϑ/r₀ only in terms of second order.

    Returns
    -------
    CreepageDerivation

    Examples
    --------
    >>> d = creepages()
    >>> d.lateral[0]
    -psi + y_dot/V
    >>> c = d.numeric(40.0, 0.0, 0.0, 0.0, 0.46 + 1.5e-4, 0.46 - 1.5e-4, 0.46, 0.75)
    >>> np.round(c.longitudinal * 1e4, 4).tolist()
    [-3.2609, 3.2609]
    """
    V, r0, a, rL, rR = sympy.symbols("V r_0 a r_L r_R", positive=True)
    yd, psi, psid, thL, thR = sympy.symbols("y_dot psi psi_dot vartheta_L vartheta_R", real=True)
    eps = sympy.Symbol("epsilon")  # bookkeeping: the order of each small quantity
    Omega = V / r0
    # Axes turned by the yaw: the rolling direction and the axle.
    ex = sympy.Matrix([sympy.cos(psi), sympy.sin(psi), 0])
    ey = sympy.Matrix([-sympy.sin(psi), sympy.cos(psi), 0])
    ez = sympy.Matrix([0, 0, 1])
    omega = Omega * ey + psid * ez
    centre = sympy.Matrix([V, yd, 0])
    point = {"L": a * ey - rL * ez, "R": -a * ey - rR * ez}
    normal = {"L": -sympy.sin(thL) * ey + sympy.cos(thL) * ez, "R": sympy.sin(thR) * ey + sympy.cos(thR) * ez}
    small = {psi: eps * psi, yd: eps * yd, psid: eps * psid, thL: eps * thL, thR: eps * thR}

    def first_order(expr):
        # Small quantities scaled by ε; the series to O(ε) keeps the terms of first order (the
        # rolling-radius differences r − r₀ appear linearly already).
        scaled = expr.subs(small, simultaneous=True)
        return sympy.expand(scaled.subs(eps, 0) + scaled.diff(eps).subs(eps, 0))

    slip, gx, gy, phi, steps = {}, [], [], [], []
    for side in ("L", "R"):
        v = centre + omega.cross(point[side])
        slip[side] = v
        gx.append(first_order(v.dot(ex) / V))
        gy.append(first_order(v.dot(ey) / V))
        phi.append(first_order(omega.dot(normal[side]) / V))
        steps += [
            Step(
                f"slip velocity of the {'left' if side == 'L' else 'right'} contact point, v_c + ω × r_P "
                "(track axes)",
                sympy.Eq(sympy.Symbol(f"v_{side}"), sympy.expand(v), evaluate=False),
            ),
            Step(
                f"spin of the {'left' if side == 'L' else 'right'} wheel, ω·n/V",
                sympy.Eq(
                    sympy.Symbol(f"varphi_{side}"), sympy.expand(sympy.trigsimp(omega.dot(normal[side]) / V))
                ),
            ),
        ]
    out = {"longitudinal": sympy.Matrix(gx), "lateral": sympy.Matrix(gy), "spin": sympy.Matrix(phi)}
    steps += [
        Step(
            "longitudinal creepages (left, right), first order",
            sympy.Eq(sympy.Symbol("gamma_x"), out["longitudinal"], evaluate=False),
        ),
        Step(
            "lateral creepages (left, right), first order",
            sympy.Eq(sympy.Symbol("gamma_y"), out["lateral"], evaluate=False),
        ),
        Step(
            "spin creepages (left, right), first order",
            sympy.Eq(sympy.Symbol("varphi"), out["spin"], evaluate=False),
        ),
    ]
    return CreepageDerivation(**out, symbols=(V, yd, psi, psid, rL, rR, r0, a, thL, thR), steps=tuple(steps))


@dataclass(frozen=True, eq=False)  # sympy expressions: compared by identity
class TraceLineDerivation:
    """The contact trace line of a yawed wheel, derived symbolically (left wheel).

    Attributes
    ----------
    sin_theta : sympy.Expr
        sin θ of the wheel angle θ at which the wheel's surface, at its profile point u, can touch a
        prismatic rail: r′ tan ψ.
    lateral_seen, radius_seen, lead : sympy.Expr
        u_e, r_e and x: where that point lies across the track (m, from the tape circle's place
        square to the track, towards the flange), below the axle (m) and ahead of it (m).
    symbols : tuple of sympy.Symbol
        u, r, r′, ψ, T: the profile point (m), its radius (m) and slope, the yaw (rad) and the
        tape-circle distance (m), as :func:`raildyn.contact.trace_line.trace_line` takes them.
    steps : tuple of Step
        The derivation, step by step.
    """

    sin_theta: sympy.Expr
    lateral_seen: sympy.Expr
    radius_seen: sympy.Expr
    lead: sympy.Expr
    symbols: tuple
    steps: tuple = ()

    def __post_init__(self):
        for name in ("sin_theta", "lateral_seen", "radius_seen", "lead"):
            _checks.instance(name, getattr(self, name), sympy.Expr)
        if not isinstance(self.symbols, tuple) or len(self.symbols) != 5:
            raise TypeError(
                f"symbols must be a tuple of 5 sympy Symbols (u, r, r′, ψ, T), got {self.symbols!r:.80}"
            )
        if not isinstance(self.steps, tuple):
            raise TypeError(f"steps must be a tuple of Step, got {self.steps!r:.80}")
        for i, step in enumerate(self.steps):
            _checks.instance(f"steps[{i}]", step, Step)


@functools.cache
def trace_line() -> TraceLineDerivation:
    """Where a yawed wheel can touch its rail: the condition on the surface normal, solved (book ch. 4).

    The left wheel is a body of revolution about the axle: its point at the axle coordinate
    s = T/2 − u (u the profile coordinate, positive towards the flange, inboard) and wheel angle θ
    lies at (r sin θ, s, −r cos θ) in the wheelset's axes, with the outward normal
    (sin θ, −dr/ds, −cos θ) = (sin θ, r′, −cos θ). Turned by ψ (nose to the left), its component along
    the track must vanish for the point to touch a rail that is straight along the track:
    sin θ cos ψ − r′ sin ψ = 0, that is sin θ = r′ tan ψ, θ measured forward; the point then lies
    r r′ sin ψ ahead of the axle (the module :mod:`raildyn.contact.trace_line` states the line).

    Returns
    -------
    TraceLineDerivation

    Examples
    --------
    >>> d = trace_line()
    >>> d.sin_theta
    r_prime*tan(psi)
    """
    u, r, T = sympy.symbols("u r T", positive=True)
    rp, psi, theta = sympy.symbols("r_prime psi theta", real=True)
    s = T / 2 - u
    point = sympy.Matrix([r * sympy.sin(theta), s, -r * sympy.cos(theta)])
    normal = sympy.Matrix([sympy.sin(theta), rp, -sympy.cos(theta)])  # dr/ds = −r′
    # The wheelset turned by ψ about the vertical (nose to the left): its axes in the track's.
    turn = sympy.Matrix(
        [[sympy.cos(psi), -sympy.sin(psi), 0], [sympy.sin(psi), sympy.cos(psi), 0], [0, 0, 1]]
    )
    longitudinal = sympy.simplify((turn * normal)[0])
    solved = sympy.solve(sympy.Eq(longitudinal, 0), sympy.sin(theta))
    sin_theta = sympy.simplify(solved[0]) if solved else rp * sympy.tan(psi)
    at = {sympy.sin(theta): sin_theta, sympy.cos(theta): sympy.sqrt(1 - sin_theta**2)}
    where = (turn * point).subs(at)
    lateral_seen = sympy.simplify(T / 2 - where[1])
    radius_seen = sympy.simplify(-where[2])
    lead = sympy.simplify(where[0] - (turn * sympy.Matrix([0, s, 0]))[0])
    steps = (
        Step(
            "a point of the left wheel, in the wheelset's axes",
            sympy.Eq(sympy.Symbol("P"), point, evaluate=False),
        ),
        Step("its outward normal", sympy.Eq(sympy.Symbol("n"), normal, evaluate=False)),
        Step("its longitudinal component in the track's axes must vanish", sympy.Eq(longitudinal, 0)),
        Step("so the wheel angle of the touching point", sympy.Eq(sympy.sin(theta), sin_theta)),
        Step("the point across the track, from the tape circle", sympy.Eq(sympy.Symbol("u_e"), lateral_seen)),
        Step("below the axle", sympy.Eq(sympy.Symbol("r_e"), radius_seen)),
        Step("ahead of the axle", sympy.Eq(sympy.Symbol("x"), lead)),
    )
    return TraceLineDerivation(sin_theta, lateral_seen, radius_seen, lead, (u, r, rp, psi, T), steps)
