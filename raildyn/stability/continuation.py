"""The whole branch of limit cycles against speed, by pseudo-arclength continuation (book chapter 7).

:func:`~raildyn.stability.bifurcation.bifurcation_diagram` follows the *stable* limit cycles down a
ramp of speeds, as a running vehicle would; the unstable cycles, which no run settles on, are the
other half of the picture. :func:`limit_cycle_branch` follows the branch through both: it starts
from one cycle (a :class:`~raildyn.stability.bifurcation.PeriodicOrbit` or a ramp's
:class:`~raildyn.stability.nonlinear.LimitCycle`), corrects it by shooting, and steps along the
curve of periodic orbits in (orbit, period, speed) by pseudo-arclength (Keller 1977), so that it
turns at the fold, where the stable and unstable cycles meet (the nonlinear critical speed), and
runs down the unstable branch towards the Hopf point, where the amplitude falls to zero at the
linear critical speed. :class:`LimitCycleBranch` holds the result and draws it.

Each shooting integrates the orbit and its n + 1 perturbations (the columns of the monodromy matrix
and the derivative in speed) as one batch on the compiled engine of
:mod:`raildyn.stability.nonlinear` (``numpy`` and scipy where the engine does not hold the model).
SI units throughout.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import array, integer, scalar
from raildyn._tables import Tabular
from raildyn.constants import MAXIMUM_SPEED
from raildyn.errors import SolverError
from raildyn.stability._shooting import compiled, flows
from raildyn.stability.bifurcation import PeriodicOrbit
from raildyn.stability.nonlinear import (
    _MAX_DISPLACEMENT,
    _MIN_RUN_SPEED,
    LimitCycle,
    _duration,
    _engine_choice,
    _model,
    _runs,
)

__all__ = ["LimitCycleBranch", "limit_cycle_branch"]

# Finite-difference steps of the shooting's Jacobian, relative to the scale of each state entry and to
# the speed. The perturbed runs share the base run's steps (see _flows), so a difference carries the
# truncation of the forward difference (about the step times the curvature of the flow, 1e-6
# relative) and the round-off of the state over the step (1e-16 / 1e-6 = 1e-10 relative).
_FD_STATE = 1.0e-6
_FD_SPEED = 1.0e-6
# The turn between two successive tangents above which a step is retried shorter: cos 37°. A
# sharper turn means the step jumped across a bend of the branch (or onto another branch).
_MIN_TURN_COSINE = 0.8
# Chord iterations (each one run of the orbit alone) after which a step counts as easy (the next is
# longer) or hard (the next is shorter).
_EASY, _HARD = 4, 7
_MAX_HALVINGS = 8  # of one step, before the continuation gives up: 1/256 of the step


@dataclass(frozen=True)
class LimitCycleBranch(Tabular):
    """A branch of limit cycles against speed, stable and unstable, with its folds.

    The points are in the order of the continuation (arclength increasing): from the starting
    cycle, typically down in speed along the stable cycles to the fold and back up the
    unstable ones towards the Hopf point.

    Attributes
    ----------
    speeds : ndarray, (k,)
        V at each point, m/s (> 0).
    amplitudes : ndarray, (k,)
        Half the peak-to-peak lateral displacement of the first wheelset over one period, m (≥ 0).
    periods : ndarray, (k,)
        The period of each cycle, s (> 0).
    stable : ndarray of bool, (k,)
        Whether each cycle is stable (:attr:`~raildyn.stability.bifurcation.PeriodicOrbit.stable`:
        every Floquet multiplier but the trivial one inside the unit circle).
    multipliers : complex ndarray, (k, state_size)
        The Floquet multipliers of each cycle.
    states : ndarray, (k, state_size)
        A point of each cycle, at the maximum of the first wheelset's lateral displacement (where
        its lateral velocity is zero), in the units of the model's state.
    arclength : ndarray, (k,)
        The scaled arclength of each point from the first (dimensionless, increasing from 0): the
        change of speed relative to the starting speed, of the period relative to the starting
        period and the RMS change of the state relative to the starting cycle's entries.
    fold_speed : float
        The speed of the fold, the turning point in speed where the stable and unstable cycles
        meet, m/s: a point of the branch (so also among ``speeds``), located where the scaled dV/ds
        falls below 1e-3; the lowest, should the branch turn more than once; inf if it does not
        turn (a supercritical branch).
    fold_amplitude : float
        The amplitude at the fold, m (≥ 0; 0 where there is no fold).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("speeds", "m/s"), ("amplitudes", "m"), ("periods", "s"), ("stable", "-"), ("arclength", "-"),
        ("multipliers", "-"), ("states", "units of the model's state"),
    )  # fmt: skip
    _scalars = (("fold_speed", "m/s"), ("fold_amplitude", "m"))

    speeds: np.ndarray
    amplitudes: np.ndarray
    periods: np.ndarray
    stable: np.ndarray
    multipliers: np.ndarray
    states: np.ndarray
    arclength: np.ndarray
    fold_speed: float
    fold_amplitude: float

    def __post_init__(self):
        k = _checks.speeds("speeds", self.speeds).size
        array("amplitudes", self.amplitudes, shape=(k,), low=0.0)
        for period in array("periods", self.periods, shape=(k,)):
            _duration("periods", period)
        stable = np.asarray(self.stable)
        if stable.dtype != bool or stable.shape != (k,):
            raise TypeError(f"stable must be an array of {k} bools, got {self.stable!r:.80}")
        n = array("states", self.states, shape=(k, None)).shape[1]
        array("multipliers", self.multipliers, shape=(k, n), dtype=complex)
        s = array("arclength", self.arclength, shape=(k,), low=0.0)
        if np.any(np.diff(s) <= 0.0):
            raise ValueError(f"arclength must increase along the branch, got {self.arclength!r:.80}")
        if self.fold_speed != np.inf:  # inf: the branch does not turn
            V = np.asarray(self.speeds, dtype=float)  # the fold is a point of the branch
            _checks.speed("fold_speed", self.fold_speed, low=V.min(), low_open=False, high=V.max())
        _checks.nonnegative("fold_amplitude", self.fold_amplitude)

    @property
    def nonlinear_critical_speed(self) -> float:
        """The lowest speed at which a limit cycle exists: the fold's, m/s (inf without a fold)."""
        return self.fold_speed

    def plot(self, ax=None, *, artists: dict | None = None) -> dict:
        """Draw the amplitude (mm) against speed (km/h): stable cycles solid, unstable dashed, folds marked.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this branch in place.

        Returns
        -------
        dict
            The artists: ``stable``, ``unstable`` and ``fold`` (``Line2D``; the fold as markers).
        """
        import matplotlib

        from raildyn import plots

        V, amp, stable = 3.6 * self.speeds, 1e3 * self.amplitudes, self.stable
        # Each unstable stretch is drawn from the stable point before it to the one after, so
        # that the two lines join.
        near_unstable = ~stable | np.r_[~stable[1:], False] | np.r_[False, ~stable[:-1]]
        if artists is None:
            ax = plots.axes_or_new(ax)
            with matplotlib.rc_context(plots.STYLE):
                artists = {
                    "stable": ax.plot([], [], "-", color=plots.COLORS[0], label="stable cycles")[0],
                    "unstable": ax.plot([], [], "--", color=plots.COLORS[3], label="unstable cycles")[0],
                    "fold": ax.plot([], [], "D", color=plots.COLORS[2], label="fold")[0],
                }
                ax.set_xlabel("speed (km/h)")
                ax.set_ylabel("amplitude of $y$ (mm)")
                ax.update_datalim(np.column_stack([V, amp]))
                ax.autoscale_view()
                ax.set_ylim(0.0, 1.1 * max(float(amp.max()), 1.0))
                ax.legend(loc="center right")
        else:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
        artists["stable"].set_data(V, np.where(stable, amp, np.nan))
        artists["unstable"].set_data(V, np.where(near_unstable, amp, np.nan))
        fold = [] if self.fold_speed == np.inf else [self.fold_speed]
        artists["fold"].set_data(3.6 * np.array(fold), [1e3 * self.fold_amplitude] * len(fold))
        return artists


def limit_cycle_branch(
    model,
    start,
    *,
    direction: str = "down",
    speed_range=(_MIN_RUN_SPEED, MAXIMUM_SPEED),
    end_amplitude: float = 2.0e-4,
    arc_step: float = 0.05,
    max_arc_step: float = 0.2,
    max_points: int = 100,
    tol: float = 1e-5,
    max_iter: int = 10,
    rtol: float = 1e-9,
    engine: str = "auto",
) -> LimitCycleBranch:
    """Follow a branch of limit cycles in speed, through its folds, by pseudo-arclength continuation.

    The unknowns are a point x of the cycle, its period T and the speed V. The point lies on the
    section where the first wheelset's lateral velocity is zero (the phase condition, as in
    :func:`~raildyn.stability.bifurcation.periodic_orbit`), and the cycle closes:
    φ_T(x; V) − x = 0 (n equations in n + 1 unknowns, a curve). From a point u on the curve and
    its unit tangent τ (J τ = 0), a step predicts u + Δs τ and Newton's method corrects the
    prediction on the plane τ·(u' − u − Δs τ) = 0 (Keller 1977), so the continuation passes a fold,
    where a step in speed would find no cycle. The Jacobian J = [M − I, f(φ_T), ∂φ_T/∂V] comes
    from one batch of n + 2 runs sharing one sequence of steps (the orbit, its n perturbations,
    whose differences give the monodromy matrix M, and one at a nearby speed); M gives each cycle's
    Floquet multipliers. The corrections are chord iterations on the last cycle's J (each a run of
    the orbit alone), J refreshed where they converge slowly. Where dV/ds changes sign, regula
    falsi on the step places the fold. The unknowns are scaled (V by the starting speed, T by the
    starting period, the state entries by their sizes on the starting cycle, RMS), so that Δs is a
    relative change; it grows by half after a correction of at most four iterations and halves
    after one of more than seven, a failed one or a turn of the tangent by more than 37°.

    Parameters
    ----------
    model : NonlinearModel
        The nonlinear model, as for :func:`~raildyn.stability.bifurcation.periodic_orbit`.
    start : PeriodicOrbit or LimitCycle
        The cycle to start from: an orbit from :func:`~raildyn.stability.bifurcation.periodic_orbit`,
        or a hunting :class:`~raildyn.stability.nonlinear.LimitCycle` (from
        :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude`; its final state and frequency
        give the guess, and it is corrected by shooting first).
    direction : {"down", "up"}
        The way in speed of the first step ("down": towards the fold of a subcritical branch).
    speed_range : pair of float
        (low, high), m/s, within [1, :data:`~raildyn.constants.MAXIMUM_SPEED`], low < high: the
        continuation stops where the branch leaves it.
    end_amplitude : float
        The amplitude at which the continuation stops, m, in (0, 0.05] (no wheelset on the rails
        moves further): the branch is taken to end at a
        Hopf point (zero amplitude) just beyond. Default 0.2 mm, the amplitude below which
        :func:`~raildyn.stability.bifurcation.bifurcation_diagram` counts a motion as decayed.
    arc_step : float
        The first step Δs, dimensionless, in [1e-6, 1] (a millionth changes nothing measurable).
    max_arc_step : float
        The largest step, dimensionless, in [arc_step, 1].
    max_points : int
        The most points on the branch, in [2, 1000]: the continuation stops there.
    tol : float
        Newton's convergence on the scaled step (dimensionless), in (0, 0.01]: a coarser one would
        leave the cycles unconverged by a per cent.
    max_iter : int
        Newton (chord) iterations per point before the step is retried shorter, in [1, 50].
    rtol : float
        Relative tolerance of the integrations, in [1e-13, 1). The default 1e-9 lies four orders below
        Newton's ``tol``, which bounds the cycles; the car of chapter 7 gives the same fold speed to
        1e-7 and fold amplitude to 5e-5 as at 1e-10, in two thirds of the time.
    engine : str
        ``"auto"``, ``"compiled"`` or ``"scipy"``, as for :func:`~raildyn.stability.nonlinear.simulate`.

    Returns
    -------
    LimitCycleBranch
        Speeds (m/s), amplitudes (m), periods (s), stability and multipliers of each cycle, and
        the fold (:attr:`LimitCycleBranch.nonlinear_critical_speed`).

    Raises
    ------
    SolverError
        If an integration fails, the correction of the starting cycle does not converge (or
        converges to the centred running), or a step halved eight times still does not converge.

    Notes
    -----
    The continuation stops at the first of: the amplitude below ``end_amplitude``, the speed out
    of ``speed_range``, ``max_points`` points, or a step that would carry the cycle through zero
    amplitude (the Hopf point passed; the shorter steps tried first approach it).

    Examples
    --------
    The soft suspended wheelset of chapter 5 hunts on its flanges at 60 m/s. Its branch of cycles
    falls, stable all the way and without a fold, to zero amplitude at its linear critical speed
    (54.5 m/s): this wheelset's Hopf bifurcation is supercritical, if steep.

    >>> from raildyn import stability
    >>> from raildyn.wheelset import NonlinearWheelset, Wheelset
    >>> model = NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))
    >>> cycle = stability.limit_cycle_amplitude(model, 60.0, duration=4.0)
    >>> branch = stability.limit_cycle_branch(model, cycle)
    >>> bool(branch.stable.all()), branch.fold_speed, round(float(branch.speeds[-1]), 1)
    (True, inf, 54.5)
    """
    m = _model(model)
    _checks.instance("start", start, (PeriodicOrbit, LimitCycle), "PeriodicOrbit or LimitCycle")
    sign = {"down": -1.0, "up": 1.0}[_checks.choice("direction", direction, ("down", "up"))]
    low, high = array("speed_range", speed_range, shape=(2,))
    _checks.speed("speed_range", low, low=_MIN_RUN_SPEED, low_open=False)
    _checks.speed("speed_range", high)
    if not low < high:
        raise ValueError(f"speed_range must be (low, high) with low < high, m/s, got {speed_range!r}")
    end_amplitude = scalar("end_amplitude", end_amplitude, low=0.0, low_open=True, high=_MAX_DISPLACEMENT)
    ds = scalar("arc_step", arc_step, low=1e-6, high=1.0)
    ds_max = scalar("max_arc_step", max_arc_step, low=ds, high=1.0)
    max_points = integer("max_points", max_points, low=2, high=1000)
    tol = scalar("tol", tol, low=0.0, low_open=True, high=1e-2)
    max_iter = integer("max_iter", max_iter, low=1, high=50)
    rtol = _checks.tolerance("rtol", rtol)
    engine = _engine_choice(engine)
    compiled(m, engine)
    if not low <= start.speed <= high:
        raise ValueError(f"start.speed must lie in speed_range {speed_range!r}, m/s, got {start.speed!r}")
    n = array("start.state", start.state, shape=(m.state_size,)).size
    if isinstance(start, LimitCycle):
        if start.frequency_hz <= 0.0:
            raise ValueError("start must be a cycle that oscillates (frequency_hz > 0), got frequency_hz 0")
        x, T = _on_section(m, start.speed, start.state, 1.0 / start.frequency_hz, engine)
    else:
        x, T = np.array(start.state, dtype=float), float(start.period)
    shooting = _Shooting(m, x, T, start.speed, rtol, engine)
    # The starting cycle, corrected at its own speed (the plane fixes the speed).
    fixed = np.zeros(n + 1)
    fixed[-1] = 1.0
    corrected = shooting.correct(shooting.scaled(x, T, start.speed), fixed, None, tol, max_iter)
    if corrected is None:
        raise SolverError(f"the starting cycle at V = {start.speed:.6g} m/s did not converge by shooting")
    w, point, _ = corrected
    if point.lateral <= 0.0 or point.amplitude < end_amplitude:  # x = 0 closes for any T: the centre
        raise SolverError(
            f"the starting cycle at V = {start.speed:.6g} m/s shrank to the centred running (amplitude "
            f"{point.amplitude:.3g} m): there is no cycle near the start"
        )
    tangent = np.linalg.svd(point.jacobian)[2][-1]  # the Jacobian's null vector: the branch's direction
    tangent *= sign * np.sign(tangent[-1]) if tangent[-1] != 0.0 else 1.0
    points, arc, folds = [point], [0.0], []
    while len(points) < max_points:
        for _ in range(_MAX_HALVINGS + 1):
            stepped = _step(shooting, w, tangent, points[-1].jacobian, ds, tol, max_iter)
            if stepped is not None:
                break
            ds *= 0.5
        else:
            if points[-1].amplitude < 4.0 * end_amplitude:  # the Hopf point is within the halvings
                break
            raise SolverError(
                f"the continuation stalled at V = {points[-1].speed:.6g} m/s, amplitude "
                f"{points[-1].amplitude:.3g} m: {_MAX_HALVINGS} halvings of the step did not converge"
            )
        w_new, new, new_tangent, iterations = stepped
        if not low <= new.speed <= high:
            break
        before = w
        if tangent[-1] * new_tangent[-1] < 0.0 and len(points) + 1 < max_points:  # the speed turns: a fold
            fold = _fold(shooting, w, tangent, points[-1].jacobian, ds, new_tangent[-1], tol, max_iter)
            if fold is not None:
                arc.append(arc[-1] + float(np.linalg.norm(fold[0] - w)))
                folds.append(len(points))
                points.append(fold[1])
                before = fold[0]
        arc.append(arc[-1] + float(np.linalg.norm(w_new - before)))
        w, tangent = w_new, new_tangent
        points.append(new)
        if iterations <= _EASY:
            ds = min(1.5 * ds, ds_max)
        elif iterations > _HARD:
            ds *= 0.5
        if new.amplitude < end_amplitude:
            break
    return _branch(points, np.array(arc), folds)


def _step(shooting, w, tangent, jacobian, ds, tol, max_iter):
    """One step of length ds along the tangent, corrected: (w, point, tangent, iterations), or None where
    the correction fails, the tangent turns sharply or the cycle passes through zero amplitude."""
    result = shooting.correct(w + ds * tangent, tangent, jacobian, tol, max_iter)
    if result is None:
        return None
    w_new, point, iterations = result
    new_tangent = _tangent(point.jacobian, tangent)
    if new_tangent @ tangent < _MIN_TURN_COSINE or point.lateral <= 0.0:
        return None
    return w_new, point, new_tangent, iterations


# The fold is located where the tangent's speed component, the scaled dV/ds, is below this: the speed
# there is then within about ½ |d²V/ds²| (1e-3 / |d²V/ds²|)² = 5e-7 / |d²V/ds²| of the turning point.
_FOLD_TANGENT = 1.0e-3


def _fold(shooting, w, tangent, jacobian, ds, end_slope, tol, max_iter):
    """The fold between w (arclength 0) and its step ds, where dV/ds changed sign: (w, point) or None.

    Regula falsi (Illinois) on the step length s for the scaled dV/ds of the cycle at w + s τ.
    """
    lo, f_lo, hi, f_hi = 0.0, tangent[-1], ds, end_slope
    found = None
    for _ in range(8):
        s = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        stepped = _step(shooting, w, tangent, jacobian, s, tol, max_iter)
        if stepped is None:
            return found
        found = stepped[:2]
        f = stepped[2][-1]
        if abs(f) < _FOLD_TANGENT:
            break
        if f * f_lo > 0.0:
            lo, f_lo, f_hi = s, f, 0.5 * f_hi
        else:
            hi, f_hi, f_lo = s, f, 0.5 * f_lo
    return found


@dataclass(frozen=True)
class _Point:
    """One corrected cycle and what its shooting measured."""

    speed: float
    period: float
    state: np.ndarray
    amplitude: float
    lateral: float  # the first wheelset's lateral displacement on the section (> 0 at a maximum)
    multipliers: np.ndarray
    jacobian: np.ndarray  # the scaled n × (n + 1) Jacobian of φ_T(x; V) − x


class _Shooting:
    """The shooting equations of one model, scaled about a starting cycle, and their Newton correction."""

    def __init__(self, model, x, period, speed, rtol, engine):
        self.model, self.rtol, self.engine = model, rtol, engine
        n = model.state_size
        self.iy = model.lateral_index
        self.iv = self.iy + n // 2  # the lateral velocity of the same wheelset: the phase condition
        self.free = np.array([i for i in range(n) if i != self.iv])
        x = np.asarray(x, dtype=float)
        # Each entry's size on the starting cycle, floored at 1 % of the largest (an entry near zero,
        # such as the velocity on the section, would otherwise scale by nothing).
        self.size = np.maximum(np.abs(x), 1e-2 * np.abs(x).max())
        # The scale of the unknowns (x_free, T, V): the state by its RMS over the entries, so that a
        # step of Δs changes speed, period and state each by a like fraction.
        self.scale = np.concatenate([self.size[self.free] * np.sqrt(self.free.size), [period, speed]])

    def scaled(self, x, period, speed):
        return np.concatenate([x[self.free], [period, speed]]) / self.scale

    def unscaled(self, w):
        u = w * self.scale
        x = np.zeros(self.model.state_size)
        x[self.free] = u[:-2]
        return x, float(u[-2]), float(u[-1])

    def evaluate(self, w, full=True):
        """The residual φ_T(x) − x at the scaled unknowns w; with ``full``, the cycle point it makes.

        Only the orbit is run for the residual; ``full`` runs the whole batch (the orbit, its n
        perturbations and the run at a nearby speed) for the scaled Jacobian, the multipliers and
        the amplitude. Raises SolverError where the unknowns leave the runs' ranges.
        """
        x, T, V = self.unscaled(w)
        if not (_MIN_RUN_SPEED <= V <= MAXIMUM_SPEED and 1e-3 <= T <= 120.0):
            raise SolverError(f"the continuation left the runs' ranges (V = {V:.6g} m/s, T = {T:.6g} s)")
        n = x.size
        if not full:
            ends, _ = flows(self.model, x[:, None], V, None, T, self.rtol, self.engine)
            return ends[:, 0] - x, None
        h = _FD_STATE * self.size
        dV = _FD_SPEED * V
        starts = np.column_stack([x, x[:, None] + np.diag(h), x])
        ends, lateral = flows(self.model, starts, V, dV, T, self.rtol, self.engine)
        end = ends[:, 0]
        monodromy = (ends[:, 1 : n + 1] - end[:, None]) / h
        J = np.empty((n, n + 1))
        J[:, :-2] = monodromy[:, self.free] - np.eye(n)[:, self.free]
        J[:, -2] = self.model.rhs(T, end, V)  # d/dT of φ_T(x)
        J[:, -1] = (ends[:, n + 1] - end) / dV
        point = _Point(V, T, x, 0.5 * float(np.ptp(lateral)), float(x[self.iy]), np.linalg.eigvals(monodromy),
                       J * self.scale)  # fmt: skip
        return end - x, point

    def correct(self, w, plane, jacobian, tol, max_iter):
        """Chord Newton on φ_T(x) − x = 0 and plane·(w − w₀) = 0 from w₀ = w, with a fixed Jacobian.

        The Jacobian (of the last cycle found, or of the guess) is refreshed where a step shrinks by
        less than half. Returns the corrected unknowns, the cycle there (one full batch of runs) and
        the iterations taken, or None where Newton fails.
        """
        w0, w = w, w.copy()
        previous = np.inf
        try:
            for iteration in range(1, max_iter + 1):
                residual, point = self.evaluate(w, full=jacobian is None)
                if point is not None:
                    jacobian = point.jacobian
                step = np.linalg.solve(np.vstack([jacobian, plane]), -np.append(residual, plane @ (w - w0)))
                size = float(np.linalg.norm(step))
                if not np.isfinite(size):
                    return None
                w = w + step
                if size < tol:
                    _, point = self.evaluate(w)
                    return w, point, iteration
                jacobian = None if size > 0.5 * previous else jacobian
                previous = size
        except (SolverError, np.linalg.LinAlgError):
            return None
        return None


def _tangent(J, previous):
    """The unit tangent of the branch: J τ = 0, oriented along ``previous``."""
    A = np.vstack([J, previous])
    b = np.zeros(A.shape[0])
    b[-1] = 1.0
    tau = np.linalg.solve(A, b)
    return tau / np.linalg.norm(tau)


def _on_section(model, speed, state, period, engine):
    """A point of the cycle through ``state`` on the section ẏ = 0 at a maximum of y, and the period guess.

    One and a half periods are run and sampled; the first downward crossing of zero by the first
    wheelset's lateral velocity, interpolated between samples, is the point (Newton corrects it).
    """
    T = _duration("start period", period)
    iy = model.lateral_index
    iv = iy + model.state_size // 2
    (run,), _ = _runs([model], [speed], [np.asarray(state, dtype=float)], 1.5 * T, T, 1e-8, "RK45", engine,
                      None)  # fmt: skip
    v = run[iv]
    down = np.flatnonzero((v[:-1] > 0.0) & (v[1:] <= 0.0) & (run[iy, :-1] > 0.0))
    if not down.size:
        raise ValueError("start must be a cycle whose lateral motion oscillates about zero, got no crossing")
    k = down[0]
    a = v[k] / (v[k] - v[k + 1])
    x = (1.0 - a) * run[:, k] + a * run[:, k + 1]
    x[iv] = 0.0
    return x, T


def _branch(points, arc, folds) -> LimitCycleBranch:
    """The result: the points' fields, their stability by the one rule, and the folds (their indices)."""
    V = np.array([p.speed for p in points])
    A = np.array([p.amplitude for p in points])
    stable = np.array(
        [PeriodicOrbit(p.speed, p.period, p.state, p.amplitude, p.multipliers, 0.0).stable for p in points]
    )
    lowest = folds[int(np.argmin(V[folds]))] if folds else 0
    return LimitCycleBranch(
        V, A, np.array([p.period for p in points]), stable, np.array([p.multipliers for p in points]),
        np.array([p.state for p in points]), arc, float(V[lowest]) if folds else np.inf,
        float(A[lowest]) if folds else 0.0,
    )  # fmt: skip
