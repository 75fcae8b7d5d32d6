"""Vehicle–bridge interaction (book chapter 10). The package grows module by module.

* :mod:`raildyn.bridge.beam` — the simply supported beam under a moving force, modal.
"""

from raildyn.bridge.beam import MovingForceResponse, SimplySupportedBeam, fryba_deflection, moving_force

__all__ = ["MovingForceResponse", "SimplySupportedBeam", "fryba_deflection", "moving_force"]
