"""The one mechanism every chapter's widgets share: a figure drawn once and a set of controls.

A :class:`LiveFigure` owns a matplotlib ``Figure`` on an Agg canvas (no pyplot, so
no global state and no auto-display) and an ``ipywidgets.Image`` that shows it.
:func:`assemble` wires named controls to a redraw function and adds a reset
button. The redraw function updates the existing artists (``set_data``,
``set_ydata``...) and never builds a new figure.
"""

from __future__ import annotations

import base64
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import ipywidgets as widgets
import matplotlib
from matplotlib.figure import Figure

from raildyn import _checks
from raildyn._progress import in_the_app
from raildyn.plots import STYLE, Blitter

# A widget's figure: at most 10 × 10 panels, at most 40 in a side and 600 dpi (a frame of at most
# 24,000 pixels a side, already far beyond a screen; the frames are encoded after every change).
_MAX_PANELS = 10
_MAX_INCHES = 40.0
_DPI = (10, 600)


class LiveFigure:
    """A figure that is built once and re-rendered to PNG after each change.

    The artists that move on a slider are registered with :meth:`animate`. The
    rest of the figure (axes, ticks, labels, fixed curves) is drawn once and kept
    as a bitmap; a new frame restores that bitmap and draws only the moving
    artists on it (blitting). The bitmap is drawn again only when the view
    changes: an axis limit moves, or :meth:`invalidate` is called after another
    change to the fixed parts.

    Parameters
    ----------
    nrows, ncols : int
        Grid of axes, as in ``Figure.subplots``, each 1–10.
    figsize : tuple of float
        Width and height in inches, each in (0, 40].
    dpi : int
        Resolution of the PNG frames, 10–600; 80 keeps a frame near 30 kB and fast to encode.
    **subplot_kw
        Passed on to ``Figure.subplots`` (``sharex``, ``subplot_kw``, ...).
    """

    def __init__(self, nrows: int = 1, ncols: int = 1, *, figsize=(8.0, 3.6), dpi: int = 80, **subplot_kw):
        nrows = _checks.integer("nrows", nrows, low=1, high=_MAX_PANELS)
        ncols = _checks.integer("ncols", ncols, low=1, high=_MAX_PANELS)
        figsize = tuple(_checks.array("figsize", figsize, shape=(2,), low=0.0, low_open=True).tolist())
        if max(figsize) > _MAX_INCHES:
            raise ValueError(f"figsize must be at most {_MAX_INCHES} inches a side, got {figsize!r}")
        dpi = _checks.integer("dpi", dpi, low=_DPI[0], high=_DPI[1])
        self.dpi = dpi
        with matplotlib.rc_context(STYLE):
            self.figure = Figure(figsize=figsize, dpi=dpi, layout="constrained")
            self._frames = Blitter(self.figure)
            self.axes = self.figure.subplots(nrows, ncols, squeeze=False, **subplot_kw)
        self.image = widgets.Image(format="png", layout=widgets.Layout(width=f"{figsize[0] * dpi:.0f}px"))

    def animate(self, *artists):
        """Register artists that change on every update; return the first, for chaining."""
        self._frames.animate(*artists)
        return artists[0] if artists else None

    def invalidate(self) -> None:
        """Draw the fixed parts again on the next render (after a change that is not a limit)."""
        self._frames.invalidate()

    def render(self) -> bytes:
        """Draw what changed and return the frame as PNG bytes."""
        with matplotlib.rc_context(STYLE):
            return self._frames.frame()

    def refresh(self) -> bytes:
        """Render and show the new frame in the image widget; return its PNG bytes."""
        frame = self.render()
        self.image.value = frame
        return frame


class LiveBox(widgets.VBox):
    """The container of a live widget, which also knows how to show itself without a kernel.

    In Jupyter and Voilà the widget view is shown. Pages rendered without a
    kernel (the book) pick the ``text/html`` or ``image/png`` part of the same
    display bundle: precomputed frames behind HTML range inputs when a
    ``static`` source is set, else the current frame as a picture. The
    lecture-room app never shows that part, so there the frames are not drawn
    (a page of the app is ready seconds sooner).
    """

    static: Callable[[], str] | None = None
    live: LiveFigure | None = None

    def _repr_mimebundle_(self, **kwargs):
        data = super()._repr_mimebundle_(**kwargs)
        if data is None:
            return None
        if self.static is not None and not in_the_app():
            data["text/html"] = self.static()
        else:
            data["image/png"] = base64.b64encode(self.children[-1].value).decode("ascii")
        return data


def assemble(
    controls: Mapping[str, widgets.ValueWidget],
    live: LiveFigure,
    redraw: Callable[[dict], None],
    *,
    status: widgets.HTML | None = None,
    columns: int = 2,
) -> tuple[widgets.Box, Callable[..., bytes]]:
    """Wire controls to a redraw function; return ``(container, update)``.

    Parameters
    ----------
    controls : mapping of name to ipywidgets control
        The names are the keyword arguments that ``update`` accepts; each control is
        an ``ipywidgets.ValueWidget`` (a slider, a dropdown, ...).
    live : LiveFigure
        The figure that ``redraw`` draws into.
    redraw : callable
        ``redraw(values)`` with ``values`` a dict of the current control values;
        it computes the model and updates the artists of ``live`` in place, and
        returns None (anything else is refused: it would be lost).
    status : ipywidgets.HTML, optional
        A text line (numbers such as the RMS) that ``redraw`` may update.
    columns : int
        Controls per row, >= 1.

    Returns
    -------
    container : ipywidgets.VBox
    update : callable
        ``update(**values)`` sets the named controls, redraws once and returns
        the PNG bytes of the new frame. Unknown names raise ``ValueError``.
    """
    controls = _controls("controls", controls)
    live = _checks.instance("live", live, LiveFigure)
    redraw = _checks.function("redraw", redraw)
    if status is not None:
        _checks.instance("status", status, widgets.HTML, "ipywidgets.HTML or None")
    columns = _checks.integer("columns", columns, low=1)
    defaults = {name: control.value for name, control in controls.items()}
    state = {"quiet": False}

    def current() -> dict:
        return {name: control.value for name, control in controls.items()}

    def draw() -> bytes:
        returned = redraw(current())
        if returned is not None:
            raise TypeError(
                f"redraw must return None (it moves the artists in place), returned {returned!r:.80}"
            )
        return live.refresh()

    def on_change(_change) -> None:
        if not state["quiet"]:
            draw()

    def update(**values) -> bytes:
        unknown = sorted(set(values) - set(controls))
        if unknown:
            raise ValueError(f"unknown control(s) {unknown}; this widget has {sorted(controls)}")
        # Set every value first and draw once, instead of once per control.
        state["quiet"] = True
        try:
            for name, value in values.items():
                controls[name].value = value
        finally:
            state["quiet"] = False
        return draw()

    for control in controls.values():
        control.observe(on_change, names="value")

    reset = widgets.Button(description="Reset", tooltip="Back to the starting values")
    reset.on_click(lambda _button: update(**defaults))

    items = list(controls.values())
    rows = [widgets.HBox(items[i : i + columns]) for i in range(0, len(items), columns)]
    rows.append(widgets.HBox([reset] + ([status] if status is not None else [])))
    container = LiveBox([*rows, live.image])
    container.live = live
    container.add_class("raildyn-widget")  # the browser tests find a widget's controls and picture by it
    draw()
    return container, update


def _controls(name: str, value) -> Mapping:
    """``value`` if it is a mapping of control names (str) to ipywidgets controls, else a TypeError."""
    if not (
        isinstance(value, Mapping)
        and all(isinstance(k, str) and isinstance(c, widgets.ValueWidget) for k, c in value.items())
    ):
        raise TypeError(
            f"{name} must be a mapping of names to ipywidgets controls (ValueWidget), got {value!r:.80}"
        )
    return value


def slider(
    description: str,
    value: float,
    low: float,
    high: float,
    step: float,
    *,
    fmt: str = ".2f",
    continuous: bool = True,
) -> widgets.FloatSlider:
    """A float slider with its unit in the description and a readable width."""
    return widgets.FloatSlider(
        value=value,
        min=low,
        max=high,
        step=step,
        description=description,
        readout_format=fmt,
        continuous_update=continuous,
        style={"description_width": "initial"},
        layout=widgets.Layout(width="360px"),
    )


@dataclass(frozen=True)
class Recipe:
    """How to make one widget: its controls, its figure, and the set-up of its artists.

    ``setup(live, status)`` draws the fixed parts of the figure once, creates the
    artists that move, and returns ``redraw(values)``. Keeping the three apart
    lets :meth:`build` make the live widget and :meth:`static_html` the
    kernel-free copy with the same code (and lets the benchmarks draw one frame
    from nothing, the way ``interact`` redraws: ``benchmarks/common.py``).

    ``controls`` and ``setup`` are stored, and called by :meth:`build`,
    :meth:`static_html` and :meth:`defaults`, which check what they return.

    Parameters
    ----------
    controls : callable
        ``controls()`` returns a new dict of control name to ipywidgets control.
    setup : callable
        ``setup(live, status)`` returns ``redraw(values)`` (see :func:`assemble`).
    figure : dict, optional
        Keyword arguments of :class:`LiveFigure`.
    static : dict, optional
        Control name to the values precomputed for the page without a kernel (one or
        two controls, each with at least one value).
    title : str, optional
        What the figure shows (the alternative text of the page without a kernel).
    prepare : callable, optional
        ``prepare()``, run by :meth:`static_html` before its frames: work for the whole grid that
        is cheaper done at once than frame by frame (chapter 7's bifurcation diagrams of the grid
        as one batch of the compiled engine), which the live widget, drawing one value at a time,
        does not need.
    """

    controls: Callable[[], dict]
    setup: Callable[[LiveFigure, widgets.HTML], Callable[[dict], None]]
    figure: dict = field(default_factory=dict)
    static: dict = field(default_factory=dict)
    """Control name to the values precomputed for the page without a kernel (one or two controls)."""
    title: str = "interactive figure"
    prepare: Callable[[], object] | None = None

    def __post_init__(self):
        _checks.function("controls", self.controls)
        _checks.function("setup", self.setup)
        if self.prepare is not None:
            _checks.function("prepare", self.prepare)
        _checks.instance("figure", self.figure, dict, "dict of LiveFigure keyword arguments")
        _checks.instance("static", self.static, dict, "dict of control name to values")
        if len(self.static) > 2 or not all(
            isinstance(k, str) and hasattr(v, "__len__") and len(v) > 0 for k, v in self.static.items()
        ):
            raise ValueError(
                "static must map one or two control names to non-empty sequences of values, "
                f"got {self.static!r:.80}"
            )
        _checks.instance("title", self.title, str, "string")

    def _controls(self) -> dict:
        """A new set of the controls, checked (``controls`` is the user's callable)."""
        made = self.controls()
        if not isinstance(made, dict):
            raise TypeError(f"controls must return a dict of ipywidgets controls, returned {made!r:.80}")
        _controls("controls", made)
        missing = sorted(set(self.static) - set(made))
        if missing:
            raise ValueError(f"static names controls {missing} that controls() does not make: {sorted(made)}")
        return made

    def _setup(self, live: LiveFigure, status: widgets.HTML) -> Callable[[dict], None]:
        redraw = self.setup(live, status)
        if not callable(redraw):
            raise TypeError(f"setup must return the redraw function, returned {redraw!r:.80}")
        return redraw

    def build(self) -> tuple[widgets.Box, Callable[..., bytes]]:
        """The live widget: ``(container, update)``."""
        controls = self._controls()
        live = LiveFigure(**self.figure)
        status = widgets.HTML()
        container, update = assemble(controls, live, self._setup(live, status), status=status)
        if self.static:
            container.static = self.static_html
        return container, update

    def static_html(self) -> str:
        """The kernel-free counterpart: frames over :attr:`static` behind HTML range inputs.

        The copy opens on the live widget's starting values, so every grid of :attr:`static` must
        hold its control's starting value; a grid that does not raises ``ValueError``.
        """
        from raildyn.widgets._static import frames_html

        controls = self._controls()
        for name, values in self.static.items():
            if controls[name].value not in list(values):
                raise ValueError(
                    f"static[{name!r}] must hold the control's starting value {controls[name].value!r}, so "
                    f"that the page without a kernel opens where the live widget does; got {list(values)}"
                )
        labels = {name: controls[name].description for name in self.static}
        start = {name: _nearest(values, controls[name].value) for name, values in self.static.items()}
        if self.prepare is not None:
            self.prepare()
        live = LiveFigure(**self.figure)
        _, update = assemble(controls, live, self._setup(live, widgets.HTML()))
        return frames_html(update, self.static, labels, alt=self.title, start=start)

    def defaults(self) -> dict:
        """The starting value of every control."""
        return {name: control.value for name, control in self._controls().items()}


def _nearest(values, value) -> int:
    """Index of the grid value closest to ``value`` (equal, for values that are not numbers)."""
    try:
        return min(range(len(values)), key=lambda i: abs(values[i] - value))
    except TypeError:
        return list(values).index(value) if value in values else 0
