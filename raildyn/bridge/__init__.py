"""Vehicle–bridge interaction (book chapter 10).

* :mod:`raildyn.bridge.beam` — the simply supported beam under a moving force, modal.
* :mod:`raildyn.bridge.loads` — axle sequences: a train as moving forces.
"""

from raildyn.bridge.beam import MovingForceResponse, SimplySupportedBeam, fryba_deflection, moving_force
from raildyn.bridge.loads import AxleSequence

__all__ = ["AxleSequence", "MovingForceResponse", "SimplySupportedBeam", "fryba_deflection", "moving_force"]
