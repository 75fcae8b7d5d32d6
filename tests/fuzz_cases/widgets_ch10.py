"""Fuzz registry: the chapter-10 widgets (raildyn.widgets.chapter10).

Each factory takes no arguments, so only the unknown keyword applies (Python refuses it before
the body runs); tests/test_widgets_ch10.py and tests/test_widget_contract.py make the valid calls.
"""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz(f"raildyn.widgets.chapter10.{name}", lambda: call())
    for name in ("load_models", "moving_load_explorer", "track_receptance", "train_resonance")
]
