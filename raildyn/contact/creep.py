"""The creepages and creep-force laws of chapter 4 in one import, under their former home.

The code lives in :mod:`~raildyn.contact.kalker` (sign convention, creep coefficients, Kalker's
linear theory), :mod:`~raildyn.contact.saturation` (Carter, Shen–Hedrick–Elkins),
:mod:`~raildyn.contact.johnson_vermeulen`, :mod:`~raildyn.contact.polach` and
:mod:`~raildyn.contact.creepages`. This module imports every public name it used to define, so that
``raildyn.contact.creep.X`` keeps working; import from :mod:`raildyn.contact` instead.
"""

# This module is the old home of the creep laws, kept for one issue (issue 33) and then deleted.

from raildyn.contact.creepages import WheelsetCreepages, wheelset_creepages
from raildyn.contact.johnson_vermeulen import (
    JohnsonVermeulenCoefficients,
    johnson_vermeulen,
    johnson_vermeulen_coefficients,
)
from raildyn.contact.kalker import (
    KALKER_NU,
    CreepCoefficients,
    CreepForces,
    KalkerCoefficients,
    creep_coefficients,
    kalker_coefficients,
    kalker_linear,
)
from raildyn.contact.polach import POLACH_DRY, POLACH_WET, PolachAdhesion, polach, polach_adhesion
from raildyn.contact.saturation import carter, carter_coefficient, saturation_factor, shen_hedrick_elkins

__all__ = [
    "KALKER_NU",
    "POLACH_DRY",
    "POLACH_WET",
    "CreepCoefficients",
    "CreepForces",
    "JohnsonVermeulenCoefficients",
    "KalkerCoefficients",
    "PolachAdhesion",
    "WheelsetCreepages",
    "carter",
    "carter_coefficient",
    "creep_coefficients",
    "johnson_vermeulen",
    "johnson_vermeulen_coefficients",
    "kalker_coefficients",
    "kalker_linear",
    "polach",
    "polach_adhesion",
    "saturation_factor",
    "shen_hedrick_elkins",
    "wheelset_creepages",
]
