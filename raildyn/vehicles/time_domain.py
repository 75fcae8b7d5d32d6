"""A linear vehicle's response in time over a track profile (chapter 6).

:func:`time_response` gives the history over a track profile, by the first-order hold of
``scipy.signal.lsim`` with its step loop compiled, as a :class:`TimeResponse`;
:func:`periodic_profile` is a profile sampled over one period with its exact slope
(:class:`PeriodicProfile`), the input it takes. The model, its inputs and the speed are as in
:mod:`raildyn.vehicles.response`, which has the responses in frequency (FRF, PSD, RMS).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.errors import SolverError
from raildyn.vehicles._shared import _steady_system

__all__ = ["PeriodicProfile", "TimeResponse", "periodic_profile", "time_response"]


@dataclass(frozen=True)
class TimeResponse(Tabular):
    """A time history.

    Attributes
    ----------
    t : ndarray, (n_t,)
        s, strictly increasing.
    y : ndarray, (n_t,)
        Output (m, m/s or m/s²), of either sign.
    inputs : ndarray, (n_t, q)
        Track heights at the inputs, m, of either sign.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("t", "s"), ("y", "m, m/s or m/s²"), ("inputs", "m"))

    t: np.ndarray
    y: np.ndarray
    inputs: np.ndarray

    def __post_init__(self):
        t = _checks.time_grid("t", self.t)
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "y", _checks.array("y", self.y, shape=t.shape))
        inputs = _checks.array("inputs", self.inputs, shape=(t.size, None))
        if inputs.shape[1] == 0:
            raise ValueError(f"inputs must hold at least one input, got shape {inputs.shape}")
        object.__setattr__(self, "inputs", inputs)


@dataclass(frozen=True)
class PeriodicProfile:
    """A track profile sampled over one period, with its exact slope.

    Attributes
    ----------
    heights : ndarray, (n,)
        The samples, m (of either sign), every ``dx`` from x = 0; not empty.
    dx : float
        m, > 0.
    slopes : ndarray, (n,)
        dz/dx at the samples, the derivative of the sample's Fourier series (computed from
        ``heights`` and ``dx``, not given).
    """

    heights: np.ndarray
    dx: float
    slopes: np.ndarray = field(init=False, repr=False)

    def __post_init__(self):
        z = _checks.array("heights", self.heights, ndim=1, allow_empty=False)
        dx = _checks.positive("dx", self.dx)
        n = z.size
        rate = np.fft.irfft(2j * np.pi * np.fft.rfftfreq(n, dx) * np.fft.rfft(z), n=n)
        object.__setattr__(self, "heights", z)
        object.__setattr__(self, "dx", dx)
        object.__setattr__(self, "slopes", rate)

    @property
    def period(self) -> float:
        """n·dx, m."""
        return self.heights.size * self.dx

    def _along(self, values, x, rails) -> np.ndarray:
        x = _checks.array("x", x, allow_empty=False)
        if rails is not None:
            _checks.array("rails", rails)
        grid = np.arange(values.size) * self.dx
        return np.interp(np.mod(x, self.period), grid, values, period=self.period)

    def height(self, x, rails=None) -> np.ndarray:
        """The profile at distances x (m), the signature :func:`time_response` takes.

        Parameters
        ----------
        x : array_like
            m, finite, of any sign and shape, not empty; beyond one period the profile repeats.
        rails : array_like, optional
            Ignored (both rails alike); numbers if given.

        Returns
        -------
        ndarray
            m, shaped like ``x``.
        """
        return self._along(self.heights, x, rails)

    def slope(self, x, rails=None) -> np.ndarray:
        """dz/dx at distances x (m), for ``profile_rate`` of :func:`time_response`.

        Parameters
        ----------
        x : array_like
            m, finite, of any sign and shape, not empty.
        rails : array_like, optional
            Ignored; numbers if given.

        Returns
        -------
        ndarray
            Shaped like ``x``.
        """
        return self._along(self.slopes, x, rails)


def periodic_profile(height, dx) -> PeriodicProfile:
    """A track profile sampled over one period, and its slope.

    ``height`` (m) is sampled every ``dx`` (m) over exactly one period of length
    n·dx (a synthesized sample is periodic); beyond it the profile repeats. The
    slope is the exact derivative of the sample's Fourier series, so the damper
    inputs of :func:`time_response` carry no finite-difference error.

    Parameters
    ----------
    height : array_like, (n,)
        m, finite, of either sign; not empty.
    dx : float
        Sample spacing, m (> 0).

    Returns
    -------
    PeriodicProfile

    Examples
    --------
    >>> z = 0.01 * np.sin(2 * np.pi * np.arange(100) * 0.5 / 25.0)
    >>> track = periodic_profile(z, 0.5)
    >>> round(float(track.slope(np.array([0.0]))[0]), 6)  # 0.01 · 2π/25
    0.002513
    """
    return PeriodicProfile(_checks.array("height", height, ndim=1, allow_empty=False), dx)


def _lsim(A, B, C, D, U, dt: float) -> np.ndarray:
    """The single output of x' = A x + B u, y = C x + D u from rest, u linear between the samples U.

    ``scipy.signal.lsim``'s first-order hold (its ``interp=True``), the same matrix exponential:
    over one step, with u going linearly from u₀ to u₁,

        [x(Δt); u₁; u₁ − u₀] = exp([[AΔt, BΔt, 0], [0, 0, I], [0, 0, 0]]) [x₀; u₀; u₁ − u₀],

    so x₁ = A_d x₀ + B_d0 u₀ + B_d1 u₁. lsim steps this in a Python loop, some 5 µs a step (30 ms of
    the ride widget's 5,500 steps); here the input terms of every step are one matrix product and
    the recurrence runs compiled (``raildyn.vehicles._march_kernel``, imported here only when it
    runs, as it loads numba). ``tests/test_vehicles_response.py`` holds the
    two to round-off. ``U`` is (n_steps, inputs), ``dt`` the step (> 0 unless there is one step).
    """
    from raildyn.vehicles._march_kernel import march

    n, m = A.shape[0], B.shape[1]
    x = np.zeros((U.shape[0], n))
    if U.shape[0] > 1:
        block = np.zeros((n + 2 * m, n + 2 * m))
        block[:n, :n] = A * dt
        block[:n, n : n + m] = B * dt
        block[n : n + m, n + m :] = np.eye(m)
        step = scipy.linalg.expm(block.T)  # transposed, as lsim: the states are rows
        Ad = step[:n, :n]
        Bd1 = step[n + m :, :n]
        Bd0 = step[n : n + m, :n] - Bd1
        march(np.ascontiguousarray(Ad), U[:-1] @ Bd0 + U[1:] @ Bd1, x)
    return x @ C[0] + U @ D[0]


def time_response(
    vehicle,
    profile: Callable,
    speed,
    t,
    output="body z",
    derivative: int = 0,
    profile_rate: Callable | None = None,
) -> TimeResponse:
    """History of an output as the vehicle runs over a profile (``scipy.signal.lsim``'s first-order hold).

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
    profile : callable
        ``profile(x, rails)`` → track input (m) at each input at distances x
        (m, array (n_t, q)); ``rails`` is ``input_rails`` of the vehicle's system
        broadcast like x. The leading axle is at x = V t. It must return finite
        numbers (of either sign) shaped like x.
    profile_rate : callable, optional
        The slope dz/dx with the same signature and the same demands on what it
        returns; without it the damper inputs use a finite-difference slope.
    speed : float
        m/s, in [0.001, :data:`~raildyn.constants.MAXIMUM_SPEED`] and below the critical speed of a lateral
        model.
    t : array_like
        Uniform, strictly increasing times, s, starting from rest at static equilibrium.
    output : str, (str, float) or array_like
        See :meth:`raildyn.linear_model.LinearSystem.output_vector`.
    derivative : {0, 1, 2}
        Displacement, velocity or acceleration of the output.

    Returns
    -------
    TimeResponse

    Raises
    ------
    ValueError
        If ``profile`` or ``profile_rate`` returns a non-finite value or an array not shaped like x.
    raildyn.errors.SolverError
        If the simulated output is not finite (inputs so large that the history overflows).
    """
    vehicle, V = _steady_system(vehicle, speed)
    profile = _checks.function("profile", profile)
    if profile_rate is not None:
        _checks.function("profile_rate", profile_rate)
    tt = _checks.time_grid("t", t, uniform=True)
    d = _checks.integer("derivative", derivative, low=0, high=2)
    o = vehicle.output_vector(output)
    x = V * tt[:, None] - vehicle.input_positions[None, :]
    rails = np.broadcast_to(vehicle.input_rails, x.shape)
    w = _checks.returned("profile", profile(x, rails), shape=x.shape)
    if profile_rate is not None:
        wdot = V * _checks.returned("profile_rate", profile_rate(x, rails), shape=x.shape)
    else:
        wdot = np.gradient(w, tt, axis=0) if tt.size > 1 else np.zeros_like(w)
    n, q = vehicle.size, w.shape[1]
    mats = vehicle.matrices(V)
    A = mats.state_matrix()
    B = np.vstack([np.zeros((n, 2 * q)), np.linalg.solve(mats.M, np.hstack([mats.GK, mats.GC]))])
    if d == 0:
        Cs, D = np.concatenate([o, np.zeros(n)])[None, :], np.zeros((1, 2 * q))
    elif d == 1:
        Cs, D = np.concatenate([np.zeros(n), o])[None, :], np.zeros((1, 2 * q))
    else:
        Cs, D = (o @ A[n:])[None, :], (o @ B[n:])[None, :]
    with np.errstate(over="ignore", invalid="ignore"):
        y = _lsim(A, B, Cs, D, np.hstack([w, wdot]), tt[1] - tt[0] if tt.size > 1 else 0.0)
    if not np.all(np.isfinite(y)):
        step = int(np.argmin(np.isfinite(y)))
        raise SolverError("the output became non-finite (the track inputs are too large)", step=step,
                          time=float(tt[step]))  # fmt: skip
    return TimeResponse(tt, y, w)
