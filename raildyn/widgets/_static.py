"""Static counterparts of the widgets, for pages read without a kernel (the published book).

The frames are drawn at build time by the widget's own model and plot code over
a small grid of the main control values, then shown with a native HTML range
input and a few lines of JavaScript that swap the pictures. No extra library:
the frames are palette PNGs (:func:`raildyn.plots.compact_png`) inlined
as data URIs, so the page works offline.
"""

from __future__ import annotations

import base64
import html
import itertools
import json
import uuid
from collections.abc import Callable, Mapping, Sequence

from raildyn.plots import compact_png

_SCRIPT = """
(function () {
  var root = document.getElementById(%(id)s);
  var frames = %(frames)s, sizes = %(sizes)s;
  var inputs = root.querySelectorAll("input[type=range]");
  var outputs = root.querySelectorAll("output");
  var labels = %(labels)s;
  var img = root.querySelector("img");
  function show() {
    var index = 0;
    for (var k = 0; k < inputs.length; k++) {
      var i = parseInt(inputs[k].value, 10);
      index = index * sizes[k] + i;
      outputs[k].textContent = labels[k][i];
    }
    img.src = "data:image/png;base64," + frames[index];
  }
  for (var k = 0; k < inputs.length; k++) { inputs[k].addEventListener("input", show); }
  show();
})();
"""


def frames_html(
    update: Callable[..., bytes],
    grid: Mapping[str, Sequence],
    labels: Mapping[str, str],
    *,
    alt: str,
    start: Mapping[str, int] | None = None,
) -> str:
    """HTML for a picture whose one or two range inputs step through precomputed frames.

    Parameters
    ----------
    update : callable
        The widget's ``update(**values)``, returning a PNG frame.
    grid : mapping of control name to the values to precompute (8–16 each, one or two controls)
    labels : mapping of control name to the label shown beside its range input
    alt : str
        Text alternative of the picture.
    start : mapping of control name to the index of the grid value shown first (default 0)
    """
    names = list(grid)
    if not 1 <= len(names) <= 2:
        raise ValueError(f"grid must name one or two controls, got {names}")
    frames = [
        base64.b64encode(compact_png(update(**dict(zip(names, combo, strict=True))))).decode("ascii")
        for combo in itertools.product(*(grid[n] for n in names))
    ]
    first = [dict(start or {}).get(n, 0) for n in names]
    first_index = first[0] * (len(grid[names[1]]) if len(names) == 2 else 1) + (
        first[1] if len(names) == 2 else 0
    )
    element = f"raildyn-static-{uuid.uuid4().hex[:10]}"
    inputs = "".join(
        f'<label style="margin-right:1.5em">{html.escape(labels[n])} '
        f'<input type="range" min="0" max="{len(grid[n]) - 1}" step="1" value="{i0}" '
        f'data-control="{html.escape(n)}" aria-label="{html.escape(labels[n])}"> <output></output></label>'
        for n, i0 in zip(names, first, strict=True)
    )
    script = _SCRIPT % {
        "id": json.dumps(element),
        "frames": json.dumps(frames),
        "sizes": json.dumps([len(grid[n]) for n in names]),
        "labels": json.dumps(
            [[f"{v:g}" if isinstance(v, float) else str(v) for v in grid[n]] for n in names]
        ),
    }
    return (
        f'<div class="raildyn-static" id="{element}">'
        f'<div class="raildyn-static-controls">{inputs}</div>'
        f'<img alt="{html.escape(alt)}" style="max-width:100%" '
        f'src="data:image/png;base64,{frames[first_index]}">'
        f"<script>{script}</script></div>"
    )
