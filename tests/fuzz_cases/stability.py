"""Fuzz registry: chapters 5 and 7, the wheelset, the linear model protocol, lateral stability and hunting.

The valid calls are the cheapest meaningful ones: the soft suspended wheelset of chapter 5
(critical speed 54.6 m/s) at 60 m/s, where it hunts; nonlinear runs of a few tenths of a
second on coarse steps; two speeds per sweep; a 2 x 2 critical speed map. The plots of
the results draw on new pyplot figures (closed after each call) or move artists drawn once.
"""

from __future__ import annotations

import functools

import numpy as np
from fuzzing import call, fuzz, on
from matplotlib.figure import Figure

from raildyn import stability as st
from raildyn import wheelset as wh
from raildyn.contact.profiles import s1002_wheel, uic60_rail
from raildyn.linear_model import Assembler, LinearSystem
from raildyn.vehicles import VerticalCar

SOFT = wh.Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)  # linear critical speed 54.6 m/s
NW = wh.NonlinearWheelset(SOFT)
STATE = np.array([1e-3, 0.0, 0.0, 0.0])
SPEEDS = [20.0, 60.0]
RUN = {"duration": 0.2, "max_step": 5e-3}  # a few tenths of a second on coarse steps: cheap

# A 2-DOF system with one track input, every field given.
M2 = np.diag([2.0, 1.0])
C2 = np.array([[3.0, -1.0], [-1.0, 1.0]])
K2 = np.array([[300.0, -100.0], [-100.0, 100.0]])
G2 = np.array([[0.0], [100.0]])


def system2_call():
    return call(
        M2, C2, 0.1 * C2, K2, GK=G2, GC=0.01 * G2, labels=("body z", "wheel z"),
        input_positions=[0.0], input_kinds=("vertical",), input_rails=[1.0], gravity_load=[-19.6, -9.8],
        wheelsets=(),
    )  # fmt: skip


def system2():
    c = system2_call()
    return LinearSystem(*c.args, **c.kwargs)


def assembler():
    return Assembler(["body z", "wheel z"], n_inputs=1)


def built_assembler():
    """Two masses on springs, the lower one on the track: ready for system()."""
    asm = assembler()
    asm.mass("body z", 1000.0)
    asm.mass("wheel z", 100.0)
    asm.element({"body z": 1.0, "wheel z": -1.0}, 1e5, 2e3)
    asm.element({"wheel z": 1.0}, 1e7, inputs={0: 1.0})
    return asm


def wheelset_assembler():
    return Assembler(["wheelset y", "wheelset ψ"], n_inputs=2)


@functools.cache
def sweep():
    return st.mode_sweep(SOFT, SPEEDS)


@functools.cache
def critical():
    return st.critical_speed(SOFT, (20.0, 80.0), tol=0.5, scan=8)


@functools.cache
def sweep_artists():
    return sweep().plot(Figure().subplots(1, 2), critical=critical())


def factory(k_y, k_psi):
    """A wheelset of the given primary lateral and yaw stiffness (N/m, N·m/rad)."""
    return wh.Wheelset(lateral_stiffness=k_y, yaw_stiffness=k_psi)


@functools.cache
def speed_map():
    return st.critical_speed_map(factory, [1.0e6, 2.0e6], [2.0e6, 3.0e6], (20.0, 100.0), tol=0.5, scan=8,
                                 progress=False)  # fmt: skip


@functools.cache
def cycle():
    return st.limit_cycle_amplitude(NW, 60.0, **RUN)


@functools.cache
def run():
    return st.simulate(NW, 60.0, STATE, **RUN)


@functools.cache
def diagram():
    # 0.8 s: each quarter compared holds a whole period of the 6 Hz hunting, as LimitCycle.hunting asks.
    return st.bifurcation_diagram(NW, [70.0, 40.0], duration=0.8, max_step=1e-2, refine=1, progress=False)


@functools.cache
def orbit_guess():
    """A point of the limit cycle at 60 m/s and its period (s): shooting converges in one step from it."""
    orbit = st.periodic_orbit(NW, 60.0, [0.0103, -1.1e-4, 0.0, -0.229], 0.1742, rtol=1e-6, tol=1e-4)
    return orbit.state, orbit.period


def orbit():
    state, period = orbit_guess()
    return st.PeriodicOrbit(60.0, period, state, 0.0103, np.array([1.0, 0.1, 0.0, 0.0]), 1e-7)


# The ramp's options: a step or tolerance a thousand times coarser is still an option; zero refinement
# keeps the grid; the first displacement may start either side and small.
BIFURCATION_ACCEPTS = {
    "max_step": "big mm",
    "rtol": "mm",
    "threshold": "tiny",
    "initial_displacement": "negative tiny",
    "refine": "zero",
}

ENTRIES = [
    # ---------------------------------------------------------------- raildyn.linear_model
    fuzz(
        "raildyn.linear_model.Assembler",
        lambda: call(["body z", "wheel z"], n_inputs=1),
        accepts={"n_inputs": "zero"},
    ),
    fuzz(
        "raildyn.linear_model.Assembler.block",
        lambda: on(assembler(), ["body z", "wheel z"], C1=np.eye(2), K=np.eye(2)),
        # a block of creep damping or stiffness holds entries of either sign (creep, gravity)
        accepts={"C1": "zero negative none", "K": "zero negative none"},
    ),
    fuzz(
        "raildyn.linear_model.Assembler.element",
        lambda: on(assembler(), {"body z": 1.0, "wheel z": -1.0}, 1e5, 2e3, inputs={0: 1.0}),
        accepts={"stiffness": "zero big mm", "damping": "zero big mm", "inputs": "none"},
    ),
    fuzz("raildyn.linear_model.Assembler.index", lambda: on(assembler(), "wheel z")),
    fuzz(
        "raildyn.linear_model.Assembler.mass",
        lambda: on(assembler(), "body z", 1000.0),
        accepts={"value": "big tiny mm"},
    ),
    fuzz("raildyn.linear_model.Assembler.system", lambda: on(built_assembler(), input_kinds=("vertical",))),
    fuzz(
        "raildyn.linear_model.Assembler.track_force",
        lambda: on(assembler(), "wheel z", 0, 1e7, 1e3),
        # a force per unit input: either sign (a cross-level pushes the wheelset to the low rail)
        accepts={"j": "zero", "stiffness": "zero negative big mm", "damping": "zero negative big mm"},
    ),
    fuzz("raildyn.linear_model.Assembler.vector", lambda: on(assembler(), {"body z": 1.0})),
    fuzz(
        "raildyn.linear_model.LinearSystem",
        system2_call,
        # C0, C1 and K hold creep and gravity terms of either sign; G_K, G_C forces of either sign; the
        # weight is negative downwards; a rail of -1 is the right one, 0 both
        accepts={
            "C0": "zero negative",
            "C1": "zero negative",
            "K": "zero negative",
            "GK": "zero negative none",  # None: zeros of the other's shape
            "GC": "zero negative none",
            "input_positions": "zero none",  # None: all at the leading axle
            "input_rails": "zero negative none",  # None: both rails
            "gravity_load": "zero negative none",  # None: no weight
        },
    ),  # fmt: skip
    fuzz(
        "raildyn.linear_model.LinearSystem.axle_frf",
        lambda: on(system2(), np.array([1.0, 5.0, 20.0]), 30.0, output="body z"),
        accepts={"speed": "tiny", "omega": "zero", "derivative": "zero"},
    ),
    fuzz(
        "raildyn.linear_model.LinearSystem.input_forces",
        lambda: on(built_assembler().system(), [1e-3, 2e-3], [0.0, 0.1], [1e-3], [0.05]),
        accepts={s: "zero negative list" for s in ("q", "qdot", "w", "wdot")},  # displacements of either sign
    ),
    fuzz("raildyn.linear_model.LinearSystem.linear_system", lambda: on(system2())),
    fuzz(
        "raildyn.linear_model.LinearSystem.matrices", lambda: on(system2(), 30.0), accepts={"speed": "tiny"}
    ),
    fuzz("raildyn.linear_model.LinearSystem.output_vector", lambda: on(system2(), "body z")),
    fuzz("raildyn.linear_model.LinearSystem.replace", lambda: on(system2(), K=2.0 * K2)),
    fuzz("raildyn.linear_model.LinearSystem.state_matrices", lambda: on(system2(), [10.0, 30.0])),
    fuzz(
        "raildyn.linear_model.LinearSystem.state_space",
        lambda: on(system2(), 30.0, outputs=["body z"]),
        accepts={"speed": "tiny", "outputs": "none", "derivative": "zero"},  # None: every coordinate
    ),
    fuzz("raildyn.linear_model.LinearSystem.static_deflection", lambda: on(system2())),
    fuzz(
        "raildyn.linear_model.SystemMatrices",
        lambda: call(M2, C2, K2, G2, 0.01 * G2, ("body z", "wheel z"), 30.0),
        # C and K hold creep and gravity terms of either sign, G_K and G_C forces of either sign
        accepts={
            "speed": "tiny",
            "C": "zero negative",
            "K": "zero negative",
            "GK": "zero negative",
            "GC": "zero negative",
        },
    ),
    fuzz("raildyn.linear_model.SystemMatrices.state_matrix", lambda: on(system2().matrices(30.0))),
    fuzz("raildyn.linear_model.as_linear_system", lambda: call(SOFT)),
    # The base class's methods, on a model that inherits them (VerticalCar defines only linear_system).
    fuzz("raildyn.linear_model.LinearModelBase", lambda: call()),
    fuzz("raildyn.linear_model.LinearModelBase.linear_system", lambda: on(VerticalCar())),
    fuzz(
        "raildyn.linear_model.LinearModelBase.matrices",
        lambda: on(VerticalCar(), 30.0),
        accepts={"speed": "tiny"},
    ),
    fuzz("raildyn.linear_model.LinearModelBase.replace", lambda: on(VerticalCar(), body_mass=30000.0)),
    fuzz(
        "raildyn.linear_model.LinearModelBase.state_space",
        lambda: on(VerticalCar(), 30.0, outputs=["body z"], derivative=1),
        accepts={"speed": "tiny", "outputs": "none", "derivative": "zero"},
    ),
    # ---------------------------------------------------------------- raildyn.wheelset
    fuzz(
        "raildyn.wheelset.kinematic_wavelength", lambda: call(0.46, 0.75, 0.15), accepts={"conicity": "tiny"}
    ),
    fuzz(
        "raildyn.wheelset.rigid_bogie_wavelength",
        lambda: call(0.46, 0.75, 0.15, 1.28),
        accepts={"conicity": "tiny"},
    ),
    fuzz(
        "raildyn.wheelset.kinematic_oscillation",
        lambda: call(0.46, 0.75, 0.15, 1.28),
        accepts={"conicity": "tiny"},
    ),
    fuzz(
        "raildyn.wheelset.KinematicOscillation",
        lambda: call(9.5, 18.9),
        accepts={"wavelength": "big tiny mm", "rigid_bogie_wavelength": "big tiny mm"},
    ),
    fuzz(
        "raildyn.wheelset.KinematicOscillation.plot",
        lambda: on(wh.KinematicOscillation(9.5, 18.9), distance=np.linspace(0.0, 60.0, 50), amplitude=5.0),
        accepts={"amplitude": "big tiny mm", "distance": "none"},  # None: 0 to 60 m
    ),
    fuzz(
        "raildyn.wheelset.Wheelset",
        lambda: call(),
        # a coned wheelset may have no cone, no creep (a test case), no primary suspension
        accepts={
            "yaw_inertia": "mm",
            "conicity": "zero",
            "f11": "zero big mm",
            "f22": "zero big mm",
            "f23": "zero big mm",
            "f33": "zero big mm",
            "contact_angle": "zero",
            "contact_angle_parameter": "zero",
            "lateral_stiffness": "zero big mm",
            "yaw_stiffness": "zero big mm",
            "lateral_damping": "zero big mm",
            "yaw_damping": "zero big mm",
        },
    ),  # fmt: skip
    fuzz("raildyn.wheelset.Wheelset.free", lambda: on(SOFT)),
    fuzz("raildyn.wheelset.Wheelset.on_profiles", lambda: on(SOFT, s1002_wheel(), uic60_rail(1 / 40), 3e-3)),
    fuzz("raildyn.wheelset.Wheelset.linear_system", lambda: on(SOFT)),
    fuzz("raildyn.wheelset.Wheelset.replace", lambda: on(SOFT, conicity=0.2)),
    fuzz(
        "raildyn.wheelset.CreepTerms",
        lambda: call(np.eye(2), np.array([[0.0, -1.0], [1.0, 0.5]]), np.diag([1.0, -1.0])),
        accepts={"C1": "zero negative", "K_creep": "zero negative", "K_gravity": "zero negative"},
    ),
    fuzz("raildyn.wheelset.creep_terms", lambda: call(SOFT)),
    fuzz(
        "raildyn.wheelset.add_wheelset",
        lambda: call(wheelset_assembler(), "wheelset y", "wheelset ψ", SOFT, alignment=0, cross_level=1),
        accepts={"alignment": "zero none", "cross_level": "none"},  # None: the input is not modelled
    ),
    fuzz("raildyn.wheelset.wickens_critical_speed", lambda: call(SOFT)),
    fuzz(
        "raildyn.wheelset.WheelRailContact",
        lambda: call(
            rolling_radius_difference=lambda y: 0.3 * y,
            contact_angle_difference=lambda y: 0.4 * y,
            tread_angles=lambda y: np.stack([0.05 + 0.2 * y, 0.05 - 0.2 * y]),
        ),
        # −1 rad, what the changed callback returns, is a contact angle (difference) within ±π/2
        accepts={
            "friction": "tiny",
            "flange_clearance": "tiny",
            "flange_stiffness": "zero big mm",
            "flange_angle": "tiny",  # any angle in (0, π/2), as Nadal's limit takes
            "flange_radius_excess": "zero tiny",  # a flange contact at the tape circle's radius or just above
            "contact_angle_difference": "returns-negative",
            "tread_angles": "returns-negative",
        },
    ),
    fuzz(
        "raildyn.wheelset.contact_forces",
        lambda: call(SOFT, wh.WheelRailContact(), 1e-3, 1e-3, 0.01, 0.01, 30.0),
        # displacements and rates of either sign; arrays broadcast (the speeds too, each > 0)
        accepts={
            **{p: "zero negative list mm big" for p in ("y", "psi", "ydot", "psidot")},
            "speed": "list tiny",
        },
    ),
    fuzz(
        "raildyn.wheelset.tread_contact_angles",
        lambda: call(SOFT, wh.WheelRailContact(), 1e-3),
        # a displacement of either side (the cone's angles continue linearly, as contact_forces' do)
        accepts={"y": "zero negative list mm big"},
    ),
    fuzz(
        "raildyn.wheelset.NonlinearWheelset",
        lambda: call(SOFT, wh.WheelRailContact()),
        accepts={"wheelset": "none", "contact": "none"},  # the defaults
    ),
    fuzz(
        "raildyn.wheelset.NonlinearWheelset.replace",
        lambda: on(NW, contact=wh.WheelRailContact(friction=0.2)),
    ),
    fuzz(
        "raildyn.wheelset.NonlinearLateral",
        lambda: call(SOFT.linear_system(), wh.WheelRailContact()),
        accepts={"start": "zero negative big"},  # the vehicle's place along its curve, either side of s = 0
    ),
    fuzz(
        "raildyn.wheelset.NonlinearLateral.replace",
        lambda: on(wh.NonlinearLateral(SOFT.linear_system()), start=5.0),
        accepts={"start": "zero negative big"},
    ),
    fuzz(
        "raildyn.wheelset.NonlinearLateral.compiled_rhs",
        lambda: on(wh.NonlinearLateral(SOFT.linear_system()), 50.0),
        accepts={"speed": "tiny"},
    ),
    fuzz(
        "raildyn.wheelset.CompiledRHS",
        lambda: call(*[getattr(NW.compiled_rhs(60.0), f) for f in ("kernel", "row", "stacked")]),
        # a row is any floats of the engine's layout; its entries are the model's, of either sign; a model
        # may give no stacked right-hand side of its own
        accepts={"row": "zero negative huge", "stacked": "none"},
    ),
    fuzz(
        "raildyn.wheelset.NonlinearLateral.rhs",
        lambda: on(wh.NonlinearLateral(SOFT.linear_system()), 0.0, STATE, 60.0),
        accepts={"t": "zero negative big", "state": "zero negative", "speed": "tiny"},
    ),
    # ---------------------------------------------------------------- raildyn.stability (linear)
    fuzz("raildyn.stability.eigenvalues_against_speed", lambda: call(SOFT, SPEEDS)),
    fuzz("raildyn.stability.largest_real_part", lambda: call(SOFT, SPEEDS)),
    fuzz(
        "raildyn.stability.mac",
        lambda: call(
            np.array([[1.0, 0.0], [0.5, 1.0], [0.0, 2.0]]), np.array([[2.0, 1.0], [1.0, 0.0], [0.0, 1.0]])
        ),
        accepts={
            "a": "negative complex",
            "b": "negative complex",
        },  # a vector and its negative are the same mode
    ),
    fuzz(
        "raildyn.stability.track_modes",
        # real eigenvalues and vectors (overdamped modes) keep the test's changes real
        lambda: call(np.array([[-1.0, -2.0], [-1.1, -2.1]]), np.array([np.eye(2), np.eye(2)[::-1]])),
        accepts={"eigenvalues": "zero negative complex", "vectors": "negative complex"},
    ),
    fuzz(
        "raildyn.stability.TrackedModes",
        lambda: call(np.array([[-1.0, -2.0], [-1.1, -2.1]]), np.array([np.eye(2), np.eye(2)])),
        accepts={"eigenvalues": "zero negative complex", "vectors": "negative complex"},
    ),
    fuzz("raildyn.stability.mode_sweep", lambda: call(SOFT, SPEEDS)),
    fuzz(
        "raildyn.stability.ModeSweep",
        lambda: call(
            np.array(SPEEDS),
            sweep().eigenvalues.real,
            sweep().frequencies_hz,
            sweep().damping_ratios,
            sweep().shapes.real,
            sweep().labels,
            sweep().coordinates,
        ),  # fmt: skip
        # real parts only, so that the test's changes stay real; damping ratios of either sign
        accepts={
            "eigenvalues": "zero negative complex",
            "frequencies_hz": "zero",
            "damping_ratios": "zero negative",
            "shapes": "negative",
        },  # fmt: skip
    ),
    fuzz(
        "raildyn.stability.ModeSweep.plot",
        lambda: on(sweep(), critical=critical(), artists=sweep_artists()),
        accepts={
            "critical": "none",
            "artists": "none",  # None: draw anew
            "real_limits": "negative none",
            "imag_limits": "none",
            "damping_limits": "none",
        },  # fmt: skip
    ),
    fuzz(
        "raildyn.stability.critical_speed",
        lambda: call(SOFT, (20.0, 80.0), tol=0.5, scan=8),
        accepts={"tol": "big tiny mm"},
    ),
    fuzz(
        "raildyn.stability.CriticalSpeed",
        lambda: call(
            54.6, 5.3, complex(0.0, 33.4), "crossing", np.array([1.0, 0.6]), ("wheelset y", "wheelset ψ")
        ),
        accepts={
            "speed": "tiny",
            "eigenvalue": "type",
            "frequency_hz": "zero big mm",
            "mode_shape": "negative",
        },  # 1.0: a real eigenvalue
    ),
    fuzz("raildyn.stability.CriticalSpeed.amplitude", lambda: on(critical(), "wheelset ψ")),
    # +inf is the documented answer "stable over the range" / "no limit cycle on the grid" (x = 1e300
    # makes the lateral stiffness 1e300 N/m: a wheelset stable at every speed).
    fuzz(
        "raildyn.stability.critical_speed_map",
        lambda: call(
            factory,
            [1.0e6, 2.0e6],
            [2.0e6],
            (20.0, 100.0),
            x_name="k_y",
            y_name="k_ψ",
            tol=0.5,
            scan=8,
            progress=False,
        ),
        accepts={
            "tol": "big tiny mm",
            "x": "zero",
            "y": "zero",
            "x_name": "unknown",
            "y_name": "unknown",
        },  # names label the plot
        infinite=("speeds",),
    ),
    fuzz(
        "raildyn.stability.CriticalSpeedMap",
        lambda: call(np.array([1.0, 2.0]), np.array([3.0]), np.array([[50.0, 60.0]]), "x", "y"),
        accepts={
            "x": "zero negative",
            "y": "zero negative",
            "speeds": "inf",
            "x_name": "unknown",
            "y_name": "unknown",
        },  # fmt: skip
        infinite=("speeds",),
    ),
    fuzz(
        "raildyn.stability.CriticalSpeedMap.plot",
        lambda: on(speed_map(), levels=[0.0, 200.0, 400.0]),
        accepts={"levels": "none"},  # None: 50 km/h apart
    ),
    fuzz(
        "raildyn.stability.CriticalSpeedMap.plot_curves",
        lambda: on(speed_map(), Figure().subplots()),
        accepts={"ax": "none", "artists": "none"},  # None: new axes; draw anew
    ),
    # ---------------------------------------------------------------- raildyn.stability (nonlinear)
    fuzz(
        "raildyn.stability.simulate",
        lambda: call(NW, 60.0, STATE, 0.2, max_step=5e-3, rtol=1e-6),
        accepts={
            "max_step": "big mm",
            "rtol": "mm",
            "initial_state": "zero negative",
        },  # any state; the centred one stays there
    ),
    fuzz(
        "raildyn.stability.NonlinearRun",
        lambda: call(60.0, run().t, run().states, 0),
        accepts={"speed": "tiny", "states": "zero negative", "lateral_index": "zero"},
    ),
    fuzz(
        "raildyn.stability.NonlinearRun.plot",
        lambda: on(run(), flange_clearance=9.1e-3),
        accepts={"flange_clearance": "none big tiny mm"},  # None: not marked
    ),
    fuzz(
        "raildyn.stability.limit_cycle_amplitude",
        lambda: call(NW, 60.0, initial_displacement=12e-3, duration=0.2, max_step=5e-3, rtol=1e-6),
        accepts={
            "max_step": "big mm",
            "rtol": "mm",
            "initial_displacement": "negative tiny",
        },  # a start to the right
    ),
    fuzz(
        "raildyn.stability.LimitCycle",
        lambda: call(60.0, 0.01, 5.7, 1.0, cycle().state, 0.01, 8.0),
        accepts={
            "speed": "tiny",
            "amplitude": "zero big mm",
            "frequency_hz": "zero big mm",
            "growth": "zero big mm",
            "state": "zero negative",
            "oscillation": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.stability.LimitCycle.hunting",
        lambda: on(cycle(), threshold=2e-4),
        accepts={"threshold": "big tiny mm"},
    ),
    fuzz(
        "raildyn.stability.bifurcation_diagram",
        lambda: call(NW, [70.0, 40.0], duration=0.8, max_step=1e-2, refine=1, progress=False, rtol=1e-6),
        accepts=BIFURCATION_ACCEPTS,
        infinite=("nonlinear_critical_speed",),  # inf: no limit cycle on the grid (a start too small)
    ),
    fuzz(
        "raildyn.stability.bifurcation_diagrams",
        lambda: call(
            [NW, NW], [70.0, 40.0], duration=0.8, max_step=1e-2, refine=1, progress=False, rtol=1e-6
        ),  # fmt: skip
        accepts=BIFURCATION_ACCEPTS,
        infinite=("nonlinear_critical_speed",),  # inf: no limit cycle on the grid (a start too small)
    ),
    fuzz(
        "raildyn.stability.BifurcationDiagram",
        lambda: call(
            np.array([70.0, 40.0]),
            np.array([0.01, 0.002]),
            np.array([5.5, 0.0]),
            np.array([True, False]),
            55.0,
            2e-4,
        ),  # fmt: skip
        accepts={
            "threshold": "big tiny mm",
            "amplitudes": "zero",
            "frequencies_hz": "zero",
            "nonlinear_critical_speed": "inf",
        },
        infinite=("nonlinear_critical_speed",),  # decayed motion: 0 m, 0 Hz; no hunting: +inf
    ),
    fuzz(
        "raildyn.stability.BifurcationDiagram.plot",
        lambda: on(diagram(), linear_critical_speed=54.6),
        accepts={"linear_critical_speed": "none tiny"},  # None: left out
    ),
    fuzz(
        "raildyn.stability.periodic_orbit",
        lambda: call(NW, 60.0, orbit_guess()[0], orbit_guess()[1], tol=1e-4, max_iter=1, rtol=1e-6),
        accepts={"tol": "big mm", "rtol": "mm"},  # 1e-3 is a tolerance too (a coarse one)
    ),
    fuzz(
        "raildyn.stability.PeriodicOrbit",
        lambda: call(60.0, orbit().period, orbit().state, 0.0103, orbit().multipliers, 1e-7),
        accepts={
            "speed": "tiny",
            "state": "zero negative",
            "amplitude": "zero big mm",
            "multipliers": "zero negative complex",
            "residual": "zero big mm",
        },
    ),
]
