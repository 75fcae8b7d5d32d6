"""Train resistance: the Davis formula (original and modified), grade and curve resistance, routes.

The Davis formula gives the rolling and air resistance of a rail vehicle per ton
of weight in US customary units (lbf per short ton, mph, short tons, ft²)
{davis1926}; :func:`davis_resistance` evaluates either form and converts to and
from SI at the edge. A :class:`Route` is grade and curvature against position.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY, MAXIMUM_SPEED, MPH
from raildyn.train.vehicles import FT, LB, LBF

__all__ = [
    "CURVE_RESISTANCE",
    "MODIFIED_DAVIS_K",
    "MPH",
    "SHORT_TON",
    "Route",
    "curve_resistance",
    "davis_resistance",
    "grade_force",
]

#: kg per short ton (2000 lb, exact).
SHORT_TON = 2000 * LB

# Original Davis coefficients by vehicle kind {davis1926}: B in lb/ton per mph, c_a in lb/ton per
# (ft²·mph²/(ton-per-axle·axles)). Freight cars B = 0.045, c_a = 0.0005; locomotives and passenger
# cars B = 0.03 with c_a = 0.0024 for a locomotive at the head and 0.00034 for a trailing car.
_DAVIS_ORIGINAL = {"freight": (0.045, 0.0005), "locomotive": (0.03, 0.0024), "passenger": (0.03, 0.00034)}
# Modified (AREA Committee 16) form: R = 0.6 + 20/w + 0.01 V + K V²/(w n), with K = 0.07 for
# conventional equipment, 0.0935 for containers and 0.16 for trailers on flat cars {hay1982}.
#: Drag coefficient c_a of the modified Davis formula by kind of equipment {hay1982}.
MODIFIED_DAVIS_K = {"conventional": 0.07, "container": 0.0935, "trailer on flat car": 0.16}

# AREA curve resistance: 0.8 lb per ton per degree of curve {hay1982}. A degree of curve (arc
# definition, 100 ft of arc) is D = 18000/(π R_ft), so per unit curvature in SI:
#: Curve resistance per unit mass and unit curvature, N/(kg·m⁻¹) (AREA 0.8 lb/ton per degree {hay1982}).
CURVE_RESISTANCE = 0.8 * LBF / SHORT_TON * 18000 / np.pi * FT  # N per kg per (1/m)

# Steepest grade (rise over run) a route or a grade force takes: 15 %, beyond any adhesion
# railway (main lines stay under about 4 %, the steepest tramways reach about 13.5 %). Steeper
# lines are rack railways, which these models (wheel-rail adhesion) do not describe.
_MAX_GRADE = 0.15
# Sharpest curvature (1/m) a route or a resistance formula takes: 0.1, a radius of 10 m, tighter
# than any railway curve (tram curves go down to about 15 m); the AREA formula and the coupler
# geometry are meant for curves far gentler than this.
_MAX_CURVATURE = 0.1


def _bounded(name, value, limit, unit):
    """``value`` as a finite array with every entry within ±``limit`` (the stated domain)."""
    arr = _checks.array(name, value, allow_empty=False)
    if np.abs(arr).max() > limit:
        raise ValueError(f"{name} must be within ±{limit} {unit}, got {arr.flat[np.argmax(np.abs(arr))]!r}")
    return arr


_UNITS = {"SI": "m/s", "US": "mph"}


def davis_resistance(
    speed,
    mass,
    axles,
    frontal_area,
    *,
    kind: str = "freight",
    form: str = "original",
    units: str = "SI",
    drag_coefficient: float | None = None,
):
    """Rolling and air resistance of a rail vehicle on level tangent track, by the Davis formula.

    Original form {davis1926}, per short ton of weight:

    .. math:: R_t = 1.3 + 29/w + B V + c_a A_f V^2/(w n) \\quad \\text{lb/ton}

    modified (AREA) form {hay1982}:

    .. math:: R_t = 0.6 + 20/w + 0.01 V + c_a V^2/(w n) \\quad \\text{lb/ton}

    with ``w`` the weight per axle in short tons, ``n`` the axles, ``V`` in mph
    and the frontal area ``A_f`` in ft². The resistance of the vehicle is ``R_t`` times its weight in
    tons: a quadratic A + BV + CV² in the speed, whose coefficients are the vehicle's Davis
    coefficients (book ch. 9).

    Parameters
    ----------
    speed : float or array
        Speed, m/s (``units="SI"``) or mph (``units="US"``); its sign is ignored; at most
        200 m/s (447 mph), above the wheel–rail speed record, in size.
    mass : float or array
        Mass of one vehicle, kg (SI) or weight in short tons (US), in [10, 1e6] kg
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "mass").
    axles : int or array
        Number of axles, whole numbers >= 1.
    frontal_area : float or array
        m² (SI) or ft² (US), in [0.5, 30] m² (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "frontal_area");
        used by the original form
        only.
    kind : {"freight", "locomotive", "passenger"}
        Original-form coefficients.
    form : {"original", "modified"}
        Which Davis formula.
    units : {"SI", "US"}
        Units of the arguments and of the result.
    drag_coefficient : float, optional
        Overrides C (original) or K (modified; default 0.07, conventional equipment).

    Returns
    -------
    float or ndarray
        Resistance, N (SI) or lbf (US).

    Examples
    --------
    >>> round(davis_resistance(50.0, 143.0, 4, 88.0, units="US"), 1)  # one 143-ton car at 50 mph
    733.6
    """
    _checks.choice("form", form, ("original", "modified"))
    _checks.choice("units", units, ("SI", "US"))
    _checks.choice("kind", kind, _DAVIS_ORIGINAL)
    v = np.abs(
        _bounded("speed", speed, MAXIMUM_SPEED if units == "SI" else MAXIMUM_SPEED / MPH, _UNITS[units])
    )
    m = _checks.array("mass", mass, low=0.0, low_open=True, allow_empty=False)
    n = _checks.array("axles", axles, low=1.0, allow_empty=False)
    if np.any(n != np.round(n)):
        raise ValueError(f"axles must be whole numbers, got {axles!r}")
    a = _checks.array("frontal_area", frontal_area, low=0.0, low_open=True, allow_empty=False)
    if drag_coefficient is not None:
        _checks.nonnegative("drag_coefficient", drag_coefficient)
    # One vehicle's mass and frontal area, each in its plausible range (in SI: the US figures converted).
    _checks.plausible_array("mass", m if units == "SI" else m * SHORT_TON, "mass")
    _checks.plausible_array("frontal_area", a if units == "SI" else a * FT**2, "frontal_area")
    if units == "SI":
        v, tons, area = v / MPH, m / SHORT_TON, a / FT**2
    else:
        tons, area = m, a
    w = tons / n
    if form == "original":
        b, c = _DAVIS_ORIGINAL[kind]
        c = c if drag_coefficient is None else drag_coefficient
        per_ton = 1.3 + 29.0 / w + b * v + c * area * v**2 / (w * n)
    else:
        k = MODIFIED_DAVIS_K["conventional"] if drag_coefficient is None else drag_coefficient
        per_ton = 0.6 + 20.0 / w + 0.01 * v + k * v**2 / (w * n)
    force = per_ton * tons
    if units == "SI":
        force = force * LBF
    return force if force.ndim else float(force)


def grade_force(mass, grade):
    """Gravity component along the track, positive resisting an uphill climb.

    ``F = m g sin(arctan(grade))`` with ``grade`` the rise over run (0.01 = 1 %).

    Parameters
    ----------
    mass : float or array
        Mass, kg (> 0).
    grade : float or array
        Rise over run, + uphill in the direction of travel, within ±0.15 (steeper than any
        adhesion railway; steeper lines use a rack); broadcasts against ``mass``.

    Returns
    -------
    ndarray
        Force along the track, N (+ resisting the motion).

    Examples
    --------
    >>> float(grade_force(1000.0, 0.01).round(2))  # one tonne on a 1 % climb
    98.06
    """
    m = _checks.array("mass", mass, low=0.0, low_open=True, allow_empty=False)
    gr = _bounded("grade", grade, _MAX_GRADE, "(rise over run)")
    return m * GRAVITY * gr / np.sqrt(1.0 + gr**2)


def curve_resistance(mass, curvature):
    """Curve resistance: the AREA 0.8 lb/ton per degree of curve {hay1982} written per 1/m.

    Parameters
    ----------
    mass : float or array
        Mass, kg (> 0).
    curvature : float or array
        1/R, 1/m (its sign, the direction of the curve, is ignored), within ±0.1 1/m (a radius
        of 10 m, tighter than any railway curve); broadcasts against ``mass``.

    Returns
    -------
    ndarray
        Resistance, N (>= 0).
    """
    m = _checks.array("mass", mass, low=0.0, low_open=True, allow_empty=False)
    k = np.abs(_bounded("curvature", curvature, _MAX_CURVATURE, "1/m"))
    return CURVE_RESISTANCE * m * k


@dataclass(frozen=True)
class Route:
    """Grade and curvature against position along the line.

    Segment ``k`` runs from ``positions[k]`` to ``positions[k+1]`` (the last one
    without end, and the first one also backwards) with constant ``grade[k]``,
    horizontal curvature ``curvature[k]`` and vertical curvature
    ``vertical_curvature[k]``.

    Parameters
    ----------
    positions : sequence of float
        Start of each segment along the line, m; strictly increasing.
    grade : sequence of float
        Rise over run of each segment, + uphill in the direction of travel; within ±0.15
        (steeper than any adhesion railway: main lines stay under about 4 %, the steepest
        tramways reach about 13.5 %, and steeper lines use a rack).
    curvature : sequence of float, optional
        Horizontal curvature of each segment, 1/m (+ to the left), within ±0.1 1/m (a
        radius of 10 m, tighter than any railway curve); 0 by default.
    vertical_curvature : sequence of float, optional
        Vertical curvature of each segment, 1/m (+ for a sag, − for a crest), within
        ±0.1 1/m; 0 by default.
    """

    positions: tuple
    grade: tuple
    curvature: tuple | None = None
    vertical_curvature: tuple | None = None
    # The segment table as arrays, set in __post_init__: starts (m) and [grade, curvature,
    # vertical curvature] by segment.
    _x: np.ndarray = field(init=False, repr=False, compare=False)
    _table: np.ndarray = field(init=False, repr=False, compare=False)
    _level: bool = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        x = _checks.array("positions", self.positions, ndim=1, allow_empty=False)
        if np.any(np.diff(x) <= 0):
            raise ValueError(f"positions must be strictly increasing, got {self.positions!r}")
        limits = {"grade": (_MAX_GRADE, "(rise over run)"), "curvature": (_MAX_CURVATURE, "1/m")}
        limits["vertical_curvature"] = limits["curvature"]
        for name, (limit, unit) in limits.items():
            value = getattr(self, name)
            if value is None and name == "grade":
                raise TypeError("grade must be a sequence of numbers, one per segment, got None")
            arr = np.zeros(x.size) if value is None else _bounded(name, value, limit, unit)
            if arr.shape != (x.size,):
                raise ValueError(
                    f"{name} must hold one value per segment, shape ({x.size},), got {arr.shape}"
                )
            object.__setattr__(self, name, tuple(float(a) for a in arr))
        object.__setattr__(self, "positions", tuple(float(a) for a in x))
        object.__setattr__(self, "_x", x)
        object.__setattr__(self, "_table", np.array([self.grade, self.curvature, self.vertical_curvature]))
        object.__setattr__(self, "_level", not np.any(self._table[:2]))

    @property
    def is_level(self) -> bool:
        """True when the route is level tangent track everywhere (no grade, no horizontal curve)."""
        return self._level

    @classmethod
    def level(cls) -> Route:
        """Level tangent track everywhere.

        Returns
        -------
        Route
            One segment with no grade and no curvature.
        """
        return cls((0.0,), (0.0,))

    def _segment(self, position):
        position = _checks.array("position", position, allow_empty=False)
        return np.clip(np.searchsorted(self._x, position, side="right") - 1, 0, self._x.size - 1)

    def grade_at(self, position) -> np.ndarray:
        """Grade at a position along the line.

        Parameters
        ----------
        position : float or array
            Position along the line, m (any; the first segment extends backwards, the last forwards).

        Returns
        -------
        ndarray
            Rise over run, the shape of ``position``.
        """
        return self._table[0][self._segment(position)]

    def curvature_at(self, position) -> np.ndarray:
        """Horizontal curvature at a position along the line.

        Parameters
        ----------
        position : float or array
            Position along the line, m (any; the first segment extends backwards, the last forwards).

        Returns
        -------
        ndarray
            Curvature, 1/m (+ to the left), the shape of ``position``.
        """
        return self._table[1][self._segment(position)]

    def vertical_curvature_at(self, position) -> np.ndarray:
        """Vertical curvature at a position along the line.

        Parameters
        ----------
        position : float or array
            Position along the line, m (any; the first segment extends backwards, the last forwards).

        Returns
        -------
        ndarray
            Curvature, 1/m (+ sag, − crest), the shape of ``position``.
        """
        return self._table[2][self._segment(position)]
