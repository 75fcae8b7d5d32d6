"""The catalogue of time-integration schemes, by name, and the one call that runs any of them.

``METHODS`` names every scheme that both runs (:func:`~raildyn.integrators.integrate`) and is analysed
on the test oscillator (:mod:`raildyn.integrators.analysis`); ``PARAMETERS`` gives
the parameters each one accepts, with their defaults. Both are defined in the package's
ground floor (``_common``), which the runs and the analysis share; ``integrate`` sits above the
runs it dispatches to.
"""

from __future__ import annotations

from raildyn import _checks
from raildyn.integrators import linear, nonlinear
from raildyn.integrators._common import FIRST_ORDER, METHODS, PARAMETERS, IntegrationResult

__all__ = ["METHODS", "PARAMETERS", "integrate"]


def integrate(method: str, M, C, K, t, x0, v0, force=None, **params) -> IntegrationResult:
    """Run the scheme named ``method`` (one of ``METHODS``) with its parameters.

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative: an undamped or unstable
        system is integrated as it is (a blow-up raises SolverError).
    t : array_like, shape (m,)
        Uniform time grid, s.
    x0, v0 : array_like, shape (n,), or float
        Initial displacement (m) and velocity (m/s).
    force : None, array_like (n, m) or callable
        f in N, following the scheme: sampled on ``t`` for every scheme; as a callable,
        ``force(t)`` for the linear schemes and ``force(t, x, v)`` for the first-order
        ones (``FIRST_ORDER``).
    **params
        The scheme's parameters (``PARAMETERS``): ``theta`` (wilson), ``gamma`` and
        ``beta`` (newmark), ``alpha`` (hht_alpha); any other name is refused with a
        TypeError naming it.

    Returns
    -------
    IntegrationResult

    Raises
    ------
    raildyn.errors.SolverError
        If the run blows up (see each scheme).

    Examples
    --------
    >>> import numpy as np
    >>> r = integrate("wilson", 1.0, 0.0, 1.0, np.linspace(0, 1, 11), 1.0, 0.0, theta=1.4)
    >>> r.method, r.steps
    ('wilson', 10)
    """
    _checks.choice("method", method, METHODS)
    unknown = sorted(set(params) - set(PARAMETERS[method]))
    if unknown:
        raise TypeError(
            f"{method} takes the parameters {sorted(PARAMETERS[method]) or 'none'}, got unknown "
            f"{', '.join(unknown)}"
        )
    module = nonlinear if method in FIRST_ORDER else linear
    return getattr(module, method)(M, C, K, t, x0, v0, force, **params)
