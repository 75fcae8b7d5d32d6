"""Registry of the reproducible figures: each has an id, a caption and the book's figure number.

Each chapter registers its figures in ``raildyn/figures/chNN.py`` with the
:func:`register` decorator; every such module is imported below, so adding a
chapter's figures needs no edit here.

``python -m raildyn figures --out DIR`` writes every registered figure; a
notebook shows the same figure, captioned, with ``raildyn.figures.show(id)``. A figure
function builds a new ``matplotlib.figure.Figure`` (no pyplot, so the command
line needs no display) from the raildyn models and plot helpers.
"""

from __future__ import annotations

import base64
import html
import importlib
import io
import pkgutil
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import matplotlib
from matplotlib.figure import Figure

from raildyn import plots
from raildyn._progress import progress_bar

__all__ = ["REGISTRY", "FigureSpec", "FigureView", "make", "new_figure", "register", "save_all", "show"]


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
        The book's chapter the figure belongs to.
    draw : callable
        ``draw()`` builds and returns the figure (a ``matplotlib.figure.Figure``).
    """

    id: str
    caption: str
    book_figure: str | None
    chapter: int
    draw: Callable[[], Figure]


#: Every registered figure, by id; filled by :func:`register` when ``raildyn.figures`` is imported.
#:
#: :meta hide-value:
REGISTRY: dict[str, FigureSpec] = {}


def register(id: str, caption: str, *, chapter: int, book_figure: str | None = None):
    """Decorator adding a figure function to ``REGISTRY`` under ``id``.

    Parameters
    ----------
    id : str
        Stable identifier of the figure, also its file name (``fig1.4``); unique.
    caption : str
        What the figure shows, in the companion's words.
    chapter : int
        The book's chapter the figure belongs to.
    book_figure : str or None, optional
        The figure number in Garg & Dukkipati (1984), where the figure mirrors one.

    Returns
    -------
    callable
        The decorator: it registers ``draw`` (a function of no arguments returning a
        ``matplotlib.figure.Figure``) and returns it unchanged. It raises ``ValueError``
        if ``id`` is registered already.
    """

    def add(draw: Callable[[], Figure]) -> Callable[[], Figure]:
        if id in REGISTRY:
            raise ValueError(f"figure id {id!r} is registered twice")
        REGISTRY[id] = FigureSpec(id, caption, book_figure, chapter, draw)
        return draw

    return add


def make(id: str) -> Figure:
    """Build the registered figure ``id`` and return it.

    The figure is drawn inside ``matplotlib.rc_context(raildyn.plots.STYLE)``, so
    matplotlib's defaults are left as they were.

    Parameters
    ----------
    id : str
        A key of ``REGISTRY`` (``"fig1.4"``).

    Returns
    -------
    matplotlib.figure.Figure
        A new figure, not attached to pyplot.

    Raises
    ------
    ValueError
        If ``id`` is not registered; the message lists the registered ids.
    """
    if id not in REGISTRY:
        raise ValueError(f"unknown figure id {id!r}; registered: {sorted(REGISTRY)}")
    with matplotlib.rc_context(plots.STYLE):
        return REGISTRY[id].draw()


class FigureView:
    """A registered figure ready for display in a notebook, with its caption.

    Jupyter shows the ``text/html`` part (picture and caption); the book prefers
    it too. The ``image/png`` part serves front ends without HTML.

    Parameters
    ----------
    spec : FigureSpec
        The registered figure: its id, caption and book figure number.
    figure : matplotlib.figure.Figure
        The figure drawn by ``spec.draw``.
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
    """The registered figure ``id`` with its caption, for display in a notebook.

    Parameters
    ----------
    id : str
        A key of ``REGISTRY`` (``"fig1.4"``).

    Returns
    -------
    FigureView
        The figure built by :func:`make` with its caption; Jupyter and the book
        display it as a captioned picture.
    """
    figure = make(id)
    return FigureView(REGISTRY[id], figure)


def save_all(
    out: str | Path,
    *,
    formats: Iterable[str] = ("png",),
    ids: Iterable[str] | None = None,
    progress: bool = True,
) -> list[Path]:
    """Write the registered figures (all, or ``ids``) to ``out``; return the paths written.

    Parameters
    ----------
    out : str or pathlib.Path
        Directory to write to; created (with its parents) if missing.
    formats : iterable of str, optional
        File formats matplotlib can write (``"png"``, ``"pdf"``, ``"svg"``); one file
        per figure and format, ``<id>.<format>``, at 150 dpi.
    ids : iterable of str or None, optional
        The ids to write, in this order; None (the default) writes every registered
        figure, sorted by id.
    progress : bool, optional
        Show a progress bar (default True).

    Returns
    -------
    list of pathlib.Path
        The files written, figure by figure and format by format.
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    chosen = sorted(REGISTRY) if ids is None else list(ids)
    written = []
    for fid in progress_bar(chosen, desc="figures") if progress else chosen:
        fig = make(fid)
        for fmt in formats:
            path = out / f"{fid}.{fmt}"
            fig.savefig(path, dpi=150)
            written.append(path)
    return written


def new_figure(**kwargs) -> Figure:
    """A new figure with the constrained layout, for a registered figure function to draw on.

    Parameters
    ----------
    **kwargs
        Passed on to ``matplotlib.figure.Figure`` (``figsize``, ``dpi``, ...).

    Returns
    -------
    matplotlib.figure.Figure
        A new figure, not attached to pyplot (so no display is needed).
    """
    return Figure(layout="constrained", **kwargs)


def _load_chapters() -> None:
    for module in sorted(m.name for m in pkgutil.iter_modules(__path__) if m.name.startswith("ch")):
        importlib.import_module(f"{__name__}.{module}")


_load_chapters()
