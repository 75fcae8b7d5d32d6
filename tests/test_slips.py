"""A student's slips refused with a message that names them (issue 31, item 6).

Each test holds one slip that raildyn used to compute on (or to fail on with a message naming
nothing the caller passed): complex numbers and booleans taken for numbers, a speed typed in km/h,
lengths in millimetres, a friction coefficient in per cent, absurd masses and contact patches,
steps that would fill the memory, finite input that overflowed into NaN, a class passed for a model,
repeated or empty labels, and records that contradict themselves. The fuzz test
(``tests/test_fuzz.py``) tries these kinds of slip on every public callable; here are the named
cases, each with the message it must give.
"""

from __future__ import annotations

import re
import tracemalloc

import numpy as np
import pytest

from raildyn import _checks, constants, contact, curving, stability, train, vehicles
from raildyn.bridge import SimplySupportedBeam, moving_force_response
from raildyn.constants import MAXIMUM_SPEED, PLAUSIBLE_RANGES
from raildyn.errors import SolverError
from raildyn.linear_model import Assembler, SystemMatrices
from raildyn.ride import sperling_harmonic
from raildyn.suspension import clearance_force
from raildyn.track import Curve, axle_delays
from raildyn.validation.identification import coast_down
from raildyn.validation.measured import StrainRecord
from raildyn.vehicles import LateralCar, VerticalCar, VerticalFreightCar, rock_and_roll, track_frf
from raildyn.wheelset import NonlinearWheelset, WheelRailContact, Wheelset, add_wheelset

# --------------------------------------------------------------------------- one speed limit


def test_one_speed_limit_for_the_whole_package():
    # 200 m/s = 720 km/h, above the wheel-rail record of 574.8 km/h (TGV V150, 3 April 2007).
    assert MAXIMUM_SPEED == 200.0 > 574.8 / 3.6
    assert PLAUSIBLE_RANGES["speed"].high == MAXIMUM_SPEED
    from pathlib import Path

    from raildyn.track import cant

    assert cant.MAXIMUM_SPEED is MAXIMUM_SPEED  # re-exported, not defined again
    # no module defines a speed limit of its own (the track's was 1000 m/s, the train's a copy)
    package = Path(constants.__file__).parent
    for path in package.rglob("*.py"):
        if path.name != "constants.py":
            text = path.read_text(encoding="utf-8")
            assert not re.search(r"^\s*_?MAX(IMUM)?_SPEED\s*=\s*[-\d.]", text, re.M), path


@pytest.mark.parametrize(
    "call",
    [
        pytest.param(lambda: Wheelset().matrices(300.0), id="Wheelset.matrices"),
        pytest.param(lambda: track_frf(VerticalCar(), [1.0, 2.0], 300.0), id="track_frf"),
        pytest.param(
            lambda: stability.simulate(NonlinearWheelset(), 300.0, [1e-3, 0.0, 0.0, 0.0], 0.1), id="simulate"
        ),
        pytest.param(
            lambda: moving_force_response(SimplySupportedBeam(), 300.0, 1e5), id="moving_force_response"
        ),
        pytest.param(lambda: axle_delays([0.0, 2.5], 300.0), id="axle_delays"),
        pytest.param(
            lambda: contact.wheelset_creepages(300.0, 0.0, 0.0, 0.0, 0.46, 0.46, 0.46, 0.75),
            id="wheelset_creepages",
        ),
        pytest.param(
            lambda: rock_and_roll(VerticalFreightCar(), [25.0, 300.0], cycles=4), id="rock_and_roll"
        ),
    ],
)
def test_a_speed_typed_in_kmh_is_refused(call):
    # 300 typed for a 300 km/h train: the message says the limit and suggests the slip.
    with pytest.raises(
        ValueError, match=r"speeds? must be in [(\[][0-9.]+, 200.0\] m/s .*300 km/h is 83.33 m/s"
    ):
        call()


def test_a_critical_speed_is_searched_within_the_speed_limit():
    with pytest.raises(ValueError, match=r"speed_range\[1\] must be in \(1.0, 200.0\] m/s"):
        stability.critical_speed(LateralCar(), (1.0, 300.0))
    # a car stable up to the limit is reported so, as for any stable range
    stable = stability.critical_speed(LateralCar(), (1.0, 50.0))
    assert stable.status == "stable over the range" and stable.speed == np.inf


# --------------------------------------------------------------------------- millimetres, per cent, tonnes


def test_lengths_in_millimetres_are_refused():
    with pytest.raises(ValueError, match=r"rolling_radius must be in \[0.1, 1.5\] m .*460 mm is 0.46 m"):
        Wheelset(rolling_radius=460.0)
    with pytest.raises(ValueError, match=r"half_gauge must be in \[0.15, 1.1\] m .*got 1435.0"):
        Wheelset(half_gauge=1435.0)
    with pytest.raises(
        ValueError, match=r"semi_bogie_spacing must be in \[0.01, 100.0\] m .*9500 mm is 9.5 m"
    ):
        VerticalCar(semi_bogie_spacing=9500.0)


@pytest.mark.parametrize("mu", [5.0, 30.0])
def test_a_friction_coefficient_above_one_is_refused(mu):
    with pytest.raises(ValueError, match=r"friction must be in \(0.0, 1.0\]"):
        WheelRailContact(friction=mu)
    with pytest.raises(ValueError, match=r"friction must be in \(0.0, 1.0\]"):
        contact.polach(1e-3, 0.0, 0.0, 1e5, mu, 6e-3, 4e-3)
    if mu == 30.0:  # a percentage
        with pytest.raises(ValueError, match=r"a percentage\? 30 % is 0.3"):
            contact.fastsim(1e-3, 0.0, 0.0, 1e5, mu, 6e-3, 4e-3)


def test_contact_semi_axes_of_metres_are_refused():
    with pytest.raises(ValueError, match=r"a must be in \[1e-05, 0.05\] m"):
        contact.fastsim(1e-3, 0.0, 0.0, 1e5, 0.3, 6.0, 6.0)
    with pytest.raises(ValueError, match=r"b must be in \[1e-05, 0.05\] m"):
        contact.creep_coefficients(6e-3, 6.0)


def test_a_mass_of_a_billion_kilograms_is_refused():
    with pytest.raises(ValueError, match=r"mass must be in \[10.0, 1000000.0\] kg"):
        Wheelset(mass=1e9)
    with pytest.raises(ValueError, match=r"body_mass must be in \[10.0, 1000000.0\] kg"):
        LateralCar(body_mass=1e9)
    with pytest.raises(ValueError, match=r"body_mass .* a mass in tonnes\? 3.2 t is 3200 kg"):
        VerticalCar(body_mass=3.2)


def test_each_range_states_its_reason():
    for name, r in PLAUSIBLE_RANGES.items():
        assert r.low < r.high and r.what and len(r.reason) > 60, name
    with pytest.raises(ValueError, match="low must be below high"):
        constants.PlausibleRange("a length", 2.0, 1.0, "m", "a reason")


# --------------------------------------------------------------------------- complex values and booleans


def test_complex_values_are_refused_not_cast():
    with pytest.raises(TypeError, match="M must hold real numbers, got complex values"):
        SystemMatrices(
            np.eye(1) * (1 + 1j), np.eye(1), np.eye(1), np.zeros((1, 1)), np.zeros((1, 1)), ("q",), 30.0
        )
    with pytest.raises(TypeError, match="x must hold real numbers, got complex values"):
        _checks.array("x", np.array([1.0, 2.0 + 1e-9j]))
    with pytest.raises(TypeError, match="x must be a real number"):
        _checks.scalar("x", np.array(1.0 + 0j))


def test_one_number_is_checked_as_cheaply_and_as_strictly_as_an_array():
    # The short path for one number (a law's parameter inside a model's loop) accepts what the array
    # checks accept and leaves every refusal, with its message, to them.
    assert float(_checks.array("x", 2.0, low=0.0)) == 2.0 and _checks.array("x", 0.0, low=0.0).ndim == 0
    with pytest.raises(ValueError, match=r"x must be >= 0.0 everywhere, got -1.0"):
        _checks.array("x", -1.0, low=0.0)
    with pytest.raises(ValueError, match=r"x must be > 0.0 everywhere, got 0.0"):
        _checks.array("x", 0.0, low=0.0, low_open=True)
    with pytest.raises(ValueError, match="x must contain only finite numbers"):
        _checks.array("x", np.inf)
    assert float(_checks.smoothing_speed("v", 1.0e-3)) == 1.0e-3
    with pytest.raises(ValueError, match=r"v must be in \[1e-06, 1\] m/s"):
        _checks.smoothing_speed("v", 2.0)
    assert _checks.broadcast() == () and _checks.broadcast(a=np.zeros(3), b=1.0, c=np.ones(3)) == (3,)
    assert _checks.broadcast(a=np.zeros((2, 3)), b=np.zeros(3)) == (2, 3)
    with pytest.raises(ValueError, match=r"b has shape \(4,\), which does not broadcast against a"):
        _checks.broadcast(a=np.zeros(3), b=np.zeros(4))


def test_booleans_are_not_numbers():
    with pytest.raises(TypeError, match="amplitude must hold numbers, not booleans"):
        sperling_harmonic(amplitude=True, frequency=2.0)
    with pytest.raises(TypeError, match="frequency must hold numbers, not booleans"):
        sperling_harmonic(1.0, np.array([True, False]))


# --------------------------------------------------------------------------- memory and work


def _no_integration(monkeypatch):
    """Make every entry of the integration runner fail the test: the call must refuse before any run."""
    from raildyn.integrators import runner

    def ran(*args, **kwargs):
        raise AssertionError("an integration ran: the refusal must come before any work")

    for name in ("dormand_prince", "dormand_prince_batch", "solve_ivp"):
        monkeypatch.setattr(runner, name, ran)


def test_a_step_that_would_fill_the_memory_is_refused_before_allocating(monkeypatch):
    model, bogie = NonlinearWheelset(), vehicles.Bogie().nonlinear()
    curve = Curve(radius=600.0, cant=0.1, transition_length=30.0, arc_length=20.0, straight=10.0)
    _no_integration(monkeypatch)
    tracemalloc.start()
    try:
        with pytest.raises(ValueError, match=r"max_step = 1e-300 would need .* GiB of memory"):
            stability.simulate(model, 30.0, [1e-3, 0.0, 0.0, 0.0], 1.0, max_step=1e-300)
        with pytest.raises(ValueError, match=r"max_step = 1e-09 would need .* GiB of memory"):
            curving.curve_entry(bogie, 25.0, curve, max_step=1e-9)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    # The runs would need GiB; refused before allocating, the calls' peak stays far below that.
    assert peak < 50e6, f"{peak / 1e6:.0f} MB allocated before the refusal"


def test_a_hopeless_periodic_orbit_gives_up_within_its_budget(monkeypatch):
    # A car's orbit guessed at a period of 100 s: each integration used to run to its own bound of
    # 10⁶ evaluations (about 50 s here, 104 s in the issue); the shooting now shares 10⁵ in all, and the
    # evaluations its runs make are counted here.
    from raildyn.integrators import runner

    model = LateralCar().nonlinear()
    state = np.zeros(model.state_size)
    state[model.lateral_index] = 0.01
    budgets = []

    class Counted(runner.EvaluationBudget):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            budgets.append(self)

    monkeypatch.setattr(runner, "EvaluationBudget", Counted)
    # The shooting's budget cut tenfold, so that spending it takes a second, not ten: the same mechanism.
    from raildyn.stability import bifurcation

    assert bifurcation._SHOOTING_EVALUATIONS == 100_000
    monkeypatch.setattr(bifurcation, "_SHOOTING_EVALUATIONS", 10_000)
    with pytest.raises(SolverError, match="needed more than 10000 evaluations"):
        stability.periodic_orbit(model, 70.0, state, 100.0, max_iter=3)
    # One budget for the whole shooting, spent: the runs stopped at its evaluations in all.
    assert [(b.limit, b.used <= b.limit) for b in budgets] == [(10_000, True)]


# --------------------------------------------------------------------------- finite input, non-finite output


def test_finite_absurd_input_never_gives_a_silent_nan():
    model = train.braking_model(5, 1)
    for rhs in (model.rhs, model.rhs_numpy):
        with pytest.raises(ValueError, match=r"y holds sizes at which the forces overflow"):
            rhs(1.0, np.full(12, 1e300))
    with pytest.raises(ValueError, match=r"mass_per_length must be in \[1.0, 1000000.0\] kg/m"):
        SimplySupportedBeam(mass_per_length=1e-300)
    assert np.isfinite(clearance_force(1e300, 0.01, 1.0e6))  # finite, as it should be
    with pytest.raises(ValueError, match=r"the force overflows: deflection, clearance, stop_stiffness"):
        clearance_force(1e300, 0.01, 1.0e10)


# --------------------------------------------------------------------------- messages naming the parameter


def test_a_class_passed_for_a_model_is_named():
    with pytest.raises(TypeError, match=r"model must be a linear model, an instance such as Wheelset\(\)"):
        stability.critical_speed(Wheelset, (1.0, 100.0))
    with pytest.raises(
        TypeError, match=r"model must be a nonlinear model, an instance such as NonlinearWheelset"
    ):
        stability.simulate(NonlinearWheelset, 30.0, [1e-3, 0.0, 0.0, 0.0], 0.1)


def test_empty_creepages_are_refused_under_their_own_names():
    coefficients = contact.creep_coefficients(6e-3, 4e-3)
    with pytest.raises(ValueError, match="longitudinal must not be empty"):
        contact.kalker_linear([], 0.0, 0.0, coefficients)
    with pytest.raises(ValueError, match="longitudinal must not be empty"):
        contact.polach([], 0.0, 0.0, 1e5, 0.3, 6e-3, 4e-3)
    with pytest.raises(ValueError, match="longitudinal must not be empty"):
        contact.fastsim([], 0.0, 0.0, 1e5, 0.3, 6e-3, 4e-3)
    with pytest.raises(ValueError, match="lateral_velocity must not be empty"):
        contact.wheelset_creepages(30.0, [], 0.0, 0.0, 0.46, 0.46, 0.46, 0.75)


def test_a_tiny_radius_is_named_not_left_to_overflow():
    with pytest.raises(ValueError, match=r"radius must be in \[50.0, inf\]"):
        curving.stiffness.self_steering_curving(vehicles.Bogie(), 1e-300)
    with pytest.raises(ValueError, match=r"wheel_rolling_radius must be in \[0.1, 1.5\] m"):
        contact.hertz_contact(1e5, 1e-300, np.inf, 0.3)  # was a ZeroDivisionError


# --------------------------------------------------------------------------- labels and records


def test_repeated_or_empty_labels_are_refused_everywhere():
    M = np.eye(2)
    Z = np.zeros((2, 2))
    with pytest.raises(ValueError, match="labels must not repeat a name"):
        SystemMatrices(M, Z, Z, np.zeros((2, 1)), np.zeros((2, 1)), ("a", "a"), 30.0)
    with pytest.raises(ValueError, match="labels must not hold an empty name"):
        Assembler(["a", ""])
    asm = Assembler(["a", "b"])
    with pytest.raises(ValueError, match="labels must not repeat a name"):
        asm.block(["a", "a"], K=np.eye(2))
    with pytest.raises(ValueError, match="psi must be another coordinate than y"):
        add_wheelset(asm, "a", "a", Wheelset())
    add_wheelset(asm, "a", "b", Wheelset())
    with pytest.raises(ValueError, match="is already a wheelset's coordinate"):
        add_wheelset(asm, "a", "b", Wheelset())


def test_impossible_records_are_refused():
    t = np.arange(0.0, 60.0, 1.0)
    with pytest.raises(ValueError, match="speed must fall over the record"):
        coast_down(t, 20.0 + 0.01 * t, 4.0e5)  # a coast-down that speeds up
    record = dict(
        time=np.arange(0.0, 1.0, 0.01),
        strain=np.zeros((1, 100)),
        channels=("g",),
        positions=np.array([1.0]),
        units=("-",),
        provenance="a test",
    )
    StrainRecord(rate_hz=100.0, **record)  # the time vector's own rate
    with pytest.raises(ValueError, match=r"rate_hz must be the sampling rate of time, 1/Δt = 100 Hz"):
        StrainRecord(rate_hz=1000.0, **record)
