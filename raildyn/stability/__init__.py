"""Lateral stability (book chapter 7): eigenvalues against speed, mode tracking, critical speed, hunting.

The linear models of :mod:`raildyn.wheelset` and :mod:`raildyn.vehicles`
follow the one protocol (:class:`raildyn.linear_model.LinearModel`), and their
systems read M q̈ + (C₀ + C₁/V) q̇ + K q = 0 without the track,
so the state matrix at every speed of a sweep is built at once and all
eigenvalues come from one batched ``numpy.linalg`` call.

* :func:`~raildyn.stability.linear.eigenvalues_against_speed` — every eigenvalue at every speed;
* :func:`~raildyn.stability.linear.mode_sweep` — eigenvalues, frequencies and damping ratios with each
  mode followed across speed by its modal assurance criterion (MAC), so
  that crossing branches keep their labels;
* :func:`~raildyn.stability.linear.critical_speed` (defined in :mod:`raildyn.stability.critical`) —
  the lowest speed at which the largest real part becomes positive, by a batched coarse scan and a
  bracketed regula falsi;
* :func:`~raildyn.stability.linear.critical_speed_map` — the critical speed over a grid of two parameters;
* :func:`~raildyn.stability.search.critical_speeds` — the search itself, for many systems at once (a
  stack of :class:`~raildyn.stability.search.StateMatrices`, which a family of models affine in its
  parameters, :class:`raildyn.linear_model.AffineFamily`, gives without assembling each member);
* :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude`,
  :func:`~raildyn.stability.bifurcation.bifurcation_diagram` — nonlinear hunting: the
  amplitude of the limit cycle against speed and the nonlinear critical speed;
  :func:`~raildyn.stability.bifurcation.bifurcation_diagrams` runs a family of vehicles side by side;
  :func:`~raildyn.stability.continuation.limit_cycle_branch` follows the whole branch of limit cycles,
  stable and unstable, through its fold by pseudo-arclength continuation.
  The nonlinear models are integrated by a compiled engine (numba) that takes scipy RK45's
  steps a few hundred times faster; ``engine="scipy"`` runs the reference it is tested against.
"""

from raildyn.stability.bifurcation import (
    BifurcationDiagram,
    PeriodicOrbit,
    bifurcation_diagram,
    bifurcation_diagrams,
    periodic_orbit,
)
from raildyn.stability.continuation import LimitCycleBranch, limit_cycle_branch
from raildyn.stability.critical import CriticalSpeed, CriticalSpeedMap, critical_speed, critical_speed_map
from raildyn.stability.linear import (
    ModeSweep,
    TrackedModes,
    eigenvalues_against_speed,
    largest_real_part,
    mac,
    mode_sweep,
    track_modes,
)
from raildyn.stability.nonlinear import LimitCycle, NonlinearRun, limit_cycle_amplitude, simulate
from raildyn.stability.search import (
    CRITICAL_SPEED_STATUSES,
    MAX_SCAN_SPEEDS,
    CriticalSpeeds,
    StateMatrices,
    critical_speeds,
)

__all__ = [
    "CRITICAL_SPEED_STATUSES",
    "MAX_SCAN_SPEEDS",
    "BifurcationDiagram",
    "CriticalSpeed",
    "CriticalSpeedMap",
    "CriticalSpeeds",
    "LimitCycle",
    "LimitCycleBranch",
    "ModeSweep",
    "NonlinearRun",
    "PeriodicOrbit",
    "StateMatrices",
    "TrackedModes",
    "bifurcation_diagram",
    "bifurcation_diagrams",
    "critical_speed",
    "critical_speed_map",
    "critical_speeds",
    "eigenvalues_against_speed",
    "largest_real_part",
    "limit_cycle_amplitude",
    "limit_cycle_branch",
    "mac",
    "mode_sweep",
    "periodic_orbit",
    "simulate",
    "track_modes",
]
