"""What the widget tests share: a widget's status line, and the median time of its updates."""

from __future__ import annotations

import statistics
import time


def status_line(container) -> str:
    """The text of a raildyn widget's status line (the last child of its controls' row)."""
    return container.children[-2].children[-1].value


def median_update_ms(update, control: str, values) -> float:
    """Median wall time, ms, of ``update(control=value)`` over ``values``."""
    times = []
    for value in values:
        start = time.perf_counter()
        update(**{control: value})
        times.append(time.perf_counter() - start)
    return 1e3 * statistics.median(times)
