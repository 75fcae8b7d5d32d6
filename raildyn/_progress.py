"""How raildyn shows itself where it runs: the one progress bar of its long computations (sweeps, maps,
long simulations), and whether its kernel serves the lecture-room app."""

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


def in_the_app() -> bool:
    """Whether this kernel serves a page of the lecture-room app (Voilà names its kernels in
    ``VOILA_KERNEL_ID``). The app shows live widgets and no worked answer, so what only a page without a
    kernel or a reader of the answers would see is not worked out there."""
    return bool(os.environ.get("VOILA_KERNEL_ID"))
