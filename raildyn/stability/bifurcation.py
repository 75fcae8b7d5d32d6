"""The bifurcation diagram and periodic orbits of nonlinear hunting (book chapter 7).

Built on the runs and limit cycles of :mod:`raildyn.stability.nonlinear`:
:func:`bifurcation_diagram` follows the limit-cycle amplitude down a ramp of speeds (and up again
from the centre) to find the nonlinear critical speed; :func:`bifurcation_diagrams` runs a family
of vehicles side by side; :func:`periodic_orbit` finds one limit cycle exactly by shooting, with
its Floquet multipliers. SI units throughout.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from raildyn import _checks
from raildyn._checks import array, integer, positive, scalar
from raildyn._progress import progress_bar
from raildyn._tables import Tabular
from raildyn.errors import SolverError
from raildyn.stability.nonlinear import (
    _MAX_DISPLACEMENT,
    _MAX_DURATION,
    _MIN_RUN_SPEED,
    _cycles,
    _displaced,
    _displacement,
    _duration,
    _engine_choice,
    _integrate,
    _method,
    _model,
)

__all__ = [
    "BifurcationDiagram",
    "PeriodicOrbit",
    "bifurcation_diagram",
    "bifurcation_diagrams",
    "periodic_orbit",
]

# Evaluations of the (batched) right-hand side one periodic_orbit may make in all its integrations: a
# shooting that converges takes some 14 000 (a wheelset) to 25 000 (a bogie or a car, about 1.5 s), so
# four times that is ample, and a hopeless guess (a period of 100 s) fails in a few seconds instead of
# running each of its integrations up to raildyn.stability.nonlinear's budget (about 50 s for a car).
_SHOOTING_EVALUATIONS = 100_000


@dataclass(frozen=True)
class BifurcationDiagram(Tabular):
    """Limit-cycle amplitude against speed and the nonlinear critical speed.

    Attributes
    ----------
    speeds : ndarray
        m/s (> 0), decreasing (the order of the ramp).
    amplitudes : ndarray
        Lateral amplitude of the first wheelset, m (≥ 0).
    frequencies_hz : ndarray
        Frequency of the motion at each speed, Hz (≥ 0; 0 where there is no oscillation).
    hunting : ndarray of bool
        Whether the motion at each speed is a sustained oscillation
        (:meth:`~raildyn.stability.nonlinear.LimitCycle.hunting`).
    nonlinear_critical_speed : float
        Lowest speed at which a limit cycle persists, m/s, refined by bisection between the
        grid speeds, so within their range (inf if there is none on the grid).
    threshold : float
        Amplitude of the oscillation below which the motion counts as decayed, m (> 0).
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("speeds", "m/s"), ("amplitudes", "m"), ("frequencies_hz", "Hz"), ("hunting", "-"))
    _scalars = (("nonlinear_critical_speed", "m/s"), ("threshold", "m"))

    speeds: np.ndarray
    amplitudes: np.ndarray
    frequencies_hz: np.ndarray
    hunting: np.ndarray
    nonlinear_critical_speed: float
    threshold: float

    def __post_init__(self):
        n = _checks.speeds("speeds", self.speeds).size
        array("amplitudes", self.amplitudes, shape=(n,), low=0.0)
        array("frequencies_hz", self.frequencies_hz, shape=(n,), low=0.0)
        hunting = np.asarray(self.hunting)
        if hunting.dtype != bool:
            raise TypeError(f"hunting must be an array of bools, got {self.hunting!r:.80}")
        if hunting.shape != (n,):
            raise ValueError(f"hunting must have shape ({n},), got {hunting.shape}")
        if self.nonlinear_critical_speed != np.inf:  # inf: no limit cycle on the grid
            V = np.asarray(self.speeds, dtype=float)
            _checks.speed(  # the lowest speed itself where every speed of the ramp hunts
                "nonlinear_critical_speed", self.nonlinear_critical_speed, low=V.min(), low_open=False,
                high=V.max(),
            )  # fmt: skip
        positive("threshold", self.threshold)

    def plot(
        self,
        ax=None,
        *,
        linear_critical_speed: float | None = None,
        artists: dict | None = None,
        branch=None,
    ) -> dict:
        """Draw the amplitude (mm) against speed (km/h), with the nonlinear and linear critical speeds.

        Filled markers joined by a line: sustained hunting; open markers: motion that dies away.
        Each critical speed is a vertical line labelled with its value at the top of the axes. With a
        ``branch``, the whole diagram: the continued branch of cycles over the ramp's points, its
        stable part solid, its unstable part dashed and its fold marked.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        linear_critical_speed : float, optional
            The linear critical speed of the same vehicle, m/s (in (0,
            :data:`~raildyn.constants.MAXIMUM_SPEED`]; from
            :func:`~raildyn.stability.linear.critical_speed`), drawn as a dashed line; left out if None.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this diagram in place (a
            widget's redraw), and a critical speed that is absent is hidden.
        branch : LimitCycleBranch, optional
            The branch of limit cycles of the same vehicle, from
            :func:`~raildyn.stability.continuation.limit_cycle_branch`, drawn by its own
            :meth:`~raildyn.stability.continuation.LimitCycleBranch.plot` on the same axes.

        Returns
        -------
        dict
            The artists: ``cycles`` and ``decaying`` (``Line2D``), and the vertical lines
            ``nonlinear`` and ``linear`` with their labels ``nonlinear_text`` and ``linear_text``
            (hidden where the nonlinear critical speed is infinite or no linear one is given); with
            a branch, ``branch``, the dict of its artists.
        """
        import matplotlib

        from raildyn import plots

        V, amp, hunt = 3.6 * self.speeds, 1e3 * self.amplitudes, self.hunting
        marks = {"nonlinear": 3.6 * self.nonlinear_critical_speed, "linear": np.nan}
        if linear_critical_speed is not None:
            marks["linear"] = 3.6 * _checks.speed("linear_critical_speed", linear_critical_speed)
        if artists is None:
            ax = plots.axes_or_new(ax)
            with matplotlib.rc_context(plots.STYLE):
                artists = {
                    "cycles": ax.plot([], [], "o-", color=plots.COLORS[0], label="limit cycle")[0],
                    "decaying": ax.plot(
                        [], [], "o", mfc="none", color=plots.COLORS[0], label="motion dies away"
                    )[0],
                }
                for key, colour, style, name in (
                    ("linear", 1, "--", "linear"),
                    ("nonlinear", 2, ":", "nonlinear"),
                ):
                    artists[key] = ax.axvline(
                        0.0, color=plots.COLORS[colour], ls=style, label=f"{name} $V_c$"
                    )
                    artists[f"{key}_text"] = ax.text(
                        0.0, 1.0, "", transform=ax.get_xaxis_transform(), color=plots.COLORS[colour],
                        ha="center", va="bottom", fontsize="small",
                    )  # fmt: skip
                ax.set_xlabel("speed (km/h)")
                ax.set_ylabel("amplitude of $y$ (mm)")
                ax.set_xlim(V.min() - 0.05 * np.ptp(V) - 1.0, V.max() + 0.05 * np.ptp(V) + 1.0)
                ax.set_ylim(0.0, 1.1 * max(float(amp.max()), 1.0))
                ax.legend(loc="center right")
        else:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
        if branch is not None:
            # Known by what it does, not by its class: continuation builds on this module, not the reverse.
            if not (
                callable(getattr(branch, "plot", None))
                and isinstance(getattr(branch, "amplitudes", None), np.ndarray)
            ):
                raise TypeError(
                    f"branch must be a LimitCycleBranch (limit_cycle_branch), got {type(branch).__name__}"
                )
            artists["branch"] = branch.plot(artists["cycles"].axes, artists=artists.get("branch"))
            top = 1.1 * max(float(amp.max()), 1e3 * float(branch.amplitudes.max()), 1.0)
            artists["cycles"].axes.set_ylim(0.0, top)
        artists["cycles"].set_data(V[hunt], amp[hunt])
        artists["decaying"].set_data(V[~hunt], amp[~hunt])
        for key, value in marks.items():
            shown = bool(np.isfinite(value))
            artists[key].set_visible(shown)
            artists[f"{key}_text"].set_visible(shown)
            if shown:
                artists[key].set_xdata([value, value])
                artists[f"{key}_text"].set_x(value)
                artists[f"{key}_text"].set_text(f"{value:.0f} km/h")
        return artists


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
    rtol: float = 1e-6,
    method: str = "RK45",
    engine: str = "auto",
) -> BifurcationDiagram:
    """Limit-cycle amplitude along a speed ramp-down, and the nonlinear critical speed.

    The highest speed starts from a large lateral displacement of the first
    wheelset; each lower speed starts from the final state of the one above
    (a slow ramp-down in steps), so the branch of large limit cycles is
    followed below the linear critical speed as far as it exists (a
    subcritical Hopf bifurcation). Where the branch ends, ``refine`` bisection
    steps between the last hunting and the first decaying speed locate the
    nonlinear critical speed.

    Parameters
    ----------
    model : NonlinearModel
        The nonlinear model, as for :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude`.
    speeds : array_like, shape (n_speeds,)
        Speeds of the ramp, m/s, each in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`], in any order:
        they are run from the highest down.
    initial_displacement : float
        Starting lateral displacement of the first wheelset at the highest speed (and after
        a speed where the motion died away), m, either side, 0 < |y₀| ≤ 0.05 m (as for
        :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude`).
    duration : float
        Simulated time at each speed, s, in [0.001, 120]: at least four periods of the hunting,
        so that each quarter of the run compared holds one
        (:meth:`~raildyn.stability.nonlinear.LimitCycle.hunting`).
    max_step : float
        Largest solver step, s (> 0).
    threshold : float
        Amplitude of the oscillation below which the motion counts as decayed, m, in (0, 0.05]
        (no wheelset on the rails moves further).
    refine : int
        Number of bisection steps on the nonlinear critical speed, in [0, 30] (30 halve the
        bracket a billion times).
    progress : bool
        Show a progress bar.
    rtol : float
        Relative tolerance of the solver, in [1e-13, 1) (as for
        :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude`). Where friction makes
        the model stiff, an explicit method's steps are set by stability rather than accuracy,
        and a coarse tolerance costs little accuracy.
    method : str
        The integration method, as for :func:`~raildyn.stability.nonlinear.simulate`
        (``"BDF"`` for a model made stiff by friction).
    engine : str
        ``"auto"``, ``"compiled"`` or ``"scipy"``, as for :func:`~raildyn.stability.nonlinear.simulate`.

    Returns
    -------
    BifurcationDiagram
        Amplitudes (m), frequencies (Hz) and hunting flags along the ramp, and the nonlinear
        critical speed (m/s); draw it with :meth:`BifurcationDiagram.plot`.

    Raises
    ------
    SolverError
        If an integration fails.

    Notes
    -----
    Where the branch of cycles ends in a fold, a run just below the fold lingers near the
    lost cycle for a time that grows without bound as the speed nears the fold, and may pass
    for hunting; a decaying motion of two modes can also beat, its amplitude rising for a
    while. Long runs place the fold closely; a short run's ramp should keep its speeds a
    step apart that each run judges with a margin (``refine=0``), the fold then lying within
    one step below the nonlinear critical speed found.
    """
    return bifurcation_diagrams(
        [model], speeds, initial_displacement=initial_displacement, duration=duration, max_step=max_step,
        threshold=threshold, refine=refine, progress=progress, rtol=rtol, method=method, engine=engine,
    )[0]  # fmt: skip


def bifurcation_diagrams(
    models,
    speeds,
    *,
    initial_displacement: float = 12.0e-3,
    duration: float = 8.0,
    max_step: float = 2.0e-3,
    threshold: float = 2.0e-4,
    refine: int = 4,
    progress: bool = True,
    rtol: float = 1e-6,
    method: str = "RK45",
    engine: str = "auto",
) -> list[BifurcationDiagram]:
    """The bifurcation diagrams of several models at once, their ramps run side by side.

    Each model's diagram is that of :func:`~raildyn.stability.bifurcation.bifurcation_diagram`; the
    compiled engine advances all models at each speed of the ramp, and at each bisection step, as
    one batch (in parallel threads). For a family of vehicles, such as one car with a range of
    conicities or of yaw stiffnesses.

    Parameters
    ----------
    models : sequence of NonlinearModel
        At least one; all with the same ``state_size`` and ``lateral_index``.
    speeds, initial_displacement, duration, max_step, threshold, refine, progress, rtol, method, engine
        As for :func:`~raildyn.stability.bifurcation.bifurcation_diagram`, the same for every model.

    Returns
    -------
    list of BifurcationDiagram
        One per model, in their order.

    Raises
    ------
    SolverError
        If an integration fails.
    """
    V = np.sort(_checks.speeds("speeds", speeds, low=_MIN_RUN_SPEED, low_open=False))[::-1]
    y_start = _displacement(initial_displacement)
    T = _duration("duration", duration)
    h = positive("max_step", max_step)
    scalar("threshold", threshold, low=0.0, low_open=True, high=_MAX_DISPLACEMENT)
    refine = integer("refine", refine, low=0, high=30)
    r = _checks.tolerance("rtol", rtol)
    method, engine = _method(method), _engine_choice(engine)
    if isinstance(models, (str, bytes)) or not isinstance(models, (list, tuple)) or not models:
        raise TypeError(f"models must be a non-empty list of nonlinear models, got {models!r:.80}")
    first = [_model(m) for m in models]
    for i, m in enumerate(first[1:], start=1):
        if (m.state_size, m.lateral_index) != (first[0].state_size, first[0].lateral_index):
            raise ValueError(
                f"models[{i}] must have the state_size and lateral_index of models[0] "
                f"({first[0].state_size}, {first[0].lateral_index}), got ({m.state_size}, {m.lateral_index})"
            )
    items = V
    if _checks.flag("progress", progress):
        items = progress_bar(V, desc="bifurcation diagram (ramp-down)")
    k = len(models)
    cycles = [[] for _ in range(k)]
    states = [_displaced(first[0], y_start) for _ in range(k)]
    for v in items:
        for i, cycle in enumerate(_cycles(first, [v] * k, states, T, h, r, method, engine)):
            cycles[i].append(cycle)
            # Continue the branch from the cycle; after a decay, start again displaced.
            states[i] = cycle.state if cycle.hunting(threshold) else _displaced(first[0], y_start)
    hunting = [np.array([c.hunting(threshold) for c in row]) for row in cycles]
    # The nonlinear critical speed: bisect between each model's last hunting and first decaying speed.
    vnl = np.full(k, np.inf)
    brackets = {}
    for i in range(k):
        if hunting[i].any():
            j = int(np.flatnonzero(hunting[i]).max())
            vnl[i] = V[j]
            if j + 1 < V.size and not hunting[i][j + 1]:
                brackets[i] = [V[j], V[j + 1], cycles[i][j].state]
    for _ in range(refine if brackets else 0):
        order = sorted(brackets)
        mids = [0.5 * (brackets[i][0] + brackets[i][1]) for i in order]
        trials = _cycles(
            [first[i] for i in order],
            mids, [brackets[i][2] for i in order], T, h, r, method, engine,
        )  # fmt: skip
        for i, mid, trial in zip(order, mids, trials, strict=True):
            if trial.hunting(threshold):
                brackets[i][0], brackets[i][2] = mid, trial.state
            else:
                brackets[i][1] = mid
    for i, (high, _, _) in brackets.items():
        vnl[i] = float(high)
    return [
        BifurcationDiagram(
            V,
            np.array([c.amplitude for c in cycles[i]]),
            np.array([c.frequency_hz for c in cycles[i]]),
            hunting[i],
            float(vnl[i]),
            threshold,
        )
        for i in range(k)
    ]


@dataclass(frozen=True)
class PeriodicOrbit:
    """A periodic solution of a nonlinear model found by shooting.

    Attributes
    ----------
    speed : float
        m/s (> 0).
    period : float
        T, s, in [0.001, 120] (as the guess of :func:`periodic_orbit`).
    state : ndarray
        A point of the orbit, where the first wheelset's lateral velocity is zero.
    amplitude : float
        Half the peak-to-peak lateral displacement of the first wheelset over one period, m (≥ 0).
    multipliers : complex ndarray
        Floquet multipliers (eigenvalues of the monodromy matrix), one per state entry; the
        orbit is stable when all but the trivial one (≈ 1) lie inside the unit circle.
    residual : float
        Norm of φ_T(x₀) − x₀ at the solution, in units of the state (≥ 0).
    """

    speed: float
    period: float
    state: np.ndarray
    amplitude: float
    multipliers: np.ndarray
    residual: float

    def __post_init__(self):
        _checks.speed("speed", self.speed)
        _duration("period", self.period)
        n = array("state", self.state, ndim=1, allow_empty=False).size
        _checks.nonnegative("amplitude", self.amplitude)
        array("multipliers", self.multipliers, shape=(n,), dtype=complex)
        _checks.nonnegative("residual", self.residual)

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
    model : NonlinearModel
        A nonlinear model (:class:`~raildyn.wheelset.NonlinearLateral`,
        :class:`~raildyn.wheelset.NonlinearWheelset`).
    speed : float
        Speed V, m/s, in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`] (below walking pace the creep
        damping 2f/V makes the equations too stiff to run).
    state : array_like, shape (state_size,)
        Guess of a point on the orbit (for instance the ``state`` at the end of a
        :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude` run), in the units of the model's
        state: finite, not all zero (the centred state is the trivial solution).
    period : float
        Guess of T, s, in [0.001, 120] (1 / ``frequency_hz`` of the settled motion).
    tol : float
        Convergence on the relative size of the Newton step (dimensionless, > 0).
    max_iter : int
        Largest number of Newton steps, in [1, 100].
    rtol : float
        Relative tolerance of the DOP853 integrations, in [1e-13, 1).

    Returns
    -------
    PeriodicOrbit
        The period (s), a point of the orbit, its amplitude (m), Floquet multipliers and the
        residual of the periodicity condition.

    Raises
    ------
    SolverError
        If an integration fails (see :func:`~raildyn.stability.nonlinear.simulate`), Newton's
        method does not converge in ``max_iter`` steps, or the integrations together take more
        than 100 000 evaluations of the right-hand side (four times what a converging shooting
        needs: the work is bounded to a few seconds).

    Notes
    -----
    The centred state is a trivial solution of the same equations: a guess
    far from any cycle may converge to it (amplitude 0).
    """
    V = _checks.speed("speed", speed, low=_MIN_RUN_SPEED, low_open=False)
    T = _duration("period", period)
    positive("tol", tol)
    iterations = integer("max_iter", max_iter, low=1, high=100)
    rtol = _checks.tolerance("rtol", rtol)
    m = _model(model)
    rhs = partial(m.rhs, speed=V)
    n = m.state_size
    x = array("state", state, shape=(n,)).copy()
    if not x.any():
        raise ValueError("state must not be all zero: the centred state is the trivial solution, no orbit")
    iy = m.lateral_index
    iv = iy + n // 2  # the lateral velocity of the same wheelset
    free = [i for i in range(n) if i != iv]

    def section(t, z):
        return z[iv]

    section.direction = -1.0  # a maximum of the lateral displacement
    # Move the guess along its own trajectory to the section ẏ = 0, so that it meets the phase condition.
    from raildyn.integrators.runner import EvaluationBudget

    budget = EvaluationBudget(_SHOOTING_EVALUATIONS)  # the whole shooting's work, shared by each run below
    sol = _integrate(rhs, 2.0 * T, x, "DOP853", rtol, 1e-12, V, budget=budget, events=section)
    if sol.t_events[0].size:
        x = sol.y_events[0][0].copy()
    x[iv] = 0.0

    def flow(starts, t_end):
        """φ_t(x₀) for each column of ``starts``, integrated as one system.

        The columns share one sequence of adaptive steps, so the differences between
        neighbouring trajectories that the finite differences below take carry the
        truncation error of the perturbation, not the noise of two step sequences.
        """
        k = starts.shape[1]

        def rhs(t, z):
            return m.rhs(t, z.reshape(n, k), V).reshape(-1)

        sol = _integrate(rhs, t_end, starts.reshape(-1), "DOP853", rtol, 1e-12, V, budget=budget)
        return sol.y[:, -1].reshape(n, k)

    # Finite-difference steps relative to each entry, with a floor so that an entry near 0 (such
    # as the lateral velocity on the section) is not perturbed below the integration noise.
    scale = np.maximum(np.abs(x), 1e-2 * np.abs(x).max())
    h = 1e-5 * scale
    for _ in range(iterations):
        starts = np.column_stack([x] + [x + h[i] * np.eye(n)[i] for i in free])
        ends = flow(starts, T)
        end, residual = ends[:, 0], ends[:, 0] - x
        J = np.empty((n, n))
        J[:, :-1] = (ends[:, 1:] - starts[:, 1:] - residual[:, None]) / h[free]
        J[:, -1] = rhs(T, end)  # d/dT of φ_T(x₀)
        try:
            step = np.linalg.solve(J, -residual)
        except np.linalg.LinAlgError:
            raise SolverError(f"shooting at V = {V:.6g} m/s met a singular Jacobian") from None
        x[free] += step[:-1]
        T += step[-1]
        if not 0.0 < T <= _MAX_DURATION:
            raise SolverError(f"shooting at V = {V:.6g} m/s drove the period to {T:.6g} s, out of (0, 120]")
        if np.linalg.norm(step[:-1] / scale[free]) < tol and abs(step[-1]) < tol * T:
            break
    else:
        raise SolverError(f"shooting did not converge in {max_iter} iterations at V = {V:.6g} m/s")
    # Monodromy matrix (central differences, all trajectories on one step sequence) and one period of
    # the orbit, for the multipliers and the amplitude.
    shifts = np.diag(h)
    ends = flow(np.column_stack([x[:, None] + shifts, x[:, None] - shifts, x]), T)
    monodromy = (ends[:, :n] - ends[:, n : 2 * n]) / (2 * h)
    end = ends[:, -1]
    # One period, read at 400 points from the solver's dense output (DOP853's own interpolant).
    sol = _integrate(rhs, T, x, "DOP853", rtol, 1e-12, V, dense_output=True)
    lateral = sol.sol(np.linspace(0.0, T, 401))[iy]
    return PeriodicOrbit(
        V,
        float(T),
        x,
        float(0.5 * (lateral.max() - lateral.min())),
        np.linalg.eigvals(monodromy),
        float(np.linalg.norm(end - x)),
    )
