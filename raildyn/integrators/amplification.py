"""The amplification matrix of each scheme on the test oscillator x'' + 2ξω x' + ω² x = 0.

Applied to one oscillator with a constant step, every scheme of this package is a
linear recursion z₊ = A z; A is its amplification matrix {Bathe 1996, §9.4.1}.
Its eigenvalues tell all: the scheme is stable while the spectral radius
ρ(A), the largest modulus of its eigenvalues, stays at or below 1, and the principal
pair exp(s̄Δt), s̄ = −ξ̄ω̄ ± iω̄ (the computed characteristic roots), gives the computed
frequency ω̄ and decay, hence the period elongation and the amplitude decay plotted
against Δt/T in {Bathe 1996, Figs. 9.2–9.4}. The period is T = 1 s, so ω = 2π rad/s
and Δt = Δt/T. :func:`~raildyn.integrators.stability_limit` and
:func:`~raildyn.integrators.first_order_step_limit` are what a
run that blows up quotes (``_divergence``); :mod:`raildyn.integrators.analysis` builds the
charts, the model's step limits and the convergence study on them. The matrices come from
the schemes' own steps (:mod:`raildyn.integrators.recursions`), so this module sits below the runs.
"""

from __future__ import annotations

import numbers
from functools import lru_cache
from math import factorial

import numpy as np

from raildyn import _checks
from raildyn._checks import array, scalar
from raildyn.integrators._common import FIRST_ORDER, METHODS, PARAMETERS
from raildyn.integrators.recursions import (
    _recursion,
    central_difference_step,
    houbolt_step,
    newmark_step,
    wilson_step,
)
from raildyn.vibration import first_order_matrix

__all__ = [
    "amplification_matrix",
    "amplitude_decay",
    "first_order_step_limit",
    "period_elongation",
    "spectral_radius",
    "stability_limit",
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
        return _recursion(central_difference_step(M, C, K, h), 2, 1)[0]
    if method == "houbolt":
        return _recursion(houbolt_step(M, C, K, h), 3, 1)[0]
    if method == "wilson":
        return _recursion(wilson_step(M, C, K, h, params["theta"]), 3, 1)[0]
    if method in ("newmark", "average_acceleration", "linear_acceleration", "hht_alpha"):
        alpha = params.get("alpha", 0.0)
        gamma, beta = {
            "newmark": (params.get("gamma"), params.get("beta")),
            "average_acceleration": (0.5, 0.25),
            "linear_acceleration": (0.5, 1 / 6),
            "hht_alpha": (0.5 - alpha, (1 - alpha) ** 2 / 4),
        }[method]
        return _recursion(newmark_step(M, C, K, h, gamma, beta, alpha), 3, 1)[0]
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
