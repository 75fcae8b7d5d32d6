"""A wheel on a discrete track (raildyn.bridge.impact): contact, energy, an independent integrator,
Jenkins et al.'s P2, and the linear force spectrum."""

from __future__ import annotations

import numpy as np
import pytest

from raildyn.bridge.defects import DippedJoint, Roughness, WheelFlat
from raildyn.bridge.impact import (
    contact_force_spectrum,
    jenkins_p2,
    lumped_track,
    wheel_on_track,
)
from raildyn.bridge.sleepers import DiscreteTrack
from raildyn.bridge.wheels import VehicleWheels, Wheel, WheelBlock
from raildyn.constants import GRAVITY
from raildyn.errors import SolverError

TRACK = DiscreteTrack(bays=40, quiet_bays=12)
JOINT_X = float(TRACK.sleeper_positions[20]) + 0.275  # midway between two sleepers
WHEEL = Wheel()


def _joint_run(speed, total, ramp=2.0, track=TRACK, wheel=WHEEL, **options):
    joint = DippedJoint(JOINT_X, (total / 2, total / 2), ramp)
    return wheel_on_track(wheel, speed, joint, track=track, start=JOINT_X - ramp - 0.3, distance=ramp + 1.2,
                          **options)  # fmt: skip


def test_the_hertz_spring_is_chapter_4s():
    from raildyn.contact import hertz_contact

    # C_H from the approach at the static load, and the tangent stiffness by a central difference.
    c = hertz_contact(WHEEL.static_load, 0.46, np.inf, 0.3)
    assert WHEEL.hertz_constant * c.approach**1.5 == pytest.approx(WHEEL.static_load, rel=1e-12)
    d = 1e-9
    slope = WHEEL.hertz_constant * ((c.approach + d) ** 1.5 - (c.approach - d) ** 1.5) / (2 * d)
    assert WHEEL.contact_stiffness == pytest.approx(slope, rel=1e-6)
    # About 94 GN/m^1.5 for a 0.46 m wheel on a 0.3 m crown (textbook values lie at 87-100).
    assert 85e9 < WHEEL.hertz_constant < 100e9


def test_a_smooth_rail_carries_the_static_load():
    run = wheel_on_track(WHEEL, 1.0, track=TRACK, distance=1.2, record_every=10)
    assert run.contact_force[0, 0] == pytest.approx(WHEEL.static_load, rel=1e-12)
    # Crawling over the sleepers, the wheel feels only the rail's stiffness varying along a bay: a few
    # tenths of a per cent (the static deflection differs by that much over a sleeper and between two).
    assert np.ptp(run.contact_force) < 0.01 * WHEEL.static_load
    # The sleepers under the wheel carry the load: the rail seats' forces add up to the wheel's.
    assert run.pad_forces[-1].sum() == pytest.approx(WHEEL.static_load, rel=2e-3)


def test_contact_and_energy_at_a_joint_that_throws_the_wheel_off():
    run = _joint_run(30.0, 0.02, ramp=0.5)
    f, gap = run.contact_force, run.wheel - run.rail - run.irregularity
    assert run.contact_loss_time[0] > 1e-3  # 20 mrad at 108 km/h lifts the wheel
    assert np.all(f >= 0.0)
    pressed = f > 0.0
    assert np.allclose(f[pressed], WHEEL.hertz_constant * gap[pressed] ** 1.5, rtol=1e-9)
    assert np.all(gap[~pressed] <= 1e-15)
    # The energy balance: what the rolling fed in, less what the dampers took, is what the system
    # holds. Newmark's rule keeps it to its truncation error: here under 1e-3 of the energy exchanged.
    exchanged = np.ptp(run.energy) + run.dissipated[-1]
    assert np.abs(run.balance).max() < 1e-3 * exchanged


@pytest.mark.slow  # scipy's RK45 on the same equations, seconds
def test_the_march_agrees_with_scipys_rk45():
    small = DiscreteTrack(bays=16, quiet_bays=5, elements_per_bay=2)
    x = float(small.sleeper_positions[8]) + 0.275
    joint = DippedJoint(x, (0.004, 0.004), 0.3)
    runs = [
        wheel_on_track(WHEEL, 25.0, joint, track=small, start=x - 0.05, distance=0.2, method=m)
        for m in ("newmark", "scipy")
    ]
    # RK45 at rtol 1e-8 is the reference; Newmark's rule at 10 µs lengthens the P1 bounce's period
    # (about 0.6 ms) by (ωΔt)²/12 ≈ 0.1 %, which moves the force by a few tenths of a per cent.
    peak = runs[1].contact_force.max()
    assert np.abs(runs[0].contact_force - runs[1].contact_force).max() < 0.01 * peak
    for a, b in zip(runs[0].peaks(x), runs[1].peaks(x), strict=True):
        assert a == pytest.approx(b, rel=3e-3)
    assert np.abs(runs[1].balance).max() < 1e-2 * (np.ptp(runs[1].energy) + runs[1].dissipated[-1])


@pytest.mark.parametrize(("speed", "total"), [(20.0, 0.004), (30.0, 0.004), (10.0, 0.01)])
def test_p2_against_jenkins(speed, total):
    # Jenkins et al. (1974) picture P2 as the wheel and a track mass sharing the wheel's momentum 2αV
    # and riding down on one spring and damper. Fitted to this track (ζ ≈ 0.33), their estimate is
    # within 30 % of the run's rise above Q₀: the track is not one mass (the fit moves by ±20 % with its
    # band) and their damping term, 1 − πζ/2, is the first-order part of the damped peak's factor.
    k, m, c = lumped_track(TRACK, JOINT_X)  # over 5–60 Hz, around the P2 resonance (some 35 Hz)
    run = _joint_run(speed, total)
    assert run.contact_loss_time[0] == 0.0  # the estimate's range: the wheel keeps contact
    p1, p2 = run.peaks(JOINT_X)
    estimate = jenkins_p2(WHEEL, speed, total, m, k, c)
    assert p1 > p2 > WHEEL.static_load
    assert abs(p2 - estimate) < 0.3 * (estimate - WHEEL.static_load)


def test_p2_rises_in_proportion_to_the_dip_angle_times_the_speed():
    # Jenkins' scaling, which holds however the track is lumped: while the wheel keeps contact the
    # run is nearly linear, and (P2 − Q₀)/(2αV) stays within 10 % over speed and angle (what is left:
    # the Hertz spring's stiffening and the sleepers' passing).
    rises = [(_joint_run(v, a).peaks(JOINT_X)[1] - WHEEL.static_load) / (a * v)
             for v, a in ((10.0, 0.01), (20.0, 0.004), (30.0, 0.004), (40.0, 0.003))]  # fmt: skip
    assert max(rises) < 1.1 * min(rises)


def test_a_flat_strikes_once_a_revolution():
    flat = WheelFlat(0.0008, first=TRACK.sleeper_positions[15])
    run = wheel_on_track(WHEEL, 10.0, flat, track=TRACK, start=float(TRACK.sleeper_positions[15]) - 0.1,
                         distance=3.5)  # fmt: skip
    strikes = run.x[np.flatnonzero(np.diff((run.irregularity[:, 0] > 0).astype(int)) == 1) + 1]
    assert np.diff(strikes) == pytest.approx(2 * np.pi * 0.46, abs=2e-3)
    for x in strikes:
        assert run.peaks(x)[0] > 1.2 * WHEEL.static_load


@pytest.mark.slow  # a time run of seconds against the receptances
def test_the_force_spectrum_of_small_roughness_matches_the_receptances():
    # A wheel standing midway between sleepers while a small random roughness (rms 2 µm against a
    # Hertz compression of 70 µm: linear) passes under it at 30 m/s for 116 m. Welch's estimate averages
    # some 37 segments of 0.2 s; each of 12 bands averages some 15 frequencies of it, which leaves a
    # scatter of about ±4 %: the bands agree within 8 %.
    from raildyn.random_vibration import welch_psd
    from raildyn.track import synthesize_irregularity

    def psd(w):
        return 1e-13 * (w / 10.0) ** -2.0  # m²/(rad/m): falls as Ω⁻², a usual short-wave roughness

    sample = synthesize_irregularity(psd, 120.0, 0.002, (0.03, 2.0), rng=4)
    rough = Roughness(sample.x, sample.z - sample.z.mean())
    run = wheel_on_track(WHEEL, 30.0, rough, track=TRACK, start=JOINT_X, distance=116.0, standing=True,
                         time_step=2e-5, record_every=5)  # fmt: skip
    force = run.contact_force[:, 0]
    spec = welch_psd(force - force.mean(), run.t[1] - run.t[0], nperseg=2048)
    f = spec.omega / (2 * np.pi)
    measured = spec.psd * 2 * np.pi  # per Hz
    keep = (f > 40.0) & (f < 900.0)
    linear = contact_force_spectrum(WHEEL, 30.0, psd, f[keep], track=TRACK, position=JOINT_X)
    ratio = [measured[keep][b].mean() / linear[b].mean() for b in np.array_split(np.arange(keep.sum()), 12)]
    assert np.allclose(ratio, 1.0, atol=0.08), np.round(ratio, 3)


def test_a_vehicle_on_its_wheels():
    from raildyn.vehicles import VerticalCar, VerticalFreightCar

    car = VerticalCar()
    block = VehicleWheels(car).block()
    total = car.body_mass + 2 * car.bogie_mass + 4 * 1813.0
    # One rail carries half the car; its four wheels the same share each (the car is symmetric).
    assert block.static_loads.sum() == pytest.approx(total * GRAVITY / 2, rel=1e-12)
    assert np.allclose(block.static_loads, block.static_loads[0], rtol=1e-12)
    assert block.offsets.tolist() == pytest.approx(car.axle_positions.tolist())
    # Lifting everything by 1 m (the body and bogies' heights, the wheels') strains no spring.
    rigid = np.zeros(block.mass.shape[0])
    labels = car.linear_system().labels
    rigid[[i for i, name in enumerate(labels) if name.endswith("z")]] = 1.0
    rigid[block.contact_dofs] = 1.0
    assert np.allclose(block.stiffness @ rigid, 0.0, atol=1e-6 * np.abs(block.stiffness).max())
    # A freight car's left and right inputs under an axle become one wheel on this rail.
    freight = VehicleWheels(VerticalFreightCar()).block()
    assert freight.offsets.size == 4 and freight.static_loads.sum() == pytest.approx(
        (VerticalFreightCar().body_mass + 4 * 1813.0) * GRAVITY / 2, rel=1e-9
    )
    # Over a joint each wheel strikes in turn; the bogie's two wheels alike, within what the body's
    # and the other wheel's motion change (a few per cent).
    track = DiscreteTrack(bays=90, quiet_bays=12)
    x = float(track.sleeper_positions[60]) + 0.275
    run = wheel_on_track(VehicleWheels(car), 30.0, DippedJoint(x, (0.003, 0.003), 0.5), track=track,
                         start=x - 0.6, distance=3.9)  # fmt: skip
    assert run.contact_force.shape[1] == 4
    p_lead, p_trail = run.peaks(x, 0), run.peaks(x, 1)
    assert p_trail[0] == pytest.approx(p_lead[0], rel=0.05)
    assert p_lead[0] > 1.3 * block.static_loads[0]
    exchanged = np.ptp(run.energy) + run.dissipated[-1]
    assert np.abs(run.balance).max() < 1e-3 * exchanged


@pytest.mark.slow  # scipy's RK45 on the same equations, seconds
def test_two_wheels_on_a_bogie_frame_against_rk45():
    # A bogie frame (1,300 kg, half the frame on one rail) on two wheels 2.5 m apart through primary
    # springs: two contacts coupled through the frame and the rail, against RK45 on the same equations.
    small = DiscreteTrack(bays=24, quiet_bays=5, elements_per_bay=2)
    k1, c1, mw = 1.22e6, 4e3, 906.5
    one = np.array([[1.0, -1.0], [-1.0, 1.0]])
    stiffness = np.zeros((3, 3))
    damping = np.zeros((3, 3))
    for wheel in (1, 2):
        stiffness[np.ix_([0, wheel], [0, wheel])] += k1 * one
        damping[np.ix_([0, wheel], [0, wheel])] += c1 * one
    loads = np.full(2, (1300.0 / 2 + mw) * GRAVITY)
    block = WheelBlock(np.diag([1300.0, mw, mw]), damping, stiffness, np.array([1, 2]), loads,
                       np.array([0.0, 2.5]), np.full(2, WHEEL.hertz_constant))  # fmt: skip
    x = float(small.sleeper_positions[12]) + 0.275
    joint = DippedJoint(x, (0.004, 0.004), 0.3)
    runs = [
        wheel_on_track(block, 25.0, joint, track=small, start=x - 0.05, distance=0.15, method=m)
        for m in ("newmark", "scipy")
    ]
    peak = runs[1].contact_force.max()
    assert np.abs(runs[0].contact_force - runs[1].contact_force).max() < 0.01 * peak
    assert np.abs(runs[0].balance).max() < 1e-3 * (np.ptp(runs[0].energy) + runs[0].dissipated[-1])


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="angles"):
        DippedJoint(1.0, (0.06, 0.01))
    with pytest.raises(ValueError, match="angles"):
        DippedJoint(1.0, (0.0, 0.01))
    with pytest.raises(ValueError, match="depth"):
        WheelFlat(0.006)
    with pytest.raises(ValueError, match="pad_stiffness"):
        DiscreteTrack(pad_stiffness=225.0)  # kN/mm typed as N/m
    with pytest.raises(ValueError, match="sleeper_spacing"):
        DiscreteTrack(sleeper_spacing=1.5)
    with pytest.raises(ValueError, match="sprung_mass"):
        Wheel(sprung_mass=1e4, primary_stiffness=1e6)
    with pytest.raises(ValueError, match="start"):
        wheel_on_track(WHEEL, 10.0, track=TRACK, start=0.1)
    with pytest.raises(TypeError, match="irregularity"):
        wheel_on_track(WHEEL, 10.0, "joint", track=TRACK)


def test_a_non_finite_contact_force_stops_the_run():
    # A block whose Hertz constant went infinite after its checks (nothing a caller can pass does that):
    # the first step's contact force is not finite, and the run stops there, naming it.
    block = WHEEL.block()
    object.__setattr__(block, "hertz_constants", np.array([np.inf]))
    with pytest.raises(SolverError, match="non-finite") as caught:
        wheel_on_track(block, 10.0, track=TRACK, distance=0.1)
    assert caught.value.step == 1
