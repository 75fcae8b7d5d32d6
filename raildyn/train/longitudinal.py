"""Longitudinal dynamics of a whole train: the run of its equations of motion, and the chapter's case.

:func:`simulate` integrates a :class:`~raildyn.train.model.TrainModel` (the equations of
motion and the quasi-statics, in :mod:`raildyn.train.model`) through the integration runner
of :mod:`raildyn.integrators.runner`: RK45 in compiled code
(:func:`~raildyn.integrators.runner.dormand_prince`, the steps of ``solve_ivp``'s RK45 without
its Python per step), the other methods through its bounded ``solve_ivp``. :func:`braking_model`
builds the chapter's standard case.

Failure policy: the runner raises :class:`raildyn.errors.SolverError` (with the time reached
and the reason) when a run runs out of its budget of evaluations or its step shrinks to
nothing; :func:`simulate` adds where the train's forces stopped being finite and the run at
the output times passed (``partial``). A ``TrainRun`` that is returned is a success. The
results (``TrainRun``, ``CouplerPeak``, ``QuasiStatic``) live in ``raildyn.train.results``.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn._progress import progress_bar
from raildyn.constants import MAXIMUM_SPEED
from raildyn.errors import SolverError
from raildyn.train.couplers import _MAX_EXTENSION, DraftGear
from raildyn.train.forces import AirBrake
from raildyn.train.model import TrainModel  # defined there; importable from here for one more issue
from raildyn.train.resistance import Route
from raildyn.train.results import TrainRun
from raildyn.train.vehicles import _MAX_VEHICLES, make_consist

# Imported where used, to keep this module's import cheap (tests/test_imports.py): raildyn.train._kernel

__all__ = ["braking_model", "simulate"]

# The methods solve_ivp offers by name.
METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")

# Longest simulated time, s: a day, longer than any journey one run models; at 200 m/s the
# front position still resolves well under a micrometre in float64.
_MAX_DURATION = 86_400.0
# Most output times of a run (its arrays are vehicles x samples).
_MAX_SAMPLES = 1_000_000
# Steps of the compiled integrator between two updates of the progress bar: some 0.1 s of a
# 150-wagon run, so the bar moves smoothly and the return to Python costs nothing measurable.
_CHUNK = 2000
# The budget of a run, in evaluations of its right-hand side (the runner's one rule): about 50
# times what an hour of a 100-car emergency stop takes (2e6), the runner's largest budget. It
# bounds every run, whatever its tolerances and max_step.
_MAX_EVALUATIONS = 100_000_000


def simulate(
    model: TrainModel,
    duration: float,
    initial_speed: float,
    *,
    initial_extension: float = 0.0,
    samples: int = 601,
    rtol: float = 1e-7,
    atol=None,
    method: str = "RK45",
    max_step: float | None = None,
    progress: bool = False,
) -> TrainRun:
    """Integrate the longitudinal equations of the whole train.

    The default method, RK45, runs in compiled code (the Dormand–Prince pair of
    :func:`raildyn.integrators.runner.dormand_prince`, with the steps, error control and dense
    output of ``scipy.integrate.solve_ivp``'s RK45); the other methods are ``solve_ivp``'s, through
    the same runner (:func:`raildyn.integrators.runner.solve_ivp`).

    Parameters
    ----------
    model : TrainModel
        The train, its route and its driver's settings.
    duration : float
        Simulated time, s; 0 < duration <= 86400 (a day: longer than any journey one run
        models).
    initial_speed : float
        Speed of every vehicle at t = 0, m/s (negative runs backwards), at most 200 in size
        (above the wheel–rail speed record).
    initial_extension : float
        Coupler extension Δx at t = 0, m: 0 centres the slack, ``+slack/2`` starts stretched
        and ``−slack/2`` bunched; within ±1 m.
    samples : int
        Number of output times, 2 to 1000000, uniform over [0, duration].
    rtol : float
        Relative tolerance, in [1e-13, 1) (above scipy's floor of 100 machine epsilons).
        Explicit methods are held back by the stiff draft gear rather than by
        accuracy, so a tight ``rtol`` costs little: for the standard braking run
        1e-5 misplaces the peak coupler force by ~13 % and 1e-7 agrees with an
        implicit solution to 0.1 %.
    atol : float or array (2n,), optional
        Absolute tolerance, in [1e-13, 1), in the units of the state (m, m, m/s); default
        1e-3 m on the front position, 1e-6 m on the extensions, 1e-5 m/s on speeds.
    method : {"RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA"}
        A ``solve_ivp`` method; RK45 runs compiled, taking the steps ``solve_ivp`` would.
    max_step : float, optional
        Largest step, s (> 0); unlimited by default.
    progress : bool
        Show a tqdm bar of simulated time.

    Returns
    -------
    TrainRun
        The run at the ``samples`` output times.

    Raises
    ------
    raildyn.errors.SolverError
        If the forces are not finite at the start, the run needs more than 10⁸
        right-hand-side calls (about 50 times what an hour of a 100-car emergency stop
        takes), or the integrator stops before ``duration`` (a step that shrinks below
        the spacing of floating-point numbers, as it does when the solution runs into a
        force that overflows);
        ``time`` is the last time reached (s), ``partial`` the run at the output
        times passed (or None). A trial step that overshoots into such a force is
        rejected and retried, so a run that avoids it still succeeds.

    Examples
    --------
    An emergency stop of one SD40-2 and ten loaded hoppers from 54 km/h:

    >>> run = simulate(braking_model(10, 1), 60.0, 15.0, samples=601)
    >>> peak = run.peak
    >>> peak.kind, peak.coupler, round(peak.force / 1e3), round(run.stop_time(), 1)
    ('buff', 8, -77, 45.3)
    """
    from raildyn.train import _kernel

    _checks.instance("model", model, TrainModel)
    duration = _checks.scalar("duration", duration, low=0.0, high=_MAX_DURATION, low_open=True)
    initial_speed = _checks.scalar("initial_speed", initial_speed, low=-MAXIMUM_SPEED, high=MAXIMUM_SPEED)
    initial_extension = _checks.scalar(
        "initial_extension", initial_extension, low=-_MAX_EXTENSION, high=_MAX_EXTENSION
    )
    samples = _checks.integer("samples", samples, low=2, high=_MAX_SAMPLES)
    rtol = _checks.tolerance("rtol", rtol)
    n = model.size
    if atol is None:
        atol = np.r_[1e-3, np.full(n - 1, 1e-6), np.full(n, 1e-5)]
    elif np.ndim(atol) == 0:
        atol = _checks.tolerance("atol", atol)
    else:
        atol = _checks.array("atol", atol, shape=(2 * n,))
        for a in atol:
            _checks.tolerance("atol", a)
    _checks.choice("method", method, METHODS)
    max_step = np.inf if max_step is None else _checks.positive("max_step", max_step)
    _checks.flag("progress", progress)
    y0 = model.initial_state(initial_speed, initial_extension)
    t_eval = np.linspace(0.0, duration, samples)
    # y0 is the model's own state: the compiled loop needs no check.
    if not _kernel.all_finite(model._rhs_one(0.0, y0)):
        raise SolverError(
            "the forces on the train are not finite at the start (an overflow)", step=0, time=0.0
        )
    atol = np.array(np.broadcast_to(atol, (2 * n,)), dtype=float)  # a writable copy, as numba takes it
    integrate = _integrate if method == "RK45" else _integrate_solve_ivp
    bar = progress_bar(total=round(duration), desc="simulated time (s)") if progress else None
    try:
        return integrate(model, y0, t_eval, rtol, atol, method, max_step, bar)
    finally:
        if bar is not None:
            bar.close()


def _integrate(model, y0, t_eval, rtol, atol, method, max_step, bar):
    """RK45 in compiled code (the runner's Dormand–Prince): the steps of solve_ivp's RK45, faster.

    The arguments are those of :func:`simulate`, checked; ``method`` is "RK45". The run goes
    in chunks of ``_CHUNK`` steps, between which the progress bar moves; a chunk resumes
    where the last stopped, so the steps are those of one uninterrupted run.
    """
    from raildyn.integrators import runner
    from raildyn.train import _kernel

    data = _kernel.pack(*model._packed)
    try:
        run = runner.dormand_prince(
            _kernel.rhs_dopri, data, y0, t_eval, rtol=rtol, atol=atol, max_step=max_step,
            budget=_MAX_EVALUATIONS, label=f"the {method} run of the train", chunk=_CHUNK,
            progress=None if bar is None else _mover(bar),
        )  # fmt: skip
    except SolverError as err:
        blocked = int(data[0, _kernel.H_NON_FINITE])
        note = (
            f" The forces on the train were not finite (an overflow in the model) at {blocked} trial "
            f"stages, the last at t = {data[0, _kernel.H_LAST_NON_FINITE]:.6g} s."
            if blocked
            else ""
        )
        raise _with_partial(err, model, note) from None
    return model.run_from_states(run.t, run.y, run.evaluations)


def _integrate_solve_ivp(model, y0, t_eval, rtol, atol, method, max_step, bar):
    """:func:`_integrate` with the runner's ``solve_ivp``: the other methods, and RK45's reference.

    A non-finite force is handed to the solver as NaN, so the trial step is rejected (as the
    compiled run does); a run that gets stuck there stops, and the runner says so.
    """
    from raildyn.integrators import runner

    try:
        sol = runner.solve_ivp(
            model._rhs_one, (0.0, t_eval[-1]), y0, method=method, rtol=rtol, atol=atol, t_eval=t_eval,
            max_step=max_step, budget=_MAX_EVALUATIONS, label=f"the {method} run of the train",
            non_finite="reject", progress=None if bar is None else _mover(bar),
        )  # fmt: skip
    except SolverError as err:
        raise _with_partial(err, model, "") from None
    return model.run_from_states(sol.t, sol.y, int(sol.nfev))


def _mover(bar):
    """The progress callback that moves ``bar`` to the whole seconds simulated."""

    def move(t):
        if int(t) > bar.n:
            bar.update(int(t) - bar.n)

    return move


def _with_partial(err: SolverError, model, note: str) -> SolverError:
    """The runner's failure, with the train's note and the run at the output times passed (or None)."""
    return SolverError(err.reason + note, step=err.step, time=err.time, partial=_partial(model, err.partial))


def _partial(model, trajectory):
    """The run at the output times passed before a failure, or None where there is none to give."""
    if trajectory is None or not trajectory.t.size or trajectory.y.shape[0] != 2 * model.size:
        return None
    try:
        return model.run_from_states(trajectory.t, trajectory.y, trajectory.evaluations)
    except ValueError:  # the states had left the coupler law's domain before the failure
        return None


def braking_model(
    cars: int = 100,
    locomotives: int = 2,
    *,
    slack: float = 0.025,
    propagation_speed: float = 250.0,
    gear: DraftGear | None = None,
    route: Route | None = None,
) -> TrainModel:
    """The chapter's standard case: ``locomotives`` SD40-2 + ``cars`` loaded hoppers in emergency.

    The throttle is at idle and the emergency air brake is applied at t = 0 from
    the front.

    Parameters
    ----------
    cars : int
        Number of loaded hoppers (>= 1); with the locomotives at most 1000 vehicles (see
        :class:`~raildyn.train.vehicles.Consist`).
    locomotives : int
        Number of SD40-2 at the front (>= 0).
    slack : float
        Slack of every coupler, m (>= 0); ignored when ``gear`` is given.
    propagation_speed : float
        Speed of the brake-pipe signal, m/s (> 0).
    gear : DraftGear, optional
        The coupler law; :class:`DraftGear` with ``slack`` by default.
    route : Route, optional
        The line; level tangent track by default.

    Returns
    -------
    TrainModel
        The train on its route, air brake applied at t = 0, throttle at idle.

    Examples
    --------
    >>> model = braking_model(100, 2)
    >>> model.size, round(model.consist.train_length), model.air_brake.propagation_speed
    (102, 1657, 250.0)
    >>> run = simulate(model, 40.0, 20.0, initial_extension=0.0125, samples=401)
    >>> run.peak.kind
    'buff'
    """
    cars = _checks.integer("cars", cars, low=1, high=_MAX_VEHICLES)
    locomotives = _checks.integer("locomotives", locomotives, low=0, high=_MAX_VEHICLES - cars)
    text = f"{cars} loaded hopper" if locomotives == 0 else f"{locomotives} SD40-2 + {cars} loaded hopper"
    gear = DraftGear(slack=slack) if gear is None else gear
    return TrainModel(
        make_consist(text),
        gear=gear,
        route=Route.level() if route is None else route,
        air_brake=AirBrake(start=0.0, propagation_speed=propagation_speed),
    )
