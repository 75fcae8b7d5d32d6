"""Fuzz registry: chapter 2, numerical integration, and the suspension force laws."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import integrators as ig
from raildyn import suspension as sus
from raildyn.integrators import runner

W2 = (2 * np.pi) ** 2  # the stiffness of a 1 kg oscillator of period 1 s
T = np.linspace(0.0, 0.5, 11)  # 10 steps of 0.05 s: inside every scheme's stability limit
T_MAX = np.linspace(0.0, 2.0, 41)  # two periods: interior maxima to find


def hardening(t, x, v):
    """A small cubic spring force on one coordinate, N."""
    return -10.0 * x**3


def hardening_tangent(t, x, v):
    """Its tangent (∂f/∂x, ∂f/∂v) as a pair."""
    return (np.array([[-30.0 * x[0] ** 2]]), np.zeros((1, 1)))


def load(t):
    """A sinusoidal external force f(t), N."""
    return np.array([np.sin(2 * np.pi * t)])


def result():
    return ig.rk4(1.0, 0.1, W2, T_MAX, 1.0, 0.0)


def reference():
    return ig.rk4(1.0, 0.1, W2, T_MAX[::2], 1.0, 0.0)


def chart():
    return ig.scheme_accuracy("central_difference", [0.05, 0.1])


def damper():
    return sus.FrictionDamper(friction_force=100.0, velocity_scale=1e-3)


def decay_rhs():
    """y' = −data[member, 0] y, compiled to the runner's signature (compiled once, on first use)."""
    global _DECAY
    if _DECAY is None:
        import numba

        @numba.njit(runner.RHS_SIGNATURE, cache=True)
        def decay(t, y, member, data, out):
            out[0] = -data[member, 0] * y[0]

        _DECAY = decay
    return _DECAY


_DECAY = None


def decay(t, y):
    """y' = −2 y, for scipy's engine."""
    return -2.0 * y


# M, C, K of a linear run; C and K may be zero or negative (the equations of a system that is
# undamped, or unstable, are integrated as they are); x0, v0 and the force take any sign.
# An abstract system has no plausible size: any mass, damping, stiffness or start is valid.
ANY = "zero negative mm big"
LINEAR = {"M": "mm big tiny", "C": ANY, "K": ANY, "x0": ANY, "v0": ANY}
LOAD = {**LINEAR, "force": "returns-negative"}
FIRST = {**LINEAR, "force": "returns-negative"}
STEP = {"M": "mm big tiny", "C": ANY, "K": ANY, "h": "mm big tiny"}

ENTRIES = [
    # --- linear schemes, f(t) as a callable or as samples
    fuzz(
        "raildyn.integrators.newmark",
        lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, load, gamma=0.6, beta=0.3),
        accepts={
            **LOAD,
            "beta": "zero",
        },  # β in [0, 1]: β = 0 is the explicit member
    ),
    fuzz(
        "raildyn.integrators.average_acceleration",
        lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, load),
        accepts=LOAD,
    ),
    fuzz(
        "raildyn.integrators.linear_acceleration",
        lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, np.sin(T)[None, :]),
        accepts={
            **LINEAR,
            "force": "zero negative none",
        },  # None: no load
    ),
    fuzz(
        "raildyn.integrators.hht_alpha",
        lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, load, alpha=-0.1),
        accepts={
            **LOAD,
            "alpha": "zero negative",
        },  # α in [−⅓, 0]
    ),
    fuzz(
        "raildyn.integrators.wilson", lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, load, theta=1.5), accepts=LOAD
    ),
    fuzz(
        "raildyn.integrators.central_difference", lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, load), accepts=LOAD
    ),
    fuzz("raildyn.integrators.houbolt", lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, load), accepts=LOAD),
    fuzz(
        "raildyn.integrators.integrate",
        lambda: call("wilson", 1.0, 0.1, W2, T, 1.0, 0.0, load, theta=1.5),
        accepts=LOAD,
    ),
    # --- nonlinear schemes, f(t, x, v)
    fuzz(
        "raildyn.integrators.forward_euler",
        lambda: call(1.0, 0.1, W2, np.linspace(0, 0.05, 11), 0.1, 0.0, hardening),
        accepts=FIRST,
    ),
    fuzz("raildyn.integrators.rk4", lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, hardening), accepts=FIRST),
    fuzz("raildyn.integrators.abm", lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, hardening), accepts=FIRST),
    fuzz(
        "raildyn.integrators.newmark_newton",
        lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, hardening, jacobian=hardening_tangent, max_iter=10),
        accepts={
            "M": "big mm",
            "C": "big mm",
            "K": "mm",
            "beta": "tiny",
            "tol": "mm",
            **FIRST,
            "jacobian": "returns-negative",
        },
    ),
    fuzz(
        "raildyn.integrators.stiff",
        lambda: call(1.0, 0.1, W2, T, 1.0, 0.0, hardening, jacobian=hardening_tangent, rtol=1e-6, atol=1e-9),
        # A start a thousand times larger stiffens the cubic spring a millionfold: Radau spends its budget of
        # evaluations and says so (SolverError). The budget is lowered to 10 000 here, above the 6 812 of
        # the stiffest accepted change (K × 1000), so that each such call ends within the usual time limit.
        patches={"raildyn.integrators.nonlinear.MAX_STIFF_EVALUATIONS": 10_000},
        accepts={
            "M": "big mm",
            "C": "big mm",
            "K": "mm",
            "rtol": "mm",
            "atol": "mm",
            **FIRST,
            "jacobian": "returns-negative",
        },
    ),
    # --- the linear steps and their recursion matrices
    fuzz(
        "raildyn.integrators.recursions.newmark_step",
        lambda: call(np.eye(1), np.zeros((1, 1)), W2 * np.eye(1), 0.05, 0.5, 0.25),
        accepts={**STEP, "beta": "zero", "alpha": "zero"},  # β in [0, 1], α in [−⅓, 0]
    ),
    fuzz(
        "raildyn.integrators.recursions.wilson_step",
        lambda: call(np.eye(1), np.zeros((1, 1)), W2 * np.eye(1), 0.05, 1.4),
        accepts=STEP,
    ),
    fuzz(
        "raildyn.integrators.recursions.central_difference_step",
        lambda: call(np.eye(1), np.zeros((1, 1)), W2 * np.eye(1), 0.05),
        accepts=STEP,
    ),
    fuzz(
        "raildyn.integrators.recursions.houbolt_step",
        lambda: call(np.eye(1), np.zeros((1, 1)), W2 * np.eye(1), 0.05),
        accepts=STEP,
    ),
    fuzz(
        "raildyn.integrators.recursions.recursion_matrices",
        lambda: call(ig.linear.central_difference_step(np.eye(1), np.zeros((1, 1)), np.eye(1), 0.1), 2, 1),
        accepts={"step": "returns-negative"},  # a step is any linear map: its entries take any sign
    ),
    fuzz(
        "raildyn.integrators.recursions.RecursionMatrices",
        lambda: call(np.eye(2), np.ones((2, 1)), np.ones((2, 1))),
        accepts={"*": "zero negative"},
    ),  # a result: its entries take any value
    # --- results
    fuzz(
        "raildyn.integrators.IntegrationResult",
        lambda: call(T, np.cos(T)[None], -np.sin(T)[None], -np.cos(T)[None], "exact", 10, 0),
        accepts={"*": "zero negative", "method": "unknown"},
    ),  # method is a free label
    fuzz(
        "raildyn.integrators.IntegrationResult.deviation_from",
        lambda: on(result(), reference()),
        accepts={"after": "zero negative"},
    ),
    fuzz(
        "raildyn.integrators.IntegrationResult.maxima", lambda: on(result(), 0, "x"), accepts={"dof": "zero"}
    ),
    fuzz(
        "raildyn.integrators.IntegrationResult.plot",
        lambda: on(result(), None, dof=0, quantity="v", scale=2.0),
        accepts={"dof": "zero", "scale": "negative big tiny mm"},
    ),
    # The table of every result (raildyn._tables.Tabular, one implementation): its entries stand
    # here, on the integrators' result, once for all the results that share it.
    fuzz("raildyn.integrators.IntegrationResult.table", lambda: on(result())),
    fuzz(
        "raildyn.integrators.IntegrationResult.to_csv",
        lambda: on(result(), "result.csv"),
        accepts={"path": "unknown"},  # any file name in an existing folder (here the test's own) is valid
    ),
    fuzz("raildyn.integrators.IntegrationResult.to_pandas", lambda: on(result())),
    fuzz(
        "raildyn.integrators.Deviation",
        lambda: call(np.array([0.1]), np.array([0.2]), np.array([0.3]), np.array([0.0, 0.5])),
        accepts={"displacement": "zero", "velocity": "zero", "acceleration": "zero", "times": "negative"},
    ),
    fuzz(
        "raildyn.integrators.Maxima",
        lambda: call(np.array([1.0, 2.0]), np.array([0.5, 0.25])),
        accepts={"times": "negative", "values": "zero negative"},
    ),
    fuzz(
        "raildyn.integrators.ForceJacobian",
        lambda: call(np.array([[1.0]]), np.array([[-2.0]])),
        accepts={"wrt_displacement": "zero negative", "wrt_velocity": "zero negative"},
    ),
    # --- analysis on the test oscillator
    fuzz(
        "raildyn.integrators.amplification_matrix",
        lambda: call("newmark", 0.1, 0.05, gamma=0.6, beta=0.3),
        accepts={"dt_over_T": "list mm", "damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.integrators.spectral_radius",
        lambda: call("wilson", 0.1, 0.05, theta=1.4),
        accepts={"dt_over_T": "list mm", "damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.integrators.period_elongation",
        lambda: call("hht_alpha", 0.1, 0.05, alpha=-0.1),
        accepts={"dt_over_T": "list mm", "damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.integrators.amplitude_decay",
        lambda: call("houbolt", 0.1, 0.05),
        accepts={"dt_over_T": "list mm", "damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.integrators.stability_limit",
        lambda: call("linear_acceleration", 0.05),
        accepts={"damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.integrators.first_order_step_limit",
        lambda: call("rk4", -100.0),
        accepts={"eigenvalue": "negative complex big tiny mm"},
    ),
    fuzz(
        "raildyn.integrators.stable_step",
        lambda: call("central_difference", 1.0, 0.1, W2),
        accepts={"M": "big tiny mm", "C": "zero negative big mm", "K": "zero negative big mm"},
        infinite=("return",),  # no stiffness: stable at any step, the documented +inf
    ),
    fuzz(
        "raildyn.integrators.stiffness_ratio",
        lambda: call(1.0, 101.0, 100.0),
        accepts={"M": "big mm", "C": "zero negative mm", "K": "negative big mm"},
    ),
    fuzz(
        "raildyn.integrators.scheme_accuracy",
        lambda: call("central_difference", [0.05, 0.1], 0.05),
        accepts={"damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.integrators.SchemeAccuracy",
        lambda: call(
            "rk4", {}, 0.0, np.array([0.1]), np.array([0.99]), np.array([0.01]), np.array([0.02]), 0.45
        ),
        accepts={"stability_limit_dt_over_T": "big mm", "*": "zero negative"},
    ),  # a result: its values are what the analysis computed
    fuzz("raildyn.integrators.SchemeAccuracy.plot_spectral_radius", lambda: on(chart(), None)),
    fuzz("raildyn.integrators.SchemeAccuracy.plot_period_elongation", lambda: on(chart(), None)),
    fuzz("raildyn.integrators.SchemeAccuracy.plot_amplitude_decay", lambda: on(chart(), None)),
    fuzz("raildyn.integrators.convergence_study", lambda: call("rk4", (8, 16), 0.5)),
    fuzz(
        "raildyn.integrators.ConvergenceStudy",
        lambda: call(
            "rk4", {}, np.array([8, 16]), np.array([0.125, 0.0625]), np.array([1e-3, 6e-5]), np.array([4.0])
        ),
        accepts={"*": "zero negative"},
    ),  # a result
    # --- suspension force laws: array_like inputs broadcast against each other (the module's rule),
    # so a list or an extra axis that still broadcasts is a valid call
    fuzz(
        "raildyn.suspension.spring_force",
        lambda: call([0.0, 0.01], 1.0e6, 10.0),
        accepts={
            "deflection": "zero negative shape",
            "stiffness": "zero list big mm",
            "preload": "zero negative list big mm",
        },
    ),
    fuzz(
        "raildyn.suspension.damper_force",
        lambda: call([-0.1, 0.2], 2.0e4),
        accepts={"velocity": "zero negative shape", "damping": "zero list big mm"},
    ),
    fuzz(
        "raildyn.suspension.coulomb_friction",
        lambda: call([-1.0, 0.5], 500.0, velocity_scale=0.01),
        accepts={
            "velocity": "zero negative shape",
            "friction_force": "zero list big mm",
            "velocity_scale": "list none",  # None: the ideal law
        },
    ),
    fuzz(
        "raildyn.suspension.coulomb_friction_slope",
        lambda: call([0.0, 1e-3], 1.0e4, velocity_scale=1.0e-3),
        accepts={
            "velocity": "zero negative shape",
            "friction_force": "zero list big mm",
            "velocity_scale": "list mm",
        },
    ),
    fuzz(
        "raildyn.suspension.friction_error_bound",
        lambda: call(0.03, 500.0, 0.01),
        accepts={
            "velocity": "zero negative list big mm",
            "friction_force": "zero list big mm",
            "velocity_scale": "list",
        },
    ),
    fuzz(
        "raildyn.suspension.friction_amplitude_loss",
        lambda: call(1.0e4, 5.0e6),
        accepts={"friction_force": "zero list big mm", "stiffness": "list big tiny mm"},
    ),
    fuzz(
        "raildyn.suspension.clearance_force",
        lambda: call([-0.02, 0.005, 0.02], 0.01, 1.0e6, 1.0e5),
        accepts={
            "deflection": "zero negative shape",
            "clearance": "zero big mm",
            "stop_stiffness": "zero big mm",
            "stiffness": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.suspension.FrictionDamper",
        lambda: call(100.0, 1e-3),
        accepts={
            "friction_force": "zero list big mm",
            "velocity_scale": "list mm",
        },  # one value per coordinate
    ),
    fuzz(
        "raildyn.suspension.FrictionDamper.force",
        lambda: on(damper(), 0.1, np.zeros(1), np.array([0.01])),
        accepts={"t": "zero negative big mm", "x": "zero negative", "v": "zero negative"},
    ),
    fuzz(
        "raildyn.suspension.FrictionDamper.jacobian",
        lambda: on(damper(), 0.1, np.zeros(1), np.array([0.01])),
        accepts={"t": "zero negative big mm", "x": "zero negative", "v": "zero negative"},
    ),
    # --- the integration runner
    fuzz("raildyn.integrators.runner.EvaluationBudget", lambda: call(1000), accepts={"limit": "big"}),
    fuzz(
        "raildyn.integrators.runner.EvaluationBudget.spend",
        lambda: on(runner.EvaluationBudget(1000), 10),
        accepts={"count": "zero huge"},  # a run may overspend; the next one then has nothing left
    ),
    fuzz(
        "raildyn.integrators.runner.Trajectory",
        lambda: call(np.array([0.0, 0.5]), np.array([[1.0, 0.5]]), np.array([0.4]), 12, 2),
        accepts={"*": "zero negative", "t": "zero"},  # a result: its entries take any value
    ),
    fuzz(
        "raildyn.integrators.runner.dormand_prince",
        lambda: call(
            decay_rhs(),
            [[2.0]],
            np.array([1.0]),
            np.array([0.0, 0.5, 1.0]),
            rtol=1e-6,
            atol=1e-9,
            max_step=0.5,
            chunk=100,
        ),  # fmt: skip
        accepts={
            "data": "zero negative huge",
            "y0": "zero negative",
            "rtol": "mm",
            "atol": "mm",
            "max_step": "inf big mm none",  # None: unlimited, the default
            "member": "zero",
            "chunk": "huge",
        },  # any rate of decay or growth, any start; a longer chunk only moves progress less often
    ),
    fuzz(
        "raildyn.integrators.runner.dormand_prince_batch",
        lambda: call(
            decay_rhs(),
            np.array([[2.0], [1.0]]),
            np.array([[1.0], [2.0]]),
            np.array([0.0, 0.5, 1.0]),
            rtol=1e-6,
            atol=1e-9,
            max_step=0.5,
        ),  # fmt: skip
        accepts={
            "data": "zero negative huge",
            "states": "zero negative",
            "rtol": "mm",
            "atol": "mm",
            "max_step": "inf big mm none",
        },
    ),
    fuzz(
        "raildyn.integrators.runner.solve_ivp",
        lambda: call(decay, (0.0, 1.0), np.array([1.0]), rtol=1e-6, atol=1e-9, budget=10_000),
        accepts={
            "y0": "zero negative",
            "fun": "returns-negative",
            "rtol": "mm",
            "atol": "mm",
            "budget": "big",
        },
    ),
]
