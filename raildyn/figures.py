"""Registry of the reproducible figures: each has an id, a caption and the book's figure number.

``python -m raildyn figures --out DIR`` writes every registered figure; a
notebook shows the same figure, captioned, with ``raildyn.figures.show(id)``. A figure
function builds a new ``matplotlib.figure.Figure`` (no pyplot, so the command
line needs no display) from the raildyn models and plot helpers.
"""

from __future__ import annotations

import base64
import html
import io
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.figure import Figure

from raildyn import plots, vibration


@dataclass(frozen=True)
class FigureSpec:
    """One reproducible figure.

    Attributes
    ----------
    id : str
        Stable identifier, also the file name (``fig1.4``).
    caption : str
        What the figure shows, in the companion's words.
    book_figure : str or None
        The figure number in Garg & Dukkipati (1984), where it mirrors one.
    chapter : int
    draw : callable
        Builds and returns the figure.
    """

    id: str
    caption: str
    book_figure: str | None
    chapter: int
    draw: Callable[[], Figure]


REGISTRY: dict[str, FigureSpec] = {}


def register(id: str, caption: str, *, chapter: int, book_figure: str | None = None):
    """Decorator adding a figure function to ``REGISTRY`` under ``id``."""

    def add(draw: Callable[[], Figure]) -> Callable[[], Figure]:
        if id in REGISTRY:
            raise ValueError(f"figure id {id!r} is registered twice")
        REGISTRY[id] = FigureSpec(id, caption, book_figure, chapter, draw)
        return draw

    return add


def make(id: str) -> Figure:
    """Build the registered figure ``id`` and return it."""
    if id not in REGISTRY:
        raise ValueError(f"unknown figure id {id!r}; registered: {sorted(REGISTRY)}")
    with matplotlib.rc_context(plots.STYLE):
        return REGISTRY[id].draw()


class FigureView:
    """A registered figure ready for display in a notebook, with its caption.

    Jupyter shows the ``text/html`` part (picture and caption); the book prefers
    it too. The ``image/png`` part serves front ends without HTML.
    """

    def __init__(self, spec: FigureSpec, figure: Figure):
        self.spec = spec
        self.figure = figure

    def _png(self) -> bytes:
        buffer = io.BytesIO()
        self.figure.savefig(buffer, format="png", dpi=100)
        return buffer.getvalue()

    def _repr_mimebundle_(self, include=None, exclude=None):
        png = base64.b64encode(self._png()).decode("ascii")
        book = f" (book Fig. {self.spec.book_figure})" if self.spec.book_figure else ""
        caption = f"Figure {self.spec.id}{book}. {self.spec.caption}"
        html_text = (
            f'<figure class="raildyn-figure"><img src="data:image/png;base64,{png}" '
            f'alt="{html.escape(caption)}" style="max-width:100%">'
            f"<figcaption>{html.escape(caption)}</figcaption></figure>"
        )
        return {"text/html": html_text, "image/png": png, "text/plain": caption}


def show(id: str) -> FigureView:
    """The registered figure ``id`` with its caption, for display in a notebook."""
    figure = make(id)
    return FigureView(REGISTRY[id], figure)


def save_all(
    out: str | Path,
    *,
    formats: Iterable[str] = ("png",),
    ids: Iterable[str] | None = None,
    progress: bool = True,
) -> list[Path]:
    """Write the registered figures (all, or ``ids``) to ``out``; return the paths written."""
    from tqdm.auto import tqdm

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    chosen = sorted(REGISTRY) if ids is None else list(ids)
    written = []
    for fid in tqdm(chosen, desc="figures", disable=not progress):
        fig = make(fid)
        for fmt in formats:
            path = out / f"{fid}.{fmt}"
            fig.savefig(path, dpi=150)
            written.append(path)
    return written


def _figure(**kwargs) -> Figure:
    return Figure(layout="constrained", **kwargs)


@register(
    "fig1.4",
    "Locus of the characteristic roots s₁, s₂ of an SDOF system as the damping factor ξ grows from 0: "
    "a quarter circle of radius ω_n while ξ < 1, the double root −ω_n at ξ = 1, then two real roots, "
    "one tending to 0 and the other to −∞.",
    chapter=1,
    book_figure="1.4",
)
def root_locus_figure() -> Figure:
    fig = _figure(figsize=(5.5, 4.2))
    ax = fig.subplots()
    xi = np.r_[np.linspace(0.0, 1.0, 201), np.linspace(1.0, 4.0, 301)[1:]]
    locus = vibration.root_locus(1.0, xi)
    plots.root_locus(locus, ax=ax)
    for value in (0.0, 0.5, 1.0, 2.0):
        s = vibration.root_locus(1.0, [value])[0]
        ax.plot(s.real, s.imag, "k.", ms=6)
        ax.annotate(f"ξ = {value:g}", (s[0].real, s[0].imag), textcoords="offset points", xytext=(6, 4))
    ax.set_xlim(-4.2, 0.6)
    ax.set_xlabel(r"Re $s/\omega_n$")
    ax.set_ylabel(r"Im $s/\omega_n$")
    ax.set_title("Roots of $s^2 + 2\\xi\\omega_n s + \\omega_n^2 = 0$")
    return fig


@register(
    "fig1.5",
    "Free response of an underdamped SDOF system (ξ = 0.1, ω_n = 2π rad/s, x₀ = 1, v₀ = 0) inside its "
    "envelope A e^{−ξω_n t}; the peaks x₁ and x₂ are one damped period T_d apart and ln(x₁/x₂) = δ.",
    chapter=1,
    book_figure="1.5",
)
def underdamped_response_figure() -> Figure:
    system = vibration.SDOF.from_modal(2 * np.pi, 0.1)
    x0, v0 = 1.0, 0.0
    t = np.linspace(0.0, 4.0, 1200)
    fig = _figure(figsize=(6.5, 3.6))
    ax = fig.subplots()
    plots.time_history(t, system.free_response(t, x0, v0), ax=ax, envelope=system.envelope(t, x0, v0))
    times, values = system.decay_peaks(x0, v0, count=3)
    (t1, t2), (x1, x2) = times[1:], values[1:]  # the second and third maxima, clear of the axis
    ax.plot([t1, t2], [x1, x2], "s", color=plots.COLORS[1])
    ax.annotate("$x_1$", (t1, x1), textcoords="offset points", xytext=(4, 6))
    ax.annotate("$x_2$", (t2, x2), textcoords="offset points", xytext=(4, 6))
    ax.annotate("", (t1, -0.85), (t2, -0.85), arrowprops={"arrowstyle": "<->"})
    ax.text(0.5 * (t1 + t2), -0.8, "$T_d = 2\\pi/\\omega_d$", ha="center", va="bottom")
    ax.set_title(f"δ = ln(x₁/x₂) = {np.log(x1 / x2):.4f};  2πξ/√(1−ξ²) = {system.log_decrement:.4f}")
    return fig
