"""Physical constants shared by every raildyn model, and the plausible range of each physical quantity.

* :data:`GRAVITY` — standard gravity g = 9.80665 m/s², the conventional value
  fixed by the 3rd CGPM (1901) and used by ISO 80000-3. It is chosen over the
  rounded 9.81 because it is a definition rather than a local measurement: the
  train's tonnage ratings (AAR, in short tons force) and the vehicles' weights
  then convert with the same number.
* :data:`STEEL_YOUNGS_MODULUS`, :data:`STEEL_POISSON_RATIO` — wheel and rail
  steel, E = 210 GPa and ν = 0.3 (Johnson 1985, *Contact Mechanics*; the values
  Kalker 1990 and most vehicle-dynamics codes use).
* :data:`STEEL_SHEAR_MODULUS` — G = E/(2(1 + ν)) = 80.8 GPa, the shear modulus
  that goes with them, so that Hertz's patch and Kalker's coefficients describe
  the same steel.
* :data:`STANDARD_RAIL_SPACING` — 2a_r = 1.5 m, the distance between the rails' centres of
  standard-gauge track: the base of the cant and of the cross-level alike.
* :data:`MPH` — one mile per hour in m/s, 1609.344/3600 (the international mile of
  1959, exact), for sources in US units: the FRA's track-class speed limits, Davis's
  resistance formula.
* :data:`MAXIMUM_SPEED` — the one speed limit of the whole package, 200 m/s.
* :data:`PLAUSIBLE_RANGES` — for each physical quantity a model takes (a speed, a wheel
  radius, a mass...), the range that every real railway vehicle and track falls in, with the
  reason. A value outside it is refused with a message that names the parameter: a speed
  typed in km/h, a length in millimetres or a friction coefficient in per cent is a slip,
  not a railway, and computing on would print a confident wrong answer.
"""

from __future__ import annotations

import dataclasses
import math
import types

from raildyn._numbers import scalar  # below this module; raildyn._checks, above it, reads the table here

__all__ = [
    "GRAVITY",
    "MAXIMUM_FREQUENCY",
    "MAXIMUM_SPEED",
    "MPH",
    "PLAUSIBLE_RANGES",
    "STANDARD_RAIL_SPACING",
    "STEEL_POISSON_RATIO",
    "STEEL_SHEAR_MODULUS",
    "STEEL_YOUNGS_MODULUS",
    "PlausibleRange",
]

GRAVITY = 9.80665  # m/s², standard gravity (3rd CGPM, 1901; ISO 80000-3)
STEEL_YOUNGS_MODULUS = 2.1e11  # Pa (Johnson 1985)
STEEL_POISSON_RATIO = 0.3  # (Johnson 1985)
STEEL_SHEAR_MODULUS = STEEL_YOUNGS_MODULUS / (2.0 * (1.0 + STEEL_POISSON_RATIO))  # Pa, isotropic elasticity
MPH = 1609.344 / 3600  # m/s per mile per hour (international mile, 1959: exact)

STANDARD_RAIL_SPACING = 1.5
"""2a_r, m: the lateral distance between the two rails' centres (their running-band centres)
of standard-gauge (1435 mm) track, the base on which cant and cross-level are measured and
stated: the 1500 mm of EN 13803 (whence its 11.8 V²/R) and of UIC practice. A cross-level Δz
rolls the plane of the rails by Δz/(2a_r), as a cant h_t does by h_t/(2a_r)."""

MAXIMUM_SPEED = 200.0
"""The largest speed any raildyn function accepts, m/s (720 km/h).

It lies above the speed record of a train on wheels and rails, 574.8 km/h = 159.7 m/s (the
TGV V150 trainset of SNCF and Alstom, 3 April 2007, on the LGV Est), so every real train
passes, and a speed typed in km/h where m/s is meant is caught whenever it exceeds 200 (a
300 km/h train typed as 300)."""

MAXIMUM_FREQUENCY = 1.0e6
"""The highest circular frequency of a vehicle's frequency response, rad/s (about 160 kHz).

The vehicle models are rigid bodies on springs, meant for motions below some 100 Hz (a
car body's modes lie near 1 Hz, a wheelset on the track's stiffness near 50-100 Hz); the
bound lies four orders above, and keeps ω²M, and ω² times a response, finite. One bound for
:meth:`raildyn.linear_model.LinearSystem.axle_frf` and every response of
:mod:`raildyn.vehicles.response`."""


@dataclasses.dataclass(frozen=True)
class PlausibleRange:
    """The values a physical quantity takes on real railway vehicles and track.

    Attributes
    ----------
    what : str
        The quantity in words, for messages (e.g. ``"a wheel's rolling radius"``).
    low, high : float
        The range, in ``unit``; a function may refuse ``low`` itself where its formula divides
        by the quantity (its docstring says so).
    unit : str
        The SI unit (``""`` for a pure number).
    reason : str
        Why the range holds every real case, with the source of each figure.

    Examples
    --------
    >>> PLAUSIBLE_RANGES["speed"].high
    200.0
    """

    what: str
    low: float
    high: float
    unit: str
    reason: str

    def __post_init__(self):
        for name in ("what", "unit", "reason"):
            if not isinstance(getattr(self, name), str):
                raise TypeError(f"{name} must be a string, got {getattr(self, name)!r:.80}")
        if not self.what or not self.reason:
            raise ValueError("what and reason must not be empty: a range states the quantity and why")
        low, high = scalar("low", self.low), scalar("high", self.high)
        if not low < high:
            raise ValueError(f"low must be below high, got low = {low!r} and high = {high!r}")

    def __contains__(self, value) -> bool:
        return math.isfinite(value) and self.low <= value <= self.high


_WHEEL_RADIUS = (
    "The rolling radius of real wheels runs from about 0.17-0.18 m (the 335-360 mm wheels of the "
    "low-floor wagons that carry lorries on the Alpine rolling highways) through 0.3-0.65 m "
    "(wagons, coaches, locomotives) to about 1.0-1.15 m for the largest steam driving wheels of the "
    "20th century (2.0-2.3 m in diameter) and 1.37 m for the 9 ft (2.74 m) drivers of 1850s "
    "broad-gauge express engines. A radius typed in millimetres (460 for 0.46 m) lies far above."
)
_HALF_GAUGE = (
    "Half the lateral distance between a wheelset's two contact points (or between the rails' "
    "centres): from about 0.2 m on 381 mm (15 in) minimum-gauge lines, through 0.3-0.55 m on "
    "narrow gauges (600-1067 mm) and 0.75 m on standard gauge (1435 mm), to about 0.87 m on the "
    "1676 mm broad gauge of India and Iberia (1.07 m on Brunel's 2140 mm gauge, the widest ever "
    "built). 1435 typed for the standard gauge in millimetres lies far above."
)
_VEHICLE_LENGTH = (
    "A dimension of one vehicle or its running gear (a spacing of bogies, axles or springs, a "
    "wheelbase, a lever arm, a height or the vehicle's length): wagons and coaches are 10-30 m "
    "long, and even the longest single railway vehicles, the multi-bogie Schnabel cars that carry "
    "transformers, stay well under 100 m, which bounds every such dimension; a dimension typed in "
    "millimetres (9500 for a 9.5 m half bogie spacing, 1800 for a 1.8 m height) lies far above. No "
    "spacing or lever arm of a vehicle is below 1 cm (a height may be 0)."
)
_MASS = (
    "The mass of one body of a vehicle model (a car body, a bogie frame, a side frame, a "
    "wheelset, a motor, a whole vehicle): from about 10 kg, below any part worth a body of its "
    "own, to 1000 t: six-axle locomotives weigh up to about 200 t and loaded heavy-haul wagons "
    "about 140 t, and even the largest Schnabel cars spread their load over span bolsters and "
    "many bogies, each a body well under 1000 t. A mass typed in grams, or an absurd 10^9 kg, "
    "lies outside."
)
_INERTIA = (
    "A moment of inertia of one body of a vehicle model: from 1 kg·m² (below any wheelset's, "
    "about 100-1500 kg·m²) to 5e8 kg·m², above the yaw or pitch inertia m L²/12 of a 1000 t body "
    "70 m long (4.1e8 kg·m²); a car body's pitch inertia (about 2e6 kg·m²) typed a thousand times "
    "too large lies above."
)
_FRICTION = (
    "A coefficient of friction μ between wheel and rail (or in a friction damper): dry, clean "
    "rail steel reaches about 0.6 in the field and a little more in the laboratory, lubricated "
    "or wet rail much less; a coefficient of 1 would already hold a wheel on a vertical wall by "
    "friction alone, so values above 1 are slips, e.g. a percentage (30 for 0.3). μ = 0 is "
    "refused only where a formula divides by it."
)
_CONTACT_SEMI_AXIS = (
    "A semi-axis a or b of a wheel-rail contact patch: a few millimetres in service (about 6 mm "
    "under a 10 t wheel load on a 0.46 m wheel); 50 mm would need a load and radii far beyond "
    "any wheel, and a semi-axis in millimetres (6 for 0.006 m) lies above. The lower bound, "
    "10 µm, is the scale of the surfaces' roughness, below which Hertz's smooth bodies no "
    "longer describe the patch."
)
_WHEEL_LOAD = (
    "The normal load on one wheel-rail contact: up to about 200 kN (a 40 t axle of heavy-haul "
    "freight); 1 MN, a 100 t wheel load, bounds every real wheel with a margin, and a load typed "
    "a thousand times too large (in the wrong unit) lies above. 1 N is far below any wheel's "
    "share of a vehicle's weight."
)
_RAIL_LENGTH = (
    "The length of one rail of jointed track, between its joints: from about 6 m (short rails in "
    "switches and sidings) through the 39 ft (11.9 m) of North American practice and 18-36 m in "
    "Europe to the 120 m rolled lengths of today's mills; 150 m bounds them, and a length typed in "
    "millimetres (11900) lies far above."
)
_TRACK_LENGTH = (
    "A length along the track of one of its features (a joint dip's half-length, a bump, the "
    "wavelength of a sinusoid, the spacing of a profile's samples): from 1 mm, below the scale of "
    "the rail's own roughness (corrugation wavelengths are 30-80 mm), to 1 km, beyond any "
    "wavelength that moves a vehicle (EN 13848 measures track geometry up to 200 m wavelengths)."
)
_IRREGULARITY = (
    "The size of a deterministic track irregularity (a joint's dip, a bump's height, a sinusoid's "
    "amplitude): at most 0.1 m, above the 3 in (76 mm) the FRA allows even on class 1 track for a "
    "profile deviation; a track that far out has failed, and a size typed in millimetres lies far "
    "above."
)
_SPAN = (
    "The span of a bridge: from 1 m (a culvert) to 2 km, beyond the longest spans that carry "
    "trains (the suspension bridges of road and rail reach about 1.4 km)."
)
_BEAM_MASS = (
    "The mass per length of a beam: from 1 kg/m, below the lightest rail (about 5 kg/m), to "
    "1000 t/m, above any bridge deck or track structure (a heavy concrete box girder carries some "
    "tens of tonnes a metre)."
)
_FLEXURAL_RIGIDITY = (
    "The flexural rigidity EI of a beam: from 1 N·m² (a beam of unit rigidity, with which a "
    "weigh-in-motion reads loads in units of EI/c; the lightest rail has about 1e5 N·m²) to "
    "1e16 N·m², above the stiffest bridge girders (about 1e14 N·m²)."
)
_FRONTAL_AREA = (
    "The frontal area of a rail vehicle, for its aerodynamic drag: from 0.5 m² to 30 m², around "
    "the 9-15 m² of main-line vehicles (the largest loading gauges are about 3.6 m wide and 6 m "
    "tall: 22 m²)."
)
_TRACTION_FORCE = (
    "A tractive or braking force of one vehicle: up to 2 MN, above the strongest locomotives "
    "(about 1.2 MN for a two-unit heavy-haul locomotive); a force typed a thousand times too large "
    "lies above."
)
_POWER = (
    "The power of one vehicle at the rail: up to 20 MW, above the most powerful locomotives (about "
    "12 MW for a two-unit electric locomotive)."
)
_COUPLER_TRAVEL = (
    "A travel of a coupler or its draft gear (slack, gear travel): up to 0.5 m, above the slack "
    "and travel of real couplings (a few centimetres each, some 0.1-0.2 m in all); a travel typed "
    "in millimetres lies far above."
)
_AXLE_LOAD = (
    "The vertical load on one wheelset (both wheels), N: twice the wheel-load bound, 2 MN "
    "(a 200 t axle); the heaviest real axle loads are about 40 t (0.4 MN)."
)

#: Each physical quantity's plausible range, by name: its interval, unit and the reason with its
#: sources. raildyn's checks refuse a value outside it (``raildyn._checks.plausible``)
#: and each parameter's docstring states the range it is held to.
PLAUSIBLE_RANGES = types.MappingProxyType(
    {
        "speed": PlausibleRange(
            "a vehicle's speed",
            0.0,
            MAXIMUM_SPEED,
            "m/s",
            "See MAXIMUM_SPEED: above the 574.8 km/h (159.7 m/s) wheel-rail speed record of the "
            "TGV V150 (3 April 2007); a speed typed in km/h above 200 is caught.",
        ),
        "wheel_radius": PlausibleRange("a wheel's rolling radius", 0.1, 1.5, "m", _WHEEL_RADIUS),
        "half_gauge": PlausibleRange(
            "half the lateral spacing of a wheelset's contact points", 0.15, 1.1, "m", _HALF_GAUGE
        ),
        "vehicle_length": PlausibleRange("a dimension of a vehicle", 0.01, 100.0, "m", _VEHICLE_LENGTH),
        "mass": PlausibleRange("the mass of a body of a vehicle", 10.0, 1.0e6, "kg", _MASS),
        "inertia": PlausibleRange(
            "a moment of inertia of a body of a vehicle", 1.0, 5.0e8, "kg·m²", _INERTIA
        ),
        "friction": PlausibleRange("a coefficient of friction", 0.0, 1.0, "", _FRICTION),
        "contact_semi_axis": PlausibleRange(
            "a semi-axis of a wheel-rail contact patch", 1.0e-5, 0.05, "m", _CONTACT_SEMI_AXIS
        ),
        "wheel_load": PlausibleRange("the normal load on one wheel", 1.0, 1.0e6, "N", _WHEEL_LOAD),
        "axle_load": PlausibleRange("the vertical load on one wheelset", 1.0, 2.0e6, "N", _AXLE_LOAD),
        "rail_length": PlausibleRange("the length of a rail between joints", 1.0, 150.0, "m", _RAIL_LENGTH),
        "track_length": PlausibleRange("a length along the track", 1.0e-3, 1.0e3, "m", _TRACK_LENGTH),
        "irregularity": PlausibleRange("a track irregularity's size", 0.0, 0.1, "m", _IRREGULARITY),
        "span": PlausibleRange("a bridge's span", 1.0, 2.0e3, "m", _SPAN),
        "beam_mass": PlausibleRange("the mass per length of a beam", 1.0, 1.0e6, "kg/m", _BEAM_MASS),
        "flexural_rigidity": PlausibleRange(
            "the flexural rigidity of a beam", 1.0, 1.0e16, "N·m²", _FLEXURAL_RIGIDITY
        ),
        "frontal_area": PlausibleRange("a vehicle's frontal area", 0.5, 30.0, "m²", _FRONTAL_AREA),
        "traction_force": PlausibleRange(
            "a tractive or braking force of one vehicle", 0.0, 2.0e6, "N", _TRACTION_FORCE
        ),
        "power": PlausibleRange("the power of one vehicle", 0.0, 2.0e7, "W", _POWER),
        "coupler_travel": PlausibleRange("a travel of a coupler", 0.0, 0.5, "m", _COUPLER_TRAVEL),
    }
)
