"""Registry of the reproducible figures: each has an id, a caption and the book's figure number.

Each chapter registers its figures in ``raildyn/figures/chNN.py`` with the
:func:`register` decorator; every such module is imported when ``REGISTRY`` is first reached
(or a figure made, shown or registered), so adding a chapter's figures needs no edit here, and
importing this module does not import every chapter's models (tests/test_imports.py). A
chapter's figures are numbered in the order they are registered (Figure 7.1, 7.2, ...), which is
the order its notebook shows them.

``python -m raildyn figures --out DIR`` writes every registered figure; a
notebook shows the same figure, captioned, with ``raildyn.figures.show(id)``. A figure
function builds a new ``matplotlib.figure.Figure`` (no pyplot, so the command
line needs no display) from the raildyn models and plot helpers.
"""

from __future__ import annotations

import base64
import html
import importlib
import inspect
import io
import os
import pkgutil
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import matplotlib
from matplotlib.backend_bases import FigureCanvasBase
from matplotlib.figure import Figure

from raildyn import _checks, plots
from raildyn._progress import progress_bar

__all__ = ["REGISTRY", "FigureSpec", "FigureView", "make", "new_figure", "register", "save_all", "show"]

#: The book's chapters (Garg & Dukkipati 1984 has eleven).
_CHAPTERS = (1, 11)
#: An id is also a file name: a letter or digit, then letters, digits, ".", "_" or "-".
_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]*")
#: A figure number of the book: chapter.number, with an optional letter ("1.4", "6.12b").
_BOOK_FIGURE = re.compile(r"[0-9]+\.[0-9]+[a-z]?")


def _check_spec(id, caption, book_figure, chapter) -> None:
    """The checks shared by :class:`FigureSpec` and :func:`register`."""
    if not isinstance(id, str):
        raise TypeError(f"id must be a string, got {id!r} of type {type(id).__name__}")
    if not _ID.fullmatch(id):
        raise ValueError(
            f"id must be a file name of letters, digits, '.', '_' and '-' (e.g. 'fig1.4'), got {id!r}"
        )
    _checks.instance("caption", caption, str, "string")
    if book_figure is not None:
        _checks.instance("book_figure", book_figure, str, "string or None")
        if not _BOOK_FIGURE.fullmatch(book_figure):
            raise ValueError(
                f"book_figure must be a figure number such as '1.4' (or None), got {book_figure!r}"
            )
    _checks.integer("chapter", chapter, low=_CHAPTERS[0], high=_CHAPTERS[1])
    # An id that looks like a book figure number is one: "fig1.4" exactly when book_figure is "1.4".
    looks = re.fullmatch(r"fig([0-9]+\.[0-9]+[a-z]?)", id)
    if (looks.group(1) if looks else None) != book_figure:
        raise ValueError(
            f"id {id!r} and book_figure {book_figure!r} disagree: a figure that mirrors book Fig. N.M has "
            "the id 'figN.M', and only such a figure may have an id of that form (raildyn's own: "
            "'fig7.bifurcation')"
        )


@dataclass(frozen=True)
class FigureSpec:
    """One reproducible figure.

    Attributes
    ----------
    id : str
        Stable identifier, also the file name (``fig1.4``): letters, digits, ".",
        "_" and "-", starting with a letter or a digit.
    caption : str
        What the figure shows, in the companion's words.
    book_figure : str or None
        The figure number in Garg & Dukkipati (1984), where it mirrors one
        (chapter.number, e.g. ``"1.4"``).
    chapter : int
        The book's chapter the figure belongs to, 1–11.
    draw : callable
        ``draw()`` builds and returns the figure (a ``matplotlib.figure.Figure``);
        it is called, and what it returns checked, by :func:`make`.
    """

    id: str
    caption: str
    book_figure: str | None
    chapter: int
    draw: Callable[[], Figure]

    def __post_init__(self):
        _check_spec(self.id, self.caption, self.book_figure, self.chapter)
        _checks.function("draw", self.draw)


#: Every registered figure, by id; filled by :func:`register` from the chapters' modules, which are
#: imported when it is first reached.
#:
#: :meta hide-value:
REGISTRY: dict[str, FigureSpec]

# The registry itself; REGISTRY is this dict, served by __getattr__ once the chapters are loaded.
_REGISTRY: dict[str, FigureSpec] = {}
_LOADED = False


def register(id: str, caption: str, *, chapter: int, book_figure: str | None = None):
    """Decorator adding a figure function to ``REGISTRY`` under ``id``.

    Parameters
    ----------
    id : str
        Stable identifier of the figure, also its file name; unique, of letters, digits, ".",
        "_" and "-". A figure that mirrors book Fig. N.M is ``figN.M`` (``fig1.4``), and only
        such a figure may have an id of that form; raildyn's own figures are named by chapter
        and subject (``fig7.bifurcation``). An id registered already raises ``ValueError``.
    caption : str
        What the figure shows, in the companion's words.
    chapter : int
        The book's chapter the figure belongs to, 1–11.
    book_figure : str or None, optional
        The figure number in Garg & Dukkipati (1984), where the figure mirrors one
        (e.g. ``"1.4"``).

    Returns
    -------
    callable
        The decorator: it registers ``draw`` (a function of no arguments returning a
        ``matplotlib.figure.Figure``) and returns it unchanged.
    """
    _check_spec(id, caption, book_figure, chapter)
    registry = _registry()  # the chapters' own figures first, so that their numbers do not move
    if id in registry:
        raise ValueError(f"figure id {id!r} is registered already")

    def add(draw: Callable[[], Figure]) -> Callable[[], Figure]:
        if id in registry:
            raise ValueError(f"figure id {id!r} is registered twice")
        registry[id] = FigureSpec(id, caption, book_figure, chapter, draw)
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
    registry = _registry()
    spec = registry[_checks.choice("id", id, registry)]
    with matplotlib.rc_context(plots.STYLE):
        figure = spec.draw()
    if not isinstance(figure, Figure):
        raise TypeError(
            f"the draw function of figure {id!r} must return a matplotlib.figure.Figure, "
            f"returned {figure!r:.80} of type {type(figure).__name__}"
        )
    return figure


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
        self.spec = _checks.instance("spec", spec, FigureSpec)
        self.figure = _checks.instance("figure", figure, Figure, "matplotlib.figure.Figure")

    def _png(self) -> bytes:
        buffer = io.BytesIO()
        self.figure.savefig(buffer, format="png", dpi=100)
        return buffer.getvalue()

    def _repr_mimebundle_(self, include=None, exclude=None):
        png = base64.b64encode(self._png()).decode("ascii")
        caption = _caption(self.spec)
        html_text = (
            f'<figure class="raildyn-figure" id="{html.escape(self.spec.id)}">'
            f'<img src="data:image/png;base64,{png}" alt="{html.escape(self.spec.caption)}" '
            'style="max-width:100%">'
            f"<figcaption>{html.escape(caption)}</figcaption></figure>"
        )
        return {"text/html": html_text, "image/png": png, "text/plain": caption}


def _caption(spec: FigureSpec) -> str:
    """The caption a reader sees: "Figure 7.1. <what it shows>", numbered within its chapter in the order
    of registration, with the book's figure it mirrors; the id (a file name) stays out of it."""
    book = f" (book Fig. {spec.book_figure})" if spec.book_figure else ""
    registry = _registry()
    if registry.get(spec.id) is not spec:  # a figure made outside the registry has no number
        return f"{spec.caption}{book}"
    same = [s.id for s in registry.values() if s.chapter == spec.chapter]
    return f"Figure {spec.chapter}.{same.index(spec.id) + 1}{book}. {spec.caption}"


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
    return FigureView(_registry()[id], figure)


def save_all(
    out: str | Path,
    *,
    formats: Iterable[str] = ("png",),
    ids: Iterable[str] | None = None,
    progress: bool = True,
    data: bool = False,
) -> list[Path]:
    """Write the registered figures (all, or ``ids``) to ``out``; return the paths written.

    Parameters
    ----------
    out : str or pathlib.Path
        Directory to write to; created (with its parents) if missing.
    formats : str or iterable of str, optional
        File formats matplotlib can write (``"png"``, ``"pdf"``, ``"svg"``), at least
        one; one file per figure and format, ``<id>.<format>``, at 150 dpi.
    ids : str or iterable of str or None, optional
        The registered ids to write (at least one), in this order; None (the default)
        writes every registered figure, sorted by id.
    progress : bool, optional
        Show a progress bar (default True).
    data : bool, optional
        Also write each figure's data beside its picture, ``<id>.csv``: every point that its panels
        draw, one row a point, with the panel's axis labels and their units (default False).

    Returns
    -------
    list of pathlib.Path
        The files written, figure by figure and format by format (the table after the pictures).
    """
    _checks.instance("out", out, (str, os.PathLike), "str or pathlib.Path")
    formats = _names("formats", formats, FigureCanvasBase.get_supported_filetypes())
    registry = _registry()
    chosen = sorted(registry) if ids is None else _names("ids", ids, registry)
    progress = _checks.flag("progress", progress)
    data = _checks.flag("data", data)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for fid in progress_bar(chosen, desc="figures") if progress else chosen:
        fig = make(fid)
        for fmt in formats:
            path = out / f"{fid}.{fmt}"
            fig.savefig(path, dpi=150)
            written.append(path)
        if data:
            from raildyn.figures import _data

            written.append(_data.write(fig, out / f"{fid}.csv"))
    return written


def _names(name: str, value, options) -> list[str]:
    """A name or an iterable of names, each one of ``options``, at least one (for save_all)."""
    items = [value] if isinstance(value, str) else value
    try:
        items = list(items)
    except TypeError:
        raise TypeError(f"{name} must be a string or an iterable of strings, got {value!r:.80}") from None
    if not items:
        raise ValueError(f"{name} must name at least one of {sorted(options)}, got {value!r}")
    return [_checks.choice(name, item, options) for item in items]


def new_figure(**kwargs) -> Figure:
    """A new figure with the constrained layout, for a registered figure function to draw on.

    Parameters
    ----------
    **kwargs
        Passed on to ``matplotlib.figure.Figure``: its parameters (``figsize``,
        ``dpi``, ...) and its settable properties; any other keyword raises ``TypeError``.

    Returns
    -------
    matplotlib.figure.Figure
        A new figure, not attached to pyplot (so no display is needed).
    """
    unknown = sorted(k for k in kwargs if k not in _FIGURE_KEYWORDS)
    if unknown:
        raise TypeError(
            f"new_figure got unknown keyword(s) {unknown}: not parameters or properties of a Figure"
        )
    return Figure(layout="constrained", **kwargs)


_FIGURE_KEYWORDS = frozenset(inspect.signature(Figure.__init__).parameters) - {"self", "kwargs"} | {
    name[len("set_") :] for name in dir(Figure) if name.startswith("set_")
}


def _registry() -> dict[str, FigureSpec]:
    """The registry, with every chapter's figures: their modules are imported on the first call.

    While they are being imported (their :func:`register` calls this), the registry is returned as
    it is.
    """
    global _LOADED
    if not _LOADED:
        _LOADED = True
        try:
            for module in sorted(m.name for m in pkgutil.iter_modules(__path__) if m.name.startswith("ch")):
                importlib.import_module(f"{__name__}.{module}")
        except BaseException:
            _LOADED = False  # the next call tries again (and fails again, rather than give a part)
            raise
    return _REGISTRY


def __getattr__(name: str):
    # PEP 562: REGISTRY is reached here (once: it is then a plain global), so that importing this
    # module does not import the chapters' figures and with them every model.
    if name == "REGISTRY":
        globals()["REGISTRY"] = registry = _registry()
        return registry
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted({*globals(), "REGISTRY"})
