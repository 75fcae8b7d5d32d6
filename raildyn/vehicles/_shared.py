"""The private helpers several modules of :mod:`raildyn.vehicles` share.

The checks of a car body on two trucks and of a truck's ``assemble`` arguments, ``replace``
passing a change on to an inner model (lateral, three-piece and locomotive models), the body of every
lateral vehicle's ``nonlinear()``, and the
checks of a ``vehicle`` argument, of its speed and of an earlier plot's artists (the response
functions and the freight car's plots). Kept apart so that those modules import each other's
helpers from here, not from one another.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from raildyn import _checks
from raildyn._checks import nonnegative, positive
from raildyn.constants import GRAVITY
from raildyn.linear_model import Assembler, LinearSystem, as_linear_system
from raildyn.wheelset import NonlinearLateral, WheelRailContact


def _replace_through(model, changes: dict, inner: str):
    """``dataclasses.replace(model, ...)`` where a change that is not the model's own field goes to its
    field ``inner`` (a truck's wheelset, a car's truck), whose own ``replace`` passes it on again."""
    own_fields = set(type(model).__dataclass_fields__)
    own = {k: v for k, v in changes.items() if k in own_fields}
    rest = {k: v for k, v in changes.items() if k not in own_fields}
    if rest:
        own[inner] = (own.get(inner) or getattr(model, inner)).replace(**rest)
    return replace(model, **own)


def _nonlinear(model, contact, elements=()) -> NonlinearLateral:
    """The body of every lateral vehicle's ``nonlinear(contact=None)``: its linear system with ``contact``
    (default :class:`~raildyn.wheelset.WheelRailContact`) and the nonlinear ``elements`` it holds."""
    contact = (
        WheelRailContact() if contact is None else _checks.instance("contact", contact, WheelRailContact)
    )
    return NonlinearLateral(model.linear_system(), contact, elements)


def _check_body_on_two_trucks(car, spacing: str, truck_half: str, truck_half_length: float) -> None:
    """The checks every car body on two trucks shares, each naming the field at fault.

    Masses, inertias and the semi-spacing of the trucks in their plausible ranges
    (:data:`raildyn.constants.PLAUSIBLE_RANGES`); height and roll terms ≥ 0; the semi-spacing of the trucks
    (field ``spacing``) beyond the truck's half length (its field ``truck_half``), so that
    the wheelsets of the two trucks do not cross; and the two trucks' roll stiffness 2 k_φ
    above m g h, the roll moment of the body's weight h above the springs, else it topples.
    """
    for name in ("body_mass", "body_yaw_inertia", "body_roll_inertia", spacing):
        positive(name, getattr(car, name))
    for name in ("body_height", "roll_stiffness", "roll_damping"):
        nonnegative(name, getattr(car, name))
    _checks.plausible("body_mass", car.body_mass, "mass")
    _checks.plausible_fields(car, "inertia", ("body_yaw_inertia", "body_roll_inertia"))
    _checks.plausible(spacing, getattr(car, spacing), "vehicle_length")
    _checks.plausible("body_height", car.body_height, "vehicle_length", low=0.0)
    if getattr(car, spacing) <= truck_half_length:
        raise ValueError(
            f"{spacing} must exceed the truck's {truck_half} ({truck_half_length!r} m) so that the "
            f"wheelsets of the two trucks do not cross, got {getattr(car, spacing)!r}"
        )
    toppling = car.body_mass * GRAVITY * car.body_height
    if 2 * car.roll_stiffness <= toppling:
        raise ValueError(
            f"roll_stiffness {car.roll_stiffness!r} N·m/rad per truck is too soft for body_mass "
            f"{car.body_mass!r} kg at body_height {car.body_height!r} m: the two trucks' 2 k_φ must "
            f"exceed m g h = {toppling:.4g} N·m/rad, else the body topples"
        )


def _check_truck_assembly(asm, tag, body, body_yaw, first_input, *, parts=("frame",), axles: int = 2) -> int:
    """The checks of a truck's ``assemble`` arguments (see :meth:`Bogie.assemble`), each naming its argument.

    ``asm`` must hold the truck's coordinates: "frame{tag} y", "frame{tag} ψ", the yaw
    "{part}{tag} ψ" of each further part (a bolster) and "wheelset{tag}{k} y/ψ" of its
    ``axles`` wheelsets, whose alignment inputs start at ``first_input``. Returns ``q/2``,
    the index of the first cross-level input of the assembly.
    """
    _checks.instance("asm", asm, Assembler)
    _checks.instance("tag", tag, str, "str")
    labels = [f"frame{tag} y"] + [f"{part}{tag} ψ" for part in parts]
    labels += [f"wheelset{tag}{k} {q}" for k in range(1, axles + 1) for q in "yψ"]
    missing = [label for label in labels if label not in asm.labels]
    if missing:
        raise ValueError(f"tag {tag!r} names no truck of asm: {missing} are not among its labels")
    _checks.instance("body", body, dict, "dict of body label to coefficient")
    for label, coefficient in body.items():
        if label not in asm.labels:
            raise ValueError(f"body must name coordinates of asm {asm.labels}, got the key {label!r}")
        _checks.scalar(f"body[{label!r}]", coefficient)
    if body_yaw is not None and body_yaw not in asm.labels:
        raise ValueError(f"body_yaw must be None or a coordinate of asm {asm.labels}, got {body_yaw!r}")
    half = asm.GK.shape[1] // 2
    _checks.integer("first_input", first_input, low=0, high=half - axles)
    return half


def _earlier_artists(artists, keys) -> dict:
    """The ``artists`` dict an earlier ``plot()`` returned, refused by name if it is not one."""
    _checks.instance("artists", artists, dict, "dict of the artists an earlier plot() returned")
    missing = [k for k in keys if k not in artists]
    if missing:
        raise ValueError(
            f"artists must hold {list(keys)} as an earlier plot() returned them, lacks {missing}"
        )
    return artists


def _vehicle(vehicle) -> LinearSystem:
    """The system of the ``vehicle`` argument, refusing an object that is not a linear model by its name."""
    return as_linear_system(_checks.linear_model("vehicle", vehicle))


def _steady_system(vehicle, speed, name: str = "speed") -> tuple[LinearSystem, float]:
    """The vehicle's system and V, refusing a speed at which the model is unstable (no steady response)."""
    system = _vehicle(vehicle)
    # At least 1 mm/s: slower, the track's spectrum in time, S(ω/V)/V, and the creep damping C₁/V
    # overflow, and no vehicle's response is of interest.
    V = _checks.speed(name, speed, low=1.0e-3, low_open=False)
    if np.any(system.C1):
        growth = np.linalg.eigvals(system.matrices(V).state_matrix()).real.max()
        if growth >= 0:
            raise ValueError(
                f"{name} {V!r} m/s is at or above the critical speed of this vehicle (an eigenvalue has real "
                f"part {growth:.3g} 1/s >= 0): no steady response"
            )
    return system, V
