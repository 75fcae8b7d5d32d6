"""Fuzz registry: chapter 10's beam derived (raildyn.derivations.bridge)."""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz("raildyn.derivations.bridge.beam_modes", lambda: call(2), limit=20.0),
    fuzz("raildyn.derivations.bridge.beam_under_moving_force", lambda: call(2), limit=20.0),
    fuzz("raildyn.derivations.bridge.beam_under_moving_mass", lambda: call(2), limit=30.0),
]
