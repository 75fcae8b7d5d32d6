"""The parameters of the lateral three-piece truck and its freight car, each with its source.

Masses, inertias, stiffnesses and the friction of the wedges and the centre plate that
:mod:`raildyn.vehicles.three_piece` builds :class:`~raildyn.vehicles.three_piece.ThreePieceTruck`
and :func:`~raildyn.vehicles.three_piece.freight_car` from, and the derived wheelset, body mass and
friction forces. Kept apart from the models so that the models read as models and the data as data.
"""

from __future__ import annotations

import numpy as np

from raildyn import contact
from raildyn.constants import (
    GRAVITY,
    STEEL_POISSON_RATIO,
    STEEL_SHEAR_MODULUS,
    STEEL_YOUNGS_MODULUS,
)
from raildyn.vehicles.wedges import wedge_friction_force
from raildyn.wheelset import Wheelset

# Sources:
# [FC]  raildyn.vehicles.freight.VerticalFreightCar, the loaded 100-ton hopper of chapter 6 (AAR 286 000 lb
#       gross rail load; its derivations are in that class's docstring);
# [TV]  raildyn.train.vehicles, "empty hopper": 63 000 lb light weight (a typical value for the car);
# [RC]  L. Baruffaldi's MBSim model of an AmstedMaxion Ride Control truck (doctoral thesis, UNICAMP),
#       https://github.com/leo-bart/doutorado-repo, src/ridecontroltruck.cpp at commit 247ba5c
#       (the same model raildyn.vehicles.freight.GDU_ORE_CAR takes its nests and wedges from);
# [AAR] the AAR's standard for cars of 286 000 lb: 36 in wheels on a 1:20 tread taper.
# Values marked "representative" have no published source that we found; each says why it is
# reasonable, and the notebooks sweep the ones the critical speed is sensitive to.
_SIDE_FRAME_MASS = 290.0  # kg, one side frame [RC: sideFrameMass = 2 × 290, "doubled for both sides"]
_SIDE_FRAME_YAW_INERTIA = 91.0  # kg·m², one side frame about the vertical [RC: sideFrameInertiaTensor(1,1)]
_BOLSTER_MASS = 342.0  # kg [RC: bolsterMass]
_BOLSTER_YAW_INERTIA = 99.0  # kg·m², about the vertical [RC: bolsterInertiaTensor(1,1); y is up there]
_WEDGE_SPRING_FORCE = 344000.0 * (0.1857 - 0.1381)  # N: 344 kN/m from 0.1857 to 0.1381 m [RC]
_WEDGE_ANGLE = np.radians(37.5)  # bolster slope from the vertical [RC: angleBolster]
_WEDGE_FRICTION = 0.10  # at the column [doutorado-repo input.in: FRICTION_COEFF]
_WEDGE_OFFSET = 0.221  # m, each wedge ahead of or behind the bolster's centre line [RC: WRL/WFL frames]
_WHEELSET_MASS = 2000.0  # kg, with its bearings and adapters [RC: wheelL->setMass(2000)]
# Yaw inertia: the Manchester wheelset's radius of gyration (1120 kg·m² on 1813 kg, Iwnicki 1998), 0.786 m,
# at this mass (derived).
_WHEELSET_YAW_INERTIA = _WHEELSET_MASS * 1120.0 / 1813.0
_WHEEL_RADIUS = 0.0254 * 36 / 2  # m [AAR]
_CONICITY = 1.0 / 20.0  # the new wheel's tread taper [AAR]
# Half the distance between the contact points on standard gauge, m (as raildyn's Wheelset).
_HALF_GAUGE = 0.75
_SEMI_WHEELBASE = 0.865  # m [FC: semi_truck_wheelbase]
_SIDE_FRAME_SPACING = 1.0  # m, half the distance between the side frames and nests [FC: semi_spring_spacing]
_SEMI_TRUCK_SPACING = (40 + 8 / 12) * 0.3048 / 2  # m [FC: semi_truck_spacing]
_NEST_STIFFNESS = 121_000.0 * GRAVITY / 4 / 0.06  # N/m, vertical, per nest [FC: nest_stiffness]
_BODY_LENGTH, _BODY_WIDTH, _BODY_HEIGHT = 15.0, 3.2, 3.5  # m, the uniform body of [FC]'s inertias
# Side-frame pendulum: the side frame hangs from the adapter crowns at the axle centre, r₀ above the rail,
# and carries its load at the spring seat, 0.238 m above the rail [RC: sideFrameSpringBedBottomHeight]; its
# lateral stiffness per wheelset is the load on that wheelset's two adapters over the pendulum length
# (derived).
_PENDULUM_LENGTH = _WHEEL_RADIUS - 0.238
# Adapter in the pedestal jaw, longitudinal: 20 MN/m per adapter, at ±d. Representative (assumed): the
# adapters are stiff steel seats that keep the axles square to the side frames. The loaded car's critical
# speed depends on it (40.6, 34.8, 29.8 m/s at 10, 20, 40 MN/m; the empty car's 15.1, 14.6, 14.3 m/s).
_ADAPTER_LONGITUDINAL = 20.0e6
# Lateral shear of a spring nest: 0.5 of its vertical rate. Representative (assumed): the lateral rate of a
# loaded coil spring is a fraction of its vertical rate that falls as its load rises.
_NEST_LATERAL = 0.5 * _NEST_STIFFNESS
# Warp (squaring) stiffness of the wedges: 2 MN·m/rad per truck. Representative (assumed: we found no
# published value): a soft truck in warp, the classic weakness of the three-piece design; the notebooks
# sweep it, and the rigid-truck limit is its infinite value.
_WARP_STIFFNESS = 2.0e6
# Centre plate: 14 in (0.356 m) diameter, friction coefficient 0.2, friction acting at 2/3 of the radius
# (uniform pressure). Representative (assumed).
_CENTRE_PLATE_RADIUS = 0.0254 * 14 / 2
_CENTRE_PLATE_FRICTION = 0.2
_CENTRE_PLATE_ARM = 2 / 3 * _CENTRE_PLATE_RADIUS  # uniform pressure
# The reference motion at which friction is linearised: 2 Hz, the frequency of freight-truck hunting, and
# relative amplitudes of 0.5 mm and 0.5 mrad. Representative: the linear model decides whether small motions
# about the centred running grow, and friction barely slides in them; the equivalent dampers, and so the
# linear critical speed, vary as 1/(ω X).
_REFERENCE_FREQUENCY = 2.0
_REFERENCE_AMPLITUDE = 0.5e-3
_REFERENCE_ANGLE = 0.5e-3


_GROSS_MASS = 286_000 * 0.45359237  # kg, the AAR gross rail load [FC]
_LIGHT_MASS = 63_000 * 0.45359237  # kg, the empty car's light weight [TV]
_WEDGE_MASS = 12.0  # kg, one wedge [RC: wedgeMass]
_TRUCK_MASS = 2 * _WHEELSET_MASS + 2 * _SIDE_FRAME_MASS + _BOLSTER_MASS + 4 * _WEDGE_MASS  # 4970 kg
_LOADED_HEIGHT = 1.5  # m, centre of gravity above the nests, loaded [FC: cg_height]
# Empty: representative; the empty hopper's centre of gravity is about 1.5 m above the rail, 0.9 m above
# the nests.
_EMPTY_HEIGHT = 0.9


def _body_mass(total: float) -> float:
    """The mass moving laterally with the body, kg: all but the trucks' wheelsets, side frames and wedges."""
    return total - 2 * (_TRUCK_MASS - _BOLSTER_MASS)


def _wheelset(total: float) -> Wheelset:
    """The freight wheelset under a car of ``total`` mass (kg): contact, pendulum and adapters."""
    axle_load = total * GRAVITY / 4
    adapters = (total - 4 * _WHEELSET_MASS) * GRAVITY / 4  # weight on one wheelset's two adapters
    patch = contact.hertz_contact(axle_load / 2, _WHEEL_RADIUS, np.inf, _WHEEL_RADIUS,
                                  STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO)  # fmt: skip
    f = contact.creep_coefficients(patch.a, patch.b, STEEL_SHEAR_MODULUS, STEEL_POISSON_RATIO)
    return Wheelset(
        mass=_WHEELSET_MASS,
        yaw_inertia=_WHEELSET_YAW_INERTIA,
        rolling_radius=_WHEEL_RADIUS,
        half_gauge=_HALF_GAUGE,
        conicity=_CONICITY,
        axle_load=axle_load,
        f11=float(f.f11),
        f22=float(f.f22),
        f23=float(f.f23),
        f33=float(f.f33),
        lateral_stiffness=adapters / _PENDULUM_LENGTH,
        yaw_stiffness=2 * _ADAPTER_LONGITUDINAL * _SIDE_FRAME_SPACING**2,
        lateral_damping=0.0,
        yaw_damping=0.0,
    )


def _centre_plate_friction(total: float) -> float:
    """μ W (2/3) R, N·m: the centre plate under half the body's weight."""
    return _CENTRE_PLATE_FRICTION * (_body_mass(total) * GRAVITY / 2) * _CENTRE_PLATE_ARM


def _wedge_normal_force() -> float:
    """Mean column force of one wedge, N: friction over μ (``wedge_friction_force`` for one wedge)."""
    wedge = wedge_friction_force(_WEDGE_SPRING_FORCE, _WEDGE_ANGLE, _WEDGE_FRICTION, wedges=1)
    return wedge.mean / _WEDGE_FRICTION
