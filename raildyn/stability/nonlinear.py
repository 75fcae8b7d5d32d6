"""Nonlinear hunting (book chapter 7): time runs, limit cycles, the bifurcation diagram, periodic orbits.

The nonlinear models (:class:`raildyn.wheelset.NonlinearWheelset`,
:class:`raildyn.wheelset.NonlinearLateral`) expose ``rhs(t, state)``; these
functions integrate them and measure the steady hunting. RK45 runs on a compiled
engine (``raildyn.stability._engine``: the same equations in numba, many speeds or
vehicles at once, on the compiled Dormand–Prince of :mod:`raildyn.integrators.runner`)
wherever it holds the model, and on ``scipy.integrate.solve_ivp`` (through the same runner,
bounded alike) otherwise or when asked (``engine="scipy"``, the reference the tests hold the
engine to). Every run is bounded by the runner's one budget rule and fails by its one rule.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import array, integer, positive, scalar
from raildyn._progress import progress_bar
from raildyn.errors import SolverError

__all__ = [
    "BifurcationDiagram",
    "LimitCycle",
    "NonlinearRun",
    "PeriodicOrbit",
    "bifurcation_diagram",
    "bifurcation_diagrams",
    "limit_cycle_amplitude",
    "periodic_orbit",
    "simulate",
]


# ---------------------------------------------------------------------------
# Nonlinear hunting


@dataclass(frozen=True)
class NonlinearRun:
    """A time history of a nonlinear lateral model.

    Attributes
    ----------
    speed : float
        m/s (> 0).
    t : ndarray, (n_t,)
        s, strictly increasing.
    states : ndarray, (state_size, n_t)
        The model's state at each time, in its units (m, rad, m/s, rad/s).
    lateral_index : int
        Row of the first wheelset's lateral displacement.
    """

    speed: float
    t: np.ndarray
    states: np.ndarray
    lateral_index: int

    def __post_init__(self):
        _checks.speed("speed", self.speed)
        n_t = _checks.time_grid("t", self.t).size
        rows = array("states", self.states, shape=(None, n_t), allow_empty=False).shape[0]
        integer("lateral_index", self.lateral_index, low=0, high=rows - 1)

    @property
    def lateral(self) -> np.ndarray:
        """The first wheelset's lateral displacement, m."""
        return self.states[self.lateral_index]

    def plot(self, ax=None, *, flange_clearance: float | None = None) -> dict:
        """Draw the first wheelset's lateral displacement (mm) against time, with the flangeway clearance.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default.
        flange_clearance : float, optional
            e, the flangeway clearance, m (> 0); marked at ±e when given.

        Returns
        -------
        dict
            The artists: ``line`` and, with a clearance, ``flange`` (two lines).
        """
        import matplotlib

        from raildyn import plots

        if flange_clearance is not None:
            positive("flange_clearance", flange_clearance)
        ax = plots.axes_or_new(ax)
        out = {}
        with matplotlib.rc_context(plots.STYLE):
            (out["line"],) = ax.plot(self.t, 1e3 * self.lateral, color=plots.COLORS[0])
            if flange_clearance is not None:
                d = 1e3 * flange_clearance
                out["flange"] = [
                    ax.axhline(sign * d, color=plots.COLORS[1], ls="--", lw=1) for sign in (1, -1)
                ]
                ax.text(0.05, d + 0.5, "flange contact", color=plots.COLORS[1])
            ax.set_xlabel("time $t$ (s)")
            ax.set_ylabel("lateral displacement $y$ (mm)")
            ax.set_xlim(0, self.t[-1])
        return out


def simulate(
    model,
    speed,
    initial_state,
    duration,
    *,
    max_step: float = 2.0e-3,
    rtol: float = 1.0e-6,
    method: str = "RK45",
    engine: str = "auto",
):
    """Integrate a nonlinear lateral model at speed V from a state, by RK45 or another scipy method.

    The state is sampled every ``min(max_step, 1 ms)/2`` (from the solver's own interpolant), so
    that every run is read on one uniform grid whichever engine took its steps.

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        ``at_speed(V)`` gives one with ``rhs``, ``state_size`` and ``lateral_index``.
    speed : float
        V, m/s, in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`] (below walking pace the creep damping
        2f/V makes the equations too stiff to run; hunting sets in at tens of m/s).
    initial_state : array_like, (state_size,)
        In the units of the model's state (finite).
    duration : float
        s, in [0.001, 120]: two minutes of running, where hunting settles within seconds.
    max_step : float
        Largest step, s (> 0).
    rtol : float
        Relative tolerance of the integration, in [1e-13, 1).
    method : str
        The method of ``scipy.integrate.solve_ivp``: ``"RK45"`` (default), ``"DOP853"``,
        ``"BDF"``, ``"Radau"`` or ``"LSODA"``. Friction smoothed over a small velocity scale
        (the freight car's wedges and centre plates) makes a model stiff: an explicit method's
        steps are then held to about 1 ms by stability, while ``"BDF"``, whose steps follow the
        accuracy asked for, needs about a tenth of the evaluations (give it a ``max_step`` of a
        fraction of the period, not the explicit methods' 2 ms).
    engine : str
        Who runs RK45: ``"compiled"``, the numba engine (``raildyn.stability._engine``, the
        same steps as scipy's RK45 at some hundred times the speed); ``"scipy"``,
        ``scipy.integrate.solve_ivp`` on the model's ``rhs`` (the reference the engine is tested
        against); ``"auto"`` (default), the engine wherever it holds the model (not nonlinear
        suspension elements, whose laws are Python functions) and the method is RK45, else scipy.

    Returns
    -------
    NonlinearRun

    Raises
    ------
    SolverError
        If the integration fails: a step size that underflows, a state that becomes
        non-finite, or more than 10⁶ evaluations of the right-hand side (raise
        ``max_step`` or shorten ``duration``).

    Examples
    --------
    >>> from raildyn.wheelset import NonlinearWheelset, Wheelset
    >>> run = simulate(NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)), 60.0,
    ...                [1e-3, 0.0, 0.0, 0.0], 0.5)
    >>> run.states.shape[0], float(run.t[-1])
    (4, 0.5)
    """
    V = _checks.speed("speed", speed, low=_MIN_RUN_SPEED, low_open=False)
    T = _duration("duration", duration)
    h = positive("max_step", max_step)
    r = _checks.tolerance("rtol", rtol)
    method, engine = _method(method), _engine_choice(engine)
    m = _at_speed(model, V)
    y0 = array("initial_state", initial_state, shape=(m.state_size,))
    t = _samples(T, h, m.state_size)
    (states,), _ = _runs([m], [V], [y0], T, h, r, method, engine, rows=None)
    return NonlinearRun(V, t, states, m.lateral_index)


_METHODS = ("RK45", "DOP853", "BDF", "Radau", "LSODA")  # of scipy.integrate.solve_ivp


def _method(value) -> str:
    """The name of a ``solve_ivp`` method, one of :data:`_METHODS`."""
    return _checks.choice("method", value, _METHODS)


_ENGINES = ("auto", "compiled", "scipy")


def _engine_choice(value) -> str:
    """Who integrates: one of :data:`_ENGINES`."""
    return _checks.choice("engine", value, _ENGINES)


def _samples(duration: float, max_step: float, rows: int = 1) -> np.ndarray:
    """The uniform times at which a run is read, s: every min(max_step, 1 ms)/2.

    Half a millisecond reads the peak of a 15 Hz oscillation (the top of the hunting band) to
    3e-4 of its amplitude: 1 − cos(π f Δt).
    """
    spacing = 0.5 * min(max_step, 1.0e-3)
    n = _checks.samples(
        "max_step", max_step, duration, spacing, per_sample=rows
    )  # before anything is allocated
    return np.linspace(0.0, duration, n)


def _runs(
    models, speeds, starts, duration: float, max_step: float, rtol: float, method: str, engine: str, rows
):
    """Integrate each model (at its speed, ``speeds``) from its start over (0, duration), on the same samples.

    ``rows`` picks the state rows to keep (None: all). The compiled engine runs the models as
    one batch where it can (see :func:`simulate`'s ``engine``); scipy runs them one by one.
    Returns one array (rows, samples) per model and the states at ``duration``.
    """
    from raildyn.integrators import runner  # here: numba loads only when a run needs it
    from raildyn.stability import _engine

    kept = models[0].state_size if rows is None else len(rows)
    t = _samples(duration, max_step, kept * len(models))
    packed = None
    if engine != "scipy" and method == "RK45":
        try:
            packed = [_engine.pack(m) for m in models]
        except _engine.NotCompiled as why:
            if engine == "compiled":
                raise ValueError(
                    f"engine 'compiled' cannot run this model: {why}; use engine='scipy'"
                ) from None
    elif engine == "compiled":
        raise ValueError(f"engine 'compiled' runs method 'RK45' only, got method {method!r}")
    if packed is None:
        out, ends = [], []
        for m, v, y0 in zip(models, speeds, starts, strict=True):
            sol = _integrate(m.rhs, duration, y0, method, rtol, 1e-9, v, max_step=max_step, t_eval=t)
            out.append(sol.y if rows is None else sol.y[rows])
            ends.append(sol.y[:, -1].copy())
        return out, ends
    runs = runner.dormand_prince_batch(
        _engine.lateral_rhs, _engine.batch(packed), np.array(starts), t, rtol=rtol, atol=1e-9,
        max_step=max_step, rows=rows, budget=_MAX_EVALUATIONS, labels=[_label(v) for v in speeds],
    )  # fmt: skip
    return [run.y for run in runs], [run.end for run in runs]


def _label(speed: float) -> str:
    """What a run is, for the runner's failure message."""
    return f"the integration at V = {speed:.6g} m/s"


# The slowest speed a nonlinear run takes, m/s: the creep damping 2f/V of a loaded wheel grows without
# bound as V falls (some 2 × 10⁷ N·s/m at 1 m/s), so below walking pace the equations turn so stiff that
# a run spends its whole budget of evaluations on the first fraction of a second; hunting, the
# business of these runs, sets in at tens of metres a second.
_MIN_RUN_SPEED = 1.0
_MIN_DURATION = 1.0e-3  # s, the shortest run (and period) asked for
_MAX_DURATION = 120.0  # s, the longest run (and period) asked for: hunting settles within seconds
_MAX_EVALUATIONS = 1_000_000  # of a right-hand side in one integration: the bound on a run's work
# Evaluations of the (batched) right-hand side one periodic_orbit may make in all its integrations: a
# shooting that converges takes some 14 000 (a wheelset) to 25 000 (a bogie or a car, about 1.5 s), so
# four times that is ample, and a hopeless guess (a period of 100 s) fails in a few seconds instead of
# running each of its integrations up to _MAX_EVALUATIONS (about 50 s for a car).
_SHOOTING_EVALUATIONS = 100_000


def _duration(name: str, value) -> float:
    """A run's length (or a period), s, in [1 ms, 120 s]: shorter, no motion of a vehicle shows
    (its fastest modes take some 10 ms a cycle), and the measures of a run read nothing."""
    return scalar(name, value, low=_MIN_DURATION, high=_MAX_DURATION)


def _at_speed(model, speed: float):
    """``model.at_speed(speed)``, checked to offer ``rhs``, ``state_size`` and ``lateral_index``."""
    _checks.not_a_class("model", model, "a nonlinear model")
    if not callable(getattr(model, "at_speed", None)):
        raise TypeError(
            "model must be a nonlinear model with at_speed(V) (NonlinearWheelset, NonlinearLateral), "
            f"got {model!r:.80} of type {type(model).__name__}"
        )
    m = model.at_speed(speed)
    if not callable(getattr(m, "rhs", None)):
        raise TypeError(f"model.at_speed(V) must give a model with rhs(t, state), got {type(m).__name__}")
    integer("model state_size", m.state_size, low=1)
    integer("model lateral_index", m.lateral_index, low=0, high=m.state_size - 1)
    return m


def _integrate(rhs, duration: float, y0, method: str, rtol: float, atol: float, speed: float, **options):
    """``rhs`` over (0, duration) through :func:`raildyn.integrators.runner.solve_ivp`: bounded by
    ``budget`` (default :data:`_MAX_EVALUATIONS`), failing with :class:`SolverError`."""
    from raildyn.integrators import runner

    options.setdefault("budget", _MAX_EVALUATIONS)
    return runner.solve_ivp(
        rhs, (0.0, duration), y0, method=method, rtol=rtol, atol=atol, label=_label(speed), **options
    )


# The band of hunting frequencies, Hz. Hunting is the kinematic oscillation of the wheelsets and trucks,
# f = V/L with a wavelength L from about 5 m (a free wheelset on a steep cone) to some 40 m (a stiff
# bogie of long wheelbase), or a lateral mode of the car body (0.5 to 2 Hz) that it drives; over the
# speeds at which railway vehicles hunt, roughly 10 to 100 m/s, that spans about 0.3 to 15 Hz. Slower
# motion is a drift (friction letting a wheelset creep, or holding it off centre), faster one a chatter
# of friction or of the flange, not hunting.
_HUNTING_BAND_HZ = (0.3, 15.0)
# Amplitude over the last quarter of a run against that over the quarter before, above which the motion
# counts as no longer decaying.
_SUSTAINED_GROWTH = 0.95
# m: below this the crossings of the trend line are the solver's noise, and no frequency is read.
_MEASURABLE_OSCILLATION = 1.0e-6


@dataclass(frozen=True)
class LimitCycle:
    """Steady lateral oscillation of a nonlinear model at one speed.

    The measure is taken over the last half of the run, split in two quarters, on the first
    wheelset's lateral displacement y(t). Its *trend* is the least-squares straight line through
    y over the last half: a drift, or an offset at which friction holds the wheelset, is in the
    trend and not in the oscillation about it.

    Attributes
    ----------
    speed : float
        m/s (> 0).
    amplitude : float
        Half the peak-to-peak lateral displacement of the first wheelset over
        the last quarter of the run, m (≥ 0).
    frequency_hz : float
        Frequency of the oscillation about the trend, Hz (≥ 0), from the upward crossings of the
        trend line over the last half of the run (the crossing times interpolated between
        samples); 0 when there is no oscillation: fewer than two crossings, or an oscillation
        below 1 µm.
    growth : float
        Amplitude over the last quarter divided by that over the quarter before (≥ 0):
        below 1 while the motion is still dying away.
    state : ndarray
        The state at the end of the run (to start the next speed of a ramp from).
    oscillation : float
        Half the peak-to-peak, over the last quarter of the run, of the lateral displacement less
        its trend, m (≥ 0; at most about ``amplitude``): the part of the motion that oscillates.
    duration : float
        Length of the run, s (> 0): each quarter compared lasts ``duration / 4``.
    """

    speed: float
    amplitude: float
    frequency_hz: float
    growth: float
    state: np.ndarray
    oscillation: float
    duration: float

    def __post_init__(self):
        _checks.speed("speed", self.speed)
        for name in ("amplitude", "frequency_hz", "growth"):
            _checks.nonnegative(name, getattr(self, name))
        array("state", self.state, ndim=1, allow_empty=False)
        _checks.nonnegative("oscillation", self.oscillation)
        _duration("duration", self.duration)

    @property
    def cycles(self) -> float:
        """Periods of the oscillation in each quarter of the run compared: frequency_hz × duration / 4."""
        return self.frequency_hz * self.duration / 4.0

    def hunting(self, threshold: float = 2.0e-4) -> bool:
        """Whether the motion is a sustained oscillation: above ``threshold``, no longer decaying, periodic.

        Parameters
        ----------
        threshold : float
            Amplitude of the oscillation below which the motion counts as decayed, m (> 0;
            default 0.2 mm).

        Returns
        -------
        bool
            True when all of:

            * ``oscillation > threshold``: the motion about its trend, so that a drift or a
              friction-held offset, however large, is not taken for a cycle;
            * ``growth > 0.95``: no longer dying away;
            * ``0.3 Hz ≤ frequency_hz ≤ 15 Hz``: the band of hunting, V/L over the kinematic
              wavelengths L of wheelsets and trucks (about 5 to 40 m) at the speeds where
              vehicles hunt; slower motion is a drift, faster a chatter;
            * ``cycles ≥ 1``: each quarter compared holds a whole period, so that its half
              peak-to-peak is the cycle's amplitude, not a part of one swing, and ``growth``
              compares like with like (a run too short for its frequency is not judged hunting).
        """
        low, high = _HUNTING_BAND_HZ
        return (
            self.oscillation > positive("threshold", threshold)
            and self.growth > _SUSTAINED_GROWTH
            and low <= self.frequency_hz <= high
            and self.cycles >= 1.0
        )


def _measure(t: np.ndarray, x: np.ndarray, duration: float) -> dict:
    """The fields of :class:`LimitCycle` measured on a run's lateral displacement ``x`` at times ``t``."""
    last = t >= 0.75 * duration
    before = (t >= 0.5 * duration) & ~last
    amplitude = 0.5 * np.ptp(x[last])
    previous = 0.5 * np.ptp(x[before]) if before.any() else 0.0
    growth = amplitude / previous if previous > 0 else 1.0
    # The oscillation about the trend, the least-squares line through the last half.
    half = t >= 0.5 * duration
    th, xh = t[half], x[half]
    tc = th - th.mean()
    spread = tc @ tc
    slope = (tc @ xh) / spread if spread > 0 else 0.0
    r = xh - xh.mean() - slope * tc
    oscillation = 0.5 * np.ptp(r[th >= 0.75 * duration])
    frequency_hz = 0.0
    if oscillation > _MEASURABLE_OSCILLATION:
        up = np.flatnonzero((r[:-1] < 0.0) & (r[1:] >= 0.0))
        if up.size >= 2:
            # The crossing times, interpolated linearly between the samples either side.
            crossing = th[up] - r[up] * (th[up + 1] - th[up]) / (r[up + 1] - r[up])
            frequency_hz = (up.size - 1) / (crossing[-1] - crossing[0])
    return {
        "amplitude": float(amplitude),
        "frequency_hz": float(frequency_hz),
        "growth": float(growth),
        "oscillation": float(oscillation),
    }


def limit_cycle_amplitude(
    model,
    speed,
    *,
    initial_displacement: float = 12.0e-3,
    initial_state=None,
    duration: float = 8.0,
    max_step: float = 2.0e-3,
    rtol: float = 1e-6,
    method: str = "RK45",
    engine: str = "auto",
) -> LimitCycle:
    """Amplitude of the steady hunting of a nonlinear model at one speed, by direct integration.

    Starts from a lateral displacement of the first wheelset (or from
    ``initial_state``) and integrates ``duration`` seconds (RK45 by default); the
    amplitude is taken over the last quarter of the run, the frequency over the
    last half (see :class:`LimitCycle`). :meth:`LimitCycle.hunting` judges the motion
    only when each quarter holds a whole period: give a slow motion a run of at least
    four of its periods.

    Parameters
    ----------
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        The nonlinear model; ``at_speed(V)`` gives one with ``rhs``, ``state_size`` and
        ``lateral_index``.
    speed : float
        Speed V, m/s, in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`] (below walking pace the creep
        damping 2f/V makes the equations too stiff to run).
    initial_displacement : float
        Starting lateral displacement of the first wheelset, m, either side, 0 < |y₀| ≤
        0.05 m: the centred state never moves, and no wheelset on the rails is further off
        (default 12 mm: beyond the flangeway clearance, so that a large limit cycle is
        found where one exists).
    initial_state : array_like, optional
        Full starting state (finite), instead of ``initial_displacement``.
    duration : float
        Simulated time, s, in [0.001, 120].
    max_step : float
        Largest solver step, s (> 0).
    rtol : float
        Relative tolerance of the solver, in [1e-13, 1).
    method : str
        The integration method, as for :func:`~raildyn.stability.nonlinear.simulate`
        (``"BDF"`` for a model made stiff by friction).
    engine : str
        ``"auto"``, ``"compiled"`` or ``"scipy"``, as for :func:`~raildyn.stability.nonlinear.simulate`.

    Returns
    -------
    LimitCycle
        Amplitude (m), oscillation about the trend (m), frequency (Hz), growth over the last
        two quarters, final state and the run's duration (s).

    Raises
    ------
    SolverError
        If the integration fails (see :func:`~raildyn.stability.nonlinear.simulate`).

    Examples
    --------
    The suspended wheelset of chapter 5 at 60 m/s, above its linear critical speed of
    54.6 m/s: from 12 mm it settles on a limit cycle of about 10 mm at 5.7 Hz.

    >>> from raildyn.wheelset import NonlinearWheelset, Wheelset
    >>> model = NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))
    >>> cycle = limit_cycle_amplitude(model, 60.0, duration=4.0)
    >>> cycle.hunting(), round(1e3 * cycle.amplitude, 1), round(cycle.frequency_hz, 1)
    (True, 10.3, 5.7)
    """
    V = _checks.speed("speed", speed, low=_MIN_RUN_SPEED, low_open=False)
    T = _duration("duration", duration)
    h = positive("max_step", max_step)
    r = _checks.tolerance("rtol", rtol)
    method, engine = _method(method), _engine_choice(engine)
    y_start = _displacement(initial_displacement)
    m = _at_speed(model, V)
    if initial_state is None:
        y0 = _displaced(m, y_start)
    else:
        y0 = array("initial_state", initial_state, shape=(m.state_size,))
    (cycle,) = _cycles([m], [V], [y0], T, h, r, method, engine)
    return cycle


def _displaced(model, displacement: float) -> np.ndarray:
    """The model's state at rest with its first wheelset displaced laterally."""
    y0 = np.zeros(model.state_size)
    y0[model.lateral_index] = displacement
    return y0


def _cycles(models, speeds, starts, duration, max_step, rtol, method, engine) -> list[LimitCycle]:
    """The :class:`LimitCycle` of each model (at its speed, ``speeds``) from its start, run as one batch.

    The models share one ``lateral_index``, the row that is sampled.
    """
    t = _samples(duration, max_step, len(models))
    rows = [models[0].lateral_index]
    runs, ends = _runs(models, speeds, starts, duration, max_step, rtol, method, engine, rows)
    return [
        LimitCycle(speed=float(v), state=end, duration=duration, **_measure(t, run[0], duration))
        for v, run, end in zip(speeds, runs, ends, strict=True)
    ]


_MAX_DISPLACEMENT = 0.05  # m: no wheelset on the rails is further from the centre


def _displacement(value) -> float:
    """A starting lateral displacement, 0 < |y₀| ≤ 0.05 m."""
    y0 = scalar("initial_displacement", value, low=-_MAX_DISPLACEMENT, high=_MAX_DISPLACEMENT)
    if y0 == 0.0:
        raise ValueError("initial_displacement must not be 0: the centred wheelset never leaves the centre")
    return y0


@dataclass(frozen=True)
class BifurcationDiagram:
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
        Whether the motion at each speed is a sustained oscillation (:meth:`LimitCycle.hunting`).
    nonlinear_critical_speed : float
        Lowest speed at which a limit cycle persists, m/s, refined by bisection between the
        grid speeds, so within their range (inf if there is none on the grid).
    threshold : float
        Amplitude of the oscillation below which the motion counts as decayed, m (> 0).
    """

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
            _checks.speed(
                "nonlinear_critical_speed", self.nonlinear_critical_speed, low=V.min(), high=V.max()
            )
        positive("threshold", self.threshold)

    def plot(
        self, ax=None, *, linear_critical_speed: float | None = None, artists: dict | None = None
    ) -> dict:
        """Draw the amplitude (mm) against speed (km/h), with the nonlinear and linear critical speeds.

        Filled markers joined by a line: sustained hunting; open markers: motion that dies away.
        Each critical speed is a vertical line labelled with its value at the top of the axes.

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

        Returns
        -------
        dict
            The artists: ``cycles`` and ``decaying`` (``Line2D``), and the vertical lines
            ``nonlinear`` and ``linear`` with their labels ``nonlinear_text`` and ``linear_text``
            (hidden where the nonlinear critical speed is infinite or no linear one is given).
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
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        The nonlinear model, as for :func:`limit_cycle_amplitude`.
    speeds : array_like, shape (n_speeds,)
        Speeds of the ramp, m/s, each in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`], in any order:
        they are run from the highest down.
    initial_displacement : float
        Starting lateral displacement of the first wheelset at the highest speed (and after
        a speed where the motion died away), m, either side, 0 < |y₀| ≤ 0.05 m (as for
        :func:`~raildyn.stability.nonlinear.limit_cycle_amplitude`).
    duration : float
        Simulated time at each speed, s, in [0.001, 120]: at least four periods of the hunting,
        so that each quarter of the run compared holds one (:meth:`LimitCycle.hunting`).
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

    Each model's diagram is that of :func:`~raildyn.stability.nonlinear.bifurcation_diagram`; the
    compiled engine advances all models at each speed of the ramp, and at each bisection step, as
    one batch (in parallel threads). For a family of vehicles, such as one car with a range of
    conicities or of yaw stiffnesses.

    Parameters
    ----------
    models : sequence of NonlinearWheelset, NonlinearLateral or models with ``at_speed(V)``
        At least one; all with the same ``state_size`` and ``lateral_index``.
    speeds, initial_displacement, duration, max_step, threshold, refine, progress, rtol, method, engine
        As for :func:`~raildyn.stability.nonlinear.bifurcation_diagram`, the same for every model.

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
    first = [_at_speed(m, float(V[0])) for m in models]
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
        at_v = [m.at_speed(v) for m in models]
        for i, cycle in enumerate(_cycles(at_v, [v] * k, states, T, h, r, method, engine)):
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
            [models[i].at_speed(mid) for i, mid in zip(order, mids, strict=True)],
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
    model : NonlinearWheelset, NonlinearLateral or any object with ``at_speed(V)``
        The nonlinear model; ``at_speed(V)`` gives one with ``rhs``, ``state_size`` and
        ``lateral_index``.
    speed : float
        Speed V, m/s, in [1, :data:`~raildyn.constants.MAXIMUM_SPEED`] (below walking pace the creep
        damping 2f/V makes the equations too stiff to run).
    state : array_like, shape (state_size,)
        Guess of a point on the orbit (for instance the ``state`` at the end of a
        :func:`limit_cycle_amplitude` run), in the units of the model's state: finite, not
        all zero (the centred state is the trivial solution).
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
    m = _at_speed(model, V)
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
    sol = _integrate(m.rhs, 2.0 * T, x, "DOP853", rtol, 1e-12, V, budget=budget, events=section)
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
            return m.rhs(t, z.reshape(n, k)).reshape(-1)

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
        J[:, -1] = m.rhs(T, end)  # d/dT of φ_T(x₀)
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
    sol = _integrate(m.rhs, T, x, "DOP853", rtol, 1e-12, V, dense_output=True)
    lateral = sol.sol(np.linspace(0.0, T, 401))[iy]
    return PeriodicOrbit(
        V,
        float(T),
        x,
        float(0.5 * (lateral.max() - lateral.min())),
        np.linalg.eigvals(monodromy),
        float(np.linalg.norm(end - x)),
    )
