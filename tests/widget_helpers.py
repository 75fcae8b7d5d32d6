"""What the widget tests share: a widget's status line, the frames its updates draw, and the mark that
runs a chapter's widget tests in one process.

How fast an update is belongs to the benchmarks (``widget_case`` in ``benchmarks/common.py``, each
widget's goal in ``benchmarks/README.md``), not to a timed test.
"""

from __future__ import annotations

import pytest

PNG = b"\x89PNG\r\n\x1a\n"


def widgets_of(module: str) -> pytest.MarkDecorator:
    """The mark of a test that builds the widgets of one chapter module (``"chapter06"`` or
    ``"raildyn.widgets.chapter06"``): a chapter's widgets cache their model runs in the process (a rocking
    sweep, a bifurcation grid), so its tests run in one process, which makes each run once
    (``shares`` in tests/conftest.py)."""
    return pytest.mark.shares(f"widgets of {module.rsplit('.', 1)[-1]}")


def status_line(container) -> str:
    """The text of a raildyn widget's status line (the last child of its controls' row)."""
    return container.children[-2].children[-1].value


def redrawn_frames(update, control: str, values) -> list[bytes]:
    """The PNG frames of ``update(control=value)`` over ``values``, each checked to be a new picture.

    Every update must return a PNG frame, and a value that differs from the one before must draw a
    frame that differs from the one before: the update moved the figure.
    """
    frames = []
    for value in values:
        frame = update(**{control: value})
        assert isinstance(frame, bytes) and frame.startswith(PNG), f"{control}={value!r} gave no PNG frame"
        frames.append(frame)
    for k in range(1, len(frames)):
        before, value = values[k - 1], values[k]
        if value != before:
            assert frames[k] != frames[k - 1], f"{control}: {before!r} → {value!r} left the figure as it was"
    return frames
