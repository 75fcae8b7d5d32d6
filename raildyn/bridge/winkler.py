"""An infinite beam on a Winkler foundation under a constant moving force (book chapter 10).

The rail on its bed, or a long viaduct on soft supports: a beam of flexural rigidity EI and mass
m̄ per length rests on springs of modulus k (N/m per m of beam) and dashpots c (N·s/m per m), and
a force P moves along it at the speed V. In the coordinate x̄ = x − Vt that travels with the force
(x̄ > 0 ahead of it; the ``x`` that the methods take) the steady state obeys, with ′ = d/dx̄,

    EI w'''' + m̄ V² w'' − c V w' + k w = P δ_D(x̄)

(Frýba 1972, ch. 9; Kenney 1954). Scaled by the characteristic length 1/Ω_W, Ω_W = (k/(4EI))^{1/4},
and with the speed ratio α = V/V_cr, V_cr = (4kEI/m̄²)^{1/4}, and the foundation's damping ratio
ξ = c/(2√(km̄)), its characteristic polynomial in ρ = r/Ω_W (w ∝ e^{r x}) is

    ρ⁴/4 + α² ρ² − 2ξα ρ + 1 = 0.

Its roots give the steady deflection in closed form: for x > 0 the two with Re ρ < 0, for x < 0
the two with Re ρ > 0, each weighted by its residue (the Fourier integral of the solution closed
in the upper or lower half plane). Undamped, the roots reach the imaginary axis at α = 1, where
the deflection grows without bound: the critical speed. Damped, no root ever reaches the axis, and
the steady state exists at every speed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn.bridge.track import _frequencies as track_frequencies
from raildyn.bridge.track import beam_receptance

__all__ = ["WinklerBeam"]

# One UIC 60 rail (Esveld 2001, Modern Railway Track, table of rail profiles: I = 3055 cm⁴,
# 60.34 kg/m; E = 210 GPa) on a ballasted bed of 50 MN/m² per rail (within the 40–100 MN/m² that
# Esveld 2001, ch. 5, gives for the foundation modulus of ballasted track).
_RAIL_EI = 210e9 * 3055e-8  # N·m²
_RAIL_MASS = 60.34  # kg/m
_BED_MODULUS = 50.0e6  # N/m²

_MAX_SPEED_RATIO = 100.0  # v/v_cr: far beyond any train


@dataclass(frozen=True)
class WinklerBeam:
    """An infinite Euler–Bernoulli beam on a viscously damped Winkler foundation.

    Attributes
    ----------
    flexural_rigidity : float
        EI, N·m², in [1, 1e16] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "flexural_rigidity").
        Default: one UIC 60 rail,
        6.42 MN·m² (Esveld 2001).
    mass_per_length : float
        m, kg/m, in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "beam_mass"). Default: the rail's
        60.34 kg/m.
    foundation_modulus : float
        k, N/m² (N/m of deflection per m of beam, > 0). Default: 50 MN/m², a ballasted bed.
    damping : float
        c, N·s/m² (≥ 0), the foundation's viscous damping per length.

    Examples
    --------
    The rail on its bed: Ω_W, the deflection under a 100 kN wheel at rest and the critical speed:

    >>> rail = WinklerBeam()
    >>> round(rail.characteristic_length, 4), round(float(1e3 * rail.static_deflection([0.0], 1e5)[0]), 3)
    (1.1815, 1.181)
    >>> round(rail.critical_speed, 1)
    770.5
    """

    flexural_rigidity: float = _RAIL_EI
    mass_per_length: float = _RAIL_MASS
    foundation_modulus: float = _BED_MODULUS
    damping: float = 0.0

    def __post_init__(self):
        for name in ("flexural_rigidity", "mass_per_length", "foundation_modulus"):
            _checks.positive(name, getattr(self, name))
        _checks.plausible("flexural_rigidity", self.flexural_rigidity, "flexural_rigidity")
        _checks.plausible("mass_per_length", self.mass_per_length, "beam_mass")
        _checks.nonnegative("damping", self.damping)

    @property
    def characteristic_length(self) -> float:
        """Ω_W = (k/(4EI))^{1/4}, 1/m (Hetényi 1946), a wavenumber despite the name: 1/Ω_W is the length
        over which the deflection decays."""
        return (self.foundation_modulus / (4 * self.flexural_rigidity)) ** 0.25

    @property
    def critical_speed(self) -> float:
        """v_cr = (4kEI/m̄²)^{1/4}, m/s: the undamped steady state grows without bound as v → v_cr.

        (Kenney 1954; Frýba 1972, ch. 9.)
        """
        return (4 * self.foundation_modulus * self.flexural_rigidity / self.mass_per_length**2) ** 0.25

    @property
    def damping_ratio(self) -> float:
        """ξ = c/(2√(km̄)): the foundation's damping relative to its critical value."""
        return self.damping / (2 * np.sqrt(self.foundation_modulus * self.mass_per_length))

    def receptance(self, frequencies) -> np.ndarray:
        """α(f) = w/F under a harmonic point force at the frequencies f, m/N (complex).

        :func:`raildyn.bridge.track.beam_receptance` with s(ω) = k + iωc − m̄ω²; at f = 0 it is
        :meth:`static_deflection` at x = 0 per newton.

        Parameters
        ----------
        frequencies : float or array_like
            f, Hz, a number or a 1-D array, each in [0, 10 000] (undamped, not at the beam's
            cut-off √(k/m̄)/(2π), where s = 0).

        Returns
        -------
        ndarray of complex
            One per frequency.
        """
        w = 2.0 * np.pi * track_frequencies(frequencies)
        s = self.foundation_modulus + 1j * w * self.damping - self.mass_per_length * w**2
        return beam_receptance(self.flexural_rigidity, s)

    def static_deflection(self, x, force) -> np.ndarray:
        """The deflection under a force at rest at x = 0, m (Hetényi 1946).

        w(x) = (PΩ_W/(2k)) e^{−Ω_W|x|} (cos Ω_W|x| + sin Ω_W|x|).

        Parameters
        ----------
        x : array_like, (n,)
            Distance from the force, m (finite, at least one).
        force : float
            P, N (finite; downwards positive gives a downward, positive deflection).

        Returns
        -------
        ndarray, (n,)
            w, m.
        """
        xs = np.abs(_checks.array("x", x, ndim=1, allow_empty=False))
        P = _checks.scalar("force", force)
        b = self.characteristic_length
        bx = b * xs
        return P * b / (2 * self.foundation_modulus) * np.exp(-bx) * (np.cos(bx) + np.sin(bx))

    def steady_deflection(self, x, speed, force) -> np.ndarray:
        """The steady deflection about a force moving at constant speed, m, in the moving coordinate.

        The closed form of the module docstring: with ρ_j the roots of ρ⁴/4 + α²ρ² − 2ξαρ + 1 and
        p′ the derivative of the (dimensional) polynomial EI r⁴ + m̄ v² r² − c v r + k,
        w(x) = P Σ_{Re r_j < 0} e^{r_j x}/p′(r_j) ahead of the force (x ≥ 0) and
        w(x) = −P Σ_{Re r_j > 0} e^{r_j x}/p′(r_j) behind it (Frýba 1972, ch. 9).

        Parameters
        ----------
        x : array_like, (n,)
            Distance ahead of the force (negative: behind), m (finite, at least one).
        speed : float
            v, m/s, in [0, :data:`~raildyn.constants.MAXIMUM_SPEED`] and at most 100 v_cr; without damping
            it must stay below the critical speed,
            where the undamped steady state does not exist.
        force : float
            P, N (finite; downwards positive).

        Returns
        -------
        ndarray, (n,)
            w, m (downwards positive).

        Examples
        --------
        At half the critical speed the rail deflects 15 % more under the wheel than at rest:
        undamped, the roots are ρ = ±√(1 − α²) ± i√(1 + α²), and their residues sum at x = 0 to
        (PΩ_W/(2k))/√(1 − α²). On its ballasted bed the rail's critical speed (770 m/s) lies far
        beyond any train; on a foundation 500 times softer it falls to 163 m/s, within reach:

        >>> soft = WinklerBeam(foundation_modulus=1.0e5)
        >>> round(soft.critical_speed, 1)
        162.9
        >>> w = soft.steady_deflection([0.0], 0.5 * soft.critical_speed, 1e5)[0]
        >>> round(float(w / soft.static_deflection([0.0], 1e5)[0]), 4)
        1.1547
        """
        xs = _checks.array("x", x, ndim=1, allow_empty=False)
        vcr = self.critical_speed
        v = _checks.speed("speed", speed, low_open=False)
        if v > _MAX_SPEED_RATIO * vcr:
            raise ValueError(
                f"speed must be at most {_MAX_SPEED_RATIO:g} v_cr = {_MAX_SPEED_RATIO * vcr:.4g} m/s, "
                f"got {speed!r}"
            )
        P = _checks.scalar("force", force)
        zeta = self.damping_ratio
        alpha = v / vcr
        if zeta == 0.0 and alpha >= 1.0 - 1e-9:
            raise ValueError(
                f"speed must be below the critical speed {vcr:.6g} m/s on an undamped foundation (the "
                f"steady deflection grows without bound as v → v_cr), got {speed!r}; add damping to go beyond"
            )
        rho = np.roots([0.25, 0.0, alpha**2, -2 * zeta * alpha, 1.0])
        b = self.characteristic_length
        r = b * rho
        dp = (
            4 * self.flexural_rigidity * r**3 + 2 * self.mass_per_length * v**2 * r - self.damping * v
        )  # p′(r)
        ahead = rho.real < 0
        if np.count_nonzero(ahead) != 2:  # no root on the axis: two decay ahead, two behind
            raise ValueError(f"speed {speed!r} puts a root of the characteristic polynomial on the axis")
        w = np.empty(xs.size)
        front = xs >= 0
        # Each term decays away from the force: e^{r x} with Re r < 0 ahead, Re r > 0 behind.
        w[front] = np.real((np.exp(np.outer(xs[front], r[ahead])) / dp[ahead]).sum(axis=1))
        w[~front] = -np.real((np.exp(np.outer(xs[~front], r[~ahead])) / dp[~ahead]).sum(axis=1))
        return P * w
