"""Time integration of ``M x'' + C x' + K x = f(t, x, x')`` and the stability and accuracy of each scheme.

Chapter 2 of the companion (numerical methods). Three families, one result type
(:class:`IntegrationResult`: t, x, v, a, step and iteration counts, success,
message):

* linear systems, direct integration with a constant step: :func:`central_difference`
  (explicit), :func:`houbolt`, :func:`wilson`, :func:`newmark` with the presets
  :func:`average_acceleration` and :func:`linear_acceleration`, and :func:`hht_alpha`;
  the effective stiffness is factorized once and each step is one product with a
  precomputed matrix;
* first-order schemes for nonlinear forces: :func:`forward_euler`, :func:`rk4`,
  :func:`abm` (Adams–Bashforth–Moulton predictor–corrector);
* implicit nonlinear: :func:`newmark_newton` (Newton–Raphson iterations each step)
  and :func:`stiff` (scipy's BDF or Radau).

A run that blows up raises :class:`DivergenceError` naming the step and the
stability limit of the scheme (or stops with ``success=False`` when asked).
On the test oscillator, :func:`amplification_matrix`, :func:`spectral_radius`,
:func:`period_elongation`, :func:`amplitude_decay` and :func:`stability_limit`
describe each scheme named in ``METHODS`` against Δt/T. SI units throughout.
"""

from raildyn.integrators._common import DivergenceError, IntegrationResult
from raildyn.integrators.analysis import (
    METHODS,
    PARAMETERS,
    amplification_matrix,
    amplitude_decay,
    period_elongation,
    spectral_radius,
    stability_limit,
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

_BY_NAME = {
    "central_difference": central_difference,
    "houbolt": houbolt,
    "wilson": wilson,
    "newmark": newmark,
    "average_acceleration": average_acceleration,
    "linear_acceleration": linear_acceleration,
    "hht_alpha": hht_alpha,
    "forward_euler": forward_euler,
    "rk4": rk4,
    "abm": abm,
}


def integrate(method: str, M, C, K, t, x0, v0, force=None, **params) -> IntegrationResult:
    """Run the scheme named ``method`` (one of ``METHODS``) with its parameters.

    ``force`` follows the scheme: f(t) (sampled array or ``force(t)``) for the
    linear schemes, f(t, x, v) for the first-order ones. See each function.

    Examples
    --------
    >>> import numpy as np
    >>> r = integrate("wilson", 1.0, 0.0, 1.0, np.linspace(0, 1, 11), 1.0, 0.0, theta=1.4)
    >>> r.method, r.steps, r.success
    ('wilson', 10, True)
    """
    if method not in _BY_NAME:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    return _BY_NAME[method](M, C, K, t, x0, v0, force, **params)


__all__ = [
    "METHODS",
    "PARAMETERS",
    "DivergenceError",
    "IntegrationResult",
    "abm",
    "amplification_matrix",
    "amplitude_decay",
    "average_acceleration",
    "central_difference",
    "forward_euler",
    "hht_alpha",
    "houbolt",
    "integrate",
    "linear_acceleration",
    "newmark",
    "newmark_newton",
    "period_elongation",
    "rk4",
    "spectral_radius",
    "stability_limit",
    "stiff",
    "wilson",
]
