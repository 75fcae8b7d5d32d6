"""Chapter 9: a long freight train in emergency braking, vectorised right-hand side against a per-car loop.

Both runs use the same ``solve_ivp`` method (RK45), tolerances, state and
physics, one state per call; the baseline evaluates the right-hand side the
straightforward way, one vehicle and one coupler at a time in Python, raildyn
(``train.simulate``) in its compiled loop (``raildyn.train._kernel``), with the
finiteness check of every right-hand side that its failure policy makes. A 600 s run with the loop takes
minutes, so both are timed over the same shorter span (``SPAN``), which covers the
brake application, the run-in and the stop; the raildyn 600 s run is timed as well
to give the factor over real time. Also the chapter's widget update.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from benchmarks.common import Case, timed, widget_case
from raildyn import train
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
    fast = timed(lambda i: _simulate(model, SPAN), repeats)
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
        real_time,
        widget_case(
            "braking_run slack", chapter09.BRAKING_RUN, "slack_mm", [0, 25, 50, 75], repeats, "≤ 100 ms"
        ),
        widget_case(
            "string_lining draft",
            chapter09.STRING_LINING,
            "radius",
            [150, 250, 400, 800],
            repeats,
            "≤ 100 ms",
        ),
    ]
