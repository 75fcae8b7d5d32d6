"""The friction wedges of a three-piece truck: the force they rub with and the energy they dissipate.

Each spring nest of a three-piece truck carries friction wedges that rub with a nearly constant
force F against the relative motion (Coulomb, :func:`raildyn.suspension.coulomb_friction`).
:func:`wedge_friction_force` gives F from the wedge geometry (:class:`WedgeFriction`), and
:func:`wedge_energy_per_cycle` the energy dissipated over one cycle of imposed harmonic motion
(4 F X for the ideal law), from which the equivalent viscous damper of a linear model follows.
Both the vertical freight car (:mod:`raildyn.vehicles.freight`) and the lateral three-piece truck
(:mod:`raildyn.vehicles.three_piece`) use them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.suspension import coulomb_friction

__all__ = ["WedgeFriction", "wedge_energy_per_cycle", "wedge_friction_force"]


def wedge_energy_per_cycle(
    friction_force, amplitude, frequency, *, velocity_scale=None, n: int = 20_000
) -> float:
    """Energy a wedge dissipates over one cycle of imposed motion X sin ωt: ∮ F(v) v dt.

    With the ideal law (no ``velocity_scale``) the result is 4 F X, returned in that closed form: the
    kinks of F sgn(cos ωt) at the turning points would hold a quadrature to an error of about h²/24
    (4e-9 of 4FX at n = 20 000), which a model compared with its derivation would show.

    Parameters
    ----------
    friction_force : float
        F, N (≥ 0).
    amplitude : float
        X, m (> 0).
    frequency : float
        Hz (> 0).
    velocity_scale : float, optional
        v_ε of the smooth law F tanh(v/v_ε), m/s, in [1e-6, 1]; None for the ideal law.
    n : int
        Midpoint samples over the cycle for the smooth law, in [16, 10⁶]: the midpoint rule on this
        smooth periodic integrand has converged to rounding long before the upper bound, which keeps
        the work and memory small.

    Returns
    -------
    float
        J.

    Raises
    ------
    ValueError
        If the energy overflows a float (F X beyond about 1e307 J).
    """
    F = _checks.nonnegative("friction_force", friction_force)
    X = _checks.positive("amplitude", amplitude)
    w = 2 * np.pi * _checks.positive("frequency", frequency)
    if velocity_scale is not None:
        v_eps = _checks.scalar("velocity_scale", velocity_scale)
        velocity_scale = float(_checks.smoothing_speed("velocity_scale", v_eps))
    n = _checks.integer("n", n, low=16, high=10**6)
    if velocity_scale is None:
        energy = 4.0 * F * X
        if not np.isfinite(energy):
            raise ValueError(
                f"friction_force {F!r} N times amplitude {X!r} m overflows: the energy is not a finite float"
            )
        return energy
    phase = (np.arange(n) + 0.5) * (2 * np.pi / n)  # ωt at the midpoints: the integrand is periodic
    force = coulomb_friction(X * w * np.cos(phase), F, velocity_scale=velocity_scale)
    # ∮ F(v) v dt with v = Xω cos ωt and dt = dφ/ω: X ∮ F(v) cos φ dφ, no product of large numbers.
    energy = float(X * (np.sum(force * np.cos(phase)) * (2 * np.pi / n)))
    if not np.isfinite(energy):
        raise ValueError(
            f"friction_force {F!r} N times amplitude {X!r} m overflows: the energy is not a finite float"
        )
    return energy


@dataclass(frozen=True)
class WedgeFriction:
    """Column friction of the wedges of one nest, N, in each direction of the bolster's motion.

    Attributes
    ----------
    bolster_down, bolster_up : float
        N, ≥ 0.
    """

    bolster_down: float
    bolster_up: float

    def __post_init__(self):
        for name in ("bolster_down", "bolster_up"):
            object.__setattr__(self, name, _checks.nonnegative(name, getattr(self, name)))

    @property
    def mean(self) -> float:
        """The symmetric friction force that stands for both, N."""
        return 0.5 * (self.bolster_down + self.bolster_up)


def wedge_friction_force(
    spring_force, slope_angle, friction_coefficient, *, wedges: int = 2
) -> WedgeFriction:
    """Column friction of the spring-loaded wedges of one nest, bolster moving down and moving up.

    A constant-damping wedge sits between the vertical column face of the side
    frame and a slope of the bolster inclined ``slope_angle`` (rad) from the
    vertical; its spring presses it along the vertical with ``spring_force`` P.
    The wedge moves with the bolster and rubs on the column with μ times the
    column's normal force N. Its balance, with the slope taken as frictionless,
    reads N = N_b cos α and P ± μN = N_b sin α, so that

        N = P / (tan α ∓ μ),

    the upper sign when the bolster moves down (friction on the wedge acts up,
    with the spring), the lower when it moves up. The two friction forces μN of
    ``wedges`` wedges are returned. A slope with tan α <= μ locks the wedge.

    Parameters
    ----------
    spring_force : float
        P, the wedge spring's force, N (≥ 0).
    slope_angle : float
        α, rad, in (0, π/2).
    friction_coefficient : float
        μ at the column (≥ 0).
    wedges : int
        Wedges per nest (≥ 1).

    Returns
    -------
    WedgeFriction
    """
    P = _checks.nonnegative("spring_force", spring_force)
    alpha = _checks.scalar("slope_angle", slope_angle, low=0.0, high=np.pi / 2, low_open=True, high_open=True)
    mu = _checks.nonnegative("friction_coefficient", friction_coefficient)
    n = _checks.integer("wedges", wedges, low=1)
    if np.tan(alpha) <= mu:
        raise ValueError(
            f"slope_angle {slope_angle!r} rad locks the wedge: tan α = {np.tan(alpha):.4g} must exceed "
            f"friction_coefficient {mu!r}"
        )
    down = n * mu * P / (np.tan(alpha) - mu)
    up = n * mu * P / (np.tan(alpha) + mu)
    return WedgeFriction(float(down), float(up))
