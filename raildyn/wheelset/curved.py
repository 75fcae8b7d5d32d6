"""A wheelset on a curve (book chapters 5 and 8): the pure-rolling offset and the loads of an arc.

The offset at which a free coned wheelset rolls round a curve
(:func:`~raildyn.wheelset.pure_rolling_offset`), where an arc puts the track under a wheelset
(:func:`~raildyn.wheelset.track_on_arc`, the one place this geometry is written) and the loads
that a curve puts on a linear wheelset (:func:`~raildyn.wheelset.curve_loads`), from which
:func:`raildyn.curving.steady.steady_curving` finds the steady state of any vehicle. The
sharpest curve accepted is :data:`raildyn.track.cant.MINIMUM_RADIUS`. SI units throughout.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn._checks import positive, scalar
from raildyn.track.cant import MINIMUM_RADIUS
from raildyn.wheelset.kinematics import _coned_wheelset
from raildyn.wheelset.linear import Wheelset, creep_terms

__all__ = ["curve_loads", "pure_rolling_offset", "track_on_arc"]


def pure_rolling_offset(rolling_radius, half_gauge, conicity, radius) -> float:
    """Lateral offset at which a free coned wheelset rolls round a curve without slip, m.

    y₀ = r₀ a / (λ R), towards the outer rail (Garg & Dukkipati 1984, ch. 5; Wickens 2003,
    ch. 7): the outer wheel then rolls on a radius larger by λ y₀, enough to cover the outer
    rail's extra length a/R per metre.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m), a (m) and λ, as for :func:`kinematic_wavelength` (each in its range there).
    radius : float
        R, radius of the curve, m (> 0).

    Returns
    -------
    float
        y₀, m (≥ 0, towards the outer rail).

    Examples
    --------
    A wheelset of conicity 0.15 in a curve of 600 m runs 3.8 mm towards the outer rail:

    >>> round(1e3 * pure_rolling_offset(0.46, 0.75, 0.15, 600.0), 2)
    3.83
    """
    r0, a, lam = _coned_wheelset(rolling_radius, half_gauge, conicity)
    return float(r0 * a / (lam * positive("radius", radius)))


_MAX_POSITION = 100.0  # m: a wheelset's distance from the centre of its vehicle


def track_on_arc(position, curvature) -> tuple[np.ndarray, np.ndarray]:
    """Where an arc puts the track under a wheelset, in axes tangent to it at their origin.

    A wheelset x ahead of the origin of axes that follow the vehicle round an arc of curvature
    κ = 1/R meets the track's centre line displaced by y_t = ½x²κ and turned by ψ_t = xκ (the
    small-angle arc; Garg & Dukkipati 1984, ch. 8). The one place this geometry is written:
    :func:`curve_loads`, :meth:`NonlinearLateral.arc_forces` and the curving models use it.

    Parameters
    ----------
    position : float or array_like
        x, m, each within ±100 m (a wheelset's place along its vehicle); not empty.
    curvature : float or array_like
        κ, 1/m, each within ±1/50 m (the sharpest curve of :mod:`raildyn.track.cant`),
        broadcasting with ``position``; not empty.

    Returns
    -------
    y_t : ndarray
        m, to the left (towards the centre of a left-hand curve).
    psi_t : ndarray
        rad, anticlockwise.

    Examples
    --------
    >>> y_t, psi_t = track_on_arc(10.0, 1 / 500.0)
    >>> round(float(y_t), 3), round(float(psi_t), 3)
    (0.1, 0.02)
    """
    x = _checks.array("position", position, allow_empty=False)
    kappa = _checks.array("curvature", curvature, allow_empty=False)
    scalar("position", np.abs(x).max(), high=_MAX_POSITION)
    scalar("curvature", np.abs(kappa).max(), high=1.0 / MINIMUM_RADIUS)
    _checks.broadcast(position=x, curvature=kappa)
    return 0.5 * x * x * kappa, x * kappa


def curve_loads(ws: Wheelset, radius, position=0.0) -> np.ndarray:
    """The wheel–rail loads [F_y, M_z] that a curve puts on a wheelset, N and N·m.

    The vehicle is described in axes that follow it round a curve to the left of
    radius R (turning at V/R, their origin on the track's centre line, x along its
    tangent there). A wheelset x ahead of the origin meets the track displaced by
    y_t = x²/(2R) and turned by ψ_t = x/R, and its yaw rate is ψ̇ + V/R. So in the
    linear wheel–rail terms of :func:`creep_terms` the displacement becomes
    q − q_t and ψ̇/V becomes ψ̇/V + 1/R:

        f = (K_creep + K_gravity) q_t − C₁ [0, 1]ᵀ / R.

    The second term holds the longitudinal creepage a/R of the outer rail's extra
    length and the spin 1/R (Garg & Dukkipati 1984, ch. 5 and 8; Wickens 2003, ch. 7).
    These loads are independent of the speed; the cant deficiency's force acts on
    every mass and is added by :func:`raildyn.curving.steady.steady_curving`.

    Parameters
    ----------
    ws : Wheelset
    radius : float
        R, m, at least 50 (:data:`raildyn.track.cant.MINIMUM_RADIUS`; the curve turns to
        the left, +y).
    position : float
        x, the wheelset's distance ahead of the axes' origin, m, in [−100, 100] (negative
        behind): the axes follow one vehicle, and x/R must stay a small angle.

    Returns
    -------
    ndarray, (2,)
        [F_y (N), M_z (N·m)] on the wheelset held at q = 0 in the curve's axes.

    Examples
    --------
    A lone centred wheelset feels the yaw moment of its longitudinal creep, −2a²f₁₁/R:

    >>> ws = Wheelset(f23=0.0, f33=0.0)
    >>> F = curve_loads(ws, 600.0)
    >>> bool(np.isclose(F[1], -2 * ws.half_gauge**2 * ws.f11 / 600.0))
    True
    """
    terms = creep_terms(_checks.instance("ws", ws, Wheelset))
    R = scalar("radius", radius, low=MINIMUM_RADIUS)
    x = scalar("position", position, low=-_MAX_POSITION, high=_MAX_POSITION)
    track = np.array(track_on_arc(x, 1.0 / R))
    return (terms.K_creep + terms.K_gravity) @ track - terms.C1[:, 1] / R
