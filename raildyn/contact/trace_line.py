"""The contact trace line of a yawed wheel: the wheel profile that a yawed wheelset shows the rail.

A wheelset square to the track touches each rail in the vertical plane of its axle, and the wheel's
cross-section there is its profile r(u). Yawed by ψ, the wheel is a body of revolution about an axle
that no longer lies across the track: the points where its surface can touch a prismatic rail are those
whose normal has no longitudinal component, a line over the tread and flange that leads or lags the
axle (the contact trace line; Wang Kaiyun 1984, *The track of wheel contact points and the calculation
of wheel/rail geometric contact parameters*, J. Southwest Jiaotong University 1).

At the point of the wheel's profile u (positive towards the flange), of radius r and slope r′ = dr/du,
the wheel angle θ of the trace point satisfies sin θ = r′ tan ψ, and the point lies

* across the track, towards the flange, at u_e = u cos ψ + (T/2)(1 − cos ψ) − r r′ tan ψ sin ψ
  (T the tape-circle distance: the axle's projection shortens as it yaws);
* below the axle at r_e = r cos θ;
* ahead of the axle at x = ± r r′ sin ψ (+ on the left wheel, − on the right; the lead of the
  contact point, about r tan ϑ ψ: 13 mm on a 70° flange at 10 mrad).

Both wheels show the same profile (u_e, r_e): ψ enters it only through cos ψ and tan ψ sin ψ, which
are even. The rail sees that profile exactly as it sees an unyawed wheel's, so the planar search of
:func:`raildyn.contact.geometry.contact_geometry` runs on it unchanged; only the lead is odd in ψ.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

__all__ = ["MAX_YAW", "trace_line"]

_RADIUS_MAX = 2.0  # m; the largest railway wheels (steam locomotives' drivers) have a radius of ~1.1 m
# m: tape-circle distances from metre gauge (1.06 m) to the broadest, 1.676 m (1.74 m), with a margin.
_TAPE = (0.5, 2.0)

#: rad: the largest yaw the trace line takes. Beyond some 30 mrad the trace line folds over itself at the
#: flange root of a new profile (du_e/du = cos ψ − (r r′)′ tan ψ sin ψ, with (r r′)′ near 900 in the root's
#: 13 mm radius, reaches zero), where the lowest point is no longer one point of the line; a wheelset in
#: a 150 m curve yaws by some 10 to 15 mrad.
MAX_YAW = 0.03


def trace_line(lateral, radius, yaw, tape_distance):
    """The contact trace line of a wheel profile yawed by ``yaw``: where it can touch a prismatic rail.

    Parameters
    ----------
    lateral : array_like, (n,)
        u, the profile's lateral positions, m, positive towards the flange, strictly increasing (≥ 2).
    radius : array_like, (n,)
        r(u), the rolling radius at each, m, in (0, 2].
    yaw : float
        ψ, rad, in [−:data:`MAX_YAW`, :data:`MAX_YAW`].
    tape_distance : float
        T, the distance between the wheelset's tape circles, m, in [0.5, 2] (metre gauge to the broadest).

    Returns
    -------
    lateral_seen : ndarray, (n,)
        u_e, where each point of the line lies across the track, m (the module docstring).
    radius_seen : ndarray, (n,)
        r_e, how far below the axle it lies, m.
    lead : ndarray, (n,)
        r r′ sin ψ, how far ahead of the axle it lies on the left wheel, m (behind, on the right).

    Raises
    ------
    ValueError
        If the line folds over itself on this profile at this yaw (u_e not increasing), naming ``yaw``.

    Examples
    --------
    A 1:20 cone yawed by 10 mrad: the line lies r λ sin ψ = 0.23 mm ahead of the axle at the tape circle.

    >>> u = np.linspace(-0.05, 0.05, 11)
    >>> _, _, lead = trace_line(u, 0.46 + u / 20, 0.01, 1.5)
    >>> round(1e3 * float(lead[5]), 3)
    0.23
    """
    lateral = _checks.increasing("lateral", lateral)
    radius = _checks.array("radius", radius, shape=lateral.shape, low=0.0, low_open=True)
    if radius.max() > _RADIUS_MAX:
        raise ValueError(f"radius must be <= {_RADIUS_MAX} m (a railway wheel), got {radius.max()!r}")
    tape_distance = _checks.scalar("tape_distance", tape_distance, low=_TAPE[0], high=_TAPE[1])
    psi = _checks.scalar("yaw", yaw, low=-MAX_YAW, high=MAX_YAW)
    slope = np.gradient(radius, lateral)
    sin_theta = slope * np.tan(psi)
    u_e = lateral * np.cos(psi) + 0.5 * tape_distance * (1.0 - np.cos(psi)) - radius * sin_theta * np.sin(psi)
    if np.any(np.abs(sin_theta) >= 1.0) or np.any(np.diff(u_e) <= 0.0):
        raise ValueError(
            f"yaw must leave the wheel's contact trace line single-valued, got yaw = {psi!r} rad, which "
            f"folds it over on this profile (a flange root too sharp for that yaw); allowed |yaw| ≤ {MAX_YAW}"
        )
    r_e = radius * np.sqrt(1.0 - sin_theta**2)
    lead = radius * slope * np.sin(psi)
    return u_e, r_e, lead
