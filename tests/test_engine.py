"""The compiled engine of the nonlinear lateral models (raildyn.wheelset._engine) against the numpy models
and scipy's integration of them, and each law written once (the wheel–rail law, the curve's ramp, the
arc Newton) giving its compiled and its numpy callers the same answer.

Its right-hand side is the models' own equations evaluated in another order, so it is held to theirs at
round-off: 1e-13 of the largest entry. Integrated, the engine takes scipy RK45's steps until a rounding
difference tips one accept-or-reject decision (the flange and the saturation put kinks in the forces);
from there the two runs differ by the integration error, which rtol 1e-6 holds to about 1e-5 of the
motion over a run (measured 7e-6 on the wheelset's cycle, 1e-5 on the car's). Limit cycles are
therefore held to 1e-4 of their amplitude and frequency (1.5 µm of a 15 mm cycle), a tenth of what a
diagram shows, and the nonlinear critical speed to the same bisection step.
"""

import numpy as np
import pytest

from raildyn import stability
from raildyn.contact.profiles import s1002_wheel, uic60_rail
from raildyn.errors import SolverError
from raildyn.track import Curve
from raildyn.vehicles import Bogie, LateralCar
from raildyn.wheelset import (
    NonlinearLateral,
    NonlinearWheelset,
    SuspensionElement,
    WheelRailContact,
    Wheelset,
    _engine,
    contact_forces,
    profile_contact,
)

AGREEMENT = 1e-4  # relative, of a limit cycle's amplitude and frequency (module docstring)


def _wheelset():
    return NonlinearWheelset(Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6))


def _models():
    """Each model with the speed it is run at."""
    car = LateralCar().nonlinear()
    curve = Curve(radius=600.0, cant=0.1, transition_length=60.0, arc_length=100.0, straight=20.0)
    return {
        "wheelset": (_wheelset(), 60.0),
        "bogie": (Bogie().nonlinear(), 40.0),
        "car": (car, 70.0),
        "car on S1002": (
            NonlinearLateral(car.system, profile_contact(s1002_wheel(), uic60_rail(1 / 40))),
            55.0,
        ),
        "car in a curve": (car.replace(curve=curve, start=10.0), 40.0),
    }


@pytest.mark.parametrize("name", list(_models()))
def test_the_compiled_right_hand_side_is_the_models(name):
    model, speed = _models()[name]
    compiled = model.compiled_rhs(speed)
    data = compiled.row[None, :].copy()
    rng = np.random.default_rng(7)
    half = model.state_size // 2
    for _ in range(20):
        # Displacements to 15 mm (past the flange), rates to 0.15 m/s: every branch of the forces.
        state = rng.normal(size=model.state_size) * np.r_[np.full(half, 5e-3), np.full(half, 5e-2)]
        t = rng.uniform(0.0, 4.0)  # along the curve: straight, clothoid and arc
        expected = model.rhs(t, state, speed)
        out = np.empty_like(state)
        compiled.kernel(t, state, 0, data, out)
        np.testing.assert_allclose(out, expected, rtol=0, atol=1e-13 * np.abs(expected).max())


def test_the_wheelsets_limit_cycle_is_scipys():
    compiled = stability.limit_cycle_amplitude(_wheelset(), 60.0, duration=4.0, engine="compiled")
    reference = stability.limit_cycle_amplitude(_wheelset(), 60.0, duration=4.0, engine="scipy")
    assert compiled.hunting() and reference.hunting()
    assert compiled.amplitude == pytest.approx(reference.amplitude, rel=AGREEMENT)
    assert compiled.frequency_hz == pytest.approx(reference.frequency_hz, rel=AGREEMENT)
    assert compiled.amplitude == pytest.approx(10.3e-3, abs=0.05e-3)  # the docstring's cycle


@pytest.mark.slow  # a ramp of runs through scipy beside the engine's, seconds
def test_the_wheelsets_bifurcation_diagram_is_scipys():
    # Five speeds either side of the wheelset's onset, 2 s runs and two bisections: scipy takes some
    # seconds (the ramp's chaining and the bisection are the diagram's own; more of them test no more).
    speeds = np.linspace(45.0, 65.0, 5)
    kwargs = dict(duration=2.0, refine=2, progress=False)
    compiled = stability.bifurcation_diagram(_wheelset(), speeds, **kwargs)
    reference = stability.bifurcation_diagram(_wheelset(), speeds, engine="scipy", **kwargs)
    assert compiled.hunting.any() and not compiled.hunting.all()
    np.testing.assert_array_equal(compiled.hunting, reference.hunting)
    np.testing.assert_allclose(compiled.amplitudes, reference.amplitudes, rtol=AGREEMENT, atol=1e-9)
    np.testing.assert_allclose(compiled.frequencies_hz, reference.frequencies_hz, rtol=AGREEMENT)
    assert compiled.nonlinear_critical_speed == reference.nonlinear_critical_speed


@pytest.mark.slow  # a ramp of runs through scipy beside the engine's, seconds
def test_the_cars_bifurcation_diagram_is_scipys():
    # Three speeds about the car's fold, 2 s runs: scipy takes some seconds, the engine a tenth of one.
    car = LateralCar().nonlinear()
    kwargs = dict(duration=2.0, refine=1, progress=False)
    compiled = stability.bifurcation_diagram(car, [50.0, 70.0, 90.0], **kwargs)
    reference = stability.bifurcation_diagram(car, [50.0, 70.0, 90.0], engine="scipy", **kwargs)
    np.testing.assert_array_equal(compiled.hunting, reference.hunting)
    assert compiled.hunting.any() and not compiled.hunting.all()
    # A decaying run's amplitude is what is left of the 12 mm start: its error is that of the run's scale.
    scale = reference.amplitudes.max()
    np.testing.assert_allclose(compiled.amplitudes, reference.amplitudes, rtol=0, atol=AGREEMENT * scale)
    np.testing.assert_allclose(compiled.frequencies_hz, reference.frequencies_hz, rtol=AGREEMENT)
    assert compiled.nonlinear_critical_speed == reference.nonlinear_critical_speed


def test_a_batch_of_models_gives_each_models_own_diagram():
    family = [_wheelset().wheelset.replace(conicity=lam) for lam in (0.1, 0.15, 0.2)]
    models = [NonlinearWheelset(ws) for ws in family]
    speeds = np.linspace(40.0, 80.0, 5)
    together = stability.bifurcation_diagrams(models, speeds, duration=3.0, refine=2, progress=False)
    for model, diagram in zip(models, together, strict=True):
        alone = stability.bifurcation_diagram(model, speeds, duration=3.0, refine=2, progress=False)
        np.testing.assert_array_equal(diagram.amplitudes, alone.amplitudes)
        assert diagram.nonlinear_critical_speed == alone.nonlinear_critical_speed
    # A steeper cone hunts from a lower speed.
    onsets = [d.nonlinear_critical_speed for d in together]
    assert onsets[0] > onsets[1] > onsets[2]


def test_the_curve_entry_is_scipys():
    model, _ = _models()["car in a curve"]
    compiled = stability.simulate(model, 40.0, np.zeros(model.state_size), 2.0, max_step=0.01)
    reference = stability.simulate(
        model, 40.0, np.zeros(model.state_size), 2.0, max_step=0.01, engine="scipy"
    )
    np.testing.assert_array_equal(compiled.t, reference.t)
    # The coordinates, which the curve's offsets, angles of attack and flange forces are read from, to
    # 1e-4 of each one's range (measured 2e-6). The rates jump where a flange strikes its rail (a 14.6 MN/m
    # spring), so a step placed differently moves them by more: 1e-3 (measured 3e-4).
    half = model.state_size // 2
    error = np.abs(compiled.states - reference.states).max(axis=1)
    scale = np.abs(reference.states).max(axis=1)
    assert np.all(error[:half] <= AGREEMENT * scale[:half])
    assert np.all(error[half:] <= 10 * AGREEMENT * scale[half:])


def test_what_the_engine_cannot_hold_runs_on_scipy_or_is_refused():
    model = Bogie().nonlinear()
    label = model.system.labels[model.lateral_index]
    element = SuspensionElement({label: 1.0}, lambda d, v: 1e3 * d)
    with_law = model.replace(elements=(element,))
    assert model.compiled_reason is None
    assert "force laws in Python" in with_law.compiled_reason
    with pytest.raises(ValueError, match="compiled engine cannot run this model"):
        with_law.compiled_rhs(40.0)
    table = profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    python_geometry = WheelRailContact(rolling_radius_difference=lambda y: 0.3 * y)
    assert model.replace(contact=table).compiled_reason is None
    assert (
        "rolling_radius_difference is a Python function"
        in model.replace(contact=python_geometry).compiled_reason
    )
    start = np.zeros(model.state_size)
    start[model.lateral_index] = 1e-3
    run = stability.simulate(with_law, 40.0, start, 0.05)  # auto: scipy
    assert run.states.shape == (model.state_size, run.t.size)
    with pytest.raises(ValueError, match="engine 'compiled' cannot run this model"):
        stability.simulate(with_law, 40.0, start, 0.05, engine="compiled")
    with pytest.raises(ValueError, match="runs method 'RK45' only"):
        stability.simulate(model, 40.0, start, 0.05, engine="compiled", method="BDF")
    with pytest.raises(ValueError, match="engine must be one of"):
        stability.simulate(model, 40.0, start, 0.05, engine="numba")


def test_a_run_over_its_budget_fails_loudly():
    with pytest.raises(SolverError, match="more than 1000000 evaluations"):
        stability.simulate(_wheelset(), 60.0, [1e-3, 0, 0, 0], 1.0, max_step=1e-7)


class _NumpyForces(NonlinearLateral):
    """The model with the compiled engine refused: its forces in numpy, as a Python force law has them."""

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "compiled_reason", "the numpy path, for the comparison")
        object.__setattr__(self, "_row", None)


def test_the_arc_newton_gives_the_compiled_and_the_numpy_forces_one_map():
    # One Newton (raildyn.wheelset.arc_newton), its forces and Jacobian from the engine or from numpy.
    from raildyn.curving import curving_map

    model = Bogie().nonlinear()
    speeds, radii = np.linspace(10.0, 25.0, 4), np.geomspace(150.0, 3000.0, 5)
    compiled = curving_map(model, speeds, radii, 0.1)
    reference = curving_map(_NumpyForces(model.system, model.contact), speeds, radii, 0.1)
    # Both converge to the same equilibria, within Newton's tolerance (1e-9 of the weight in N): far below
    # 1e-9 m and rad.
    np.testing.assert_allclose(compiled.offset, reference.offset, rtol=0, atol=1e-9)
    np.testing.assert_allclose(compiled.angle_of_attack, reference.angle_of_attack, rtol=0, atol=1e-9)
    np.testing.assert_allclose(compiled.flange_force, reference.flange_force, rtol=1e-6, atol=1e-2)


@pytest.mark.parametrize("contact", ["cone", "S1002"])
def test_the_wheel_rail_law_is_one_function_for_the_engine_and_numpy(contact):
    # The engine's wheel_rail and contact_forces both evaluate raildyn.wheelset._law.wheelset: the same
    # numbers to the last bit, not merely close. The next test holds the law itself to chapter 4's parts.
    rail = WheelRailContact() if contact == "cone" else profile_contact(s1002_wheel(), uic60_rail(1 / 40))
    model = NonlinearWheelset(Wheelset(), rail)
    row = model.compiled_rhs(30.0).row
    rng = np.random.default_rng(3)
    y, psi = rng.normal(0.0, 6e-3, 50), rng.normal(0.0, 3e-3, 50)  # past the flange and back
    ydot, psidot = rng.normal(0.0, 0.05, 50), rng.normal(0.0, 0.05, 50)
    lateral, yaw = contact_forces(Wheelset(), rail, y, psi, ydot, psidot, 30.0)
    for i in range(50):
        assert _engine.wheel_rail(row, 0, y[i], psi[i], ydot[i], psidot[i], 30.0) == (lateral[i], yaw[i])


def test_the_curves_ramp_is_one_function_for_the_engine_and_numpy():
    # Curve.curvature and cant_at (numpy) and the engine's curve (compiled) all take raildyn.track.curve.ramp.
    curve = Curve(radius=600.0, cant=0.1, transition_length=60.0, arc_length=100.0, straight=20.0)
    row = LateralCar().nonlinear().replace(curve=curve).compiled_rhs(30.0).row
    s = np.linspace(-10.0, curve.length + 10.0, 401)
    compiled = np.array([_engine._share(row, v) for v in s])
    np.testing.assert_array_equal(compiled / curve.radius, curve.curvature(s))
    np.testing.assert_array_equal(compiled * curve.cant, curve.cant_at(s))


def test_the_wheel_rail_law_is_chapter_4s_creepages_kalker_and_saturation():
    # An independent composition in numpy of the public laws of raildyn.contact, on the cone: the
    # creepages of wheelset_creepages (less the centred spins ∓ sin ϑ₀/r₀, contact_forces says why), Kalker's
    # linear forces, Shen–Hedrick–Elkins's factor, gravity, the gravitational yaw stiffness and the flange.
    from raildyn.contact import saturation_factor, wheelset_creepages

    ws, rail = Wheelset(), WheelRailContact()
    rng = np.random.default_rng(11)
    y, psi = rng.normal(0.0, 6e-3, 40), rng.normal(0.0, 3e-3, 40)
    ydot, psidot, V = rng.normal(0.0, 0.05, 40), rng.normal(0.0, 0.05, 40), 35.0
    a, r0, W = ws.half_gauge, ws.rolling_radius, ws.axle_load
    dr, dd = 2 * ws.conicity * y, 2 * ws.contact_angle_parameter * y / a
    theta = ws.contact_angle + np.array([0.5, -0.5])[:, None] * dd
    c = wheelset_creepages(V, ydot, psi, psidot, r0 + dr / 2, r0 - dr / 2, r0, a, theta[0], theta[1])
    spin = c.spin + np.array([1.0, -1.0])[:, None] * np.sin(ws.contact_angle) / r0
    fx, fy = -ws.f11 * c.longitudinal, -ws.f22 * c.lateral - ws.f23 * spin
    mz = ws.f23 * c.lateral - ws.f33 * spin
    scale = saturation_factor(np.hypot(fx, fy), rail.friction * W / 2)
    flange = -rail.flange_stiffness * np.sign(y) * np.maximum(np.abs(y) - rail.flange_clearance, 0.0)
    lateral = (scale * fy).sum(axis=0) - W / 2 * dd + flange
    yaw = (
        a * (scale[1] * fx[1] - scale[0] * fx[0]) + (scale * mz).sum(axis=0) + W * a * ws.contact_angle * psi
    )
    ours = contact_forces(ws, rail, y, psi, ydot, psidot, V)
    # Round-off of sums of terms up to some 1e5 N: 1e-9 of the largest force.
    np.testing.assert_allclose(ours[0], lateral, rtol=0, atol=1e-9 * np.abs(lateral).max())
    np.testing.assert_allclose(ours[1], yaw, rtol=0, atol=1e-9 * np.abs(yaw).max())
