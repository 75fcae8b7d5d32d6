"""Animations of the models' own runs, which play in the page without a kernel (the book) and in Jupyter.

One player (:class:`~raildyn.animations.player.Animation`): palette PNG frames inlined as data URIs,
a play/pause button, a frame slider and the frame's time, a few lines of JavaScript and no request
off the page. :func:`~raildyn.animations.player.record` draws the frames by moving the artists of one
figure in place, as the widgets and the moving schematics of :mod:`raildyn.diagrams` do. One animation
per chapter, each from the model's own run:

* :func:`~raildyn.animations.lateral.hunting_wheelset` — chapter 5, the nonlinear wheelset hunting, in plan;
* :func:`~raildyn.animations.runs.rocking_car` — chapter 6, the freight car rocking on staggered joints;
* :func:`~raildyn.animations.lateral.hunting_bogie` — chapter 7, the bogie hunting, in plan;
* :func:`~raildyn.animations.lateral.bogie_curve_entry` — chapter 8, the bogie entering a curve;
* :func:`~raildyn.animations.runs.train_run_in` — chapter 9, the train's run-in under braking;
* :func:`~raildyn.animations.runs.bridge_crossing` — chapter 10, the load crossing the bridge.

At their defaults (40 frames of 461 × 259 px or smaller) each adds some hundreds of kilobytes of HTML
to its page; ``Animation.size`` gives the bytes.
"""

from raildyn.animations.lateral import bogie_curve_entry, hunting_bogie, hunting_wheelset
from raildyn.animations.player import Animation, record
from raildyn.animations.runs import bridge_crossing, rocking_car, train_run_in

__all__ = [
    "Animation",
    "bogie_curve_entry",
    "bridge_crossing",
    "hunting_bogie",
    "hunting_wheelset",
    "record",
    "rocking_car",
    "train_run_in",
]
