"""Fuzz registry: chapter 8's steady-curving derivations (raildyn.derivations.curving)."""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz("raildyn.derivations.curving.wheelset_curving", lambda: call(), limit=20.0),
    fuzz("raildyn.derivations.curving.bogie_curving", lambda: call(), limit=30.0),
    fuzz("raildyn.derivations.curving.bending_shear", lambda: call(), limit=30.0),
]
