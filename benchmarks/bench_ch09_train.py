"""Chapter 9: a long freight train in emergency braking: its run against a per-car loop and against its
right-hand side alone, and its factor over real time.

* The run against the loop: both use RK45 with the same tolerances, state and physics,
  one state per call; the baseline is ``solve_ivp`` with the right-hand side written the
  straightforward way, one vehicle and one coupler at a time in Python; raildyn
  (``train.simulate``) runs its compiled right-hand side (``raildyn.train._kernel``) in the
  compiled Dormand–Prince integrator (``raildyn.integrators.runner.dormand_prince``), which takes the steps
  of ``solve_ivp``'s RK45. A 600 s run with the loop takes minutes, so both are timed over the
  same shorter span (``SPAN``), which covers the brake application, the run-in and most of the stop.
* The run against its right-hand side (issue 22): the same run, against the evaluations it
  makes (``evaluations``) times the cost of one compiled evaluation, timed separately in a
  compiled loop over the run's own states, called through the same function pointer the
  integrator calls. Their ratio is what the integrator adds; goal: the run ≤ 1.5× the
  right-hand side (the table's ratio, baseline over raildyn, ≥ 0.67).
* The 600 s run of raildyn, against real time.
* The chapter's widget updates.
"""

from __future__ import annotations

import math
import time

import numba
import numpy as np
from numba import types
from scipy.integrate import solve_ivp

from benchmarks.common import Case, timed, widget_case
from raildyn import train
from raildyn.integrators.runner import RHS_SIGNATURE
from raildyn.train import _kernel
from raildyn.train.resistance import CURVE_RESISTANCE
from raildyn.widgets import chapter09

WAGONS = 150
SPAN = 60.0  # s, simulated by both versions
FULL = 600.0  # s, simulated by raildyn for the real-time factor


def _model():
    return train.braking_model(WAGONS, 2)


def loop_rhs(model):
    """The straightforward right-hand side: Python loops over vehicles and couplers."""
    n = model.size
    c = model.consist
    gear = model.gear
    mass = list(c.mass)
    brake = list(c.brake_force)
    offset = list(c.centre_offsets)
    a0, a1, a2 = (list(k) for k in model.davis_coefficients)
    brake_start = model.air_brake.start
    signal = model.air_brake.propagation_speed
    tau = model.air_brake.build_up_time

    def coupler(delta, rate):
        s = 1.0 if delta > 0 else (-1.0 if delta < 0 else 0.0)
        a = abs(delta) - 0.5 * gear.slack
        eps = gear.smoothing
        if a >= eps:
            u, slope = a, 1.0
        elif a <= -eps:
            u, slope = 0.0, 0.0
        else:
            u, slope = (a + eps) ** 2 / (4 * eps), (a + eps) / (2 * eps)
        load = 0.5 * (1.0 + math.tanh(slope * s * rate / gear.transition_rate))
        k = gear.unloading_stiffness + load * (gear.loading_stiffness - gear.unloading_stiffness)
        return s * (k * u + gear.solid_stiffness * max(u - gear.travel, 0.0))

    def rhs(t, y):
        out = np.empty(2 * n)
        out[0] = y[n]
        force = [0.0] * n
        for i in range(n):
            v = y[n + i]
            speed = abs(v)
            retard = a0[i] + a1[i] * speed + a2[i] * speed**2 + CURVE_RESISTANCE * mass[i] * 0.0
            since = t - (brake_start + offset[i] / signal)
            if since > 0:
                retard += brake[i] * (1.0 - math.exp(-since / tau))
            force[i] = -math.tanh(v / model.creep_speed) * retard
        for j in range(n - 1):
            rate = y[n + j] - y[n + j + 1]
            out[1 + j] = rate
            f = coupler(y[1 + j], rate)
            force[j] -= f
            force[j + 1] += f
        for i in range(n):
            out[n + i] = force[i] / mass[i]
        return out

    return rhs


def _solve(fun, model, span):
    n = model.size
    atol = np.r_[1e-3, np.full(n - 1, 1e-6), np.full(n, 1e-5)]
    y0 = model.initial_state(20.0, model.gear.slack / 2)
    return solve_ivp(fun, (0.0, span), y0, rtol=1e-7, atol=atol)


def _simulate(model, span):
    return train.simulate(model, span, 20.0, initial_extension=model.gear.slack / 2, samples=2)


@numba.njit(
    types.void(types.FunctionType(RHS_SIGNATURE), types.float64[::1], types.float64[:, ::1],
               types.float64[:, ::1], types.float64[::1], types.int64),
)  # fmt: skip
def _evaluate(rhs, t, y, data, out, rounds):
    """``rounds`` evaluations of ``rhs`` at each state ``y[k]`` and time ``t[k]``."""
    for _ in range(rounds):
        for k in range(t.size):
            rhs(t[k], y[k], 0, data, out)


def rhs_seconds(model, run, rounds=20):
    """Seconds of one compiled evaluation of the right-hand side: the mean over the states of ``run``."""
    n = model.size
    spacing = model._pre["spacing"]  # centre to centre at zero extension, m
    # The state [x_0, Δx, v] from the positions: Δx_i = x_i − x_{i+1} − spacing_i (to ~1e-13 m).
    extension = run.position[:-1] - run.position[1:] - spacing[:, None]
    y = np.ascontiguousarray(np.vstack([run.position[:1], extension, run.speed]).T)
    t = np.ascontiguousarray(run.t)
    data, out = _kernel.pack(*model._packed), np.empty(2 * n)
    _evaluate(_kernel.rhs_dopri, t, y, data, out, 1)
    start = time.perf_counter()
    _evaluate(_kernel.rhs_dopri, t, y, data, out, rounds)
    return (time.perf_counter() - start) / (rounds * t.size)


def check_same_answer() -> float:
    """Largest difference of the final speeds of the two versions over a short span, m/s."""
    model = _model()
    a = _simulate(model, 5.0)
    b = _solve(loop_rhs(model), model, 5.0)
    return float(np.abs(a.speed[:, -1] - b.y[model.size :, -1]).max())


def cases(repeats: int) -> list[Case]:
    model = _model()
    assert check_same_answer() < 1e-6, "the loop baseline and raildyn disagree"
    loop = loop_rhs(model)
    # The run and its right-hand side alone, in turns, so both see the same load of the machine; the
    # states are the run's own, every 0.1 s, each evaluated as often as the run makes evaluations.
    states = train.simulate(model, SPAN, 20.0, initial_extension=model.gear.slack / 2, samples=601)
    evaluations = _simulate(model, SPAN).evaluations  # the same steps: samples do not change them
    rounds = max(1, round(evaluations / states.t.size))
    fast, alone = [], []
    for _ in range(repeats):
        fast += timed(lambda i: _simulate(model, SPAN), 1)
        alone.append(evaluations * rhs_seconds(model, states, rounds))
    slow = timed(lambda i: _solve(loop, model, SPAN), max(1, min(repeats, 2)))
    full = timed(lambda i: train.simulate(model, FULL, 20.0, initial_extension=model.gear.slack / 2), 1)
    real_time = Case(
        f"{WAGONS}-wagon emergency stop, {FULL:.0f} s simulated (baseline = real time)",
        full,
        [FULL],
        "faster than real time",
        "real time",
    )
    return [
        Case(
            f"{WAGONS}-wagon emergency braking, {SPAN:.0f} s, RK45 rtol 1e-7",
            fast,
            slow,
            "≥ 20× faster",
            "Python loop over cars",
        ),
        Case(
            f"{WAGONS}-wagon emergency braking, {SPAN:.0f} s, rtol 1e-7: run time against the time of its "
            "right-hand-side evaluations alone (evaluations × one compiled evaluation, timed separately)",
            fast,
            alone,
            "run ≤ 1.5× right-hand side (ratio ≥ 0.67)",
            "right-hand side alone",
        ),
        real_time,
        widget_case("braking_run slack", chapter09.BRAKING_RUN, "slack_mm", [0, 25, 50, 75], repeats),
        widget_case("string_lining draft", chapter09.STRING_LINING, "radius", [150, 250, 400, 800], repeats),
    ]
