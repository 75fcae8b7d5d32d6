"""Lateral stability (book chapter 7): eigenvalues against speed, mode tracking, critical speed, hunting.

The linear models of :mod:`raildyn.wheelset` and :mod:`raildyn.vehicles`
follow the one protocol (:class:`raildyn.linear_model.LinearModel`), and their
systems read M q̈ + (C₀ + C₁/V) q̇ + K q = 0 without the track,
so the state matrix at every speed of a sweep is built at once and all
eigenvalues come from one batched ``numpy.linalg`` call.

* :func:`eigenvalues_against_speed` — every eigenvalue at every speed;
* :func:`mode_sweep` — eigenvalues, frequencies and damping ratios with each
  mode followed across speed by its modal assurance criterion (MAC), so
  that crossing branches keep their labels;
* :func:`critical_speed` — the lowest speed at which the largest real part
  becomes positive, by a batched coarse scan and Brent's method;
* :func:`critical_speed_map` — the critical speed over a grid of two parameters;
* :func:`limit_cycle_amplitude`, :func:`bifurcation_diagram` — nonlinear hunting:
  the amplitude of the limit cycle against speed and the nonlinear critical speed.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.optimize

from raildyn._checks import array, integer, positive, scalar
from raildyn._progress import progress_bar
from raildyn.errors import SolverError
from raildyn.linear_model import as_linear_system

__all__ = [
    "BifurcationDiagram",
    "CriticalSpeed",
    "CriticalSpeedMap",
    "LimitCycle",
    "ModeSweep",
    "PeriodicOrbit",
    "bifurcation_diagram",
    "critical_speed",
    "critical_speed_map",
    "eigenvalues_against_speed",
    "largest_real_part",
    "limit_cycle_amplitude",
    "mac",
    "mode_sweep",
    "periodic_orbit",
    "track_modes",
]


def _speeds(speeds) -> np.ndarray:
    V = array("speeds", np.atleast_1d(speeds), ndim=1)
    if V.size == 0:
        raise ValueError("speeds must hold at least one speed, got an empty array")
    if np.any(V <= 0):
        raise ValueError(f"speeds must all be > 0 m/s (creep forces divide by V), got {V[V <= 0][0]!r}")
    return V


def eigenvalues_against_speed(model, speeds) -> np.ndarray:
    """All 2n eigenvalues (1/s) at each speed (m/s), shape (n_speeds, 2n), from one batched eigvals call."""
    V = _speeds(speeds)
    return np.linalg.eigvals(as_linear_system(model).state_matrices(V))


def largest_real_part(model, speeds) -> np.ndarray:
    """max Re λ (1/s) at each speed: positive where the model is unstable."""
    return eigenvalues_against_speed(model, speeds).real.max(axis=1)


# ---------------------------------------------------------------------------
# Mode tracking


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Modal assurance criterion between the columns of a and b: |aᴴb|²/(|a|²|b|²), shape (ka, kb)."""
    a = np.asarray(a, dtype=complex)
    b = np.asarray(b, dtype=complex)
    num = np.abs(a.conj().T @ b) ** 2
    den = np.outer(np.sum(np.abs(a) ** 2, axis=0), np.sum(np.abs(b) ** 2, axis=0))
    return num / np.maximum(den, np.finfo(float).tiny)


def track_modes(eigenvalues: np.ndarray, vectors: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Reorder eigenvalues (and vectors) at each speed so that column j follows one mode.

    At each step the assignment that maximises the MAC of the state vectors
    with those of the previous speed is chosen (Hungarian algorithm), with the
    distance between eigenvalues, relative to their size, as a tie-breaker for
    conjugate partners, whose vectors are alike.

    Parameters
    ----------
    eigenvalues : complex ndarray (n_speeds, m)
    vectors : complex ndarray (n_speeds, p, m)
        Column k of ``vectors[i]`` belongs to ``eigenvalues[i, k]``.

    Returns
    -------
    eigenvalues, vectors : the same arrays with columns permuted at each speed.
    """
    lam = np.array(eigenvalues, dtype=complex, copy=True)
    vec = np.array(vectors, dtype=complex, copy=True)
    for i in range(1, lam.shape[0]):
        similarity = mac(vec[i - 1], vec[i])
        scale = np.maximum(np.abs(lam[i - 1])[:, None], 1.0)
        distance = np.abs(lam[i - 1][:, None] - lam[i][None, :]) / scale
        _, order = scipy.optimize.linear_sum_assignment((1.0 - similarity) + 0.5 * distance)
        lam[i] = lam[i, order]
        vec[i] = vec[i][:, order]
    return lam, vec


@dataclass(frozen=True)
class ModeSweep:
    """Modes of a lateral model across speed, each column one mode followed by MAC.

    Attributes
    ----------
    speeds : ndarray (n_speeds,)
        m/s.
    eigenvalues : complex ndarray (n_speeds, k)
        λ, 1/s; only the roots with Im λ ≥ 0 at the first speed are kept (one of each pair).
    frequencies : ndarray (n_speeds, k)
        Damped frequency |Im λ|/2π, Hz.
    damping_ratios : ndarray (n_speeds, k)
        ξ = −Re λ/|λ| (negative when the mode is unstable).
    shapes : complex ndarray (n_speeds, n, k)
        Displacement part of each eigenvector, largest entry 1.
    labels : tuple of str
        For each mode, the coordinate that carries the largest share of its kinetic
        energy at the first speed (the shape weighted by the mass matrix).
    coordinates : tuple of str
        The model's coordinate names.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    frequencies: np.ndarray
    damping_ratios: np.ndarray
    shapes: np.ndarray
    labels: tuple
    coordinates: tuple


def mode_sweep(model, speeds) -> ModeSweep:
    """Eigenvalues, frequencies and damping ratios of every mode against speed, modes tracked by MAC.

    All state matrices are solved in one batched ``numpy.linalg.eig`` call; the
    tracking then pairs each mode with its successor (:func:`track_modes`).

    Parameters
    ----------
    model : LinearModel or LinearSystem
    speeds : array_like (n_speeds,)
        Increasing speeds, m/s (> 0).
    """
    system = as_linear_system(model)
    V = _speeds(speeds)
    if np.any(np.diff(V) <= 0):
        raise ValueError("speeds must be strictly increasing for mode tracking")
    n = system.size
    lam, vec = np.linalg.eig(system.state_matrices(V))
    lam, vec = track_modes(lam, vec)
    # One root of each conjugate pair: the n roots highest in the upper half-plane at the first
    # speed (real roots fill in when some modes are overdamped), ordered by frequency.
    keep = np.argsort(-lam[0].imag, kind="stable")[:n]
    keep = keep[np.argsort(np.abs(lam[0, keep].imag), kind="stable")]
    lam, vec = lam[:, keep], vec[:, :n, keep]
    pivot = np.argmax(np.abs(vec), axis=1)
    scale = np.take_along_axis(vec, pivot[:, None, :], axis=1)
    shapes = vec / scale
    freq = np.abs(lam.imag) / (2 * np.pi)
    mag = np.abs(lam)
    ratio = np.divide(-lam.real, mag, out=np.zeros(mag.shape), where=mag > 0)
    names = system.labels or tuple(f"q{i}" for i in range(n))
    # Name each mode by the coordinate that carries most of its kinetic energy, Re(φ̄ᵢ (Mφ)ᵢ):
    # the largest entry of φ alone would weigh metres against radians.
    first = shapes[0]
    energy = np.real(np.conj(first) * (system.M @ first))
    labels = tuple(names[int(j)] for j in np.argmax(energy, axis=0))
    return ModeSweep(V, lam, freq, ratio, shapes, labels, tuple(names))


# ---------------------------------------------------------------------------
# Critical speed


@dataclass(frozen=True)
class CriticalSpeed:
    """The linear critical speed of a model within a range of speeds.

    Attributes
    ----------
    speed : float
        V_c, m/s: the lowest speed where max Re λ crosses zero upwards.
        ``inf`` when stable over the whole range; the lower end of the range
        when unstable already there (see ``status``).
    frequency : float
        Frequency of the mode that loses stability, Hz (nan when none does).
    eigenvalue : complex
        That mode's eigenvalue at V_c, 1/s.
    status : str
        "crossing", "stable over the range" or "unstable at the lowest speed".
    """

    speed: float
    frequency: float
    eigenvalue: complex
    status: str

    @property
    def found(self) -> bool:
        return self.status == "crossing"


def _range(speed_range) -> tuple[float, float]:
    r = np.asarray(speed_range, dtype=float).ravel()
    if r.size != 2:
        raise ValueError(f"speed_range must be (low, high) in m/s, got {speed_range!r}")
    low = scalar("speed_range[0]", float(r[0]), low=0.0, low_open=True)
    high = scalar("speed_range[1]", float(r[1]), low=low, low_open=True)
    return low, high


def critical_speed(model, speed_range=(1.0, 150.0), *, tol: float = 0.01, scan: int = 64) -> CriticalSpeed:
    """The linear critical speed: where the largest real part of the eigenvalues first becomes positive.

    A coarse batched scan of ``scan`` speeds brackets the first upward zero of
    g(V) = max Re λ(V), which Brent's method then refines to ``tol`` m/s.

    Parameters
    ----------
    model : LinearModel or LinearSystem
    speed_range : (float, float)
        Lowest and highest speed, m/s (0 < low < high).
    tol : float
        Absolute tolerance on V_c, m/s (default 0.01, well inside 0.1 m/s).
    scan : int
        Number of speeds in the coarse scan (≥ 8).

    Examples
    --------
    >>> from raildyn.wheelset import Wheelset
    >>> cs = critical_speed(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6), (1.0, 200.0))
    >>> cs.status, round(cs.speed, 1)
    ('crossing', 54.6)
    """
    system = as_linear_system(model)
    low, high = _range(speed_range)
    positive("tol", tol)
    integer("scan", scan, low=8)
    V = np.linspace(low, high, scan)
    g = largest_real_part(system, V)

    def at(speed):
        lam = eigenvalues_against_speed(system, [speed])[0]
        j = int(np.argmax(lam.real))
        return lam[j]

    if g[0] >= 0.0:
        lam = at(low)
        return CriticalSpeed(
            low, float(abs(lam.imag) / (2 * np.pi)), complex(lam), "unstable at the lowest speed"
        )
    up = np.flatnonzero((g[:-1] < 0.0) & (g[1:] >= 0.0))
    if up.size == 0:
        return CriticalSpeed(np.inf, np.nan, complex(np.nan, np.nan), "stable over the range")
    i = int(up[0])
    speed = scipy.optimize.brentq(lambda v: at(v).real, V[i], V[i + 1], xtol=tol)
    lam = at(speed)
    return CriticalSpeed(float(speed), float(abs(lam.imag) / (2 * np.pi)), complex(lam), "crossing")


@dataclass(frozen=True)
class CriticalSpeedMap:
    """Critical speed over a grid of two parameters.

    Attributes
    ----------
    x, y : ndarray
        The two parameter grids (units of the parameters).
    speeds : ndarray (len(y), len(x))
        V_c, m/s (inf where stable over the range).
    x_name, y_name : str
    """

    x: np.ndarray
    y: np.ndarray
    speeds: np.ndarray
    x_name: str
    y_name: str


def critical_speed_map(
    factory: Callable[[float, float], object],
    x,
    y,
    speed_range=(1.0, 150.0),
    *,
    x_name: str = "x",
    y_name: str = "y",
    tol: float = 0.05,
    progress: bool = True,
) -> CriticalSpeedMap:
    """Critical speed for every pair of parameters: ``factory(x_i, y_j)`` gives the model.

    Example: critical speed against conicity and primary yaw stiffness,
    ``factory = lambda lam, k: car.replace(conicity=lam, primary_yaw_stiffness=k)``.
    Shows a tqdm bar when ``progress`` is true.
    """
    xs = array("x", np.atleast_1d(x), ndim=1)
    ys = array("y", np.atleast_1d(y), ndim=1)
    if xs.size == 0 or ys.size == 0:
        raise ValueError("x and y must each hold at least one value")
    out = np.empty((ys.size, xs.size))
    pairs = [(j, i) for j in range(ys.size) for i in range(xs.size)]
    if progress:
        pairs = progress_bar(pairs, desc="critical speed map")
    for j, i in pairs:
        out[j, i] = critical_speed(factory(xs[i], ys[j]), speed_range, tol=tol).speed
    return CriticalSpeedMap(xs, ys, out, x_name, y_name)


# ---------------------------------------------------------------------------
# Nonlinear hunting


def _settle(model, speed: float, y0: np.ndarray, duration: float, max_step: float, rtol: float):
    """Integrate the nonlinear model from y0 for ``duration`` seconds (RK45); (t, states)."""
    import scipy.integrate

    sol = scipy.integrate.solve_ivp(
        model.rhs, (0.0, duration), y0, method="RK45", rtol=rtol, atol=1e-9, max_step=max_step
    )
    if not sol.success:
        raise SolverError(f"integration failed at V = {speed:.2f} m/s: {sol.message}", time=float(sol.t[-1]))
    return sol.t, sol.y


@dataclass(frozen=True)
class LimitCycle:
    """Steady lateral oscillation of a nonlinear model at one speed.

    Attributes
    ----------
    speed : float
        m/s.
    amplitude : float
        Half the peak-to-peak lateral displacement of the first wheelset over
        the last quarter of the run, m.
    frequency : float
        Hz, from the upward crossings of the mean (nan when there is no oscillation).
    growth : float
        Amplitude over the last quarter divided by that over the quarter before:
        below 1 while the motion is still dying away.
    state : ndarray
        The state at the end of the run (to start the next speed of a ramp from).
    """

    speed: float
    amplitude: float
    frequency: float
    growth: float
    state: np.ndarray

    def hunting(self, threshold: float = 2.0e-4) -> bool:
        """True when the oscillation is above ``threshold`` (m) and no longer decaying."""
        return self.amplitude > threshold and self.growth > 0.95


def limit_cycle_amplitude(
    model,
    speed,
    *,
    initial_displacement: float = 12.0e-3,
    initial_state=None,
    duration: float = 8.0,
    max_step: float = 2.0e-3,
    rtol: float = 1e-6,
) -> LimitCycle:
    """Amplitude of the steady hunting of a nonlinear model at one speed, by direct integration.

    Starts from a lateral displacement of the first wheelset (or from
    ``initial_state``) and integrates ``duration`` seconds with RK45; the
    amplitude is taken over the last quarter of the run.

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        giving ``rhs``, ``state_size`` and ``lateral_index``.
    speed : float
        m/s (> 0).
    initial_displacement : float
        Starting lateral displacement of the first wheelset, m (default 12 mm:
        beyond the flangeway clearance, so that a large limit cycle is found
        where one exists).
    initial_state : array_like, optional
        Full starting state, instead of ``initial_displacement``.
    duration : float
        Simulated time, s.
    max_step : float
        Largest solver step, s.
    rtol : float
        Relative tolerance of the solver.
    """
    V = scalar("speed", speed, low=0.0, low_open=True)
    positive("duration", duration)
    positive("max_step", max_step)
    m = model.at_speed(V)
    if initial_state is None:
        y0 = np.zeros(m.state_size)
        y0[m.lateral_index] = scalar("initial_displacement", initial_displacement)
    else:
        y0 = array("initial_state", initial_state, shape=(m.state_size,))
    t, y = _settle(m, V, y0, duration, max_step, rtol)
    x = y[m.lateral_index]
    last = t >= 0.75 * duration
    before = (t >= 0.5 * duration) & ~last
    amplitude = 0.5 * (x[last].max() - x[last].min())
    previous = 0.5 * (x[before].max() - x[before].min())
    growth = amplitude / previous if previous > 0 else 1.0
    tail, tt = x[last], t[last]
    crossings = np.flatnonzero(np.diff(np.sign(tail - tail.mean())) > 0)
    frequency = np.nan
    if amplitude > 1e-6 and crossings.size >= 2:
        frequency = (crossings.size - 1) / (tt[crossings[-1]] - tt[crossings[0]])
    return LimitCycle(V, float(amplitude), float(frequency), float(growth), y[:, -1].copy())


@dataclass(frozen=True)
class BifurcationDiagram:
    """Limit-cycle amplitude against speed and the nonlinear critical speed.

    Attributes
    ----------
    speeds : ndarray
        m/s, decreasing (the order of the ramp).
    amplitudes : ndarray
        Lateral amplitude of the first wheelset, m.
    frequencies : ndarray
        Hz.
    hunting : ndarray of bool
        Whether the motion at each speed is a sustained oscillation.
    nonlinear_critical_speed : float
        Lowest speed at which a limit cycle persists, m/s, refined by bisection
        between the grid speeds (inf if there is none on the grid).
    threshold : float
        Amplitude below which the motion counts as decayed, m.
    """

    speeds: np.ndarray
    amplitudes: np.ndarray
    frequencies: np.ndarray
    hunting: np.ndarray
    nonlinear_critical_speed: float
    threshold: float


def bifurcation_diagram(
    model,
    speeds,
    *,
    initial_displacement: float = 12.0e-3,
    duration: float = 8.0,
    max_step: float = 2.0e-3,
    threshold: float = 2.0e-4,
    refine: int = 4,
    progress: bool = True,
) -> BifurcationDiagram:
    """Limit-cycle amplitude along a speed ramp-down, and the nonlinear critical speed.

    The highest speed starts from a large lateral displacement of the first
    wheelset; each lower speed starts from the final state of the one above
    (a slow ramp-down in steps), so the branch of large limit cycles is
    followed below the linear critical speed as far as it exists (a
    subcritical Hopf bifurcation). Where the branch ends, ``refine`` bisection
    steps between the last hunting and the first decaying speed locate the
    nonlinear critical speed.
    """
    V = np.sort(_speeds(speeds))[::-1]
    positive("threshold", threshold)
    integer("refine", refine, low=0)
    items = V
    if progress:
        items = progress_bar(V, desc="bifurcation diagram (ramp-down)")
    cycles, state = [], None
    for v in items:
        cycle = limit_cycle_amplitude(
            model,
            v,
            initial_displacement=initial_displacement,
            initial_state=state,
            duration=duration,
            max_step=max_step,
        )
        cycles.append(cycle)
        state = cycle.state if cycle.hunting(threshold) else None
    hunting = np.array([c.hunting(threshold) for c in cycles])
    vnl = np.inf
    if hunting.any():
        k = int(np.flatnonzero(hunting).max())
        vnl = float(V[k])
        if k + 1 < V.size and not hunting[k + 1]:
            high, low, start = V[k], V[k + 1], cycles[k].state
            for _ in range(refine):
                mid = 0.5 * (high + low)
                trial = limit_cycle_amplitude(
                    model, mid, initial_state=start, duration=duration, max_step=max_step
                )
                if trial.hunting(threshold):
                    high, start = mid, trial.state
                else:
                    low = mid
            vnl = float(high)
    amp = np.array([c.amplitude for c in cycles])
    freq = np.array([c.frequency for c in cycles])
    return BifurcationDiagram(V, amp, freq, hunting, vnl, threshold)


@dataclass(frozen=True)
class PeriodicOrbit:
    """A periodic solution of a nonlinear model found by shooting.

    Attributes
    ----------
    speed : float
        m/s.
    period : float
        T, s.
    state : ndarray
        A point of the orbit, where the first wheelset's lateral velocity is zero.
    amplitude : float
        Half the peak-to-peak lateral displacement of the first wheelset over one period, m.
    multipliers : complex ndarray
        Floquet multipliers (eigenvalues of the monodromy matrix); the orbit is
        stable when all but the trivial one (≈ 1) lie inside the unit circle.
    residual : float
        Norm of φ_T(x₀) − x₀ at the solution, in units of the state.
    """

    speed: float
    period: float
    state: np.ndarray
    amplitude: float
    multipliers: np.ndarray
    residual: float

    @property
    def stable(self) -> bool:
        """All multipliers but the trivial one (the one closest to 1) inside the unit circle."""
        trivial = int(np.argmin(np.abs(self.multipliers - 1.0)))
        others = np.delete(self.multipliers, trivial)
        return bool(np.all(np.abs(others) < 1.0))


def periodic_orbit(
    model,
    speed,
    state,
    period,
    *,
    tol: float = 1e-7,
    max_iter: int = 12,
    rtol: float = 1e-10,
) -> PeriodicOrbit:
    """Periodic orbit through Newton shooting, from a guess of one of its points and of its period.

    Unknowns: the state x₀ with the first wheelset's lateral velocity held at
    zero (the phase condition) and the period T; equations φ_T(x₀) − x₀ = 0,
    with the Jacobian by finite differences (one integration per unknown). The
    monodromy matrix of the converged orbit gives its Floquet multipliers, so
    unstable orbits — the other branch of a subcritical bifurcation — are found
    as well as stable ones.

    Parameters
    ----------
    model : nonlinear model with ``at_speed``, ``rhs``, ``state_size``, ``lateral_index``
    speed : float
        m/s.
    state : array_like
        Guess of a point on the orbit (for instance the end of a
        :func:`limit_cycle_amplitude` run).
    period : float
        Guess of T, s (1/frequency of the settled motion).
    tol : float
        Convergence on the relative size of the Newton step.

    Notes
    -----
    The centred state is a trivial solution of the same equations: a guess
    far from any cycle may converge to it (amplitude 0).
    """
    import scipy.integrate

    V = scalar("speed", speed, low=0.0, low_open=True)
    T = positive("period", period)
    m = model.at_speed(V)
    n = m.state_size
    x = array("state", state, shape=(n,)).copy()
    iy = m.lateral_index
    iv = iy + n // 2  # the lateral velocity of the same wheelset
    free = [i for i in range(n) if i != iv]

    def section(t, z):
        return z[iv]

    section.direction = -1.0  # a maximum of the lateral displacement
    # Move the guess along its own trajectory to the section ẏ = 0, so that it meets the phase condition.
    sol = scipy.integrate.solve_ivp(
        m.rhs, (0.0, 2.0 * T), x, method="DOP853", rtol=rtol, atol=1e-12, events=section
    )
    if sol.t_events[0].size:
        x = sol.y_events[0][0].copy()
    x[iv] = 0.0

    def flow(x0, t_end):
        sol = scipy.integrate.solve_ivp(m.rhs, (0.0, t_end), x0, method="DOP853", rtol=rtol, atol=1e-12)
        if not sol.success:
            raise SolverError(
                f"shooting integration failed at V = {V:.2f} m/s: {sol.message}", time=float(sol.t[-1])
            )
        return sol.y[:, -1]

    # Finite-difference steps relative to each entry, with a floor so that an entry near 0 (such
    # as the lateral velocity on the section) is not perturbed below the integration noise.
    scale = np.maximum(np.abs(x), 1e-2 * np.abs(x).max())
    for _ in range(integer("max_iter", max_iter, low=1)):
        end = flow(x, T)
        residual = end - x
        J = np.empty((n, n))
        for col, i in enumerate(free):
            h = 1e-5 * scale[i]
            xp = x.copy()
            xp[i] += h
            J[:, col] = (flow(xp, T) - xp - residual) / h
        J[:, -1] = m.rhs(T, end)  # d/dT of φ_T(x₀)
        step = np.linalg.solve(J, -residual)
        x[free] += step[:-1]
        T += step[-1]
        if np.linalg.norm(step[:-1] / scale[free]) < tol and abs(step[-1]) < tol * T:
            break
    else:
        raise SolverError(f"shooting did not converge in {max_iter} iterations at V = {V:.2f} m/s")
    # Monodromy matrix and one period of the orbit, for the multipliers and the amplitude.
    end = flow(x, T)
    monodromy = np.empty((n, n))
    for i in range(n):
        h = 1e-5 * scale[i]
        xp = x.copy()
        xp[i] += h
        monodromy[:, i] = (flow(xp, T) - end) / h
    sol = scipy.integrate.solve_ivp(
        m.rhs, (0.0, T), x, method="DOP853", rtol=rtol, atol=1e-12, max_step=T / 200
    )
    lateral = sol.y[iy]
    return PeriodicOrbit(
        V,
        float(T),
        x,
        float(0.5 * (lateral.max() - lateral.min())),
        np.linalg.eigvals(monodromy),
        float(np.linalg.norm(end - x)),
    )
