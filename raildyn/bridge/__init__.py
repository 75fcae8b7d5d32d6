"""Vehicle–bridge interaction (book chapter 10).

* :mod:`raildyn.bridge.beam` — the simply supported beam under moving forces, modal and in closed form.
* :mod:`raildyn.bridge.continuous` — a beam continuous over several spans, by its exact modes.
* :mod:`raildyn.bridge.winkler` — an infinite beam on an elastic foundation under a moving force.
* :mod:`raildyn.bridge.track` — the track as a structure: a rail on pads, sleepers and ballast.
* :mod:`raildyn.bridge.sleepers` — the rail on discrete sleepers: a finite-element track and its receptance.
* :mod:`raildyn.bridge.defects` — what the wheel meets: a dipped joint, a wheel flat, roughness.
* :mod:`raildyn.bridge.wheels` — what rides on the rail: one wheel, or a vertical vehicle on its wheels.
* :mod:`raildyn.bridge.impact` — wheels rolling on that track: impact forces at joints and flats, roughness.
* :mod:`raildyn.bridge.loads` — what crosses: axle sequences, moving masses, sprung masses, vehicles, trains.
* :mod:`raildyn.bridge.trains` — the design trains of EN 1991-2 (HSLM-A) and regular trains.
* :mod:`raildyn.bridge.coupled` — the crossing, bridge and vehicle coupled through the wheel forces.
* :mod:`raildyn.bridge.codes` — what practice checks: impact factors, resonance, acceleration limits.
"""

from raildyn import _deprecated
from raildyn.bridge.beam import (
    MovingForceResponse,
    SimplySupportedBeam,
    fryba_deflection,
    moving_force_response,
    plot_amplification,
)
from raildyn.bridge.codes import (
    arema_impact_factor,
    cancellation_spans,
    comfort_acceleration_limit,
    deck_acceleration_limit,
    en1991_dynamic_factor,
    en1991_real_train_factor,
    resonance_speeds,
)
from raildyn.bridge.continuous import ContinuousBeam
from raildyn.bridge.coupled import BridgeCrossing, crossing
from raildyn.bridge.defects import DippedJoint, Roughness, WheelFlat
from raildyn.bridge.impact import (
    WheelOnTrack,
    contact_compliance,
    contact_force_spectrum,
    jenkins_p2,
    lumped_track,
    wheel_on_track,
)
from raildyn.bridge.loads import (
    AxleSequence,
    MovingLoad,
    moving_load,
    moving_mass,
    sprung_mass,
    train,
    vehicle,
)
from raildyn.bridge.sleepers import DiscreteResonances, DiscreteTrack, TrackMatrices
from raildyn.bridge.track import LayeredTrack, TrackResonances, beam_receptance
from raildyn.bridge.trains import HSLM_A, hslm, regular_train
from raildyn.bridge.wheels import VehicleWheels, Wheel, WheelBlock
from raildyn.bridge.winkler import WinklerBeam

__all__ = [
    "HSLM_A",
    "AxleSequence",
    "BridgeCrossing",
    "ContinuousBeam",
    "DippedJoint",
    "DiscreteResonances",
    "DiscreteTrack",
    "LayeredTrack",
    "MovingForceResponse",
    "MovingLoad",
    "Roughness",
    "SimplySupportedBeam",
    "TrackMatrices",
    "TrackResonances",
    "VehicleWheels",
    "Wheel",
    "WheelBlock",
    "WheelFlat",
    "WheelOnTrack",
    "WinklerBeam",
    "arema_impact_factor",
    "beam_receptance",
    "cancellation_spans",
    "comfort_acceleration_limit",
    "contact_compliance",
    "contact_force_spectrum",
    "crossing",
    "deck_acceleration_limit",
    "en1991_dynamic_factor",
    "en1991_real_train_factor",
    "fryba_deflection",
    "hslm",
    "jenkins_p2",
    "lumped_track",
    "moving_force_response",
    "moving_load",
    "moving_mass",
    "plot_amplification",
    "regular_train",
    "resonance_speeds",
    "sprung_mass",
    "train",
    "vehicle",
    "wheel_on_track",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())
