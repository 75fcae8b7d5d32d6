"""Rail vehicles and consists: the bodies that a longitudinal train model moves.

A :class:`Vehicle` holds what train dynamics needs of one car or locomotive (mass,
length over the coupler pulling faces, axles, frontal area, truck-centre spacing,
traction and brake capability). :func:`make_consist` builds a :class:`Consist`
from a short description such as ``"2 SD40-2 + 100 loaded hopper"``, using the
published default vehicles in :data:`VEHICLES`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace

import numpy as np

from raildyn import _checks
from raildyn.constants import GRAVITY

__all__ = ["DAVIS_KINDS", "FT", "HP", "LB", "LBF", "VEHICLES", "Consist", "Vehicle", "make_consist"]

#: kg per pound (exact, international pound).
LB = 0.45359237
#: m per foot (exact, international foot).
FT = 0.3048
#: N per pound-force (exact: one pound under standard gravity).
LBF = LB * GRAVITY
#: W per mechanical horsepower (550 ft·lbf/s).
HP = 550 * FT * LBF


@dataclass(frozen=True)
class Vehicle:
    """One rail vehicle as seen by longitudinal train dynamics.

    Parameters
    ----------
    name : str
        Name of the vehicle type, as :func:`make_consist` looks it up.
    mass : float
        Mass on the rails, kg, in [10, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "mass").
    length : float
        Length over the coupler pulling faces, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length").
    axles : int
        Number of axles (>= 1).
    frontal_area : float
        Cross-section used by the Davis air-resistance term, m², in [0.5, 30]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "frontal_area").
    truck_centres : float
        Distance between the truck (bogie) centres, m, in [0.01, 100] and < ``length``.
    kind : {"locomotive", "freight", "passenger"}
        Selects the Davis coefficients of the original form.
    max_tractive_effort : float
        Adhesion-limited starting tractive effort at full notch, N, in [0, 2e6]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "traction_force"; 0 for a wagon).
    rail_power : float
        Power at the rail at full notch, W, in [0, 2e7] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "power"; 0 for a wagon).
    max_dynamic_brake : float
        Largest dynamic-brake retarding force, N, in [0, 2e6] ("traction_force"; 0 for a wagon).
    brake_force : float
        Retarding force of a full emergency air-brake application, N, in [0, 2e6] ("traction_force").
    """

    name: str
    mass: float
    length: float
    axles: int
    frontal_area: float
    truck_centres: float
    kind: str = "freight"
    max_tractive_effort: float = 0.0
    rail_power: float = 0.0
    max_dynamic_brake: float = 0.0
    brake_force: float = 0.0

    def __post_init__(self):
        _checks.plausible("mass", self.mass, "mass")
        _checks.plausible("length", self.length, "vehicle_length")
        _checks.integer("axles", self.axles, low=1)
        _checks.plausible("frontal_area", self.frontal_area, "frontal_area")
        _checks.plausible("truck_centres", self.truck_centres, "vehicle_length")
        if self.truck_centres >= self.length:
            raise ValueError(
                f"truck_centres must be less than length = {self.length!r} m, got {self.truck_centres!r}"
            )
        _checks.instance("name", self.name, str, "string")
        _checks.choice("kind", self.kind, DAVIS_KINDS)
        for name in ("max_tractive_effort", "max_dynamic_brake", "brake_force"):
            _checks.plausible(name, getattr(self, name), "traction_force")
        _checks.plausible("rail_power", self.rail_power, "power")

    @property
    def weight(self) -> float:
        """Weight m·g, N (standard gravity, ``raildyn.constants.GRAVITY``)."""
        return self.mass * GRAVITY


#: The vehicle kinds the original Davis formula has coefficients for.
DAVIS_KINDS = ("locomotive", "freight", "passenger")

# Most vehicles in one consist. The longest train ever run had 682 wagons and 8 locomotives
# (BHP iron ore, 2001, 7.3 km); a thousand vehicles leaves room beyond it while keeping a run's
# arrays and the compiled right-hand side small, and stops a typing slip from building millions.
_MAX_VEHICLES = 1000

# Emergency brake retarding force of a wagon: a net braking ratio (shoe force over
# weight) of 10 % at the AAR loaded-car level times a composition-shoe friction
# coefficient of 0.35 gives 3.5 % of the weight; an assumed, typical value.
_BRAKE_FRACTION = 0.10 * 0.35

# Rail power of a diesel-electric locomotive: 82 % of the engine's rated power
# reaches the rail (Hay's suggested transmission efficiency) {hay1982}.
_TRANSMISSION_EFFICIENCY = 0.82

#: Published default vehicles, SI units.
VEHICLES: dict[str, Vehicle] = {
    # EMD SD40-2, a 6-axle 3000 hp road locomotive: 368,000 lb, 68 ft 10 in over the coupler
    # pulling faces, truck centres 43 ft 6 in, starting tractive effort 115,000 lbf {emd_sd40_2}.
    # Frontal area 120 ft², the upper end of Davis's 105–120 ft² for locomotives {davis1926}.
    # Dynamic brake of 360 kN (about 80,000 lbf): an assumed extended-range value.
    "SD40-2": Vehicle(
        "SD40-2",
        mass=368_000 * LB,
        length=(68 + 10 / 12) * FT,
        axles=6,
        frontal_area=120 * FT**2,
        truck_centres=(43 + 6 / 12) * FT,
        kind="locomotive",
        max_tractive_effort=115_000 * LBF,
        rail_power=_TRANSMISSION_EFFICIENCY * 3000 * HP,
        max_dynamic_brake=360e3,
        brake_force=_BRAKE_FRACTION * 368_000 * LB * GRAVITY,
    ),
    # Loaded 4-axle coal hopper at the AAR 286,000 lb gross rail load {aar_s286}; length over the
    # pulling faces 53 ft and truck centres 40 ft 8 in are assumed typical values; frontal area
    # 90 ft², Davis's figure for freight cars {davis1926}.
    "loaded hopper": Vehicle(
        "loaded hopper",
        mass=286_000 * LB,
        length=53 * FT,
        axles=4,
        frontal_area=90 * FT**2,
        truck_centres=(40 + 8 / 12) * FT,
        brake_force=_BRAKE_FRACTION * 286_000 * LB * GRAVITY,
    ),
    # The same hopper empty: 63,000 lb light weight (assumed typical); the brake rigging is
    # the same, so the empty car keeps a lower absolute brake force (AAR empty-car ratio
    # would be higher; an empty/load device is not modelled).
    "empty hopper": Vehicle(
        "empty hopper",
        mass=63_000 * LB,
        length=53 * FT,
        axles=4,
        frontal_area=90 * FT**2,
        truck_centres=(40 + 8 / 12) * FT,
        brake_force=0.25 * 0.35 * 63_000 * LB * GRAVITY,
    ),
}


@dataclass(frozen=True)
class Consist:
    """An ordered train of vehicles, front (index 0) to rear.

    Parameters
    ----------
    vehicles : tuple of Vehicle
        The vehicles, front first: at least one and at most 1000 (the longest train ever
        run had 690 vehicles; the limit stops a typing slip from building millions).
    description : str
        How the consist was described (``make_consist``'s text), for display; any text.

    Attributes
    ----------
    mass, length, axles, frontal_area, truck_centres : ndarray (n,)
        Each vehicle's value of the :class:`Vehicle` field of the same name (kg, m, -, m², m).
    max_tractive_effort, rail_power, max_dynamic_brake, brake_force : ndarray (n,)
        Each vehicle's traction and brake capability (N, W, N, N).
    locomotive : ndarray of bool (n,)
        True where the vehicle is a locomotive.
    """

    vehicles: tuple[Vehicle, ...]
    description: str = ""
    # Per-vehicle arrays, derived from ``vehicles`` in __post_init__.
    mass: np.ndarray = field(init=False, repr=False, compare=False)
    length: np.ndarray = field(init=False, repr=False, compare=False)
    axles: np.ndarray = field(init=False, repr=False, compare=False)
    frontal_area: np.ndarray = field(init=False, repr=False, compare=False)
    truck_centres: np.ndarray = field(init=False, repr=False, compare=False)
    max_tractive_effort: np.ndarray = field(init=False, repr=False, compare=False)
    rail_power: np.ndarray = field(init=False, repr=False, compare=False)
    max_dynamic_brake: np.ndarray = field(init=False, repr=False, compare=False)
    brake_force: np.ndarray = field(init=False, repr=False, compare=False)
    locomotive: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        if not isinstance(self.vehicles, tuple | list):
            raise TypeError(f"vehicles must be a tuple of Vehicle, got {type(self.vehicles).__name__}")
        object.__setattr__(self, "vehicles", tuple(self.vehicles))
        if not 1 <= len(self.vehicles) <= _MAX_VEHICLES:
            raise ValueError(f"vehicles must hold 1 to {_MAX_VEHICLES} vehicles, got {len(self.vehicles)}")
        _checks.instance("description", self.description, str, "string")
        for i, v in enumerate(self.vehicles):
            if not isinstance(v, Vehicle):
                raise TypeError(f"vehicles[{i}] must be a Vehicle, got {type(v).__name__}")
        names = ("mass", "length", "axles", "frontal_area", "truck_centres", "max_tractive_effort")
        names += ("rail_power", "max_dynamic_brake", "brake_force")
        for name in names:
            object.__setattr__(self, name, np.array([getattr(v, name) for v in self.vehicles], dtype=float))
        object.__setattr__(self, "locomotive", np.array([v.kind == "locomotive" for v in self.vehicles]))

    def __len__(self) -> int:
        return len(self.vehicles)

    @property
    def total_mass(self) -> float:
        """Mass of the train, kg."""
        return float(self.mass.sum())

    @property
    def train_length(self) -> float:
        """Length over the pulling faces, m."""
        return float(self.length.sum())

    @property
    def centre_offsets(self) -> np.ndarray:
        """Distance of each vehicle's centre behind the front coupler face, m (shape ``(n,)``)."""
        ends = np.cumsum(self.length)
        return ends - 0.5 * self.length

    @property
    def coupler_offsets(self) -> np.ndarray:
        """Distance of each coupler (the joint between vehicles j and j+1) behind the front, m.

        Shape ``(n−1,)``, front coupler first; with the slack centred. The one place
        that places the couplers along the train: runs, quasi-static results, figures
        and widgets all read it.

        Examples
        --------
        >>> make_consist("3 loaded hopper").coupler_offsets.round(2)
        array([16.15, 32.31])
        """
        return np.cumsum(self.length)[:-1]

    @property
    def couplers(self) -> int:
        """Number of couplers between vehicles (n − 1)."""
        return len(self.vehicles) - 1

    def with_vehicle(self, index: int, **changes) -> Consist:
        """A copy with one vehicle changed.

        Parameters
        ----------
        index : int
            Index of the vehicle, 0 at the front; negative counts from the rear (−n … n−1).
        **changes
            :class:`Vehicle` fields and their new values (``dataclasses.replace`` keywords).

        Returns
        -------
        Consist
            The same consist with the one vehicle replaced.
        """
        index = _checks.integer("index", index, low=-len(self), high=len(self) - 1)
        vehicles = list(self.vehicles)
        vehicles[index] = replace(vehicles[index], **changes)
        return Consist(tuple(vehicles), self.description)


_TERM = re.compile(r"^\s*(\d+)\s*[x×*]?\s*(.+?)\s*$")


def make_consist(description: str, vehicles: dict[str, Vehicle] | None = None) -> Consist:
    """Build a consist from a description such as ``"2 SD40-2 + 100 loaded hopper"``.

    Parameters
    ----------
    description : str
        Terms joined by ``+``, front first; each is ``count name`` (count >= 1; a
        missing count means 1). Plural names ending in ``s`` are accepted. At most
        1000 vehicles in all (see :class:`Consist`).
    vehicles : dict, optional
        Name to :class:`Vehicle`; defaults to :data:`VEHICLES`.

    Returns
    -------
    Consist
        The vehicles in order, front first.

    Examples
    --------
    >>> len(make_consist("2 SD40-2 + 100 loaded hoppers"))
    102
    """
    _checks.instance("description", description, str, "string")
    if not description.strip():
        raise ValueError(
            f"description must be a non-empty text such as '2 SD40-2 + 50 loaded hopper', got {description!r}"
        )
    table = VEHICLES if vehicles is None else _checks.instance("vehicles", vehicles, dict, "dict of Vehicle")
    for key, vehicle in table.items():
        _checks.instance(f"vehicles[{key!r}]", vehicle, Vehicle)
    lookup = {str(k).lower(): v for k, v in table.items()}
    out: list[Vehicle] = []
    for term in description.split("+"):
        match = _TERM.match(term)
        count, name = (int(match.group(1)), match.group(2)) if match else (1, term.strip())
        if count < 1:
            raise ValueError(f"description: a vehicle count must be >= 1, got {count} in {term.strip()!r}")
        if len(out) + count > _MAX_VEHICLES:
            raise ValueError(
                f"description asks for more than {_MAX_VEHICLES} vehicles (the most a consist holds), "
                f"got {len(out) + count} by the term {term.strip()!r}"
            )
        key = name.lower()
        if key not in lookup and key.endswith("s") and key[:-1] in lookup:
            key = key[:-1]
        if key not in lookup:
            raise ValueError(
                f"description names an unknown vehicle type {name!r}; known types: {sorted(table)}"
            )
        out.extend([lookup[key]] * count)
    return Consist(tuple(out), description)
