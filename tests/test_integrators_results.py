"""raildyn.integrators: one failure policy, one result shape, the accuracy chart drawn once, its surface.

Failure: every solver path raises raildyn.errors.SolverError with the step, the
time, the reason and the completed part of the run (``partial``); results carry
no success flag. Results: frozen dataclasses declaring every attribute. Plots:
the chapter's figures and widgets draw the accuracy curves through the methods of
SchemeAccuracy. Surface: ``__all__`` and numpydoc sections of every public name.
"""

import dataclasses
import importlib
import inspect
import re

import matplotlib
import numpy as np
import pytest
from matplotlib.figure import Figure

import raildyn.integrators
from raildyn import integrators as ri
from raildyn import suspension, vibration
from raildyn.errors import SolverError

TWO_PI = 2 * np.pi
EXPLICIT = ["central_difference", "forward_euler", "rk4", "abm", "linear_acceleration"]


# ---------------------------------------------------------------------------------------- failure policy


def test_one_failure_type_and_no_success_flag():
    assert not hasattr(ri, "DivergenceError")
    fields = {f.name for f in dataclasses.fields(ri.IntegrationResult)}
    assert fields == {"t", "x", "v", "a", "method", "steps", "iterations"}
    for name in ri.METHODS:
        function = getattr(ri, name)
        assert "on_divergence" not in inspect.signature(function).parameters, name
    for function in (ri.newmark_newton, ri.stiff):
        assert "on_divergence" not in inspect.signature(function).parameters


@pytest.mark.parametrize("method", EXPLICIT)
def test_every_blow_up_raises_solver_error_with_the_completed_part(method):
    # T = 1 s at Δt/T = 0.6: past the limit of every scheme here (1/π, √2/π, √3/π; 0.0068 for ABM and
    # 0 for forward Euler, on an undamped oscillation).
    t = np.arange(400) * 0.6
    with pytest.raises(SolverError) as info:
        ri.integrate(method, 1.0, 0.0, TWO_PI**2, t, 1.0, 0.0)
    err = info.value
    part = err.partial
    assert isinstance(part, ri.IntegrationResult) and part.method == method
    # The partial run ends just before the failing step, at its time; it is finite throughout.
    assert 0 < err.step < t.size and part.t.size == err.step
    assert err.time == pytest.approx(t[err.step], rel=1e-12)
    assert part.steps == part.t.size - 1 and part.x.shape == (1, part.t.size)
    assert np.array_equal(part.t, t[: err.step])
    assert all(np.all(np.isfinite(getattr(part, q))) for q in "xva")
    assert err.reason in str(err) and f"step {err.step}" in str(err)
    assert "stable only for" in err.reason or "amplifies" in err.reason  # the limit is named


def test_partial_history_is_the_run_itself():
    # The steps completed before the blow-up are those of the run: the same numbers as a shorter run.
    t = np.arange(300) * 0.4
    with pytest.raises(SolverError) as info:
        ri.central_difference(1.0, 0.0, TWO_PI**2, t, 1.0, 0.0)
    part = info.value.partial
    short = ri.central_difference(1.0, 0.0, TWO_PI**2, t[:12], 1.0, 0.0)
    assert np.allclose(part.x[:, :11], short.x[:, :11], rtol=1e-12, atol=0)


def test_newmark_newton_that_does_not_converge_raises():
    t = np.linspace(0.0, 2.0, 21)
    with pytest.raises(SolverError, match="did not converge in 1 iterations") as info:
        ri.newmark_newton(1.0, 0.0, 1.0, t, 1.0, 0.0, lambda tk, x, v: -10 * x**3, max_iter=1)
    assert info.value.step == 1 and info.value.partial.t.size == 1


@pytest.mark.parametrize("method", ["Radau", "BDF", "LSODA"])
def test_stiff_solver_failure_raises_solver_error(method):
    # x'' = −x + 10x³ from x = 1 escapes to infinity in finite time (t ≈ 0.60 s): scipy cannot follow.
    t = np.linspace(0.0, 2.0, 21)
    with pytest.raises(SolverError, match=f"scipy's {method} failed") as info:
        ri.stiff(1.0, 0.0, 1.0, t, 1.0, 0.0, lambda tk, x, v: 10 * x**3, method=method)
    err = info.value
    assert 0.55 < err.time < 0.65 and err.step > 0
    part = err.partial
    # The completed part is on the requested grid (issue 15), up to where scipy stopped.
    assert np.array_equal(part.t, t[: part.t.size]) and part.t[-1] <= err.time < part.t[-1] + 0.1
    assert all(np.all(np.isfinite(getattr(part, q))) for q in "xva")
    assert np.all(np.diff(part.x[0]) > 0) and part.x[0, -1] > 2.0  # it shows the escape


def test_non_finite_force_in_an_explicit_run_is_a_solver_error_not_a_value_error():
    # The force turns NaN at t = 0.5 s: the state becomes non-finite, which is a solver failure.
    t = np.linspace(0.0, 1.0, 101)

    def force(tk, x, v):
        return np.array([np.nan if tk > 0.5 else 0.0])

    with pytest.raises(SolverError) as info:
        ri.rk4(1.0, 0.0, 1.0, t, 1.0, 0.0, force)
    assert info.value.time == pytest.approx(0.51, abs=0.011)


def test_a_jacobian_must_return_two_finite_square_matrices():
    t = np.linspace(0.0, 0.1, 11)
    with pytest.raises(TypeError, match="jacobian"):
        ri.newmark_newton(1.0, 0.0, 1.0, t, 1.0, 0.0, jacobian=lambda tk, x, v: np.zeros((1, 1)))
    with pytest.raises(ValueError, match="df/dv must have shape"):
        ri.stiff(1.0, 0.0, 1.0, t, 1.0, 0.0, jacobian=lambda tk, x, v: (np.zeros((1, 1)), np.zeros(2)))


def test_integrate_names_an_unknown_parameter():
    with pytest.raises(TypeError, match=r"wilson takes the parameters \['theta'\], got unknown alpha"):
        ri.integrate("wilson", 1.0, 0.0, 1.0, np.linspace(0, 1, 11), 1.0, 0.0, alpha=0.1)


# ------------------------------------------------------------------------- results and their methods


def _dataclasses_of(module):
    return [
        value
        for name in module.__all__
        if inspect.isclass(value := getattr(module, name)) and dataclasses.is_dataclass(value)
    ]


def test_every_result_is_a_frozen_dataclass_declaring_its_attributes():
    classes = _dataclasses_of(ri) + _dataclasses_of(suspension) + [ri.linear.RecursionMatrices]
    assert {c.__name__ for c in classes} >= {
        "IntegrationResult",
        "SchemeAccuracy",
        "ConvergenceStudy",
        "Deviation",
        "ForceJacobian",
        "RecursionMatrices",
        "FrictionDamper",
    }
    for cls in classes:
        assert cls.__dataclass_params__.frozen, cls
    # Instances hold nothing beyond their declared fields.
    run = ri.average_acceleration(1.0, 0.1, 1.0, np.linspace(0.0, 1.0, 11), 1.0, 0.0)
    chart = ri.scheme_accuracy("wilson", [0.1, 0.2])
    study = ri.convergence_study("average_acceleration", (50, 100))
    damper = suspension.FrictionDamper(10.0, 0.01)
    for obj in (run, chart, study, damper, run.deviation_from(run)):
        assert set(vars(obj)) == {f.name for f in dataclasses.fields(obj)}, type(obj)
    step = ri.linear.houbolt_step(np.eye(1), np.zeros((1, 1)), np.eye(1), 0.1)
    assert isinstance(ri.linear.recursion_matrices(step, 3, 1), ri.linear.RecursionMatrices)


def test_scheme_accuracy_gathers_the_analysis_functions():
    ratios = np.linspace(0.01, 0.5, 30)
    chart = ri.scheme_accuracy("hht_alpha", ratios, 0.05, alpha=-0.1)
    assert chart.parameters == {"alpha": -0.1} and chart.damping_ratio == 0.05
    assert np.array_equal(chart.spectral_radius, ri.spectral_radius("hht_alpha", ratios, 0.05, alpha=-0.1))
    assert np.array_equal(
        chart.period_elongation_fraction, ri.period_elongation("hht_alpha", ratios, 0.05, alpha=-0.1)
    )
    assert np.array_equal(
        chart.amplitude_decay_fraction, ri.amplitude_decay("hht_alpha", ratios, 0.05, alpha=-0.1)
    )
    assert chart.stability_limit_dt_over_T == ri.stability_limit("hht_alpha", 0.05, alpha=-0.1) == np.inf
    with pytest.raises(ValueError, match="dt_over_T must be > 0"):
        ri.scheme_accuracy("rk4", [0.1, -0.1])


def test_accuracy_plots_return_their_artists_and_update_them_in_place():
    fig = Figure()
    ax_rho, ax_pe, ax_ad = fig.subplots(1, 3)
    ratios = np.linspace(0.01, 0.6, 50)
    first = ri.scheme_accuracy("central_difference", ratios)
    rho = first.plot_spectral_radius(ax_rho, color="k", label="cd")
    pe = first.plot_period_elongation(ax_pe)
    ad = first.plot_amplitude_decay(ax_ad)
    line = rho["line"]
    assert isinstance(line, matplotlib.lines.Line2D) and line.get_label() == "cd"
    x, y = line.get_data()
    # ρ > 2 is left out (NaN) past Δt/T = 1/π; below it ρ = 1 for the undamped oscillator.
    assert np.all(np.isnan(y[first.spectral_radius >= 2.0])) and np.allclose(y[x < 0.3], 1.0, atol=1e-12)
    assert np.allclose(pe["line"].get_ydata(), 100 * first.period_elongation_fraction, equal_nan=True)
    assert ax_rho.get_ylabel() == r"spectral radius $\rho(A)$" and ax_pe.get_xlabel() == r"$\Delta t/T$"
    second = ri.scheme_accuracy("houbolt", ratios)
    count = len(ax_rho.lines)
    assert second.plot_spectral_radius(artists=rho) is rho and len(ax_rho.lines) == count
    second.plot_period_elongation(artists=pe)
    second.plot_amplitude_decay(artists=ad)
    assert np.array_equal(rho["line"].get_ydata(), second.spectral_radius)  # all below 1: nothing hidden
    assert np.allclose(ad["line"].get_ydata(), 100 * second.amplitude_decay_fraction)


def test_figure_draws_the_curves_of_scheme_accuracy():
    from raildyn import figures

    fig = figures.make("fig2.spectral_radius")
    line = next(ln for ln in fig.axes[0].lines if ln.get_label() == "Houbolt")
    ratios, drawn = line.get_data()
    expected = ri.scheme_accuracy("houbolt", ratios).spectral_radius
    assert np.array_equal(drawn, expected)
    fig = figures.make("fig2.period_elongation")
    line = next(ln for ln in fig.axes[1].lines if ln.get_label() == "Wilson θ = 1.4")
    ratios, drawn = line.get_data()
    assert np.allclose(drawn, 100 * ri.amplitude_decay("wilson", ratios), rtol=1e-14, atol=0)


def test_integration_result_plot():
    t = np.linspace(0.0, 1.0, 11)
    run = ri.average_acceleration(np.eye(2), np.zeros((2, 2)), np.eye(2), t, [1.0, 2.0], [0.0, 0.0])
    ax = Figure().subplots()
    line = run.plot(ax, dof=1, quantity="v", scale=1e3, color="r")["line"]
    assert np.array_equal(line.get_xdata(), t) and np.allclose(line.get_ydata(), 1e3 * run.v[1])
    with pytest.raises(ValueError, match=r"dof must be an integer in \[0, 1\], got 2"):
        run.plot(ax, dof=2)
    with pytest.raises(ValueError, match="quantity must be one of"):
        run.plot(ax, quantity="jerk")


def test_deviation_compares_on_the_coarser_grid_exactly():
    # The exact free response sampled on a fine grid, against a scheme run on a coarse grid it holds.
    system = vibration.SDOF.from_modal(TWO_PI, 0.05)
    fine_t = np.linspace(0.0, 2.0, 2001)
    x = system.free_response(fine_t, 1.0, 0.0)
    exact = ri.IntegrationResult(fine_t, x[None], np.gradient(x, fine_t)[None], 0 * x[None], "exact", 2000, 0)
    coarse_t = np.linspace(0.0, 2.0, 101)
    run = ri.central_difference(system.mass, system.damping, system.stiffness, coarse_t, 1.0, 0.0)
    dev = run.deviation_from(exact)
    assert np.array_equal(dev.times, coarse_t)
    expected = np.abs(run.x[0] - system.free_response(coarse_t, 1.0, 0.0)).max()
    assert dev.displacement[0] == pytest.approx(expected, rel=1e-9)
    assert exact.deviation_from(run).displacement[0] == pytest.approx(expected, rel=1e-9)  # symmetric
    later = run.deviation_from(exact, after=1.0)
    assert later.times[0] == pytest.approx(1.0) and later.displacement[0] <= dev.displacement[0]
    with pytest.raises(ValueError, match="degrees of freedom"):
        run.deviation_from(
            ri.average_acceleration(np.eye(2), np.zeros((2, 2)), np.eye(2), coarse_t, [1, 0], [0, 0])
        )
    with pytest.raises(ValueError, match="share no time"):
        run.deviation_from(exact, after=3.0)


# ------------------------------------------------------------------- step limits, stiffness, orders


def test_stable_step_matches_the_runs():
    chain = vibration.chain_matrices([1000.0, 800.0, 600.0], [1e6, 5e5, 2e5])
    M, K, C = chain.M, chain.K, 1e-3 * chain.K
    w_max = vibration.modal_analysis(M, K).natural_frequencies[-1]
    limit = ri.stable_step("central_difference", M, C, K)
    assert limit == pytest.approx(2 / w_max, rel=1e-8)  # Δt <= T_min/π (Bathe 1996, §9.4.1)
    x0 = [0.01, 0.0, -0.01]
    ri.central_difference(M, np.zeros((3, 3)), K, np.arange(2000) * 0.999 * limit, x0, [0, 0, 0])
    with pytest.raises(SolverError, match="stable only for"):
        ri.central_difference(M, np.zeros((3, 3)), K, np.arange(2000) * 1.01 * limit, x0, [0, 0, 0])
    # The first-order limit is the one the divergence message names (see test_integrators).
    assert ri.stable_step("rk4", 1.0, 2000.0, 1.0) == pytest.approx(1.3926e-3, rel=1e-4)
    assert ri.stable_step("average_acceleration", M, C, K) == np.inf
    assert ri.stable_step("forward_euler", 1.0, 0.0, 1.0) == 0.0
    with pytest.raises(ValueError, match="K must be 3x3"):
        ri.stable_step("rk4", M, C, np.eye(2))


def test_stiffness_ratio_closed_form():
    # m = 1, c = 1001, k = 1000: λ = −1 and −1000 1/s.
    assert ri.stiffness_ratio(1.0, 1001.0, 1000.0) == pytest.approx(1000.0, rel=1e-10)
    with pytest.raises(ValueError, match="K is singular"):  # a rigid-body mode: the ratio is unbounded
        ri.stiffness_ratio(1.0, 0.0, 0.0)


@pytest.mark.parametrize(("method", "order"), [("central_difference", 2), ("forward_euler", 1), ("rk4", 4)])
def test_convergence_study_measures_the_order(method, order):
    study = ri.convergence_study(method, (200, 400, 800))
    assert np.array_equal(study.step_counts, [200, 400, 800])
    assert np.allclose(study.dt_over_T, [0.01, 0.005, 0.0025])
    slack = 0.2 if method == "forward_euler" else 0.1  # as in test_integrators.test_measured_order_...
    assert np.all(np.abs(study.orders - order) < slack), study.orders
    assert np.all(np.diff(study.max_error_m) < 0)


def test_convergence_study_refuses_bad_counts():
    with pytest.raises(ValueError, match="step_counts must hold at least two increasing"):
        ri.convergence_study("rk4", (400, 200))
    with pytest.raises(TypeError, match="step_counts must be an integer"):
        ri.convergence_study("rk4", (100.5, 200))
    with pytest.raises(ValueError, match="duration must be in"):
        ri.convergence_study("rk4", duration=0.0)


def test_force_jacobian_and_pair_give_the_same_run():
    damper = suspension.FrictionDamper(friction_force=0.5, velocity_scale=0.05)
    t = np.linspace(0.0, 1.0, 201)
    a = ri.newmark_newton(1.0, 0.1, 100.0, t, 0.05, 0.0, damper.force, jacobian=damper.jacobian)

    def pair(tk, x, v):
        j = damper.jacobian(tk, x, v)
        return j.wrt_displacement, j.wrt_velocity

    b = ri.newmark_newton(1.0, 0.1, 100.0, t, 0.05, 0.0, damper.force, jacobian=pair)
    assert np.array_equal(a.x, b.x)


# ------------------------------------------------------------------------------------ public surface

MODULES = [
    "raildyn.integrators",
    "raildyn.integrators.amplification",
    "raildyn.integrators.analysis",
    "raildyn.integrators.linear",
    "raildyn.integrators.nonlinear",
    "raildyn.integrators.recursions",
    "raildyn.integrators.runner",
    "raildyn.integrators.schemes",
    "raildyn.suspension",
]


def _sections(doc: str) -> set[str]:
    return set(re.findall(r"^\s*(\w+)\n\s*-{3,}\s*$", doc or "", flags=re.MULTILINE))


def _public_callables():
    seen = {}
    for module_name in MODULES:
        module = importlib.import_module(module_name)
        for name in module.__all__:
            value = getattr(module, name)
            if inspect.isfunction(value):
                seen[f"{value.__module__}.{value.__qualname__}"] = (value, "function")
            elif inspect.isclass(value) and value.__module__.startswith("raildyn"):
                for attr, member in vars(value).items():
                    if inspect.isfunction(member) and not attr.startswith("_"):
                        seen[f"{value.__module__}.{member.__qualname__}"] = (member, "method")
    return seen


@pytest.mark.parametrize("module_name", MODULES)
def test_every_public_module_has_all(module_name):
    module = importlib.import_module(module_name)
    assert hasattr(module, "__all__")
    for name in module.__all__:
        assert hasattr(module, name), f"{module_name}.__all__ names {name}, which is missing"
    # Every public function or class defined in the module is listed.
    defined = {
        name
        for name, value in vars(module).items()
        if not name.startswith("_")
        and (inspect.isfunction(value) or inspect.isclass(value))
        and getattr(value, "__module__", "") == module_name
    }
    assert defined <= set(module.__all__), sorted(defined - set(module.__all__))


@pytest.mark.parametrize("qualname", sorted(_public_callables()))
def test_every_public_function_and_method_has_parameters_and_returns(qualname):
    function, kind = _public_callables()[qualname]
    sections = _sections(inspect.getdoc(function))
    takes = [p for p in inspect.signature(function).parameters if p not in ("self", "cls")]
    if takes:
        assert "Parameters" in sections, f"{qualname} has no Parameters section"
        documented = inspect.getdoc(function).split("Parameters", 1)[1]
        for name in takes:
            assert re.search(rf"(^|[\s,*]){re.escape(name)}\b", documented), (
                f"{qualname}: {name} undocumented"
            )
    assert "Returns" in sections, f"{qualname} has no Returns section"


@pytest.mark.parametrize(
    "entry",
    [
        ri.integrate,
        ri.newmark,
        ri.central_difference,
        ri.rk4,
        ri.newmark_newton,
        ri.stiff,
        ri.scheme_accuracy,
        ri.stability_limit,
        ri.stable_step,
        ri.convergence_study,
        ri.IntegrationResult.deviation_from,
        suspension.coulomb_friction,
        suspension.coulomb_friction_slope,
        suspension.FrictionDamper,
    ],
    ids=lambda f: f.__qualname__,
)
def test_main_entry_points_have_examples(entry):
    # pytest runs them (--doctest-modules over raildyn/).
    assert "Examples" in _sections(inspect.getdoc(entry))
    assert ">>> " in inspect.getdoc(entry)


def test_package_docstring_states_the_failure_policy():
    doc = raildyn.integrators.__doc__
    assert "SolverError" in doc and "partial" in doc and "success" in doc


def test_maxima_of_a_computed_history():
    # Free vibration, T = 1 s, ξ = 0.05, sampled at T/100: maxima one damped period apart, shrinking by e^δ.
    system = vibration.SDOF.from_modal(TWO_PI, 0.05)
    t = np.linspace(0.0, 3.0, 301)
    run = ri.average_acceleration(system.mass, system.damping, system.stiffness, t, 0.0, 1.0)
    peaks = run.maxima()
    assert peaks.times.size == 3 and isinstance(peaks, ri.Maxima)
    # Sampling places each maximum within half a step (5 ms) of the true one, and the scheme's period
    # elongation at Δt/T = 0.01 is 3e-4: the spacing is T_d = 1.00125 s within 0.011 s.
    assert np.allclose(np.diff(peaks.times), 1 / np.sqrt(1 - 0.05**2), atol=0.011)
    assert np.all(np.diff(peaks.values) < 0)
    assert np.array_equal(peaks.values, run.x[0][np.isin(t, peaks.times)])
    with pytest.raises(ValueError, match="dof must be an integer"):
        run.maxima(dof=1)


def test_newmark_newton_with_a_sampled_load_needs_no_tangent():
    # A force given as samples depends on t alone: its tangent is zero, as a zero jacobian says.
    chain = vibration.chain_matrices([1000.0, 800.0], [1e6, 5e5])
    t = np.linspace(0.0, 1.0, 201)
    load = np.vstack([np.zeros(t.size), 1e3 * np.sin(7 * t)])
    zero = np.zeros((2, 2))
    a = ri.newmark_newton(chain.M, 0.01 * chain.K, chain.K, t, [0.0, 0.0], [0.0, 0.0], load)
    b = ri.newmark_newton(
        chain.M,
        0.01 * chain.K,
        chain.K,
        t,
        [0.0, 0.0],
        [0.0, 0.0],
        load,
        jacobian=lambda tk, x, v: (zero, zero),
    )
    assert np.array_equal(a.x, b.x) and a.iterations == b.iterations


# ------------------------------------------------------------------ bad input, issue 15 (chapter 2's cases)


def test_stiff_hardening_force_is_a_solver_error_or_a_finite_history_on_the_requested_grid():
    t = np.linspace(0.0, 0.5, 11)

    def hardening(tk, x, v):
        return -10.0 * x**3

    run = ri.stiff(1.0, 0.1, TWO_PI**2, t, 1.0, 0.0, hardening, rtol=1e-6, atol=1e-9)
    assert np.array_equal(run.t, t) and all(np.isfinite(getattr(run, q)).all() for q in "xva")
    # A state whose force overflows: at the start it is the caller's x0, refused by name ...
    with pytest.raises(
        ValueError, match=r"force returned a non-finite value at the initial state.*x0 = \[1e\+200\]"
    ):
        ri.stiff(1.0, 0.1, TWO_PI**2, t, 1e200, 0.0, hardening)
    # ... and later a failure of the run, never NaN accelerations.
    with pytest.raises(SolverError) as info:
        ri.stiff(1.0, 0.1, TWO_PI**2, t, 1e100, 0.0, hardening)
    assert np.array_equal(info.value.partial.t, t[: info.value.partial.t.size])


@pytest.mark.parametrize("scheme", [ri.rk4, ri.newmark_newton, ri.stiff])
def test_force_callbacks_are_checked_where_they_are_used(scheme):
    t = np.linspace(0.0, 0.5, 11)
    with pytest.raises(ValueError, match=r"force\(t, x, v\) must return 1 values"):
        scheme(1.0, 0.0, 1.0, t, 1.0, 0.0, lambda tk, x, v: np.zeros(2))
    with pytest.raises(ValueError, match="force returned a non-finite value at the initial state"):
        scheme(1.0, 0.0, 1.0, t, 1.0, 0.0, lambda tk, x, v: np.full(1, np.nan))
    with pytest.raises(ValueError, match=r"force\(t\) must return 1 values"):
        ri.newmark(1.0, 0.0, 1.0, t, 1.0, 0.0, lambda tk: np.zeros(3))
    with pytest.raises(TypeError, match="force must be a number or an array"):
        ri.wilson(1.0, 0.0, 1.0, t, 1.0, 0.0, "abc")


@pytest.mark.parametrize("scheme", [ri.newmark_newton, ri.stiff])
def test_jacobians_are_checked_where_they_are_used(scheme):
    t = np.linspace(0.0, 0.5, 11)

    def force(tk, x, v):
        return -x

    with pytest.raises(TypeError, match="jacobian must be a callable"):
        scheme(1.0, 0.0, 1.0, t, 1.0, 0.0, force, jacobian=1.0)
    with pytest.raises(
        ValueError, match=r"jacobian\(t, x, v\) returned a non-finite df/dx at the initial state"
    ):
        scheme(
            1.0,
            0.0,
            1.0,
            t,
            1.0,
            0.0,
            force,
            jacobian=lambda tk, x, v: (np.full((1, 1), np.nan), np.zeros((1, 1))),
        )
    with pytest.raises(ValueError, match=r"jacobian\(t, x, v\) df/dv must have shape \(1, 1\)"):
        scheme(1.0, 0.0, 1.0, t, 1.0, 0.0, force, jacobian=lambda tk, x, v: (np.zeros((1, 1)), np.zeros(2)))


@pytest.mark.parametrize(
    ("scheme", "setting", "value"),
    [
        (ri.stiff, "rtol", np.nan),
        (ri.stiff, "rtol", np.inf),
        (ri.stiff, "atol", 0.0),
        (ri.stiff, "atol", -1e-9),
        (ri.newmark_newton, "tol", 0.0),
        (ri.newmark_newton, "tol", 2.0),
        (ri.newmark_newton, "max_iter", 10**12),
        (ri.newmark_newton, "max_iter", 2.5),
        (ri.newmark_newton, "beta", 0.0),
        (ri.newmark, "gamma", 0.4),
        (ri.hht_alpha, "alpha", -0.5),
        (ri.wilson, "theta", np.nan),
    ],
)
def test_solver_settings_are_checked(scheme, setting, value):
    t = np.linspace(0.0, 0.5, 11)
    with pytest.raises((ValueError, TypeError), match=rf"\b{setting} must"):
        scheme(1.0, 0.0, 1.0, t, 1.0, 0.0, **{setting: value})


def test_unknown_scheme_parameters_are_named():
    t = np.linspace(0.0, 0.5, 11)
    with pytest.raises(TypeError, match="got unknown not_a_parameter"):
        ri.integrate("newmark", 1.0, 0.0, 1.0, t, 1.0, 0.0, not_a_parameter=1.0)
    with pytest.raises(TypeError, match="got unknown beta"):
        ri.stability_limit("wilson", beta=0.25)


def test_results_built_by_hand_are_checked():
    t = np.linspace(0.0, 1.0, 5)
    with pytest.raises(ValueError, match="x must contain only finite numbers"):
        ri.IntegrationResult(t, np.full((1, 5), np.nan), 0 * t[None], 0 * t[None], "x", 4, 0)
    with pytest.raises(ValueError, match=r"v must have shape \(n, m\)"):
        ri.IntegrationResult(t, 0 * t[None], np.zeros((1, 4)), 0 * t[None], "x", 4, 0)
    with pytest.raises(ValueError, match="steps must be an integer"):
        ri.IntegrationResult(t, 0 * t[None], 0 * t[None], 0 * t[None], "x", -1, 0)
    with pytest.raises(ValueError, match="wrt_velocity must be 2x2"):
        ri.ForceJacobian(np.eye(2), np.eye(3))
    with pytest.raises(ValueError, match="stability_limit_dt_over_T may be inf only"):
        ri.SchemeAccuracy(
            "rk4", {}, 0.0, np.array([0.1]), np.array([1.0]), np.array([0.0]), np.array([0.0]), np.inf
        )
    # The documented NaN of a period elongation, where the computed motion does not oscillate, is kept.
    chart = ri.scheme_accuracy("central_difference", [0.1, 0.5])
    assert np.isnan(chart.period_elongation_fraction[1]) and np.isfinite(chart.period_elongation_fraction[0])


def test_analysis_domains():
    with pytest.raises(ValueError, match="dt_over_T must be <= 1e\\+06"):
        ri.spectral_radius("newmark", 1e300)
    with pytest.raises(ValueError, match="eigenvalue must be nonzero"):
        ri.first_order_step_limit("rk4", 0.0)
    with pytest.raises(ValueError, match="duration must be in"):
        ri.convergence_study("rk4", (8, 16), 1e300)
    with pytest.raises(ValueError, match="step_counts must be an integer in"):
        ri.convergence_study("rk4", (8, 10**12))
    with pytest.raises(ValueError, match="size must be 2n or 3n"):
        ri.linear.recursion_matrices(
            ri.linear.houbolt_step(np.eye(1), np.zeros((1, 1)), np.eye(1), 0.1), 4, 1
        )
