"""One protocol for every linear model of raildyn, and the one system every model assembles into.

Every linear model — the wheelset of chapter 5, the bogie and the lateral car of
chapter 7, the vertical passenger car, the freight car and the locomotive of
chapter 6, and each model the later chapters add — follows
:class:`LinearModel`:

* ``linear_system()`` → :class:`LinearSystem`, the assembled equations
  M q̈ + (C₀ + C₁/V) q̇ + K q = G_K w(t) + G_C ẇ(t), with w the track
  irregularities met by the wheels (rail heights, alignment, cross-level);
* ``matrices(speed)`` → :class:`SystemMatrices`: M, C(V), K and the input
  matrices G_K, G_C at one speed;
* ``state_space(speed, outputs=..., derivative=...)`` → a
  ``control.StateSpace`` from the track inputs to the outputs, so that root
  loci, Bode plots and frequency responses come from python-control;
* ``replace(**changes)`` → a validated copy with some parameters changed.

The speed V is given in exactly one place: the call that evaluates the model.
Linear creep forces are proportional to creepages, which are velocities divided
by V, so the wheel–rail damping is C₁/V; models without creep (the vertical
cars) have C₁ = 0 and give the same matrices at every speed.

:class:`Assembler` builds a :class:`LinearSystem` spring by spring: every
spring k (damper c) acts on a relative displacement d = g·q − h·w, so it adds
k g gᵀ to K and k g hᵀ to G_K (c to C₀ and G_C).

:class:`AffineFamily` gives the matrices of many members of a family of models affine in some
parameters (conicity, spring stiffnesses) from a few assemblies.

The package's modules, each imported through this one: ``_system`` (:class:`LinearSystem`,
:class:`SystemMatrices`, :class:`RailWheelset`), ``_protocol`` (:class:`LinearModel`,
:class:`LinearModelBase`, :func:`as_linear_system`), ``_assembler`` (:class:`Assembler`) and
``_family`` (:class:`AffineFamily`).
"""

from raildyn.linear_model._assembler import Assembler
from raildyn.linear_model._family import AffineFamily
from raildyn.linear_model._protocol import LinearModel, LinearModelBase, as_linear_system
from raildyn.linear_model._system import INPUT_KINDS as _INPUT_KINDS
from raildyn.linear_model._system import LinearSystem, RailWheelset, SystemMatrices

INPUT_KINDS = _INPUT_KINDS
"""What a track input can be: a rail height (on the rail given by ``input_rails``), the alignment
(lateral position of the track centreline) or the cross-level (left rail height − right rail height), m."""

__all__ = [
    "INPUT_KINDS",
    "AffineFamily",
    "Assembler",
    "LinearModel",
    "LinearModelBase",
    "LinearSystem",
    "RailWheelset",
    "SystemMatrices",
    "as_linear_system",
]
