"""Curve geometry (book chapter 8), now in :mod:`raildyn.track`: this module only re-exports it.

The cant quantities and the limits of curve geometry live in :mod:`raildyn.track.cant`, the curve
with transitions in :mod:`raildyn.track.curve`, below the wheelset and the curving models that
run on them. Import them from there (``from raildyn.track import Curve``): this older path is
deprecated and will be removed.
"""

# The old import path, kept for one issue: raildyn.track.cant and raildyn.track.curve are the homes.
from raildyn.track.cant import (
    CANT_GRADIENT_LIMIT,
    MAXIMUM_CANT,
    MAXIMUM_SPEED,
    MINIMUM_RADIUS,
    STANDARD_RAIL_SPACING,
    TWIST_BASE,
    balance_speed,
    cant_deficiency,
    equilibrium_cant,
    speed_for_deficiency,
    unbalanced_acceleration,
)
from raildyn.track.curve import Curve

__all__ = [
    "CANT_GRADIENT_LIMIT",
    "MAXIMUM_CANT",
    "MAXIMUM_SPEED",
    "MINIMUM_RADIUS",
    "STANDARD_RAIL_SPACING",
    "TWIST_BASE",
    "Curve",
    "balance_speed",
    "cant_deficiency",
    "equilibrium_cant",
    "speed_for_deficiency",
    "unbalanced_acceleration",
]
