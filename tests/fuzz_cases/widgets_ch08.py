"""Fuzz registry: the chapter-8 widgets (raildyn.widgets.chapter08).

Each factory takes no arguments, so only the unknown keyword applies (Python refuses it before
the body runs); tests/test_widgets_ch08.py and tests/test_widget_contract.py make the valid calls.
"""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz(f"raildyn.widgets.chapter08.{name}", lambda: call())
    for name in ("curve_entry_speed", "curving_plan", "nadal_chart")
]
