"""Chapter 4: wheel–rail rolling contact.

* :mod:`~raildyn.contact.hertz` — Hertz's normal contact: ellipse, m and n, pressure, approach, stiffness.
* :mod:`~raildyn.contact.kalker` — Kalker's creep coefficients and linear theory, the sign convention
  and the creep forces every law returns.
* :mod:`~raildyn.contact.saturation` — Carter's 2-D law and Shen–Hedrick–Elkins's saturation.
* :mod:`~raildyn.contact.johnson_vermeulen` — Johnson and Vermeulen's law, with its own coefficients.
* :mod:`~raildyn.contact.polach` — Polach's law and its slip-speed-dependent friction.
* :mod:`~raildyn.contact.creepages` — the creepages of a wheelset's two wheels.
* :mod:`~raildyn.contact.fastsim` — Kalker's simplified theory (FASTSIM), compiled, batched over states;
  :mod:`~raildyn.contact.fastsim_python` — the same in numpy and plain Python, for the tests.
* :mod:`~raildyn.contact.profiles` — conical, S1002 and 60E1 profiles.
* :mod:`~raildyn.contact.profile_files` — measured or worn profiles read from two-column files, and the
  check that a wheel and a rail make a pair at a gauge.
* :mod:`~raildyn.contact.geometry` — wheel and rail profiles as data, and a pair's contact points,
  Δr(y), contact angles and equivalent conicity.
* :mod:`~raildyn.contact.conicity` — equivalent conicity of a tabulated Δr(y): EN 15302's kinematic
  method and the first harmonic.
* :mod:`~raildyn.contact.comparison` — every creep law on one sweep of lateral creepage, side by side.

The elastic constants default to the steel of :mod:`raildyn.constants` everywhere.
"""

from raildyn.contact.comparison import CREEP_LAWS, LateralCreepCurves, lateral_creep_curves
from raildyn.contact.conicity import harmonic_conicity, kinematic_conicity
from raildyn.contact.creepages import WheelsetCreepages, creepage_terms, wheelset_creepages
from raildyn.contact.fastsim import FastsimResult, Flexibilities, fastsim, flexibilities
from raildyn.contact.fastsim_python import fastsim_reference
from raildyn.contact.geometry import (
    ContactGeometry,
    RailProfile,
    WheelProfile,
    contact_angles,
    contact_geometry,
    equivalent_conicity,
    rolling_radius_difference,
)
from raildyn.contact.hertz import HertzCoefficients, HertzContact, hertz_coefficients, hertz_contact
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
from raildyn.contact.profile_files import (
    WORN_RAIL_FILE,
    WORN_WHEEL_FILE,
    check_pair,
    read_rail_profile,
    read_wheel_profile,
    worn_rail,
    worn_wheel,
)
from raildyn.contact.profiles import conical_wheel, s1002_wheel, uic60_rail
from raildyn.contact.saturation import (
    carter,
    carter_coefficient,
    saturation_factor,
    saturation_scale,
    shen_hedrick_elkins,
)
from raildyn.contact.trace_line import trace_line

__all__ = [
    "CREEP_LAWS",
    "KALKER_NU",
    "ContactGeometry",
    "CreepCoefficients",
    "CreepForces",
    "FastsimResult",
    "Flexibilities",
    "HertzCoefficients",
    "HertzContact",
    "JohnsonVermeulenCoefficients",
    "KalkerCoefficients",
    "LateralCreepCurves",
    "RailProfile",
    "WheelProfile",
    "WheelsetCreepages",
    "WORN_RAIL_FILE",
    "WORN_WHEEL_FILE",
    "carter",
    "carter_coefficient",
    "check_pair",
    "conical_wheel",
    "contact_angles",
    "contact_geometry",
    "creep_coefficients",
    "equivalent_conicity",
    "fastsim",
    "fastsim_reference",
    "flexibilities",
    "harmonic_conicity",
    "hertz_coefficients",
    "hertz_contact",
    "johnson_vermeulen",
    "johnson_vermeulen_coefficients",
    "kalker_coefficients",
    "kalker_linear",
    "kinematic_conicity",
    "lateral_creep_curves",
    "polach",
    "read_rail_profile",
    "read_wheel_profile",
    "polach_adhesion",
    "PolachAdhesion",
    "POLACH_DRY",
    "POLACH_WET",
    "rolling_radius_difference",
    "s1002_wheel",
    "saturation_factor",
    "saturation_scale",
    "shen_hedrick_elkins",
    "trace_line",
    "uic60_rail",
    "worn_rail",
    "worn_wheel",
    "creepage_terms",
    "wheelset_creepages",
]
