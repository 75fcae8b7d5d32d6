"""Nonlinear hunting (book chapter 7): time runs and limit cycles (the bifurcation diagram and periodic
orbits built on them are in :mod:`raildyn.stability.bifurcation`).

The nonlinear models follow :class:`raildyn.wheelset.NonlinearModel` (``rhs(t, state, speed)``;
:class:`raildyn.wheelset.NonlinearLateral` and :class:`raildyn.wheelset.NonlinearWheelset`); these
functions integrate them at the speeds they are given and measure the steady hunting. RK45 runs
on the compiled engine (the model's :meth:`~raildyn.wheelset.NonlinearLateral.compiled_rhs`: the same
equations in numba, many speeds or vehicles at once, on the compiled Dormand–Prince of
:mod:`raildyn.integrators.runner`) wherever the model says the engine holds it (its
``compiled_reason`` is None), and on ``scipy.integrate.solve_ivp`` (through the same runner, bounded
alike) otherwise or when asked (``engine="scipy"``, the reference the tests hold the engine to).
Every run is bounded by the runner's one budget rule and fails by its one rule.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from raildyn import _checks
from raildyn._checks import array, integer, positive, scalar
from raildyn._tables import Tabular
from raildyn.wheelset import NonlinearModel

__all__ = [
    "LimitCycle",
    "NonlinearRun",
    "limit_cycle_amplitude",
    "simulate",
]


# ---------------------------------------------------------------------------
# Nonlinear hunting


@dataclass(frozen=True)
class NonlinearRun(Tabular):
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

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("t", "s"), ("states", "m, rad, m/s, rad/s"))
    _scalars = (("speed", "m/s"), ("lateral_index", "-"))
    _by_row = ("states",)

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
    model : NonlinearModel
        A nonlinear model (:class:`~raildyn.wheelset.NonlinearLateral`,
        :class:`~raildyn.wheelset.NonlinearWheelset`).
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
        Who runs RK45: ``"compiled"``, the numba engine (the model's ``compiled_rhs``, the
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
    m = _model(model)
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
    from raildyn.integrators import runner

    kept = models[0].state_size if rows is None else len(rows)
    t = _samples(duration, max_step, kept * len(models))
    packed = None
    if engine != "scipy" and method == "RK45":
        why = next((m.compiled_reason for m in models if m.compiled_reason is not None), None)
        if why is None:
            packed = [m.compiled_rhs(v) for m, v in zip(models, speeds, strict=True)]
        elif engine == "compiled":
            raise ValueError(f"engine 'compiled' cannot run this model: {why}; use engine='scipy'")
    elif engine == "compiled":
        raise ValueError(f"engine 'compiled' runs method 'RK45' only, got method {method!r}")
    if packed is None:
        out, ends = [], []
        for m, v, y0 in zip(models, speeds, starts, strict=True):
            sol = _integrate(partial(m.rhs, speed=v), duration, y0, method, rtol, 1e-9, v, max_step=max_step,
                             t_eval=t)  # fmt: skip
            out.append(sol.y if rows is None else sol.y[rows])
            ends.append(sol.y[:, -1].copy())
        return out, ends
    data = np.zeros((len(packed), max(p.row.size for p in packed)))  # rows padded to the longest
    for i, p in enumerate(packed):
        data[i, : p.row.size] = p.row
    runs = runner.dormand_prince_batch(
        packed[0].kernel, data, np.array(starts), t, rtol=rtol, atol=1e-9,
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


def _duration(name: str, value) -> float:
    """A run's length (or a period), s, in [1 ms, 120 s]: shorter, no motion of a vehicle shows
    (its fastest modes take some 10 ms a cycle), and the measures of a run read nothing."""
    return scalar(name, value, low=_MIN_DURATION, high=_MAX_DURATION)


def _model(model):
    """``model``, checked to follow the nonlinear protocol, its ``state_size`` and ``lateral_index`` sound."""
    _checks.not_a_class("model", model, "a nonlinear model")
    if not isinstance(model, NonlinearModel):
        raise TypeError(
            "model must be a nonlinear model (raildyn.wheelset.NonlinearModel: rhs(t, state, speed), "
            "replace, state_size, lateral_index, compiled_reason; NonlinearLateral, NonlinearWheelset), "
            f"got {model!r:.80} of type {type(model).__name__}"
        )
    integer("model state_size", model.state_size, low=1)
    integer("model lateral_index", model.lateral_index, low=0, high=model.state_size - 1)
    return model


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
    model : NonlinearModel
        A nonlinear model (:class:`~raildyn.wheelset.NonlinearLateral`,
        :class:`~raildyn.wheelset.NonlinearWheelset`).
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
    m = _model(model)
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
