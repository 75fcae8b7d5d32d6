"""Plotting helpers shared by the notebooks, the widgets and the reproducible figures.

Each function draws on the axes it is given (or on new ones), never calls
``plt.show()`` and returns its artists in a dict, so a widget can move them
with ``set_data`` instead of drawing again. Style is applied through
``matplotlib.rc_context(STYLE)`` only: importing raildyn never changes
matplotlib's defaults.
"""

from __future__ import annotations

import matplotlib
import numpy as np

# One quiet house style for every raildyn figure.
STYLE = {
    "axes.grid": True,
    "grid.alpha": 0.3,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "font.size": 9,
    "axes.titlesize": 10,
    "axes.labelsize": 9,
    "legend.fontsize": 8,
    "legend.frameon": False,
    "lines.linewidth": 1.6,
}

COLORS = ("#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad", "#d68910")


def axes_or_new(ax):
    """The given axes, or new ones on a new pyplot figure (for notebook use)."""
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    with matplotlib.rc_context(STYLE):
        _, ax = plt.subplots(figsize=(5.5, 3.6), layout="constrained")
    return ax


def root_locus(locus: np.ndarray, roots: np.ndarray | None = None, *, ax=None) -> dict:
    """Draw the locus of the characteristic roots s₁, s₂ of an SDOF system (book Fig. 1.4).

    Parameters
    ----------
    locus : complex ndarray, shape (n, 2)
        Roots for a sweep of damping factors, normalised or in rad/s, as
        returned by :func:`raildyn.vibration.root_locus`.
    roots : complex ndarray, shape (2,), optional
        The roots to mark (the current ξ).
    ax : matplotlib Axes, optional

    Returns
    -------
    dict of artists: ``branch1``, ``branch2``, ``roots``, ``circle``.
    """
    ax = axes_or_new(ax)
    with matplotlib.rc_context(STYLE):
        scale = float(np.abs(locus[0, 0]))  # |s| at ξ = 0 is ω_n
        phi = np.linspace(np.pi / 2, 3 * np.pi / 2, 91)
        (circle,) = ax.plot(scale * np.cos(phi), scale * np.sin(phi), ls=":", color="0.6", lw=1)
        (b1,) = ax.plot(locus[:, 0].real, locus[:, 0].imag, color=COLORS[0], label="$s_1$")
        (b2,) = ax.plot(locus[:, 1].real, locus[:, 1].imag, color=COLORS[1], label="$s_2$")
        marks = np.zeros(2, complex) if roots is None else np.asarray(roots)
        (pts,) = ax.plot(marks.real, marks.imag, "o", color="k", ms=7, mfc="w", mew=2, zorder=5)
        pts.set_visible(roots is not None)
        ax.axhline(0, color="0.4", lw=0.8)
        ax.axvline(0, color="0.4", lw=0.8)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("real part")
        ax.set_ylabel("imaginary part")
        ax.legend(loc="upper left")
    return {"branch1": b1, "branch2": b2, "roots": pts, "circle": circle}


def time_history(
    t: np.ndarray, x: np.ndarray, *, ax=None, label: str | None = None, envelope=None, color=COLORS[0]
) -> dict:
    """Draw a displacement history, with an optional decay envelope ±A e^{-ξω_n t}.

    Returns
    -------
    dict of artists: ``line``, ``upper``, ``lower``.
    """
    ax = axes_or_new(ax)
    with matplotlib.rc_context(STYLE):
        (line,) = ax.plot(t, x, color=color, label=label)
        env = np.full_like(t, np.nan) if envelope is None else envelope
        (upper,) = ax.plot(t, env, ls="--", color="0.5", lw=1)
        (lower,) = ax.plot(t, -env, ls="--", color="0.5", lw=1)
        ax.axhline(0, color="0.4", lw=0.8)
        ax.set_xlabel("time $t$ (s)")
        ax.set_ylabel("displacement $x$")
    return {"line": line, "upper": upper, "lower": lower}


def frequency_curves(r: np.ndarray, curves: dict[str, np.ndarray], *, ax=None, logy: bool = False) -> dict:
    """Draw several curves against the frequency ratio r = ω/ω_n; return the lines by name."""
    ax = axes_or_new(ax)
    lines = {}
    with matplotlib.rc_context(STYLE):
        for i, (name, y) in enumerate(curves.items()):
            (lines[name],) = ax.plot(r, y, color=COLORS[i % len(COLORS)], label=name)
        if logy:
            ax.set_yscale("log")
        ax.set_xlabel(r"frequency ratio $r = \omega/\omega_n$")
    return lines


def spectrum(
    omega: np.ndarray, psd: np.ndarray, *, ax=None, label: str | None = None, color=COLORS[0]
) -> dict:
    """Draw a one-sided PSD per rad/s on log–log axes; return ``{"line": ...}``."""
    ax = axes_or_new(ax)
    with matplotlib.rc_context(STYLE):
        (line,) = ax.loglog(omega, psd, color=color, label=label)
        ax.set_xlabel(r"circular frequency $\omega$ (rad/s)")
    return {"line": line}
