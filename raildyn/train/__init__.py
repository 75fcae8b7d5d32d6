"""Train dynamics (chapter 9): consists, couplers and draft gear, train forces, longitudinal runs.

* :mod:`~raildyn.train.vehicles` — default vehicles, ``make_consist("2 SD40-2 + 100 loaded hopper")``;
* :mod:`~raildyn.train.resistance` — ``davis_resistance`` (original and modified), grade, curve, routes;
* :mod:`~raildyn.train.couplers` — slack and friction draft gear with loading/unloading branches;
* :mod:`~raildyn.train.forces` — tractive effort by notch, dynamic brake, travelling air-brake signal;
* :mod:`~raildyn.train.model` — the whole-train equations (``TrainModel``) and quasi-static forces;
* :mod:`~raildyn.train.longitudinal` — ``simulate`` (its run) and ``braking_model`` (the chapter's case);
* ``raildyn.train.results`` — what the analyses return: ``TrainRun``, ``CouplerPeak``, ``QuasiStatic``;
* :mod:`~raildyn.train.lateral` — lateral and vertical components of coupler forces: L/V, wheel unloading.

SI units throughout (m, kg, s, N); ``davis_resistance(..., units="US")`` speaks lbf, tons, mph, ft².

Every analysis returns a frozen dataclass (``TrainRun``, ``CouplerPeak``, ``QuasiStatic``,
``CouplerEffects``, ``DraftGearLoop``); those worth a picture draw it with ``plot``/``plot_*``
methods, which the figures and widgets of chapter 9 call. ``simulate`` raises
:class:`raildyn.errors.SolverError` when it cannot finish; a returned run is a success.

Examples
--------
>>> from raildyn import train
>>> run = train.simulate(train.braking_model(10, 1), 20.0, 20.0, samples=201)
>>> run.coupler_force.shape, run.peak.kind
((10, 201), 'buff')
"""

from raildyn.train.couplers import DraftGear, DraftGearLoop
from raildyn.train.forces import (
    DYNAMIC_BRAKE_FADE_SPEED,
    DYNAMIC_BRAKE_PEAK_SPEED,
    NOTCHES,
    AirBrake,
    dynamic_brake_force,
    tractive_effort,
)
from raildyn.train.lateral import CouplerEffects, coupler_angles, coupler_effects, limiting_coupler_force
from raildyn.train.longitudinal import braking_model, simulate
from raildyn.train.model import TrainModel
from raildyn.train.resistance import (
    MODIFIED_DAVIS_K,
    Route,
    curve_resistance,
    davis_resistance,
    grade_force,
)
from raildyn.train.results import CouplerPeak, QuasiStatic, TrainRun
from raildyn.train.vehicles import VEHICLES, Consist, Vehicle, make_consist

__all__ = [
    "DYNAMIC_BRAKE_FADE_SPEED",
    "DYNAMIC_BRAKE_PEAK_SPEED",
    "MODIFIED_DAVIS_K",
    "NOTCHES",
    "VEHICLES",
    "AirBrake",
    "Consist",
    "CouplerEffects",
    "CouplerPeak",
    "DraftGear",
    "DraftGearLoop",
    "QuasiStatic",
    "Route",
    "TrainModel",
    "TrainRun",
    "Vehicle",
    "braking_model",
    "coupler_angles",
    "coupler_effects",
    "curve_resistance",
    "davis_resistance",
    "dynamic_brake_force",
    "grade_force",
    "limiting_coupler_force",
    "make_consist",
    "simulate",
    "tractive_effort",
]
