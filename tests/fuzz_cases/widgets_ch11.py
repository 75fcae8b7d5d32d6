"""Fuzz registry: the chapter-11 widgets (raildyn.widgets.chapter11).

Each factory takes no arguments, so only the unknown keyword applies (Python refuses it before
the body runs); tests/test_widgets_ch11.py and tests/test_widget_contract.py make the valid calls.
"""

from __future__ import annotations

from fuzzing import call, fuzz

ENTRIES = [
    fuzz(f"raildyn.widgets.chapter11.{name}", lambda: call())
    for name in ("metrics_explorer", "prediction_vs_measurement", "sensitivity_bars")
]
