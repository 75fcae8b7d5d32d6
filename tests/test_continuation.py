"""The branch of limit cycles by pseudo-arclength continuation (raildyn.stability.continuation).

Three checks of the continuation itself, each independent of it:

* a closed form: the normal form of a subcritical Hopf bifurcation with a fold (the Bautin normal
  form), whose cycles, fold, periods and multipliers are known exactly;
* the ramp-down of :func:`~raildyn.stability.bifurcation_diagram` (direct integration from a
  disturbance) on the stable branch, long runs about the fold, and runs started either side of an
  unstable cycle (the edge of the basin of the centred running);
* :func:`~raildyn.stability.periodic_orbit` (scipy's DOP853 on the numpy right-hand side, central
  differences) on an unstable cycle, and the linear critical speed at the Hopf end.
"""

from dataclasses import dataclass

import numpy as np
import pytest
from matplotlib.figure import Figure

from raildyn import stability
from raildyn.errors import SolverError
from raildyn.vehicles import LateralCar
from raildyn.wheelset import NonlinearWheelset, Wheelset

SOFT = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)  # linear critical speed 54.48 m/s


# ---------------------------------------------------------------------------
# A closed form: the Bautin normal form


@dataclass(frozen=True)
class BautinNormalForm:
    """ṙ = r (μ + r² − r⁴), θ̇ = −ω in the plane, with μ = (V − V_H)/s and the state scaled by a (m).

    The state is [a r cos θ, a r sin θ / ω · ω] = [y, v], the second entry standing where a
    mechanical model keeps the lateral velocity (so that the section v = 0 with v falling is a
    maximum of y, as in the vehicles). Cycles: r² = (1 ± √(1 + 4μ))/2 for −¼ ≤ μ, the outer one
    stable, the inner one (μ < 0) unstable; they meet at the fold μ = −¼, r² = ½, and the inner one
    shrinks to zero at the Hopf point μ = 0 (V = V_H). Period 2π/ω; the non-trivial Floquet
    multiplier of a cycle is exp(T (μ + 3r² − 5r⁴)) = exp(T (2r² − 4r⁴)).
    """

    hopf_speed: float = 50.0
    speed_scale: float = 20.0
    omega: float = 4.0 * np.pi  # rad/s: 2 Hz
    scale: float = 0.01  # m

    state_size = 2
    lateral_index = 0
    compiled_reason = "a test model written in Python"

    def mu(self, speed):
        return (speed - self.hopf_speed) / self.speed_scale

    def rhs(self, t, state, speed):
        y, v = np.asarray(state) / self.scale
        r2 = y * y + v * v
        g = self.mu(speed) + r2 - r2 * r2
        return self.scale * np.array([g * y + self.omega * v, g * v - self.omega * y])

    def replace(self, **changes):
        return BautinNormalForm(**{**self.__dict__, **changes})


NORMAL = BautinNormalForm()


@pytest.fixture(scope="module")
def normal_branch():
    start = stability.periodic_orbit(NORMAL, 60.0, [0.011, 0.0], 0.5)
    return stability.limit_cycle_branch(NORMAL, start, end_amplitude=1e-4)


def test_normal_form_cycles_fold_periods_and_multipliers_are_exact(normal_branch):
    b, a = normal_branch, NORMAL.scale
    r = b.amplitudes / a
    mu = NORMAL.mu(b.speeds)
    # Each point closes to Newton's tolerance 1e-5 on the scaled unknowns, the runs at rtol 1e-9:
    # the cycle equation μ = r⁴ − r² holds to 1e-4 (in μ, about 2e-3 m/s of speed). The last point,
    # below end_amplitude, stands at the Hopf point, where the centred state (x = 0, a solution at any
    # speed) meets the branch and the speed of a cycle of r → 0 is no longer resolved: it is held below.
    cycles = r > 1e-3
    assert cycles[:-1].all()
    np.testing.assert_allclose(mu[cycles], (r**4 - r**2)[cycles], atol=1e-4)
    np.testing.assert_allclose(b.periods, 2 * np.pi / NORMAL.omega, rtol=1e-5)
    # The non-trivial multiplier, the one farther from 1, against exp(T (2r² − 4r⁴)); the forward
    # differences of the monodromy (steps of 1e-6 of the state) hold it to about 1e-4.
    far = np.take_along_axis(b.multipliers, np.argmax(np.abs(b.multipliers - 1), axis=1)[:, None], 1)[:, 0]
    np.testing.assert_allclose(far.real, np.exp(b.periods * (2 * r**2 - 4 * r**4)), atol=1e-3)
    # One fold, at μ = −¼ (V = 45 m/s) and r² = ½: regula falsi stops where the scaled dV/ds is
    # below 1e-3, which leaves the speed within 1e-4 m/s of the turning point.
    assert b.fold_speed == pytest.approx(45.0, abs=1e-3)
    assert b.fold_amplitude == pytest.approx(a / np.sqrt(2), rel=1e-3)
    assert b.nonlinear_critical_speed == b.fold_speed
    assert np.sum(np.diff(np.sign(np.diff(b.speeds))) != 0) == 1  # the speed turns once
    # Stable outside (r² > ½), unstable inside; the flag changes at the fold.
    fold = int(np.flatnonzero(b.speeds == b.fold_speed)[0])
    assert b.stable[:fold].all() and not b.stable[fold + 1 :].any()
    np.testing.assert_array_equal(b.stable[r**2 > 0.5 + 1e-3], True)
    # The unstable branch ends at the Hopf point, amplitude → 0 at V_H: with r² ≈ −μ there, an
    # amplitude below 0.01 a leaves V within 20 · 1e-4 = 2e-3 m/s of V_H.
    assert b.amplitudes[-1] < 1e-4
    assert b.speeds[-1] == pytest.approx(NORMAL.hopf_speed, abs=3e-3)


def test_continuation_runs_up_the_branch_too():
    # From the unstable cycle at 48 m/s upwards in speed: towards the Hopf point, where it stops.
    r2 = 0.5 * (1 - np.sqrt(1 + 4 * NORMAL.mu(48.0)))
    start = stability.periodic_orbit(NORMAL, 48.0, [NORMAL.scale * np.sqrt(r2), 0.0], 0.5)
    assert not start.stable
    b = stability.limit_cycle_branch(NORMAL, start, direction="up", end_amplitude=1e-4)
    assert np.all(np.diff(b.speeds) > 0) and not b.stable.any() and b.fold_speed == np.inf
    assert b.speeds[-1] == pytest.approx(NORMAL.hopf_speed, abs=3e-3)


# ---------------------------------------------------------------------------
# The Manchester car: the subcritical branch, against direct integration


@pytest.fixture(scope="module")
def car():
    model = LateralCar().nonlinear()
    start = stability.limit_cycle_amplitude(model, 70.0)
    return model, stability.limit_cycle_branch(model, start, end_amplitude=1e-4)


def _largest_nontrivial(multipliers):
    """|μ₂| of each cycle: the largest modulus but that of the multiplier closest to 1."""
    trivial = np.argmin(np.abs(multipliers - 1), axis=1)
    others = np.abs(multipliers).copy()
    others[np.arange(len(others)), trivial] = 0.0
    return others.max(axis=1)


def _fold_index(branch):
    return int(np.flatnonzero(branch.speeds == branch.fold_speed)[0])


@pytest.mark.slow  # the car's branch of limit cycles, 5 s, shared with the tests below
def test_car_branch_meets_the_ramp_down(car):
    model, b = car
    fold = _fold_index(b)
    stable = slice(0, fold)  # from 70 m/s down to the fold
    # The ramp-down over the branch's own stable speeds, from 12 mm at the top.
    ramp = stability.bifurcation_diagram(model, b.speeds[stable], progress=False, refine=0)
    assert ramp.hunting.all()
    # The ramp's amplitude at each speed is read in the last quarter (6-8 s) of a run started from
    # the cycle of the speed above: what is left of that start is the change of amplitude between the
    # two speeds times |μ₂|^(6 s / T), μ₂ the largest non-trivial multiplier; and its RK45 at rtol
    # 1e-6 on 2 ms steps reads the cycle to about 2e-5 (against 0.5 ms steps). The tolerance is their
    # sum, three times over.
    mu2 = _largest_nontrivial(b.multipliers)
    step = np.abs(np.diff(b.amplitudes[stable], prepend=b.amplitudes[0]))
    left = step * mu2[stable] ** (6.0 / b.periods[stable])
    tolerance = 3.0 * (left + 2e-5 * b.amplitudes[stable])
    gap = np.abs(ramp.amplitudes - b.amplitudes[stable])
    assert np.all(gap <= tolerance), (gap, tolerance)
    # And away from the fold (|μ₂| < 0.8: the ramp settles in a few periods) to 1e-3 relative.
    settled = mu2[stable] < 0.8
    assert settled.sum() >= 3
    assert np.all(gap[settled] <= 1e-3 * b.amplitudes[stable][settled])


@pytest.mark.slow  # on the car's branch (above)
def test_car_fold_against_the_ramp_estimate_and_long_runs(car):
    model, b = car
    fold = _fold_index(b)
    assert b.stable[:fold].all() and not b.stable[fold + 1 :].any()  # the flag changes at the fold
    V_fold = b.nonlinear_critical_speed
    # The ramp of the chapter 7 notebook: 11 speeds from 100 down to 50 m/s, four bisections, so its
    # estimate is known to within its last bracket, 5 m/s / 2⁴.
    ramp = stability.bifurcation_diagram(model, np.linspace(50.0, 100.0, 11), progress=False)
    bracket = 5.0 / 2**4
    assert abs(V_fold - ramp.nonlinear_critical_speed) <= bracket
    # Long runs from the fold's cycle place the fold independently: 30 s (some 90 periods) at 0.1 m/s
    # below it decay to nothing, at 0.1 m/s above it settle on a cycle.
    below = stability.limit_cycle_amplitude(model, V_fold - 0.1, initial_state=b.states[fold], duration=30.0)
    above = stability.limit_cycle_amplitude(model, V_fold + 0.1, initial_state=b.states[fold], duration=30.0)
    assert not below.hunting() and below.amplitude < 1e-6
    assert above.hunting()


@pytest.mark.slow  # on the car's branch (above)
def test_unstable_cycle_is_the_edge_of_the_basin(car):
    # Between the fold and the linear critical speed, started just inside the unstable cycle the car
    # runs centred again; just outside, it hunts on the stable cycle.
    model, b = car
    k = int(np.argmin(np.where(b.stable, np.inf, np.abs(b.speeds - 65.0))))
    assert not b.stable[k]
    inside = stability.limit_cycle_amplitude(model, b.speeds[k], initial_state=0.9 * b.states[k])
    outside = stability.limit_cycle_amplitude(model, b.speeds[k], initial_state=1.1 * b.states[k])
    assert not inside.hunting() and inside.amplitude < 1e-6
    assert outside.hunting() and outside.amplitude > b.amplitudes[k]


@pytest.mark.slow  # on the car's branch (above)
def test_unstable_cycle_against_periodic_orbit(car):
    # A second integrator: scipy's DOP853 on the numpy right-hand side, with central differences, started
    # from the branch's cycle, must find the same cycle and the same unstable multiplier.
    model, b = car
    k = int(np.argmin(np.where(b.stable, np.inf, np.abs(b.speeds - 65.0))))
    orbit = stability.periodic_orbit(model, b.speeds[k], b.states[k], b.periods[k])
    assert not orbit.stable
    # Newton's tolerance (1e-5 of the scaled unknowns) bounds both answers' distance from the cycle.
    assert orbit.amplitude == pytest.approx(b.amplitudes[k], rel=1e-4)
    assert orbit.period == pytest.approx(b.periods[k], rel=1e-5)
    assert np.abs(orbit.multipliers).max() == pytest.approx(np.abs(b.multipliers[k]).max(), rel=1e-3)


@pytest.mark.slow  # on the car's branch (above)
def test_car_branch_ends_at_the_linear_critical_speed(car):
    model, b = car
    Vc = stability.critical_speed(LateralCar(), (1.0, 200.0)).speed
    assert b.amplitudes[-1] < 1e-4
    # Near a Hopf point A(V) is concave towards it (A ∝ √|V − V_c| for a smooth law, ∝ |V − V_c|
    # for one with |ξ| terms such as saturating creep): the critical speed lies between the last point
    # and the straight line through the last two points extended to zero amplitude. 0.05 m/s: the
    # linear critical speed's own search tolerance and the points' speeds.
    V, A = b.speeds[-2:], b.amplitudes[-2:]
    reach = V[1] + A[1] * (V[1] - V[0]) / (A[0] - A[1])
    assert V[1] - 0.05 <= Vc <= reach + 0.05
    assert np.all(np.diff(b.amplitudes[_fold_index(b) :]) < 0)  # falling all the way to the Hopf point


def test_wheelset_branch_is_supercritical_down_to_its_critical_speed():
    # The soft wheelset: a steep but supercritical branch, stable all the way down to the Hopf point.
    model = NonlinearWheelset(SOFT)
    start = stability.limit_cycle_amplitude(model, 60.0, duration=4.0)
    b = stability.limit_cycle_branch(model, start, end_amplitude=5e-5)
    assert b.stable.all() and b.fold_speed == np.inf and b.nonlinear_critical_speed == np.inf
    Vc = stability.critical_speed(SOFT, (1.0, 200.0)).speed
    V, A = b.speeds[-2:], b.amplitudes[-2:]
    reach = V[1] + A[1] * (V[1] - V[0]) / (A[0] - A[1])
    assert min(V[1], reach) - 0.01 <= Vc <= max(V[1], reach) + 0.01


def test_the_compiled_and_numpy_paths_agree():
    model = NonlinearWheelset(SOFT)
    start = stability.limit_cycle_amplitude(model, 60.0, duration=4.0)
    fast = stability.limit_cycle_branch(model, start, max_points=2)
    slow = stability.limit_cycle_branch(model, start, max_points=2, engine="scipy")
    # Both converge to Newton's tolerance (1e-5 scaled) from the same start along the same steps.
    np.testing.assert_allclose(fast.speeds, slow.speeds, rtol=1e-5)
    np.testing.assert_allclose(fast.amplitudes, slow.amplitudes, rtol=1e-4)


# ---------------------------------------------------------------------------
# The plot


def test_branch_plot_and_the_whole_diagram(normal_branch):
    b = normal_branch
    fig = Figure()
    drawn = b.plot(fig.subplots())
    V, stable = drawn["stable"].get_data()
    assert np.array_equal(np.isnan(stable), ~b.stable)
    _, unstable = drawn["unstable"].get_data()
    assert np.isfinite(unstable[~b.stable]).all()
    assert np.isnan(unstable[0])  # the first points, stable and far from the fold, are not dashed
    np.testing.assert_allclose(drawn["fold"].get_data()[0], [3.6 * b.fold_speed])
    assert drawn["unstable"].get_linestyle() == "--" and drawn["stable"].get_linestyle() == "-"
    # In place: no new artists.
    count = len(fig.axes[0].lines)
    assert b.plot(artists=drawn) is drawn and len(fig.axes[0].lines) == count
    # The ramp's diagram with the branch over it.
    diagram = stability.BifurcationDiagram(
        np.array([60.0, 40.0]), np.array([0.0118, 0.0]), np.array([2.0, 0.0]), np.array([True, False]),
        60.0, 2e-4,
    )  # fmt: skip
    fig = Figure()
    whole = diagram.plot(fig.subplots(), linear_critical_speed=50.0, branch=b)
    assert whole["branch"]["fold"].axes is whole["cycles"].axes
    assert whole["cycles"].axes.get_ylim()[1] >= 1e3 * b.amplitudes.max()


def test_ramp_where_every_speed_hunts():
    # Regression: a ramp with no decaying speed has its nonlinear critical speed at its lowest speed,
    # which BifurcationDiagram refused (an open lower bound).
    model = NonlinearWheelset(SOFT)
    d = stability.bifurcation_diagram(model, [60.0, 58.0], duration=2.0, progress=False)
    assert d.hunting.all() and d.nonlinear_critical_speed == 58.0


# ---------------------------------------------------------------------------
# Bad input


@pytest.fixture(scope="module")
def wheelset_start():
    return stability.limit_cycle_amplitude(NonlinearWheelset(SOFT), 60.0, duration=4.0)


@pytest.mark.parametrize(
    "changes, error, words",
    [
        ({"direction": "sideways"}, ValueError, "direction"),
        ({"speed_range": (70.0, 50.0)}, ValueError, "speed_range"),
        ({"speed_range": (65.0, 80.0)}, ValueError, "start.speed"),
        ({"end_amplitude": 0.0}, ValueError, "end_amplitude"),
        ({"arc_step": 0.5, "max_arc_step": 0.1}, ValueError, "max_arc_step"),
        ({"max_points": 1}, ValueError, "max_points"),
        ({"tol": -1.0}, ValueError, "tol"),
        ({"engine": "fast"}, ValueError, "engine"),
    ],
)
def test_bad_options_are_refused(wheelset_start, changes, error, words):
    with pytest.raises(error, match=words):
        stability.limit_cycle_branch(NonlinearWheelset(SOFT), wheelset_start, **changes)


def test_bad_starts_are_refused(wheelset_start):
    model = NonlinearWheelset(SOFT)
    with pytest.raises(TypeError, match="start"):
        stability.limit_cycle_branch(model, wheelset_start.state)
    still = stability.LimitCycle(60.0, 0.0, 0.0, 1.0, np.zeros(4), 0.0, 4.0)  # no oscillation to follow
    with pytest.raises(ValueError, match="start"):
        stability.limit_cycle_branch(model, still)
    # A motion that dies away (40 m/s, below the critical speed): shooting finds the centre, no cycle.
    decayed = stability.limit_cycle_amplitude(model, 40.0, duration=2.0)
    with pytest.raises(SolverError, match="no cycle"):
        stability.limit_cycle_branch(model, decayed)
    with pytest.raises(TypeError, match="model"):
        stability.limit_cycle_branch("car", wheelset_start)
    with pytest.raises(ValueError, match="compiled"):
        stability.limit_cycle_branch(NORMAL, stability.periodic_orbit(NORMAL, 60.0, [0.011, 0.0], 0.5),
                                     engine="compiled")  # fmt: skip


def test_a_start_far_from_any_cycle_fails_clearly():
    # A "cycle" of a model whose centre is stable at that speed: shooting finds no closed orbit there.
    start = stability.PeriodicOrbit(40.0, 0.5, np.array([0.011, 0.0]), 0.011, np.array([1.0, 0.5]), 0.0)
    with pytest.raises(SolverError, match="starting cycle"):
        stability.limit_cycle_branch(NORMAL, start, max_iter=3)


def test_branch_result_checks_its_fields():
    ok = dict(
        speeds=np.array([60.0, 55.0]), amplitudes=np.array([0.01, 0.009]), periods=np.array([0.2, 0.2]),
        stable=np.array([True, False]), multipliers=np.ones((2, 2), complex), states=np.ones((2, 2)),
        arclength=np.array([0.0, 0.1]), fold_speed=np.inf, fold_amplitude=0.0,
    )  # fmt: skip
    stability.LimitCycleBranch(**ok)
    for name, value, error in (
        ("arclength", np.array([0.1, 0.0]), ValueError),
        ("stable", np.array([1, 0]), TypeError),
        ("amplitudes", np.array([0.01, -1.0]), ValueError),
        ("fold_amplitude", -0.01, ValueError),
        ("fold_speed", -np.inf, ValueError),
    ):
        with pytest.raises(error, match=name):
            stability.LimitCycleBranch(**{**ok, name: value})
