"""Time integration of ``M x'' + C x' + K x = f(t, x, x')`` and the stability and accuracy of each scheme.

Chapter 2 of the companion (numerical methods). Three families, one result type
(:class:`IntegrationResult`: t, x, v, a, step and iteration counts):

* linear systems, direct integration with a constant step: :func:`central_difference`
  (explicit), :func:`houbolt`, :func:`wilson`, :func:`newmark` with the presets
  :func:`average_acceleration` and :func:`linear_acceleration`, and :func:`hht_alpha`;
  the effective stiffness is factorized once and each step is one product with a
  precomputed matrix;
* first-order schemes for nonlinear forces: :func:`forward_euler`, :func:`rk4`,
  :func:`abm` (Adams–Bashforth–Moulton predictor–corrector);
* implicit nonlinear: :func:`newmark_newton` (Newton–Raphson iterations each step,
  on the force's tangent, a :class:`ForceJacobian`) and :func:`stiff` (scipy's BDF
  or Radau).

:func:`integrate` runs any scheme named in ``METHODS``. The nonlinear models of the later
chapters (the hunting of chapter 7, the train of chapter 9) run on :mod:`raildyn.integrators.runner`:
compiled Dormand–Prince and scipy's ``solve_ivp``, both bounded by one budget of evaluations and
failing by one rule (imported on its own, as it loads numba).

The modules read bottom-up: ``_common`` (the catalogue of schemes, the results, the checks) and
:mod:`~raildyn.integrators.recursions` (each linear scheme's step) import nothing of the package;
:mod:`~raildyn.integrators.amplification` (the test oscillator) builds on the steps; ``_divergence``
(why a run blew up) on the amplification; :mod:`~raildyn.integrators.linear` and
:mod:`~raildyn.integrators.nonlinear` (the runs) on those; :mod:`~raildyn.integrators.schemes`
(:func:`integrate`) on the runs; :mod:`~raildyn.integrators.analysis` (charts, a model's step
limit, convergence) on all of them.

Failure policy: every failure (a run that blows up, a Newton iteration that does
not converge, scipy giving up) raises :class:`raildyn.errors.SolverError` with the
step, the time and the reason, which names the stability limit of the scheme on
the system, and holds the completed part of the run as its ``partial``
:class:`IntegrationResult`. A returned result is a success.

On the test oscillator, :func:`amplification_matrix`, :func:`spectral_radius`,
:func:`period_elongation`, :func:`amplitude_decay` and :func:`stability_limit`
describe each scheme against Δt/T, and :func:`scheme_accuracy` gathers them into a
:class:`SchemeAccuracy` that draws the chart; :func:`convergence_study` measures the
order of accuracy; on a model, :func:`stable_step` gives the largest stable step
(for the first-order schemes through :func:`first_order_step_limit`) and
:func:`stiffness_ratio` how stiff the equations are. SI units throughout.

Examples
--------
>>> import numpy as np
>>> from raildyn.errors import SolverError
>>> t = np.arange(100) * 0.4  # T = 1 s, past the central difference limit T/π
>>> try:
...     integrate("central_difference", 1.0, 0.0, (2 * np.pi) ** 2, t, 1.0, 0.0)
... except SolverError as err:
...     print(err.partial.t.size == err.step, "stable only for dt <= T_min/pi" in str(err))
True True
"""

from raildyn.integrators._common import Deviation, ForceJacobian, IntegrationResult, Maxima
from raildyn.integrators.analysis import (
    ConvergenceStudy,
    SchemeAccuracy,
    amplification_matrix,
    amplitude_decay,
    convergence_study,
    first_order_step_limit,
    period_elongation,
    scheme_accuracy,
    spectral_radius,
    stability_limit,
    stable_step,
    stiffness_ratio,
)
from raildyn.integrators.linear import (
    average_acceleration,
    central_difference,
    hht_alpha,
    houbolt,
    linear_acceleration,
    newmark,
    wilson,
)
from raildyn.integrators.nonlinear import abm, forward_euler, newmark_newton, rk4, stiff
from raildyn.integrators.schemes import METHODS, PARAMETERS, integrate

__all__ = [
    "METHODS",
    "PARAMETERS",
    "ConvergenceStudy",
    "Deviation",
    "ForceJacobian",
    "IntegrationResult",
    "Maxima",
    "SchemeAccuracy",
    "abm",
    "amplification_matrix",
    "amplitude_decay",
    "average_acceleration",
    "central_difference",
    "convergence_study",
    "first_order_step_limit",
    "forward_euler",
    "hht_alpha",
    "houbolt",
    "integrate",
    "linear_acceleration",
    "newmark",
    "newmark_newton",
    "period_elongation",
    "rk4",
    "scheme_accuracy",
    "spectral_radius",
    "stability_limit",
    "stable_step",
    "stiff",
    "stiffness_ratio",
    "wilson",
]
