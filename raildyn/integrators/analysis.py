"""Stability and accuracy of each scheme on the test oscillator x'' + 2ξω x' + ω² x = 0.

Applied to one oscillator with a constant step, every scheme of this package is a
linear recursion z₊ = A z; A is its amplification matrix {Bathe 1996, §9.4.1}.
Its eigenvalues tell all: the scheme is stable while the spectral radius
ρ(A), the largest modulus of its eigenvalues, stays at or below 1, and the principal
pair exp(s̄Δt), s̄ = −ξ̄ω̄ ± iω̄ (the computed characteristic roots), gives the computed
frequency ω̄ and decay, hence the period elongation and the amplitude decay plotted
against Δt/T in {Bathe 1996, Figs. 9.2–9.4}. The period is
T = 1 s, so ω = 2π rad/s and Δt = Δt/T.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass
from functools import lru_cache
from math import factorial

import matplotlib
import numpy as np

from raildyn import _checks, plots
from raildyn._checks import array, integer, scalar, square_matrix
from raildyn.integrators import linear
from raildyn.integrators._common import draw_line, highest_frequency
from raildyn.integrators.schemes import FIRST_ORDER, METHODS, PARAMETERS, integrate
from raildyn.vibration import SDOF, first_order_matrix

__all__ = [
    "METHODS",
    "PARAMETERS",
    "ConvergenceStudy",
    "SchemeAccuracy",
    "amplification_matrix",
    "amplitude_decay",
    "convergence_study",
    "first_order_step_limit",
    "period_elongation",
    "scheme_accuracy",
    "spectral_radius",
    "stability_limit",
    "stable_step",
    "stiffness_ratio",
]


# The largest Δt/T analysed: beyond, (ωΔt)² passes 4e13 and the amplification matrix loses its
# digits to rounding, while every scheme has long reached its behaviour as Δt/T → ∞.
MAX_DT_OVER_T = 1.0e6
# The smallest: below, each scheme's errors in period and amplitude, of order (2πΔt/T)² ≈ 4e-7 at
# 1e-4, sink into the rounding of the amplification matrix (at 1e-6 the period error of Newmark's
# scheme reads with the wrong sign) and a step of 1e-300 T overflows its effective matrix.
MIN_DT_OVER_T = 1.0e-4


def _ratios(dt_over_T) -> np.ndarray:
    """The steps over the period as a checked 1-D array: each in [MIN_DT_OVER_T, MAX_DT_OVER_T]."""
    ratios = array("dt_over_T", np.atleast_1d(_checks.array("dt_over_T", dt_over_T)), ndim=1, low=0.0,
                   low_open=True, allow_empty=False)  # fmt: skip
    if ratios.min() < MIN_DT_OVER_T:
        raise ValueError(
            f"dt_over_T must be >= {MIN_DT_OVER_T:g} (below, the schemes' errors sink into the rounding "
            f"of the amplification matrix), got {ratios.min()!r}"
        )
    if ratios.max() > MAX_DT_OVER_T:
        raise ValueError(
            f"dt_over_T must be <= {MAX_DT_OVER_T:g} (beyond, the amplification matrix is lost to "
            f"rounding and every scheme has reached its limit as dt/T grows), got {ratios.max()!r}"
        )
    return ratios


def _parameters(method: str, params: dict) -> dict:
    _checks.choice("method", method, METHODS)
    allowed = PARAMETERS[method]
    unknown = sorted(set(params) - set(allowed))
    if unknown:
        raise TypeError(
            f"{method} takes the parameters {sorted(allowed) or 'none'}, got unknown {', '.join(unknown)}"
        )
    chosen = {**allowed, **params}
    if method == "wilson":
        chosen["theta"] = scalar("theta", chosen["theta"], low=1.0, high=3.0)
    if method == "newmark":
        chosen["gamma"] = scalar("gamma", chosen["gamma"], low=0.5, high=1.5)
        chosen["beta"] = scalar("beta", chosen["beta"], low=0.0, high=1.0)
    if method == "hht_alpha":
        chosen["alpha"] = scalar("alpha", chosen["alpha"], low=-1 / 3, high=0.0)
    return chosen


def _abm_matrix(hJ: np.ndarray) -> np.ndarray:
    """Adams–Bashforth–Moulton (4th order, PECE) on y' = J y, state (y_n, y_{n−1}, y_{n−2}, y_{n−3}).

    ``hJ`` is a stack (k, s, s) of Δt J.
    """
    k, s = hJ.shape[0], hJ.shape[-1]
    eye = np.broadcast_to(np.eye(s), hJ.shape)
    # Predictor (AB4) blocks, then the corrector (three-step AM, fourth order) fed f(predictor).
    pred = [eye + 55 / 24 * hJ, -59 / 24 * hJ, 37 / 24 * hJ, -9 / 24 * hJ]
    corr = [eye + 19 / 24 * hJ, -5 / 24 * hJ, 1 / 24 * hJ, 0 * hJ]
    A = np.zeros((k, 4 * s, 4 * s), dtype=hJ.dtype)
    for j in range(4):
        A[:, :s, j * s : (j + 1) * s] = corr[j] + 9 / 24 * hJ @ pred[j]
    A[:, s:, : 3 * s] = np.eye(3 * s)
    return A


def _matrices(method: str, h: np.ndarray, xi: float, params: dict) -> np.ndarray:
    """The amplification matrices (k, s, s) for the steps h (k,) on the oscillator ω = 2π rad/s."""
    w = 2 * np.pi
    M, C, K = np.eye(1), np.array([[2 * xi * w]]), np.array([[w * w]])
    h = h[:, None, None]
    if method == "central_difference":
        return linear._recursion(linear.central_difference_step(M, C, K, h), 2, 1)[0]
    if method == "houbolt":
        return linear._recursion(linear.houbolt_step(M, C, K, h), 3, 1)[0]
    if method == "wilson":
        return linear._recursion(linear.wilson_step(M, C, K, h, params["theta"]), 3, 1)[0]
    if method in ("newmark", "average_acceleration", "linear_acceleration", "hht_alpha"):
        alpha = params.get("alpha", 0.0)
        gamma, beta = {
            "newmark": (params.get("gamma"), params.get("beta")),
            "average_acceleration": (0.5, 0.25),
            "linear_acceleration": (0.5, 1 / 6),
            "hht_alpha": (0.5 - alpha, (1 - alpha) ** 2 / 4),
        }[method]
        return linear._recursion(linear.newmark_step(M, C, K, h, gamma, beta, alpha), 3, 1)[0]
    hJ = h * first_order_matrix(M, C, K)  # Δt J, J = [[0, 1], [−ω², −2ξω]]
    if method == "forward_euler":
        return np.eye(2) + hJ
    if method == "rk4":
        return sum(np.linalg.matrix_power(hJ, k) / factorial(k) for k in range(5))
    return _abm_matrix(hJ)


def amplification_matrix(method: str, dt_over_T, damping_ratio: float = 0.0, **params) -> np.ndarray:
    """The amplification matrix A of ``method`` on the oscillator of period T (z₊ = A z).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    dt_over_T : float or array_like
        Step over the undamped natural period, in [1e-4, 1e6] (outside, the amplification
        matrix is lost to rounding).
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters: ``theta`` (wilson), ``gamma`` and ``beta`` (newmark), ``alpha`` (hht_alpha).

    Returns
    -------
    ndarray, shape (s, s) or (k, s, s) for k values of dt_over_T
        The state is (x, v, a) for the Newmark family and Wilson-θ, (x_n, x_{n−1}) for the
        central difference, (x_n, x_{n−1}, x_{n−2}) for Houbolt, (x, v) for forward Euler
        and RK4, and four past (x, v) for the Adams–Bashforth–Moulton scheme.

    Examples
    --------
    >>> A = amplification_matrix("central_difference", 0.1)
    >>> round(float(np.trace(A)), 6)  # 2 − (ωΔt)² with ωΔt = 0.2π
    1.605216
    """
    chosen = _parameters(method, params)
    xi = scalar("damping_ratio", damping_ratio, low=0.0, high=1.0, high_open=True)
    flat = _ratios(dt_over_T)
    mats = _matrices(method, flat, xi, chosen)
    return mats[0] if np.ndim(dt_over_T) == 0 else mats


def spectral_radius(method: str, dt_over_T, damping_ratio: float = 0.0, **params):
    """ρ(A), the largest modulus of the amplification matrix's eigenvalues: the scheme is stable while ρ <= 1.

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    dt_over_T : float or array_like
        Step over the undamped natural period, in [1e-4, 1e6] (outside, the amplification
        matrix is lost to rounding).
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    float or ndarray
        ρ (dimensionless), shaped like ``dt_over_T``.

    Examples
    --------
    >>> round(float(spectral_radius("hht_alpha", 1e5, alpha=-0.1)), 4)  # (1 + α)/(1 − α)
    0.8182
    """
    mats = amplification_matrix(method, dt_over_T, damping_ratio, **params)
    return np.abs(np.linalg.eigvals(mats)).max(axis=-1)


def _principal(method, dt_over_T, damping_ratio, params):
    """The principal eigenvalue (nearest the exact exp(sΔt)) for each ratio, and the ratios."""
    mats = amplification_matrix(method, dt_over_T, damping_ratio, **params)
    ratios = _ratios(dt_over_T)
    mats = mats.reshape(ratios.size, *mats.shape[-2:])
    xi, w = damping_ratio, 2 * np.pi
    target = ratios * w * (-xi + 1j * np.sqrt(1 - xi * xi))  # s Δt of the exact motion
    lam = np.linalg.eigvals(mats)
    # The principal root is the complex one whose logarithm is nearest sΔt; spurious roots of the
    # multistep schemes (and the zero root of the (x, v, a) forms) are real at the steps of interest.
    # Where no root is complex the motion does not oscillate: take the largest root, marked real.
    complex_root = lam.imag > 1e-12 * np.abs(lam)
    logs = np.log(np.where(complex_root, lam, 1.0))
    distance = np.where(complex_root, np.abs(logs - target[:, None]), np.inf)
    pick = np.where(complex_root.any(axis=1), np.argmin(distance, axis=1), np.argmax(np.abs(lam), axis=1))
    return lam[np.arange(ratios.size), pick], ratios


def _shape(value, dt_over_T):
    return float(value[0]) if np.ndim(dt_over_T) == 0 else value


def period_elongation(method: str, dt_over_T, damping_ratio: float = 0.0, **params):
    """(T̄ − T_d)/T_d: relative error of the computed period (NaN where the principal root is real).

    T̄ = 2π/Im s̄ from the principal eigenvalue exp(s̄Δt) of A; T_d is the exact damped period.
    Positive means the computed motion is too slow (Bathe's "PE", as a fraction, not %).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    dt_over_T : float or array_like
        Step over the undamped natural period, in [1e-4, 1e6] (outside, the amplification
        matrix is lost to rounding).
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    float or ndarray
        The period elongation as a fraction, shaped like ``dt_over_T``.

    Examples
    --------
    >>> w = 2 * np.pi * 0.1  # average acceleration: ω̄Δt = 2 arctan(ωΔt/2)
    >>> closed_form = float(w / (2 * np.arctan(w / 2)) - 1)
    >>> round(period_elongation("average_acceleration", 0.1), 8), round(closed_form, 8)
    (0.03207491, 0.03207491)
    """
    return _shape(_principal_elongation(method, dt_over_T, damping_ratio, params), dt_over_T)


def _principal_elongation(method, dt_over_T, damping_ratio, params) -> np.ndarray:
    """The period elongation (k,) from the principal roots; NaN where the root is real."""
    lam, ratios = _principal(method, dt_over_T, damping_ratio, params)
    xi = damping_ratio
    phase = np.abs(np.angle(lam))
    exact = 2 * np.pi * ratios * np.sqrt(1 - xi * xi)  # ω_d Δt
    with np.errstate(divide="ignore"):
        return np.where(np.abs(lam.imag) > 1e-12 * np.abs(lam), exact / phase - 1.0, np.nan)


def amplitude_decay(method: str, dt_over_T, damping_ratio: float = 0.0, **params):
    """1 − (computed / exact amplitude) after one damped period T_d (Bathe's "AD", as a fraction).

    The computed amplitude shrinks by |exp(s̄Δt)| (the principal eigenvalue of A) a step over
    T_d/Δt steps; the exact one by exp(−ξωT_d). Zero for a scheme with no numerical damping;
    negative if it grows.

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    dt_over_T : float or array_like
        Step over the undamped natural period, in [1e-4, 1e6] (outside, the amplification
        matrix is lost to rounding).
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    float or ndarray
        The amplitude decay per period as a fraction, shaped like ``dt_over_T``.
    """
    lam, ratios = _principal(method, dt_over_T, damping_ratio, params)
    xi = damping_ratio
    steps = np.sqrt(1 - xi * xi) ** -1 / ratios  # T_d/Δt with T = 1
    physical = np.exp(-xi * 2 * np.pi * steps * ratios)
    return _shape(1.0 - np.abs(lam) ** steps / physical, dt_over_T)


@lru_cache(maxsize=256)
def _limit(method: str, xi: float, items: tuple) -> float:
    params = dict(items)
    grid = np.logspace(-3, 3, 481)
    unstable = spectral_radius(method, grid, xi, **params) > 1 + 1e-9
    if not unstable.any():
        return np.inf
    i = int(np.argmax(unstable))
    if i == 0:
        return 0.0
    lo, hi = grid[i - 1], grid[i]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if spectral_radius(method, mid, xi, **params) > 1 + 1e-9:
            hi = mid
        else:
            lo = mid
    return float(lo)


def stability_limit(method: str, damping_ratio: float = 0.0, **params) -> float:
    """Largest Δt/T for which ρ(A) <= 1, found on the amplification matrix (inf: unconditional; 0: never).

    Found by a scan of Δt/T from 10⁻³ to 10³ and bisection, so it checks the closed
    forms rather than quoting them: 1/π for the central difference, √3/π for linear
    acceleration, √2/π for RK4 on an undamped oscillator.

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    float
        The limit on Δt/T (dimensionless): inf if the scheme is unconditionally stable,
        0 if no step is.

    Examples
    --------
    >>> round(stability_limit("central_difference") * np.pi, 9)
    1.0
    """
    chosen = _parameters(method, params)
    xi = scalar("damping_ratio", damping_ratio, low=0.0, high=1.0, high_open=True)
    return _limit(method, xi, tuple(sorted(chosen.items())))


def _scalar_radius(method: str, z: np.ndarray) -> np.ndarray:
    """ρ of a first-order scheme on y' = s y with z = Δt s (complex array)."""
    if method == "forward_euler":
        return np.abs(1 + z)
    if method == "rk4":
        return np.abs(1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24)
    return np.abs(np.linalg.eigvals(_abm_matrix(z.reshape(-1, 1, 1)))).max(axis=-1)


def first_order_step_limit(method: str, eigenvalue: complex) -> float:
    """Largest Δt (s) for which a first-order scheme keeps the mode y' = s y from growing.

    For schemes of the (x, x') form (forward Euler, RK4, Adams–Bashforth–Moulton), the
    limit on a damped or non-symmetric system is set by the eigenvalues s of the
    first-order system, not by the undamped periods: a heavily damped real s (a creep
    or friction time constant) can bind first. 0 when no step is stable (an undamped
    mode under forward Euler, or Re s > 0, a mode that grows anyway).

    Parameters
    ----------
    method : {"forward_euler", "rk4", "abm"}
        A first-order scheme.
    eigenvalue : complex
        s of the mode (its characteristic root), 1/s: finite and nonzero (a mode with s = 0 sets no limit).

    Returns
    -------
    float
        The largest stable Δt, s (inf if no step is too long).

    Examples
    --------
    >>> round(first_order_step_limit("forward_euler", -100.0), 9)  # |1 + Δt s| <= 1: Δt <= 2/|s|
    0.02
    """
    _checks.choice("method", method, FIRST_ORDER)
    if isinstance(eigenvalue, bool) or not isinstance(eigenvalue, numbers.Number | np.number):
        raise TypeError(f"eigenvalue must be a real or complex number, got {eigenvalue!r:.80}")
    lam = complex(eigenvalue)
    size = abs(lam)
    if not np.isfinite(size):
        raise ValueError(f"eigenvalue must be finite, got {eigenvalue!r}")
    if size == 0.0:
        raise ValueError(
            "eigenvalue must be nonzero: a mode with s = 0 neither grows nor decays under any step, "
            "so it sets no limit"
        )
    steps = np.logspace(-4, 2, 241) / size
    unstable = _scalar_radius(method, steps * lam) > 1 + 1e-9
    if not unstable.any():
        return np.inf
    i = int(np.argmax(unstable))
    if i == 0:
        return 0.0
    lo, hi = steps[i - 1], steps[i]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if _scalar_radius(method, np.array([mid * lam]))[0] > 1 + 1e-9:
            hi = mid
        else:
            lo = mid
    return float(lo)


# ---------------------------------------------------------------------------
# A model's step limit and stiffness


def stable_step(method: str, M, C, K, **params) -> float:
    """The largest stable time step of ``method`` on the model ``M x'' + C x' + K x = 0``, s.

    For the schemes on (x, v, a) and the multistep displacement schemes the limit is
    :func:`stability_limit` times T_min = 2π/ω_max, the period of the highest undamped
    mode (viscous damping does not lower the central difference limit). For the
    first-order schemes (forward Euler, RK4, ABM) it is set by the eigenvalues of
    the first-order system (:func:`raildyn.vibration.first_order_matrix`), so that a
    heavily damped mode, such as a creep time constant, can bind first
    (:func:`first_order_step_limit`).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative.
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    float
        Δt_max, s: inf if no step is too long, 0 if none is stable.

    Examples
    --------
    >>> round(stable_step("central_difference", 1.0, 0.0, 1.0e6), 9)  # 2/ω_max, ω_max = 1000 rad/s
    0.002
    >>> round(stable_step("rk4", 1.0, 2000.0, 1.0) * 1e3, 4)  # the creep-like mode s = −2000 1/s binds
    1.3926
    """
    chosen = _parameters(method, params)
    M = square_matrix("M", M, positive_definite=True)
    C = square_matrix("C", C, size=M.shape[0], symmetric=False)
    K = square_matrix("K", K, size=M.shape[0], symmetric=False)
    if method in FIRST_ORDER:
        lam = np.linalg.eigvals(first_order_matrix(M, C, K))
        return float(min((first_order_step_limit(method, z) for z in lam if z != 0), default=np.inf))
    ratio = stability_limit(method, **chosen)
    wmax = highest_frequency(M, K)
    if np.isinf(ratio) or wmax == 0.0:
        return np.inf
    return float(ratio * 2 * np.pi / wmax)


def stiffness_ratio(M, C, K) -> float:
    """|s|max / |s|min over the eigenvalues s of the first-order system: how stiff the equations are.

    A ratio of thousands means motions on very different time scales: an explicit
    scheme must follow the fastest, an implicit one may step over it {Hairer & Wanner 1996}.

    Parameters
    ----------
    M, C, K : array_like, shape (n, n), or float
        Mass (kg; symmetric positive definite), damping (N·s/m) and stiffness (N/m);
        finite. C and K may be non-symmetric, zero or negative.

    Returns
    -------
    float
        The ratio (dimensionless).

    Raises
    ------
    ValueError
        If K is singular (a rigid-body mode, s = 0: the ratio is unbounded), or M, C and K
        span time scales beyond double precision.

    Examples
    --------
    >>> round(stiffness_ratio(1.0, 1001.0, 1000.0), 6)  # s = −1 and −1000 1/s
    1000.0
    """
    M = square_matrix("M", M, positive_definite=True)
    C = square_matrix("C", C, size=M.shape[0], symmetric=False)
    K = square_matrix("K", K, size=M.shape[0], symmetric=False)
    size = np.abs(np.linalg.eigvals(first_order_matrix(M, C, K)))
    if size.min() == 0.0:
        raise ValueError(
            "the first-order system has an eigenvalue s = 0, so the stiffness ratio is unbounded: K is "
            "singular (a rigid-body mode), or M, C and K span time scales beyond double precision"
        )
    with np.errstate(over="ignore"):
        ratio = float(size.max() / size.min())
    if not np.isfinite(ratio):
        raise ValueError(
            f"M, C and K span time scales beyond double precision: |s| from {size.min():.3g} to "
            f"{size.max():.3g} 1/s"
        )
    return ratio


# ---------------------------------------------------------------------------
# The accuracy chart of a scheme, as one result with its drawings

# ρ above this is not drawn (the charts stop at ρ = 1.6); amplitude decays are drawn within ±1000 %.
_RHO_SHOWN = 2.0
_AD_SHOWN = 1.0e3


@dataclass(frozen=True)
class SchemeAccuracy:
    """Spectral radius, period elongation and amplitude decay of one scheme against Δt/T.

    Attributes
    ----------
    method : str
        The scheme, one of ``METHODS``.
    parameters : dict
        Its parameters, defaults filled in.
    damping_ratio : float
        ξ of the test oscillator.
    dt_over_T : ndarray, shape (k,)
        Steps over the undamped period.
    spectral_radius : ndarray, shape (k,)
        ρ(A), dimensionless.
    period_elongation_fraction : ndarray, shape (k,)
        (T̄ − T_d)/T_d as a fraction (NaN where the computed motion does not oscillate).
    amplitude_decay_fraction : ndarray, shape (k,)
        Amplitude lost per period beyond the physical decay, as a fraction.
    stability_limit_dt_over_T : float
        Largest stable Δt/T (inf: unconditionally stable; 0: never stable).

    The values are checked: shaped (k,) alike and finite, ρ >= 0, with NaN only where the
    period elongation is documented to hold it and an infinite limit only for an
    unconditionally stable scheme.
    """

    method: str
    parameters: dict
    damping_ratio: float
    dt_over_T: np.ndarray
    spectral_radius: np.ndarray
    period_elongation_fraction: np.ndarray
    amplitude_decay_fraction: np.ndarray
    stability_limit_dt_over_T: float

    def __post_init__(self):
        _checks.choice("method", self.method, METHODS)
        _checks.instance("parameters", self.parameters, dict, "dict")
        scalar("damping_ratio", self.damping_ratio, low=0.0, high=1.0, high_open=True)
        k = _ratios(self.dt_over_T).size
        for name, low in (("spectral_radius", 0.0), ("amplitude_decay_fraction", None)):
            values = array(name, getattr(self, name), ndim=1, low=low)
            if values.size != k:
                raise ValueError(f"{name} must have shape ({k},) like dt_over_T, got shape {values.shape}")
        chosen = _parameters(self.method, self.parameters)
        pe = _checks._numbers("period_elongation_fraction", self.period_elongation_fraction)
        if pe.shape != (k,) or np.isinf(pe).any():
            raise ValueError(
                f"period_elongation_fraction must have shape ({k},) like dt_over_T and hold finite values "
                f"(or NaN where the motion does not oscillate), got {pe!r:.80}"
            )
        # NaN is documented where the computed motion does not oscillate, and only there.
        expected = np.isnan(_principal_elongation(self.method, self.dt_over_T, self.damping_ratio, chosen))
        if np.any(np.isnan(pe) != expected):
            raise ValueError(
                f"period_elongation_fraction may be NaN only where the computed motion of {self.method} does "
                f"not oscillate; got NaN at {np.isnan(pe).sum()} steps, expected at {expected.sum()}"
            )
        limit = _checks._numbers("stability_limit_dt_over_T", self.stability_limit_dt_over_T)
        if limit.ndim or not limit >= 0:
            raise ValueError(
                f"stability_limit_dt_over_T must be a number >= 0 (inf: unconditionally stable), "
                f"got {self.stability_limit_dt_over_T!r}"
            )
        if np.isinf(limit) and np.isfinite(stability_limit(self.method, self.damping_ratio, **chosen)):
            raise ValueError(
                f"stability_limit_dt_over_T may be inf only for an unconditionally stable scheme, "
                f"and {self.method} is not"
            )

    def _draw(self, ax, artists, y, ylabel, style) -> dict:
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of an earlier call's artists")
            if "line" not in artists:
                raise ValueError(
                    f"artists must be the dict an earlier call returned, with 'line', got {artists!r}"
                )
            artists["line"].set_data(self.dt_over_T, y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (line,) = draw_line(ax, self.dt_over_T, y, style)
            ax.set_xlabel(r"$\Delta t/T$")
            ax.set_ylabel(ylabel)
        return {"line": line}

    def plot_spectral_radius(self, ax=None, *, artists=None, **style) -> dict:
        """Draw ρ(A) against Δt/T (values above 2 left out); return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None). Set a log scale on it for a
            wide range of steps.
        artists : dict, optional
            The artists of an earlier call: their data are replaced in place (a widget's
            update) and nothing new is drawn.
        **style
            Passed to ``Axes.plot`` (``label``, ``color``...).

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        y = np.where(self.spectral_radius < _RHO_SHOWN, self.spectral_radius, np.nan)
        return self._draw(ax, artists, y, r"spectral radius $\rho(A)$", style)

    def plot_period_elongation(self, ax=None, *, artists=None, **style) -> dict:
        """Draw the period elongation in % against Δt/T; return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None).
        artists : dict, optional
            The artists of an earlier call, updated in place.
        **style
            Passed to ``Axes.plot``.

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        return self._draw(ax, artists, 100 * self.period_elongation_fraction, "period elongation (%)", style)

    def plot_amplitude_decay(self, ax=None, *, artists=None, **style) -> dict:
        """Draw the amplitude decay per period in % against Δt/T (within ±1000 %); return the artists.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Where to draw (new axes on a new figure if None).
        artists : dict, optional
            The artists of an earlier call, updated in place.
        **style
            Passed to ``Axes.plot``.

        Returns
        -------
        dict
            ``{"line": Line2D}``.
        """
        y = np.clip(100 * self.amplitude_decay_fraction, -_AD_SHOWN, _AD_SHOWN)
        return self._draw(ax, artists, y, "amplitude decay per period (%)", style)


def scheme_accuracy(method: str, dt_over_T, damping_ratio: float = 0.0, **params) -> SchemeAccuracy:
    """The accuracy chart of a scheme on the test oscillator: ρ, period elongation and amplitude decay.

    Bathe's Figs. 9.2–9.3 {Bathe 1996} for one scheme, from its amplification matrix
    (:func:`spectral_radius`, :func:`period_elongation`, :func:`amplitude_decay`,
    :func:`stability_limit`).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    dt_over_T : array_like, shape (k,)
        Steps over the undamped natural period, in [1e-4, 1e6], at least one.
    damping_ratio : float
        ξ of the oscillator, in [0, 1).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    SchemeAccuracy

    Examples
    --------
    >>> chart = scheme_accuracy("central_difference", [0.1, 0.3, 0.4])
    >>> chart.spectral_radius.round(6).tolist(), round(chart.stability_limit_dt_over_T * np.pi, 9)
    ([1.0, 1.0, 4.070901], 1.0)
    """
    chosen = _parameters(method, params)
    xi = scalar("damping_ratio", damping_ratio, low=0.0, high=1.0, high_open=True)
    ratios = _ratios(dt_over_T)
    return SchemeAccuracy(
        method,
        chosen,
        xi,
        ratios,
        np.atleast_1d(spectral_radius(method, ratios, xi, **chosen)),
        np.atleast_1d(period_elongation(method, ratios, xi, **chosen)),
        np.atleast_1d(amplitude_decay(method, ratios, xi, **chosen)),
        stability_limit(method, xi, **chosen),
    )


# ---------------------------------------------------------------------------
# Order of convergence, measured on the damped oscillator under a constant force

_STUDY_PERIOD = 1.0  # s: T of the oscillator
_STUDY_DAMPING = 0.05  # ξ
_STUDY_FORCE = 10.0  # N on the 1 kg mass
_STUDY_START = (1.0, 2.0)  # x0 (m), v0 (m/s)
# The longest study: after 100 s (100 periods at ξ = 0.05) the free motion has decayed by e^-31,
# leaving the static deflection every scheme reproduces, so a longer run measures nothing more.
_STUDY_MAX_DURATION = 100.0
# The most steps a run may take: far beyond where rounding, not the scheme, sets the error.
_STUDY_MAX_STEPS = 100_000


@dataclass(frozen=True)
class ConvergenceStudy:
    """The error of a scheme at several steps on a problem with an exact answer, and the order it shows.

    Attributes
    ----------
    method : str
        The scheme.
    parameters : dict
        Its parameters, defaults filled in.
    step_counts : ndarray of int, shape (k,)
        Steps over the run.
    dt_over_T : ndarray, shape (k,)
        The steps over the oscillator's period.
    max_error_m : ndarray, shape (k,)
        Largest |x − x_exact| over the run, m.
    orders : ndarray, shape (k − 1,)
        log₂ of successive error ratios over log₂ of the step ratios: the measured order.
    """

    method: str
    parameters: dict
    step_counts: np.ndarray
    dt_over_T: np.ndarray
    max_error_m: np.ndarray
    orders: np.ndarray

    def __post_init__(self):
        _checks.choice("method", self.method, METHODS)
        _checks.instance("parameters", self.parameters, dict, "dict")
        counts = self.step_counts
        if not (isinstance(counts, np.ndarray) and counts.dtype.kind in "iu"):
            raise TypeError(f"step_counts must be an array of integers, got {counts!r:.80}")
        counts = array("step_counts", counts, ndim=1, low=4)
        if counts.size < 2 or np.any(np.diff(counts) <= 0):
            raise ValueError(f"step_counts must hold at least two increasing counts, got {counts!r}")
        k = counts.size
        for name, size, low in (("dt_over_T", k, 0.0), ("max_error_m", k, 0.0), ("orders", k - 1, None)):
            values = array(name, getattr(self, name), ndim=1, low=low, low_open=name == "dt_over_T")
            if values.size != size:
                raise ValueError(
                    f"{name} must have {size} entries (from step_counts), got shape {values.shape}"
                )


def convergence_study(
    method: str, step_counts=(200, 400, 800), duration: float = 2.0, **params
) -> ConvergenceStudy:
    """Measure a scheme's order of accuracy against the exact response of a damped oscillator.

    The oscillator has m = 1 kg, T = 1 s and ξ = 0.05, starts from x₀ = 1 m,
    v₀ = 2 m/s and carries a constant 10 N force, which every scheme samples exactly,
    so the error against :meth:`raildyn.vibration.SDOF.forced_response` (exact for
    it) is the scheme's alone. A scheme of order p has a global error ∝ Δt^p, so
    the measured order is log(e₁/e₂)/log(Δt₁/Δt₂).

    Parameters
    ----------
    method : str
        One of ``METHODS``.
    step_counts : sequence of int
        Steps over the run, at least two, each in [4, 100000] (beyond, rounding rather than
        the scheme sets the error), in increasing order.
    duration : float
        Length of the run, s, in [0.01, 100] (after 100 periods the free motion has decayed by
        e^-31, leaving the static deflection every scheme reproduces).
    **params
        The scheme's parameters (see :func:`amplification_matrix`).

    Returns
    -------
    ConvergenceStudy

    Raises
    ------
    raildyn.errors.SolverError
        If a run blows up (a step beyond the scheme's stability limit).

    Examples
    --------
    >>> study = convergence_study("rk4", (400, 800))
    >>> round(float(study.orders[0]), 1)
    4.0
    """
    chosen = _parameters(method, params)
    if isinstance(step_counts, str) or not np.iterable(step_counts):
        raise TypeError(f"step_counts must be a sequence of integers, got {step_counts!r:.80}")
    counts = [integer("step_counts", k, low=4, high=_STUDY_MAX_STEPS) for k in step_counts]
    if len(counts) < 2 or any(b <= a for a, b in zip(counts, counts[1:], strict=False)):
        raise ValueError(f"step_counts must hold at least two increasing counts, got {step_counts!r}")
    duration = scalar("duration", duration, low=0.01, high=_STUDY_MAX_DURATION)
    system = SDOF.from_modal(2 * np.pi / _STUDY_PERIOD, _STUDY_DAMPING)
    x0, v0 = _STUDY_START
    errors = []
    for steps in counts:
        t = np.linspace(0.0, duration, steps + 1)
        load = np.full(t.size, _STUDY_FORCE)
        exact = system.forced_response(t, load, x0=x0, v0=v0)
        force = (lambda tk, x, v: np.array([_STUDY_FORCE])) if method in FIRST_ORDER else load
        run = integrate(method, system.mass, system.damping, system.stiffness, t, x0, v0, force, **chosen)
        errors.append(np.abs(run.x[0] - exact).max())
    errors = np.array(errors)
    steps = np.array(counts)
    orders = np.log(errors[:-1] / errors[1:]) / np.log(steps[1:] / steps[:-1])
    return ConvergenceStudy(method, chosen, steps, duration / steps / _STUDY_PERIOD, errors, orders)
