"""What every identification of :mod:`raildyn.validation` returns: estimates with their intervals.

:class:`ParameterFit` holds the estimates of a least-squares fit with standard errors and
confidence intervals from the Jacobian at the solution: the covariance s²(JᵀJ)⁻¹, with s² the
residual variance over n − p degrees of freedom, and Student's t quantile at the stated confidence
{seber2003}. The checks of a record every fit starts from are here too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular

# Imported where used, to keep this module's import cheap (tests/test_imports.py): scipy.stats

__all__ = ["ParameterFit"]


# The largest magnitude a record may hold: its squares (sums of squares in the fits) stay finite.
_LARGEST = 1e100


def _record(time, values, *, name="response", rows=None) -> tuple[np.ndarray, np.ndarray]:
    """A uniform time grid and a finite record of the same length (1-D, or ``rows`` × n when given)."""
    t = _checks.time_grid("time", time, uniform=True)
    if t.size < 3:
        raise ValueError(f"time must hold at least 3 samples, got {t.size}")
    x = _checks.array(name, values, allow_empty=False)
    if np.abs(x).max() > _LARGEST:
        raise ValueError(
            f"{name} must stay within ±{_LARGEST:g} (its squares must be finite), got {x.max()!r}"
        )
    if rows is None:
        if x.ndim != 1:
            raise ValueError(f"{name} must be a 1-D record, got shape {x.shape}")
        n = x.size
    else:
        x = np.atleast_2d(x)
        if x.ndim != 2 or x.shape[0] != rows:
            raise ValueError(
                f"{name} must have shape ({rows}, n), one row per sensor, got {np.shape(values)}"
            )
        n = x.shape[1]
    if n != t.size:
        raise ValueError(f"{name} must have as many samples as time ({t.size}), got {n}")
    return t, x


def _confidence(confidence) -> float:
    return _checks.scalar("confidence", confidence, low=0.0, high=1.0, low_open=True, high_open=True)


def _intervals(solution, n: int, confidence: float):
    """Standard errors and t-intervals from the Jacobian at a least-squares solution.

    cov = s² (JᵀJ)⁻¹, s² = Σr²/(n − p) {seber2003}; a rank-deficient JᵀJ (a parameter the record
    does not determine) gives an infinite standard error, which the caller refuses.
    """
    from scipy import stats

    jac = np.asarray(solution.jac, dtype=float)
    p = jac.shape[1]
    dof = n - p
    if dof < 1:
        raise ValueError(f"the record must have more samples than the {p} parameters fitted, got {n}")
    s2 = 2.0 * solution.cost / dof
    # scale the columns before inverting: the parameters differ by many orders of magnitude
    norms = np.linalg.norm(jac, axis=0)
    norms[norms == 0.0] = 1.0
    js = jac / norms
    u, sv, vt = np.linalg.svd(js, full_matrices=False)
    if sv.min() <= sv.max() * 1e-12:
        raise ValueError(
            "the record does not determine every parameter (the Jacobian is rank-deficient); "
            "give a longer record, more sensors or fix a parameter"
        )
    cov = (vt.T / sv**2) @ vt / np.outer(norms, norms) * s2
    se = np.sqrt(np.diag(cov))
    half = stats.t.ppf(0.5 + confidence / 2.0, dof) * se
    est = np.asarray(solution.x, dtype=float)
    return se, np.column_stack([est - half, est + half]), math.sqrt(2.0 * solution.cost / n)


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class ParameterFit(Tabular):
    """A least-squares fit of a model to a record: estimates, standard errors and intervals.

    Attributes
    ----------
    names : tuple of str
        The parameters, in the order of the arrays below.
    estimate : ndarray, (p,)
        The least-squares estimates (units: see the function that made the fit).
    standard_error : ndarray, (p,)
        Their standard errors, from s²(JᵀJ)⁻¹ at the solution.
    interval : ndarray, (p, 2)
        Lower and upper limits of each parameter's interval at ``confidence`` (Student's t
        with n − p degrees of freedom).
    confidence : float
        The confidence level of ``interval``, in (0, 1).
    residual_rms : float
        Root mean square of measured − fitted, in the record's unit.
    time : ndarray, (n,)
        t of the record, s.
    measured : ndarray, (n,) or (s, n)
        The record (one row per sensor where there are several).
    fitted : ndarray, same shape as ``measured``
        The model at the estimates.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units;
    # the record and the fit along time; the estimates, one per parameter, are no columns.
    _columns = (("time", "s"), ("measured", "record's unit"), ("fitted", "record's unit"))
    _scalars = (("confidence", "-"), ("residual_rms", "record's unit"))
    _by_row = ("measured", "fitted")

    names: tuple
    estimate: np.ndarray
    standard_error: np.ndarray
    interval: np.ndarray
    confidence: float
    residual_rms: float
    time: np.ndarray
    measured: np.ndarray
    fitted: np.ndarray

    def __post_init__(self):
        _checks.fields(self)
        names = _checks.strings("names", self.names, unique=True)
        p = len(names)
        for field, shape in (("estimate", (p,)), ("standard_error", (p,)), ("interval", (p, 2))):
            _checks.array(field, getattr(self, field), shape=shape)
        _checks.array("standard_error", self.standard_error, low=0.0)
        _confidence(self.confidence)
        _checks.nonnegative("residual_rms", self.residual_rms)
        t = _checks.array("time", self.time, ndim=1, allow_empty=False)
        m = _checks.array("measured", self.measured)
        if m.shape[-1] != t.size or m.ndim not in (1, 2):
            raise ValueError(f"measured must have shape (n,) or (s, n) with n = {t.size}, got {m.shape}")
        if np.shape(self.fitted) != m.shape:
            raise ValueError(
                f"fitted must have the shape of measured {m.shape}, got shape {np.shape(self.fitted)}"
            )
        _checks.array("fitted", self.fitted)

    def value(self, name: str) -> float:
        """The estimate of one parameter, by name.

        Parameters
        ----------
        name : str
            One of ``names``.

        Returns
        -------
        float
        """
        return float(self.estimate[self._index(name)])

    def bounds(self, name: str) -> tuple[float, float]:
        """The interval of one parameter at ``confidence``, by name.

        Parameters
        ----------
        name : str
            One of ``names``.

        Returns
        -------
        tuple of float
            (lower, upper).
        """
        lo, hi = self.interval[self._index(name)]
        return float(lo), float(hi)

    def _index(self, name) -> int:
        _checks.choice("name", name, self.names)
        return self.names.index(name)

    def plot(self, ax=None) -> dict:
        """Draw the record and the fitted model against time.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.

        Returns
        -------
        dict
            The artists: ``measured`` and ``fitted``, each a list of lines (one per sensor).
        """
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        measured, fitted = np.atleast_2d(self.measured), np.atleast_2d(self.fitted)
        drawn = {"measured": [], "fitted": []}
        with matplotlib.rc_context(plots.STYLE):
            for i, (m, f) in enumerate(zip(measured, fitted, strict=True)):
                color = plots.COLORS[i % len(plots.COLORS)]
                (line,) = ax.plot(self.time, m, color=color, lw=0.6, alpha=0.5, label="measured" * (i == 0))
                drawn["measured"].append(line)
                (line,) = ax.plot(self.time, f, color=color, lw=1.4, label="fitted" * (i == 0))
                drawn["fitted"].append(line)
            ax.set_xlabel("time (s)")
            ax.legend()
        return drawn
