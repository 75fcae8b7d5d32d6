"""Fuzz registry: chapter 4's creepages derived from the contact points' velocities; a yawed wheel's
trace line."""

from __future__ import annotations

from functools import cache

from fuzzing import call, fuzz, on

from raildyn.derivations.contact import creepages, trace_line


# The derivations are made when an entry first asks for them, not when the registry is collected (in
# every worker of the suite, 1.3 s).
@cache
def _derived():
    return creepages()


@cache
def _trace():
    return trace_line()


ARGS = (40.0, 0.01, 1e-3, 0.02, 0.4603, 0.4597, 0.46, 0.75, 0.05, 0.05)

ENTRIES = [
    fuzz("raildyn.derivations.contact.creepages", lambda: call()),
    fuzz(
        "raildyn.derivations.contact.CreepageDerivation",
        lambda: call(
            _derived().longitudinal,
            _derived().lateral,
            _derived().spin,
            _derived().symbols,
            steps=_derived().steps,
        ),
    ),
    fuzz(
        "raildyn.derivations.contact.CreepageDerivation.numeric",
        lambda: on(_derived(), *ARGS),
        # Rates and angles of either sign, or zero, are states of a running wheelset.
        accepts={
            "speed": "tiny",
            "lateral_velocity": "zero negative big mm",
            "yaw_angle": "zero negative big mm",
            "yaw_rate": "zero negative big mm",
            "contact_angle_left": "zero negative",
            "contact_angle_right": "zero negative",
        },
    ),
    fuzz("raildyn.derivations.contact.trace_line", lambda: call()),
    fuzz(
        "raildyn.derivations.contact.TraceLineDerivation",
        lambda: call(
            _trace().sin_theta,
            _trace().lateral_seen,
            _trace().radius_seen,
            _trace().lead,
            _trace().symbols,
            _trace().steps,
        ),
    ),
]
