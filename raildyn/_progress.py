"""The one progress bar of raildyn's long computations (sweeps, maps, long simulations)."""

from __future__ import annotations

import os


def progress_bar(iterable=None, *, total=None, desc: str = ""):
    """A tqdm bar (a widget in a notebook, text in a terminal) over ``iterable`` or ``total`` steps.

    ``RAILDYN_PROGRESS=0`` in the environment switches every bar off: the book
    build sets it, because a page read without a kernel would show the bar
    frozen at 0 %. A finished bar stays on screen: closing its widget would
    leave a dead view behind in Voilà.
    """
    from tqdm.auto import tqdm

    off = os.environ.get("RAILDYN_PROGRESS", "1") == "0"
    return tqdm(iterable, total=total, desc=desc, disable=off)
