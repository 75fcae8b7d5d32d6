"""Vehicle models: the lateral bogie and car of chapter 7 and the vertical models of chapter 6.

Every public name is importable from ``raildyn.vehicles``.
"""

from raildyn import _deprecated
from raildyn.vehicles.freight import (
    GDU_ORE_CAR,
    RockAndRoll,
    VerticalFreightCar,
    gdu_ore_car,
    rock_and_roll,
)
from raildyn.vehicles.lateral import COOPERRIDER_CAR, MANCHESTER_CAR, Bogie, LateralCar, cooperrider_car
from raildyn.vehicles.locomotive import DEFAULT_LOCOMOTIVE, VerticalLocomotive
from raildyn.vehicles.locomotive_lateral import (
    LATERAL_LOCOMOTIVE,
    LateralLocomotive,
    ThreeAxleTruck,
    rigid_truck_wavelength,
)
from raildyn.vehicles.response import ResponseSpectrum, response_spectrum, rms_over_speeds, track_frf
from raildyn.vehicles.ride_comparison import RideRun, ride_run
from raildyn.vehicles.rocking import RockingFreightCar
from raildyn.vehicles.rocking_analysis import StaticRoll
from raildyn.vehicles.rocking_runs import RockingRun, RockingSweep, rocking_run, rocking_sweep
from raildyn.vehicles.three_piece import (
    EMPTY_FREIGHT_CAR,
    LOADED_FREIGHT_CAR,
    LateralFreightCar,
    ThreePieceTruck,
    freight_car,
)
from raildyn.vehicles.time_domain import PeriodicProfile, TimeResponse, periodic_profile, time_response
from raildyn.vehicles.vertical import MANCHESTER_VERTICAL, BodyFrequencies, VerticalCar
from raildyn.vehicles.wedges import WedgeFriction, wedge_energy_per_cycle, wedge_friction_force

__all__ = [
    "COOPERRIDER_CAR",
    "MANCHESTER_CAR",
    "BodyFrequencies",
    "Bogie",
    "DEFAULT_LOCOMOTIVE",
    "EMPTY_FREIGHT_CAR",
    "GDU_ORE_CAR",
    "LOADED_FREIGHT_CAR",
    "LateralCar",
    "LateralFreightCar",
    "LATERAL_LOCOMOTIVE",
    "LateralLocomotive",
    "MANCHESTER_VERTICAL",
    "PeriodicProfile",
    "ResponseSpectrum",
    "RideRun",
    "RockAndRoll",
    "RockingFreightCar",
    "RockingRun",
    "RockingSweep",
    "StaticRoll",
    "ThreePieceTruck",
    "TimeResponse",
    "ThreeAxleTruck",
    "VerticalCar",
    "VerticalFreightCar",
    "VerticalLocomotive",
    "WedgeFriction",
    "cooperrider_car",
    "freight_car",
    "gdu_ore_car",
    "periodic_profile",
    "response_spectrum",
    "ride_run",
    "rigid_truck_wavelength",
    "rms_over_speeds",
    "rock_and_roll",
    "rocking_run",
    "rocking_sweep",
    "time_response",
    "track_frf",
    "wedge_energy_per_cycle",
    "wedge_friction_force",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())
