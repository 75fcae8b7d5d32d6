"""Plotting helpers shared by the notebooks, the widgets and the reproducible figures.

Each function draws on the axes it is given (or on new ones), never calls
``plt.show()`` and returns its artists in a dict, so a widget can move them
with ``set_data`` instead of drawing again. Style is applied through
``matplotlib.rc_context(STYLE)`` only: importing raildyn never changes
matplotlib's defaults.

Charts that belong to one result live on that result as ``.plot(ax=None)``
(e.g. :meth:`raildyn.vibration.RootLocus.plot`); the helpers here are the
generic pieces they and the widgets share.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np

from raildyn import _checks

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib, PIL

__all__ = [
    "COLORS",
    "Blitter",
    "STYLE",
    "axes_or_new",
    "compact_png",
    "frequency_curves",
    "movable_line",
    "spectrum",
    "time_history",
]

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
"""One quiet house style for every raildyn figure: rcParams for ``matplotlib.rc_context``."""

COLORS = ("#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad", "#d68910")
"""The colour cycle of raildyn figures, in order of use."""


def compact_png(png: bytes, colours: int = 64) -> bytes:
    """Re-encode a PNG frame with a small palette, to keep a page of frames light.

    64 colours are plenty for line plots and cut a frame to about a third of its RGBA size.

    The widgets' copies for the book and the animations (:mod:`raildyn.animations`) inline their
    frames in the page, so each frame's bytes count. Pillow's fast octree quantizer and zlib's
    level 6 give a frame of the same size as median cut and level 9 with ``optimize`` (24.8 kB for
    chapter 6's ride frame, both ways), in a sixth of the time (7 ms against 39 ms): median cut
    spends 12 ms choosing colours and level 9 25 ms squeezing out the last tenth, on every frame.

    Parameters
    ----------
    png : bytes
        A PNG file (any mode Pillow reads).
    colours : int
        Of the palette, in [16, 256]: 64 for the widgets' charts; the animations, with dozens of frames
        a page, take 32 (their schematics' fills and lines keep their greys, a frame is 15 % lighter).

    Returns
    -------
    bytes
        The same picture as a PNG of at most ``colours`` colours.
    """
    import io

    from PIL import Image, UnidentifiedImageError

    colours = _checks.integer("colours", colours, low=16, high=256)
    if not isinstance(png, bytes | bytearray):
        raise TypeError(f"png must be the bytes of a PNG file, got {type(png).__name__}")
    try:
        image = Image.open(io.BytesIO(png)).convert("RGB")
    except UnidentifiedImageError as error:
        raise ValueError(f"png must be the bytes of a PNG file, got {bytes(png[:16])!r}…") from error
    small = image.quantize(colors=colours, method=Image.Quantize.FASTOCTREE)
    out = io.BytesIO()
    small.save(out, format="PNG", compress_level=6)
    return out.getvalue()


class Blitter:
    """The frames of one figure whose few artists move: the rest drawn once and kept, the moving ones drawn
    on it for each frame (blitting), each frame a PNG. The widgets' live figures and the animations'
    recordings draw their frames with it.

    The fixed parts (axes, ticks, labels, fixed curves) are drawn once, without the moving artists, and
    kept as a bitmap; a frame restores that bitmap and draws only the moving artists on it. The bitmap is
    drawn again when the view changes (an axis limit moves) or after :meth:`invalidate`. A figure with a
    layout engine is laid out at its first drawing and then keeps that layout, so that it neither shifts
    from frame to frame nor spends a frame's time solving it again. With no moving artist, every frame
    draws the whole figure.

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        The figure, drawn on an Agg canvas (one is attached to it).
    moving : sequence of matplotlib.artist.Artist, optional
        Its artists that change from frame to frame; more with :meth:`animate`.
    """

    def __init__(self, figure, moving=()):
        from matplotlib.artist import Artist
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        self.figure = _checks.instance("figure", figure, Figure, "matplotlib.figure.Figure")
        if isinstance(moving, Artist) or not isinstance(moving, list | tuple):
            raise TypeError(f"moving must be a list or tuple of the figure's artists, got {moving!r:.60}")
        self.canvas = FigureCanvasAgg(figure)
        self._moving: list = []
        self._background = None
        self._view = None
        self.animate(*moving)

    def animate(self, *artists) -> None:
        """Add artists that change on every frame (they are left out of the kept bitmap).

        Parameters
        ----------
        *artists : matplotlib.artist.Artist
            Artists of the blitter's figure that the next frames move.
        """
        from matplotlib.artist import Artist

        for artist in artists:
            if not isinstance(artist, Artist):
                raise TypeError(
                    f"artists must be matplotlib artists, got {type(artist).__name__} {artist!r:.60}"
                )
            if artist.get_figure(root=True) is not self.figure:
                raise ValueError(f"artists must be drawn on the blitter's figure, got {artist!r:.60}")
        for artist in artists:
            artist.set_animated(True)
            self._moving.append(artist)
        self._background = None

    def invalidate(self) -> None:
        """Draw the fixed parts again at the next frame (after a change that is not a limit)."""
        self._background = None

    def _current_view(self) -> tuple:
        return tuple(ax.get_xlim() + ax.get_ylim() for ax in self.figure.axes)

    def frame(self) -> bytes:
        """Draw what changed and return the frame as PNG bytes.

        Returns
        -------
        bytes
            The figure's pixels as a PNG file (8-bit RGBA).
        """
        from matplotlib.collections import PathCollection

        view = self._current_view()
        if not self._moving or self._background is None or view != self._view:
            self.canvas.draw()  # the moving (animated) artists are left out of this bitmap
            if self.figure.get_layout_engine() is not None:
                # The layout is solved at the first drawing and then kept: solving it for every frame
                # would cost more than the plot, and the picture would shift as it changes.
                self.figure.set_layout_engine("none")
            self._background = self.canvas.copy_from_bbox(self.figure.bbox)
            self._view = self._current_view()
        else:
            self.canvas.restore_region(self._background)
        for artist in self._moving:
            if isinstance(artist, PathCollection):
                _draw_points_in_view(self.figure, artist)
            else:
                self.figure.draw_artist(artist)
        return _png(np.asarray(self.canvas.buffer_rgba()))


def _draw_points_in_view(figure, points) -> None:
    """Draw a scatter without the markers that its clip box would hide whole: the same pixels, less work.

    Agg transforms and clips every marker one by one, the hidden ones too: the roots chart of the
    car (``ModeSweep.plot``) has 900 roots, about 260 of them in its window, and drew in 10 ms
    instead of 3. The points are left out only for the drawing (the artist keeps all its data),
    and only when nothing else varies point by point: one size, one line width, the colours one
    or mapped from values by a norm whose limits are already set (a subset would otherwise move
    them). Anything else is drawn as it is.
    """
    offsets = np.asarray(points.get_offsets())
    values = points.get_array()
    box = points.get_clip_box()
    simple = (
        points.get_clip_on()
        and box is not None
        and len(points.get_sizes()) <= 1
        and len(points.get_linewidths()) <= 1
        and offsets.ndim == 2
        and len(offsets) > 1
        and (
            (values is None and len(points.get_facecolors()) <= 1 and len(points.get_edgecolors()) <= 1)
            or (
                values is not None
                and np.ndim(values) == 1
                and len(values) == len(offsets)
                and points.norm.scaled()
            )
        )
    )
    if not simple:
        figure.draw_artist(points)
        return
    xy = points.get_offset_transform().transform(offsets)
    # A marker's reach, px: its whole width (sqrt of the area in pt²) and line width, and a pixel of
    # antialiasing on each side; generous, since a kept marker costs little.
    size = np.sqrt(points.get_sizes().max(initial=1.0)) + points.get_linewidths().max(initial=0.0)
    reach = size * figure.dpi / 72.0 + 2.0
    keep = (
        (xy[:, 0] >= box.x0 - reach)
        & (xy[:, 0] <= box.x1 + reach)
        & (xy[:, 1] >= box.y0 - reach)
        & (xy[:, 1] <= box.y1 + reach)
    )
    if keep.all():
        figure.draw_artist(points)
        return
    points.set_offsets(offsets[keep])
    if values is not None:
        points.set_array(values[keep])
    try:
        figure.draw_artist(points)
    finally:
        points.set_offsets(offsets)
        if values is not None:
            points.set_array(values)


_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _png_chunk(kind: bytes, data: bytes) -> bytes:
    """One PNG chunk: length, type, data and the CRC-32 of type and data (PNG specification, sec. 5.3)."""
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def _png(rgba: np.ndarray) -> bytes:
    """A frame's pixels (height, width, 4 bytes of RGBA) as a PNG file, without row filters, zlib level 1.

    Pillow chooses a filter for every row by trying each one, which took as long as the compression
    itself (about 4 ms of a 800 × 300 frame's 8); a line plot compresses nearly as well unfiltered
    (the frame comes out about 5 % larger, in half the time). The static frames are recompressed
    (:func:`raildyn.plots.compact_png`). Format: PNG specification (ISO/IEC 15948), 8-bit RGBA, filter type 0.
    """
    height, width, _ = rgba.shape
    rows = np.empty((height, 4 * width + 1), np.uint8)
    rows[:, 0] = 0  # filter type 0 (none) at the start of every row
    rows[:, 1:] = rgba.reshape(height, 4 * width)
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8-bit RGBA, no interlace
    return b"".join(
        (
            _PNG_SIGNATURE,
            _png_chunk(b"IHDR", header),
            _png_chunk(b"IDAT", zlib.compress(rows, 1)),
            _png_chunk(b"IEND", b""),
        )
    )


def axes_or_new(ax):
    """The given axes, or new ones on a new pyplot figure (for notebook use).

    Parameters
    ----------
    ax : matplotlib.axes.Axes or None
        Axes to draw on; None makes a new figure with the house style. Anything else
        is refused with a TypeError naming ``ax``.

    Returns
    -------
    matplotlib.axes.Axes
    """
    import matplotlib

    if ax is not None:
        from matplotlib.axes import Axes

        return _checks.instance("ax", ax, Axes, "matplotlib.axes.Axes or None")
    import matplotlib.pyplot as plt

    with matplotlib.rc_context(STYLE):
        _, ax = plt.subplots(figsize=(5.5, 3.6), layout="constrained")
    return ax


def movable_line(ax, artists, key, x, y, *, label=None, color=None, xlabel="", ylabel="", log=False) -> dict:
    """Draw one line of a model's curve, or move the line an earlier call drew (a widget's redraw).

    The shape every ``plot_*`` method of a result with one curve shares: a first call draws on
    ``ax`` (new axes if None) and returns ``{key: line}``; a call with that dict as ``artists`` only
    sets the line's y data.

    Parameters
    ----------
    ax : matplotlib.axes.Axes or None
        Where to draw (ignored when ``artists`` is given).
    artists : dict or None
        The dict an earlier call returned (same x), or None to draw.
    key : str
        The line's name in the returned dict (the ``plot_<key>`` method's).
    x, y : array_like
        The curve, in the units to draw: finite 1-D arrays of one length (x > 0 on a log axis).
    label, color : optional
        Legend label and colour.
    xlabel, ylabel : str
        The axes' labels.
    log : bool
        Both axes logarithmic.

    Returns
    -------
    dict
        ``{key: line}``.
    """
    import matplotlib

    _checks.instance("key", key, str)
    x = _checks.array("x", x, ndim=1, allow_empty=False)
    y = _checks.array("y", y, shape=x.shape)
    if artists is not None:
        _checks.instance("artists", artists, dict, f"dict returned by an earlier plot_{key}")
        if key not in artists:
            raise ValueError(
                f"artists must hold the line {key!r} an earlier plot_{key} returned, got {sorted(artists)}"
            )
        artists[key].set_ydata(y)
        return artists
    _checks.instance("xlabel", xlabel, str)
    _checks.instance("ylabel", ylabel, str)
    if _checks.flag("log", log) and x.min() <= 0.0:
        raise ValueError(f"x must be > 0 on a log axis, got {x.min()!r}")
    ax = axes_or_new(ax)
    with matplotlib.rc_context(STYLE):
        (line,) = (ax.loglog if log else ax.plot)(x, y, color=color, label=label)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
    return {key: line}


def time_history(
    t: np.ndarray, x: np.ndarray, *, ax=None, label: str | None = None, envelope=None, color=COLORS[0]
) -> dict:
    """Draw a displacement history, with an optional decay envelope ±A e^{-ξω_n t}.

    Parameters
    ----------
    t : ndarray, shape (n,)
        Times, s, finite and strictly increasing.
    x : ndarray, shape (n,)
        Displacements (any unit), finite.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.
    label : str, optional
        Legend label of the history.
    envelope : ndarray, shape (n,), optional
        The envelope, finite and >= 0, drawn dashed at ±envelope; hidden (NaN) if None.
    color : color
        Colour of the history.

    Returns
    -------
    dict
        The artists ``line``, ``upper``, ``lower``.
    """
    import matplotlib

    t = _checks.time_grid("t", t)
    x = _checks.array("x", x, shape=t.shape)
    if envelope is not None:
        envelope = _checks.array("envelope", envelope, shape=t.shape, low=0.0)
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
    """Draw several curves against the frequency ratio r = ω/ω_n.

    Parameters
    ----------
    r : ndarray, shape (n,)
        Frequency ratios, >= 0 and strictly increasing.
    curves : dict of str to ndarray, shape (n,)
        The curves by name (their legend labels), finite.
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.
    logy : bool
        Logarithmic y axis.

    Returns
    -------
    dict
        The lines, by the names of ``curves``.
    """
    import matplotlib

    r = _checks.increasing("r", r, low=0.0)
    _checks.instance("curves", curves, dict, "dict of name to array")
    values = {name: _checks.array(f"curves[{name!r}]", y, shape=r.shape) for name, y in curves.items()}
    logy = _checks.flag("logy", logy)
    ax = axes_or_new(ax)
    lines = {}
    with matplotlib.rc_context(STYLE):
        for i, (name, y) in enumerate(values.items()):
            (lines[name],) = ax.plot(r, y, color=COLORS[i % len(COLORS)], label=name)
        if logy:
            ax.set_yscale("log")
        ax.set_xlabel(r"frequency ratio $r = \omega/\omega_n$")
    return lines


def spectrum(
    omega: np.ndarray, psd: np.ndarray, *, ax=None, label: str | None = None, color=COLORS[0]
) -> dict:
    """Draw a one-sided PSD per rad/s on log–log axes.

    Parameters
    ----------
    omega : ndarray, shape (n,)
        Circular frequencies, rad/s, > 0 and strictly increasing.
    psd : ndarray, shape (n,)
        One-sided PSD per rad/s, finite and >= 0 (zeros fall off the log axis).
    ax : matplotlib.axes.Axes, optional
        Where to draw; new axes if None.
    label : str, optional
        Legend label.
    color : color
        Line colour.

    Returns
    -------
    dict
        ``{"line": line}``.
    """
    import matplotlib

    omega = _checks.increasing("omega", omega, low=0.0, low_open=True)
    psd = _checks.array("psd", psd, shape=omega.shape, low=0.0)
    ax = axes_or_new(ax)
    with matplotlib.rc_context(STYLE):
        (line,) = ax.loglog(omega, psd, color=color, label=label)
        ax.set_xlabel(r"circular frequency $\omega$ (rad/s)")
    return {"line": line}
