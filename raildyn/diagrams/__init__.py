"""Parametric schematics of raildyn's models, drawn to scale from the same parameter sets as the models.

Each function takes the model object (a :class:`~raildyn.wheelset.Wheelset`, a
:class:`~raildyn.vehicles.Bogie`, a :class:`~raildyn.bridge.SimplySupportedBeam`, ...), reads its
lengths and draws it, labelled with the symbols of the notebooks (``book/notation.md``): change the
model and the picture changes. Like every raildyn plot, a schematic takes ``ax=None``, draws, and
returns its artists (a dict); it never calls ``plt.show()`` and never changes matplotlib's defaults.
The style is one quiet style: thin black lines, light grey bodies, springs as zigzags and dampers as
dashpots, coordinates in blue, forces and the direction of travel in red, equal aspect, no frame.

* :mod:`~raildyn.diagrams.dynamics` — chapter 1: the SDOF oscillator, a rigid body's freedoms;
* :mod:`~raildyn.diagrams.rolling` — the wheelset on the rails in section and in plan (moving);
* :mod:`~raildyn.diagrams.vehicles` — the bogie in plan, the car from the side and in plan, the
  three-piece freight truck;
* :mod:`~raildyn.diagrams.structures` — the coupler chain of a consist, the simply supported beam
  under its moving load (moving).

Three schematics move: :func:`~raildyn.diagrams.rolling.wheelset_plan` returns a ``WheelsetPlan``,
:func:`~raildyn.diagrams.structures.beam_load` a ``BeamLoad``, and
:class:`~raildyn.diagrams.vehicles.BogiePlan` draws the bogie of
:func:`~raildyn.diagrams.vehicles.bogie_plan`; each one's ``update`` moves the drawn artists in place
(no new artist, no new figure), for a widget or an animation (:mod:`raildyn.animations`).
"""

from raildyn.diagrams.dynamics import oscillator_model, rigid_body_freedoms
from raildyn.diagrams.rolling import WheelsetPlan, wheelset_plan, wheelset_section
from raildyn.diagrams.structures import BeamLoad, beam_load, coupler_chain
from raildyn.diagrams.vehicles import BogiePlan, bogie_plan, car_plan, car_side, truck_schematic

__all__ = [
    "BeamLoad",
    "BogiePlan",
    "WheelsetPlan",
    "beam_load",
    "bogie_plan",
    "car_plan",
    "car_side",
    "coupler_chain",
    "oscillator_model",
    "rigid_body_freedoms",
    "truck_schematic",
    "wheelset_plan",
    "wheelset_section",
]
