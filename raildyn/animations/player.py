"""The one animation player of raildyn: frames drawn from a model's run, played in the page without a kernel.

An :class:`Animation` holds palette PNG frames (:func:`raildyn.plots.compact_png`) and the time of
each. Its HTML (``_repr_html_``, which Jupyter and the book's pages show) is the first frame, a
play/pause button, a range input over the frames and the time, with a few lines of JavaScript that
swap the picture's ``src`` between the frames, inlined as data URIs: no request leaves the page and
no library is loaded, so it plays offline in the built book as in JupyterLab. :func:`record` makes
one from a figure, a function that moves the figure's artists in place for each frame, and the frames' labels.
"""

from __future__ import annotations

import base64
import html
import json
import uuid
from collections.abc import Callable, Sequence
from pathlib import Path

from raildyn import _checks
from raildyn._progress import progress_bar
from raildyn.plots import Blitter, compact_png

# Imported where used, to keep this module's import cheap: matplotlib, PIL, numpy

__all__ = ["Animation", "record"]

_MAX_FRAMES = 400  # a page of frames, not a film: 400 frames of 8 kB are already 4 MB
_COLOURS = 32  # of each frame's palette: the schematics' greys and the house colours survive

# The player: a frame index shown by the range input; play advances it on a timer and wraps round.
# The data- attributes are what the browser tests read (tests/test_browser.py).
_SCRIPT = """
(function () {
  var root = document.getElementById(%(id)s);
  var frames = %(frames)s, labels = %(labels)s, interval = %(interval)d;
  var img = root.querySelector("img[data-frame]");
  var slider = root.querySelector("input[data-control=frame]");
  var label = root.querySelector("output[data-label]");
  var button = root.querySelector("button[data-action=play]");
  var timer = null;
  function show(i) {
    slider.value = i;
    img.src = "data:image/png;base64," + frames[i];
    img.setAttribute("data-frame", i);
    label.textContent = labels[i];
  }
  function stop() {
    if (timer !== null) { clearInterval(timer); timer = null; }
    button.textContent = "\\u25b6 play";
    button.setAttribute("aria-pressed", "false");
  }
  button.addEventListener("click", function () {
    if (timer !== null) { stop(); return; }
    button.textContent = "\\u275a\\u275a pause";
    button.setAttribute("aria-pressed", "true");
    timer = setInterval(function () { show((parseInt(slider.value, 10) + 1) %% frames.length); }, interval);
  });
  slider.addEventListener("input", function () { stop(); show(parseInt(slider.value, 10)); });
  show(0);
})();
"""


class Animation:
    """Frames of one picture in motion, with an HTML/JavaScript player that needs no kernel.

    Parameters
    ----------
    frames : sequence of bytes
        PNG files, one per frame (at least 2, at most 400), shown in order.
    labels : sequence of str
        What the player writes beside each frame (its time, say), one per frame.
    title : str
        The picture's text alternative and the player's accessible name.
    interval : float
        s between frames when playing, in [0.02, 2].

    Attributes
    ----------
    frames : tuple of bytes
    labels : tuple of str
    title : str
    interval : float

    Examples
    --------
    >>> from raildyn.animations import hunting_wheelset
    >>> movie = hunting_wheelset(frames=4, duration=0.5, window=0.2)
    >>> len(movie.frames), "http" in movie.html()
    (4, False)
    """

    def __init__(self, frames: Sequence[bytes], labels: Sequence[str], *, title: str, interval: float = 0.1):
        if not isinstance(frames, Sequence) or not all(isinstance(f, bytes) for f in frames):
            raise TypeError(f"frames must be a sequence of PNG files (bytes), got {type(frames).__name__}")
        if not 2 <= len(frames) <= _MAX_FRAMES:
            raise ValueError(f"frames must hold 2 to {_MAX_FRAMES} frames, got {len(frames)}")
        if not all(f.startswith(b"\x89PNG\r\n\x1a\n") for f in frames):
            raise ValueError("frames must be PNG files: one does not start with the PNG signature")
        labels = _checks.strings("labels", labels)
        if len(labels) != len(frames):
            raise ValueError(f"labels must give one label per frame ({len(frames)}), got {len(labels)}")
        if not isinstance(title, str) or not title:
            raise TypeError(f"title must be a non-empty str, got {title!r:.60}")
        self.interval = _checks.scalar("interval", interval, low=0.02, high=2.0)
        self.frames, self.labels, self.title = tuple(frames), tuple(labels), title

    def html(self) -> str:
        """The player: picture, play/pause button, frame slider and label, frames inlined, no request.

        Returns
        -------
        str
            One ``<div class="raildyn-animation">`` with its script.
        """
        element = f"raildyn-animation-{uuid.uuid4().hex[:10]}"
        frames = [base64.b64encode(f).decode("ascii") for f in self.frames]
        script = _SCRIPT % {
            "id": json.dumps(element),
            "frames": json.dumps(frames),
            "labels": json.dumps(list(self.labels)),
            "interval": round(1000 * self.interval),
        }
        title = html.escape(self.title)
        return (
            f'<div class="raildyn-animation" id="{element}" data-frames="{len(frames)}">'
            f'<img alt="{title}" style="max-width:100%" data-frame="0" '
            f'src="data:image/png;base64,{frames[0]}">'
            '<div class="raildyn-animation-controls">'
            f'<button type="button" data-action="play" aria-pressed="false" aria-label="play {title}">'
            "\u25b6 play</button> "
            f'<input type="range" min="0" max="{len(frames) - 1}" step="1" value="0" data-control="frame" '
            f'aria-label="frame of {title}" style="vertical-align:middle;width:50%"> '
            f"<output data-label>{html.escape(self.labels[0])}</output></div>"
            f"<script>{script}</script></div>"
        )

    def _repr_html_(self) -> str:
        return self.html()

    @property
    def size(self) -> int:
        """Bytes of the player's HTML (what the animation adds to a page)."""
        return len(self.html().encode("utf-8"))

    def save(self, path) -> Path:
        """Write the player as a standalone HTML page, which plays offline in any browser.

        Parameters
        ----------
        path : str or pathlib.Path
            Where to write: a name ending in ``.html``, in a folder that exists.

        Returns
        -------
        pathlib.Path
            The file written.
        """
        if not isinstance(path, str | Path) or not str(path):
            raise TypeError(f"path must be a str or a pathlib.Path, got {path!r:.60}")
        target = Path(path)
        if target.suffix != ".html":
            raise ValueError(f"path must name an .html file, got {str(path)!r}")
        if not target.parent.is_dir():
            raise ValueError(f"path must be in an existing folder, got {str(path)!r}")
        page = (
            # An empty icon of its own, so that the browser asks the server for no favicon.ico.
            '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,">'
            f"<title>{html.escape(self.title)}</title></head><body>{self.html()}</body></html>\n"
        )
        target.write_text(page, encoding="utf-8")
        return target

    def __repr__(self) -> str:
        return f"Animation({self.title!r}, {len(self.frames)} frames, {self.size / 1000:.0f} kB)"


def record(
    figure,
    draw: Callable[[int], None],
    labels: Sequence[str],
    *,
    title: str,
    interval: float = 0.1,
    moving=None,
) -> Animation:
    """Draw one frame per label of one figure, moved in place by ``draw``, as an :class:`Animation`.

    Every frame is the same figure: ``draw(i)`` moves its artists for frame i (``set_data``,
    ``set_xy``; no new figure) and returns None; the figure is rendered by a
    :class:`raildyn.plots.Blitter`, as a widget's frames are, and the frame compacted to a palette
    PNG. The figure keeps the layout of its first frame, so that the picture stands still as it
    plays. Given the artists that move, the rest of the figure (axes, ticks, traces, rails) is drawn
    once and only they are drawn again on it for each frame, in a third of the time. A progress bar
    shows the frames (``RAILDYN_PROGRESS=0`` hides it).

    Parameters
    ----------
    figure : matplotlib.figure.Figure
        The figure to render, at its own size and dpi.
    draw : callable
        ``draw(i)`` for i = 0 … len(labels) − 1: moves the artists and returns None (anything else
        is refused: it would be lost).
    labels : sequence of str
        Each frame's label (its time, say): 2 to 400 of them, one frame each.
    title : str
        As for :class:`Animation`.
    interval : float
        As for :class:`Animation`.
    moving : sequence of matplotlib.artist.Artist, optional
        Every artist of ``figure`` that ``draw`` changes (one it leaves out would stand still in the
        frames). None: the whole figure is drawn for each frame.

    Returns
    -------
    Animation
    """
    from matplotlib.artist import Artist
    from matplotlib.figure import Figure

    _checks.instance("figure", figure, Figure, "matplotlib.figure.Figure")
    _checks.function("draw", draw)
    labels = _checks.strings("labels", labels)
    if not 2 <= len(labels) <= _MAX_FRAMES:
        raise ValueError(f"labels must give 2 to {_MAX_FRAMES} frames, got {len(labels)}")
    if moving is not None:
        if isinstance(moving, Artist) or not isinstance(moving, list | tuple):
            raise TypeError(f"moving must be a list or tuple of the figure's artists, got {moving!r:.60}")
        if not all(isinstance(a, Artist) and a.get_figure(root=True) is figure for a in moving):
            raise ValueError("moving must hold only artists drawn on figure")
        moving = sorted(moving, key=lambda a: a.get_zorder())  # drawn in their order, as the figure would
    frames = Blitter(figure, moving or ())
    pictures = []
    for i in progress_bar(range(len(labels)), desc=title):
        moved = draw(i)
        if moved is not None:
            raise TypeError(f"draw must move the figure's artists and return None, got {moved!r:.60}")
        pictures.append(compact_png(frames.frame(), colours=_COLOURS))
    return Animation(pictures, labels, title=title, interval=interval)
