"""Fuzz registry: chapter 4, wheel–rail contact (Hertz, creep laws, FASTSIM, profiles, comparison).

The profiles and the geometry table are built once (they are frozen and the calls only read
them); every valid call is the smallest meaningful one: a 7-shift cone table, a 4 × 4 FASTSIM
grid, three creepages.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import contact

# Changes a result dataclass holds without complaint: its fields are whatever a model computed
# (a force, a creepage or a position of any sign, a zero); NaN, inf, strings and None are refused.
RESULT = {"*": "zero negative mm big"}
# The same where every field may hold an array: a list of numbers is read as one.
RESULT_ARRAYS = {"*": "zero negative list mm big"}
# Creepages (ξ, η, φ), lateral speeds and positions, angles: any sign, zero included; a parameter
# documented as "float or array_like" takes a list of numbers.
SIGNED = "zero negative list mm big"
# A wheelset's motion and contact (wheelset_creepages and creepage_terms take the same): V, ẏ, ψ, ψ̇, the
# rolling radii, r₀, a and the contact angles; rates and angles of either sign, the radii one per contact.
CREEPAGE_MOTION = (40.0, 0.01, 1e-3, 0.02, 0.46015, 0.45985, 0.46, 0.75, 0.05, -0.05)
CREEPAGE_ACCEPTS = {
    "speed": "tiny",
    "rolling_radius_left": "list",
    "rolling_radius_right": "list",
    **dict.fromkeys(
        ("lateral_velocity", "yaw_angle", "yaw_rate", "contact_angle_left", "contact_angle_right"), SIGNED
    ),
}
ETA = np.array([0.0, 2e-3, 1e-2])


@functools.cache
def cone():
    return contact.conical_wheel(1 / 20)


@functools.cache
def s1002():
    return contact.s1002_wheel()


@functools.cache
def rail():
    return contact.uic60_rail(1 / 40)


@functools.cache
def worn_wheel():
    return contact.worn_wheel()


@functools.cache
def worn_rail():
    return contact.worn_rail(1 / 40)


@functools.cache
def geometry():
    return contact.contact_geometry(cone(), rail(), np.linspace(-3e-3, 3e-3, 7), roll=False)


@functools.cache
def coefficients():
    return contact.creep_coefficients(6e-3, 4e-3)


@functools.cache
def patch():
    return contact.fastsim(1e-3, 5e-4, 0.0, 1e5, 0.3, 6e-3, 4e-3, n_x=4, n_y=4)


@functools.cache
def curves():
    return contact.lateral_creep_curves(ETA, 1e5, 0.3, 6e-3, 4e-3)


@functools.cache
def hertz():
    return contact.hertz_contact(1e5, 0.46, -0.5, 0.3)


def _geometry_fields():
    g = geometry()
    return call(g.shift, g.wheel_position, g.rail_position, g.rolling_radius, g.contact_angle, g.roll)


def _curve_fields():
    c = curves()
    return call(
        c.lateral, c.spin, c.normal_load, c.friction, c.a, c.b, c.coefficients,
        c.kalker_linear, c.carter, c.johnson_vermeulen, c.shen_hedrick_elkins, c.polach, c.fastsim,
    )  # fmt: skip


def _fastsim_fields():
    r = patch()
    return call(
        r.fx, r.fy, r.mz, r.x, r.y, r.px, r.py, r.pz, r.slip_x, r.slip_y, r.adhesion,
        r.normal_load, r.friction, r.a, r.b,
    )  # fmt: skip


def _hertz_fields():
    h = hertz()
    return call(
        h.a, h.b, h.peak_pressure, h.approach, h.stiffness, h.theta, h.m, h.n, h.curvature_sum, h.normal_load
    )


def _wheel_fields():
    w = cone()
    return call("cone", w.lateral, w.radius, w.nominal_radius)


def _rail_fields():
    r = rail()
    return call("rail", r.lateral, r.height, r.inclination, r.gauge_face)


ENTRIES = [
    # --------------------------------------------------------------- Hertz
    fuzz("raildyn.contact.HertzCoefficients", lambda: call(1.0, 1.486, 0.717), accepts=RESULT_ARRAYS),
    fuzz("raildyn.contact.HertzContact", _hertz_fields, accepts=RESULT),
    fuzz(
        "raildyn.contact.HertzContact.pressure",
        lambda: on(hertz(), 1e-3, 5e-4),
        accepts={"x": SIGNED, "y": SIGNED},
    ),
    fuzz(
        "raildyn.contact.hertz_coefficients", lambda: call(math.radians(60)), accepts={"theta": "list tiny"}
    ),
    fuzz(
        "raildyn.contact.hertz_contact",
        lambda: call(1e5, 0.46, -0.5, 0.3),
        # A transverse radius is signed (convex > 0, concave < 0) and math.inf is a flat direction.
        accepts={
            "youngs_modulus": "big tiny mm",
            "wheel_transverse_radius": "inf negative big mm",
            "rail_transverse_radius": "inf",
            "rail_rolling_radius": "inf big mm",
            "poisson_ratio": "zero",
        },
    ),
    # --------------------------------------------------------------- creep laws
    fuzz("raildyn.contact.KalkerCoefficients", lambda: call(4.12, 3.67, 1.47, 1.19), accepts=RESULT_ARRAYS),
    fuzz(
        "raildyn.contact.CreepCoefficients",
        lambda: call(9.8e6, 8.7e6, 9.2e3, 1.8e1),
        # One value per contact in an array (a list is stored as one); f₂₃ = f₃₃ = 0 neglects spin.
        accepts={
            "f11": "list big tiny mm",
            "f22": "list big tiny mm",
            "f23": "zero list big mm",
            "f33": "zero list big mm",
        },
    ),
    fuzz(
        "raildyn.contact.CreepForces",
        lambda: call(-100.0, 50.0, 1.0),
        accepts={
            **RESULT_ARRAYS,
            "mz": "none big mm",
        },  # mz is None for the laws that give no spin moment
    ),
    fuzz(
        "raildyn.contact.WheelsetCreepages",
        lambda: call(np.array([1e-3, -1e-3]), np.array([2e-3, 2e-3]), np.array([0.1, -0.1])),
        accepts=RESULT,
    ),
    fuzz(
        "raildyn.contact.kalker_coefficients",
        lambda: call(1.5, 0.25),
        accepts={"a_over_b": "list", "poisson_ratio": "zero"},
    ),
    fuzz(
        "raildyn.contact.creep_coefficients",
        lambda: call(6e-3, 4e-3),
        accepts={"shear_modulus": "big tiny mm", "a": "list", "b": "list", "poisson_ratio": "zero"},
    ),
    fuzz(
        "raildyn.contact.kalker_linear",
        lambda: call(1e-3, 2e-3, 0.1, coefficients()),
        accepts={"longitudinal": SIGNED, "lateral": SIGNED, "spin": SIGNED},
    ),
    fuzz("raildyn.contact.carter_coefficient", lambda: call(1e5, 0.46, 6e-3)),
    fuzz(
        "raildyn.contact.carter",
        lambda: call(1e-3, 1e5, 0.3, 1.5e7),
        accepts={"friction": "tiny", "creep_coefficient": "big tiny mm", "longitudinal": SIGNED},
    ),
    fuzz(
        "raildyn.contact.johnson_vermeulen",
        lambda: call(1e-3, 2e-3, 1e5, 0.3, 6e-3, 4e-3),
        accepts={
            "friction": "tiny",
            "longitudinal": SIGNED,
            "lateral": SIGNED,
            "poisson_ratio": "zero",
            "shear_modulus": "big tiny mm",
        },
    ),
    fuzz(
        "raildyn.contact.johnson_vermeulen_coefficients",
        lambda: call(1.5, 0.3),
        accepts={"a_over_b": "list", "poisson_ratio": "zero"},
    ),
    fuzz("raildyn.contact.JohnsonVermeulenCoefficients", lambda: call(5.0, 4.5), accepts=RESULT_ARRAYS),
    fuzz(
        "raildyn.contact.saturation_factor",
        lambda: call(3e4, 1e4),
        accepts={"limit": "big tiny mm", "force": "zero list big mm"},
    ),
    fuzz("raildyn.contact.saturation_scale", lambda: call(1.5), accepts={"u": "zero list big mm"}),
    fuzz(
        "raildyn.contact.shen_hedrick_elkins",
        lambda: call(1e-3, 2e-3, 0.1, 1e5, 0.3, coefficients()),
        accepts={"friction": "tiny", "longitudinal": SIGNED, "lateral": SIGNED, "spin": SIGNED},
    ),
    fuzz(
        "raildyn.contact.polach",
        lambda: call(1e-3, 2e-3, 0.1, 1e5, 0.3, 6e-3, 4e-3),
        accepts={
            "friction": "tiny",
            "shear_modulus": "big tiny mm",
            "k_a": "tiny",
            "k_s": "tiny",
            "longitudinal": SIGNED,
            "lateral": SIGNED,
            "spin": SIGNED,
            "poisson_ratio": "zero",
        },
    ),
    fuzz(
        "raildyn.contact.PolachAdhesion",
        lambda: call(1.0, 0.4, 0.55, 0.4, 0.6),
        accepts={
            "k_a": "tiny",
            "k_s": "tiny",
            "static_friction": "tiny",
            "limit_ratio": "tiny",
            "decay_rate": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.contact.PolachAdhesion.friction",
        lambda: on(contact.POLACH_DRY, 0.5),
        accepts={"slip_speed": "zero list"},
    ),
    fuzz(
        "raildyn.contact.polach_adhesion",
        lambda: call(1e-2, 2e-3, 0.1, 1e5, 20.0, 6e-3, 4e-3),
        accepts={
            "speed": "tiny",
            "shear_modulus": "big tiny mm",
            "longitudinal": SIGNED,
            "lateral": SIGNED,
            "spin": SIGNED,
            "poisson_ratio": "zero",
        },
    ),
    fuzz(
        "raildyn.contact.wheelset_creepages",
        lambda: call(*CREEPAGE_MOTION),
        accepts=CREEPAGE_ACCEPTS,
    ),
    fuzz(
        "raildyn.contact.creepage_terms",
        lambda: call(*CREEPAGE_MOTION),
        accepts=CREEPAGE_ACCEPTS,
    ),
    # --------------------------------------------------------------- FASTSIM
    fuzz("raildyn.contact.Flexibilities", lambda: call(1e-14, 2e-14, 3e-14), accepts=RESULT_ARRAYS),
    fuzz(
        "raildyn.contact.flexibilities",
        lambda: call(6e-3, 4e-3),
        accepts={"shear_modulus": "big tiny mm", "a": "list", "b": "list", "poisson_ratio": "zero"},
    ),
    fuzz(
        "raildyn.contact.FastsimResult",
        _fastsim_fields,
        # The state (normal_load, friction, a, b) is None in a result built without it.
        accepts={
            **RESULT_ARRAYS,
            **{k: "zero negative list none" for k in ("normal_load", "friction", "a", "b")},
        },
    ),
    fuzz("raildyn.contact.FastsimResult.plot_patch", lambda: on(patch())),
    fuzz(
        "raildyn.contact.fastsim.fastsim",  # the module of the same name shadows it in resolve()
        lambda: call(1e-3, 5e-4, 0.1, 1e5, 0.3, 6e-3, 4e-3, n_x=4, n_y=4),
        accepts={
            "shear_modulus": "big tiny mm",
            "longitudinal": SIGNED,
            "lateral": SIGNED,
            "spin": SIGNED,
            "normal_load": "list",
            "friction": "list tiny",
            "a": "list",
            "b": "list",
            "poisson_ratio": "zero",
        },
    ),
    fuzz(
        "raildyn.contact.fastsim_reference",
        lambda: call(1e-3, 5e-4, 0.1, 1e5, 0.3, 6e-3, 4e-3, 5e-14, 5e-14, 5e-14, n_x=4, n_y=4),
        accepts={
            "normal_load": "big tiny mm",
            "friction": "big tiny mm",
            "l1": "big tiny mm",
            "l2": "big tiny mm",
            "l3": "big tiny mm",
            "longitudinal": SIGNED,
            "lateral": SIGNED,
            "spin": SIGNED,
        },
    ),
    # --------------------------------------------------------------- comparison
    fuzz("raildyn.contact.LateralCreepCurves", _curve_fields, accepts=RESULT),
    fuzz("raildyn.contact.LateralCreepCurves.normalised", lambda: on(curves(), "Polach")),
    fuzz("raildyn.contact.LateralCreepCurves.plot", lambda: on(curves())),
    fuzz(
        "raildyn.contact.lateral_creep_curves",
        lambda: call(ETA, 1e5, 0.3, 6e-3, 4e-3),
        accepts={
            "friction": "tiny",
            "shear_modulus": "big tiny mm",
            "lateral": "zero",
            "spin": SIGNED,
            "poisson_ratio": "zero",
        },
    ),
    # --------------------------------------------------------------- profiles and geometry
    fuzz("raildyn.contact.WheelProfile", _wheel_fields),
    fuzz("raildyn.contact.WheelProfile.radius_at", lambda: on(cone(), 3e-3), accepts={"u": SIGNED}),
    fuzz(
        "raildyn.contact.RailProfile",
        _rail_fields,
        # An upright rail; a flat head (z = 0 everywhere). The 60E1 heights are all <= 0 (none exactly 0
        # on the grid), so the change "negative", −|z|, gives back the same valid profile.
        accepts={"gauge_face": "tiny", "inclination": "zero", "height": "zero negative"},
    ),
    fuzz("raildyn.contact.conical_wheel", lambda: call(1 / 20, width=0.02), accepts={"slope": "zero"}),
    fuzz("raildyn.contact.s1002_wheel", lambda: call()),
    fuzz("raildyn.contact.uic60_rail", lambda: call(1 / 40), accepts={"inclination": "zero"}),
    fuzz("raildyn.contact.worn_wheel", lambda: call()),
    fuzz("raildyn.contact.worn_rail", lambda: call(1 / 40), accepts={"inclination": "zero"}),
    # The readers take the shipped worn profiles' files (a path as text: a missing file, a number and
    # None are the bad values); the pair check takes that worn pair at the gauge of its own track.
    fuzz(
        "raildyn.contact.read_wheel_profile", lambda: call(str(contact.WORN_WHEEL_FILE), nominal_radius=0.444)
    ),
    fuzz(
        "raildyn.contact.read_rail_profile",
        lambda: call(str(contact.WORN_RAIL_FILE), inclination=1 / 40),
        accepts={"inclination": "zero"},
    ),
    fuzz(
        "raildyn.contact.check_pair",
        lambda: call(worn_wheel(), worn_rail(), gauge=1.4351, tape_distance=1.4874),
    ),
    fuzz("raildyn.contact.ContactGeometry", _geometry_fields, accepts=RESULT),
    fuzz(
        "raildyn.contact.contact_geometry",
        lambda: call(s1002(), rail(), [-2e-3, 3e-3], yaw=0.01),
        # a yaw of either sign, or none
        accepts={"shifts": SIGNED, "yaw": "zero negative mm tiny"},
    ),
    fuzz(
        "raildyn.contact.trace_line",
        lambda: call(np.linspace(-0.05, 0.05, 11), 0.46 + np.linspace(-0.05, 0.05, 11) / 20, 0.01, 1.5),
        accepts={"yaw": "zero negative mm tiny", "radius": "list", "lateral": "list"},
    ),
    fuzz(
        "raildyn.contact.rolling_radius_difference",
        lambda: call(cone(), rail(), [-2e-3, 3e-3], roll=False),
        accepts={"shifts": SIGNED},
    ),
    fuzz(
        "raildyn.contact.contact_angles",
        lambda: call(s1002(), rail(), [-2e-3, 3e-3]),
        accepts={"shifts": SIGNED},
    ),
    fuzz(
        "raildyn.contact.equivalent_conicity",
        lambda: call(cone(), rail(), 3e-3, roll=False),
        accepts={"amplitudes": "list tiny"},
    ),
    fuzz(
        "raildyn.contact.harmonic_conicity",
        lambda: call(
            np.linspace(-0.01, 0.01, 21), 0.1 * np.linspace(-0.01, 0.01, 21), [2e-3, 5e-3], samples=32
        ),
        # Δr(y) is a measured or computed difference of radii: any sign, zero for a cylinder.
        accepts={"delta_r": "zero negative"},
    ),
    fuzz(
        "raildyn.contact.kinematic_conicity",
        lambda: call(np.linspace(-0.01, 0.01, 21), 0.1 * np.linspace(-0.01, 0.01, 21), [2e-3, 5e-3]),
        # A cylinder (Δr = 0) steers nothing: λ_e = 0. A Δr that never rises through zero (all
        # negative) is refused: the wheelset has no kinematic oscillation to measure.
        accepts={"delta_r": "zero", "amplitudes": "list"},
    ),
    fuzz(
        "raildyn.contact.ContactGeometry.equivalent_conicity",
        lambda: on(geometry(), 2e-3),
        accepts={"amplitudes": "list tiny"},
    ),
    fuzz("raildyn.contact.ContactGeometry.plot_rolling_radius_difference", lambda: on(geometry())),
    fuzz("raildyn.contact.ContactGeometry.plot_contact_angle", lambda: on(geometry())),
    fuzz("raildyn.contact.ContactGeometry.plot_equivalent_conicity", lambda: on(geometry(), [1e-3, 2e-3])),
]
