"""Vehicle–bridge interaction (book chapter 10).

* :mod:`raildyn.bridge.beam` — the simply supported beam under moving forces, modal and in closed form.
* :mod:`raildyn.bridge.loads` — what crosses: axle sequences, moving masses, sprung masses, vehicles, trains.
* :mod:`raildyn.bridge.coupled` — the crossing, bridge and vehicle coupled through the wheel forces.
"""

from raildyn.bridge.beam import MovingForceResponse, SimplySupportedBeam, fryba_deflection, moving_force
from raildyn.bridge.coupled import BridgeCrossing, crossing
from raildyn.bridge.loads import (
    AxleSequence,
    MovingLoad,
    moving_forces,
    moving_mass,
    sprung_mass,
    train,
    vehicle,
)

__all__ = [
    "AxleSequence",
    "BridgeCrossing",
    "MovingForceResponse",
    "MovingLoad",
    "SimplySupportedBeam",
    "crossing",
    "fryba_deflection",
    "moving_force",
    "moving_forces",
    "moving_mass",
    "sprung_mass",
    "train",
    "vehicle",
]
