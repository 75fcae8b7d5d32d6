"""The railway wheelset on tangent and curved track (book chapter 5): kinematics, linear and nonlinear
dynamics.

* :mod:`raildyn.wheelset.kinematics` — Klingel's kinematic oscillation of a free coned wheelset
  and of a rigid two-axle bogie (:func:`kinematic_wavelength`, :func:`rigid_bogie_wavelength`);
* :mod:`raildyn.wheelset.linear` — a :class:`Wheelset` parameter set and its linear lateral–yaw
  equations with Kalker's linear creep forces (f₁₁, f₂₂, f₂₃, f₃₃), gravitational stiffness
  and spin, on a primary suspension to a frame moving at the speed V: a linear model of the one
  protocol (:class:`raildyn.linear_model.LinearModel`: ``Wheelset().matrices(V)``,
  ``state_space(V)``), whose wheel–rail terms (:func:`creep_terms`, :func:`add_wheelset`) the
  bogie and car models of :mod:`raildyn.vehicles` assemble too;
* :mod:`raildyn.wheelset.curved` — on a curve: the pure-rolling offset r₀a/(λR) of a free
  wheelset (:func:`pure_rolling_offset`) and the loads a curve of radius R puts on a wheelset
  through its creepages and gravitational stiffness (:func:`curve_loads`), from which
  :func:`raildyn.curving.steady.steady_curving` finds the steady state of any vehicle;
* :mod:`raildyn.wheelset.contact` — the nonlinear contact (:class:`WheelRailContact`): a
  rolling-radius difference Δr(y), saturating creep forces and a flange modelled as a stiff
  spring beyond the flangeway clearance, on a cone or from a profile pair
  (:func:`profile_contact`);
* :mod:`raildyn.wheelset.protocol` — the nonlinear protocol (:class:`NonlinearModel`:
  ``rhs(t, state, speed)``, ``replace``, ``compiled_reason``);
* :mod:`raildyn.wheelset.equilibrium` — the one Newton's method towards a nonlinear model's
  equilibria on arcs (:func:`arc_newton`);
* :mod:`raildyn.wheelset.nonlinear` — its models, the nonlinear lateral vehicle and the nonlinear
  wheelset (:class:`NonlinearLateral`, :class:`NonlinearWheelset`), which
  a compiled engine (the package's ``_engine``, on the one wheel–rail law of ``_law``) runs where it
  holds them.

The contact geometry (Δr(y), contact-angle difference) enters as callables so
that the profiles of chapter 4 can be plugged in; the default is a cone of
conicity λ. Coordinates: x forward, y to the left, z up; ψ is the yaw angle
(positive turning to the left). SI units throughout. Every name is imported from here
(``from raildyn.wheelset import Wheelset``); the submodules say where each one lives.
"""

from raildyn.wheelset.contact import (
    ContactTable,
    ContactTables,
    WheelForces,
    WheelRailContact,
    contact_forces,
    profile_contact,
    tread_contact_angles,
    wheel_forces,
)
from raildyn.wheelset.curved import curve_loads, pure_rolling_offset, track_on_arc
from raildyn.wheelset.equilibrium import arc_newton
from raildyn.wheelset.kinematics import (
    KinematicOscillation,
    kinematic_oscillation,
    kinematic_wavelength,
    rigid_bogie_wavelength,
)
from raildyn.wheelset.linear import CreepTerms, Wheelset, add_wheelset, creep_terms, wickens_critical_speed
from raildyn.wheelset.nonlinear import NonlinearLateral, NonlinearWheelset, SuspensionElement
from raildyn.wheelset.protocol import CompiledRHS, NonlinearModel

__all__ = [
    "CompiledRHS",
    "ContactTable",
    "ContactTables",
    "CreepTerms",
    "KinematicOscillation",
    "NonlinearLateral",
    "NonlinearModel",
    "NonlinearWheelset",
    "SuspensionElement",
    "WheelForces",
    "WheelRailContact",
    "Wheelset",
    "add_wheelset",
    "arc_newton",
    "contact_forces",
    "creep_terms",
    "curve_loads",
    "kinematic_oscillation",
    "kinematic_wavelength",
    "profile_contact",
    "pure_rolling_offset",
    "rigid_bogie_wavelength",
    "track_on_arc",
    "tread_contact_angles",
    "wheel_forces",
    "wickens_critical_speed",
]
