"""Lateral and vertical effects of coupler forces: string-lining, jack-knifing and wheel unloading.

On a curve the coupler between two vehicles is not in line with either body:
it follows the track tangent at the joint while each body follows the chord
through its truck centres. For vehicles centred on the track, the angle between
coupler and body is the angle the track turns between the vehicle centre and the
joint, ``θ ≈ κ (L_i + L_{i+1})/4`` for curvature ``κ`` and lengths ``L`` (exact for
two equal vehicles on a circle, with a relative error of order (κL)² otherwise).
A tension ``F`` then pulls each body end toward the inside of the curve with
``F sin θ`` (string-lining); a compression pushes it outward (jack-knifing)
{cole2006}. The same geometry in the vertical plane, with the vertical curvature
of a sag or crest, gives the vertical force that unloads the trucks.

Each body carries the end forces to its two trucks as a beam on two supports;
the truck-side ``L/V`` is the truck's lateral force over the vertical load on
one rail under the truck, ``m g/4``. The steady curving forces of the trucks
themselves (chapter 8) are not included.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.constants import GRAVITY
from raildyn.train.vehicles import Consist

__all__ = ["CouplerEffects", "coupler_angles", "coupler_effects", "limiting_coupler_force"]


def coupler_angles(consist: Consist, curvature) -> np.ndarray:
    """Angle between each coupler and the bodies it joins, ``θ = κ (L_i + L_{i+1})/4``.

    Parameters
    ----------
    consist : Consist
        The vehicles, front first.
    curvature : float or array (n−1,)
        Track curvature κ at the couplers, 1/m: a number, or one value per coupler
        (its sign gives the sign of the angle). At each coupler ``|κ| L <= 2`` for both
        vehicle lengths ``L``: a vehicle longer than the curve's diameter cannot sit on it.

    Returns
    -------
    ndarray (n−1,)
        Angles, rad, front coupler first.

    Examples
    --------
    >>> from raildyn.train import make_consist
    >>> coupler_angles(make_consist("3 loaded hopper"), 1 / 200).round(4)  # rad
    array([0.0404, 0.0404])
    """
    _checks.instance("consist", consist, Consist)
    return _angles(consist, curvature, "curvature")


def _angles(consist: Consist, curvature, name: str) -> np.ndarray:
    """:func:`coupler_angles` of a checked consist, naming the curvature ``name`` in errors."""
    k = _checks.array(name, curvature)
    if k.ndim not in (0, 1) or (k.ndim == 1 and k.size != consist.couplers):
        raise ValueError(f"{name} must be a number or hold {consist.couplers} values, got shape {k.shape}")
    length = consist.length
    longer = np.maximum(length[:-1], length[1:])
    fits = np.abs(k) * longer <= 2.0
    if not fits.all():
        j = int(np.argmin(fits))
        kj = float(np.broadcast_to(k, fits.shape)[j])
        raise ValueError(
            f"{name} must be at most 2/L = {2.0 / longer[j]:.4g} 1/m in size at coupler {j}, where a vehicle "
            f"of length L = {longer[j]:.4g} m meets it (a vehicle longer than the curve's diameter cannot "
            f"sit on the track), got {kj!r}"
        )
    return k * 0.25 * (length[:-1] + length[1:])


def _truck_loads(consist: Consist, end_force: np.ndarray) -> np.ndarray:
    """Loads (n, 2) on the front and rear trucks from forces at the coupler ends (n−1,) of every body."""
    n = len(consist)
    front = np.zeros(n)
    rear = np.zeros(n)
    front[1:] = end_force  # coupler j acts at the front end of vehicle j+1
    rear[:-1] = end_force  # ... and at the rear end of vehicle j
    lever = consist.length / consist.truck_centres
    mean = 0.5 * (front + rear)
    moment = 0.5 * (front - rear) * lever
    return np.stack([mean + moment, mean - moment], axis=1)


@dataclass(frozen=True)
class CouplerEffects(Tabular):
    """Lateral and vertical effects of coupler forces on each vehicle.

    Attributes
    ----------
    lateral_force : ndarray (n, 2)
        Lateral force on the front and rear truck, N (+ toward the outside of the curve).
    l_over_v : ndarray (n, 2)
        Truck-side L/V: ``|lateral force| / (m g/4)``.
    vertical_force : ndarray (n, 2)
        Upward force on each truck from the couplers, N (+ unloads the truck).
    unloading : ndarray (n, 2)
        Fraction of the static truck load ``m g/2`` removed (+) or added (−).
    mode : ndarray of str (n−1,)
        For each coupler: "string-lining" (tension on a curve), "jack-knifing"
        (compression on a curve) or "" (straight or no force).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("lateral_force", "N"), ("l_over_v", "-"), ("vertical_force", "N"), ("unloading", "-"))

    lateral_force: np.ndarray
    l_over_v: np.ndarray
    vertical_force: np.ndarray
    unloading: np.ndarray
    mode: np.ndarray

    def __post_init__(self):
        lateral = _checks.array("lateral_force", self.lateral_force, ndim=2, allow_empty=False)
        n = lateral.shape[0]
        object.__setattr__(self, "lateral_force", _checks.array("lateral_force", lateral, shape=(n, 2)))
        for name in ("l_over_v", "vertical_force", "unloading"):
            object.__setattr__(self, name, _checks.array(name, getattr(self, name), shape=(n, 2)))
        if not isinstance(self.mode, np.ndarray | list | tuple):
            raise TypeError(f"mode must be an array of strings, one per coupler, got {self.mode!r:.80}")
        mode = np.asarray(self.mode)
        if mode.shape != (n - 1,) or (mode.size and mode.dtype.kind != "U"):
            raise ValueError(f"mode must hold {n - 1} strings, one per coupler, got {self.mode!r:.80}")
        object.__setattr__(self, "mode", mode)


def coupler_effects(consist: Consist, forces, curvature=0.0, vertical_curvature=0.0) -> CouplerEffects:
    """Lateral (L/V) and vertical (unloading) effects of the coupler forces ``forces`` (N, + tension).

    Parameters
    ----------
    consist : Consist
        The vehicles, front first.
    forces : array (n−1,)
        Coupler forces, N.
    curvature : float or array (n−1,)
        Horizontal curvature at each coupler, 1/m (magnitude used; the result is
        given relative to the outside of the curve); within the geometric limit of
        :func:`~raildyn.train.lateral.coupler_angles`.
    vertical_curvature : float or array (n−1,)
        1/m, + in a sag, − on a crest; within the same limit.

    Returns
    -------
    CouplerEffects
        Truck forces, L/V, unloading and the mode of each coupler.

    Examples
    --------
    >>> from raildyn.train import make_consist
    >>> c = make_consist("3 loaded hopper")
    >>> e = coupler_effects(c, [200e3, 200e3], curvature=1 / 200)
    >>> bool(e.lateral_force[1, 0] < 0)  # tension pulls the middle car toward the inside
    True
    """
    _checks.instance("consist", consist, Consist)
    f = _checks.array("forces", forces, shape=(consist.couplers,))
    theta = np.abs(_angles(consist, curvature, "curvature"))
    phi = _angles(consist, vertical_curvature, "vertical_curvature")
    lateral_end = -f * np.sin(theta)  # tension (f > 0) pulls inward
    lateral = _truck_loads(consist, lateral_end)
    # In a sag (φ > 0) the coupler line lies below the bodies, so tension lifts the car ends.
    vertical = _truck_loads(consist, f * np.sin(phi))
    weight = consist.mass * GRAVITY
    l_over_v = np.abs(lateral) / (weight[:, None] / 4)
    unloading = vertical / (weight[:, None] / 2)
    mode = np.where(
        (theta > 0) & (f > 0), "string-lining", np.where((theta > 0) & (f < 0), "jack-knifing", "")
    )
    return CouplerEffects(lateral, l_over_v, vertical, unloading, mode)


def limiting_coupler_force(consist: Consist, curvature, l_over_v: float, vehicle: int = 1) -> float:
    """The coupler force, the same in every coupler, that brings one vehicle's truck-side L/V to a limit.

    The L/V of :func:`coupler_effects` is proportional to the size of the coupler
    force (draft and buff alike), so the force is ``l_over_v`` over the L/V of the
    vehicle's worse truck at 1 N. For the middle of three equal vehicles this is
    ``F = (L/V)(m g/4)/sin θ``.

    Parameters
    ----------
    consist : Consist
        The vehicles, front first (at least two).
    curvature : float or array (n−1,)
        Horizontal curvature at the couplers, 1/m (not zero everywhere).
    l_over_v : float
        The truck-side L/V to reach (> 0).
    vehicle : int
        Index of the vehicle, 0 at the front; negative counts from the rear.

    Returns
    -------
    float
        Size of the coupler force, N (> 0): a tension string-lines the vehicle, a
        compression of the same size jack-knifes it.

    Examples
    --------
    >>> from raildyn.train import make_consist
    >>> round(limiting_coupler_force(make_consist("3 loaded hopper"), 1 / 150, 0.5) / 1e3)  # kN
    2955
    """
    _checks.instance("consist", consist, Consist)
    if consist.couplers < 1:
        raise ValueError(f"consist must hold at least two vehicles, got {len(consist)}")
    limit = _checks.positive("l_over_v", l_over_v)
    n = len(consist)
    vehicle = _checks.integer("vehicle", vehicle, low=-n, high=n - 1)
    per_newton = (
        coupler_effects(consist, np.ones(consist.couplers), curvature=curvature).l_over_v[vehicle].max()
    )
    if per_newton == 0.0:
        raise ValueError(
            f"curvature must turn the track at the couplers of vehicle {vehicle}; got {curvature!r}, "
            "where coupler forces have no lateral component"
        )
    return float(limit / per_newton)
