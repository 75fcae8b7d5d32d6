"""Fuzz registry: the animations of raildyn.animations, their player, and the frames' compaction.

Each valid call is a short run drawn in two frames, so that a hundred changed calls stay cheap."""

from __future__ import annotations

import io
import tempfile
from pathlib import Path

from fuzzing import call, fuzz, on

from raildyn import animations, plots
from raildyn.bridge import SimplySupportedBeam, moving_mass
from raildyn.track import Curve
from raildyn.train import braking_model
from raildyn.vehicles import Bogie, RockingFreightCar
from raildyn.wheelset import Wheelset

# a start to either side: y₀ is signed
SIGNED = "negative"
# a model left at None is the chapter's default one
DEFAULT = "none"


def _png() -> bytes:
    from PIL import Image

    out = io.BytesIO()
    Image.new("RGB", (8, 8), "white").save(out, format="PNG")
    return out.getvalue()


def _figure():
    from matplotlib.figure import Figure

    fig = Figure(figsize=(1.0, 1.0), dpi=20)
    fig.subplots().plot([0, 1], [0, 1])
    return fig


def _draw(i):
    return None


def _movie():
    return animations.Animation([_png(), _png()], ["a", "b"], title="two frames")


def _blitter():
    fig = _figure()
    return plots.Blitter(fig, fig.axes[0].lines[:])


ENTRIES = [
    fuzz("raildyn.plots.compact_png", lambda: call(_png(), colours=32)),
    fuzz("raildyn.plots.Blitter", lambda: (lambda fig: call(fig, fig.axes[0].lines[:]))(_figure())),
    fuzz("raildyn.plots.Blitter.animate", lambda: (lambda b: on(b, b.figure.axes[0].lines[0]))(_blitter())),
    fuzz("raildyn.plots.Blitter.frame", lambda: on(_blitter())),
    fuzz("raildyn.plots.Blitter.invalidate", lambda: on(_blitter())),
    fuzz("raildyn.animations.Animation", lambda: call([_png(), _png()], ["a", "b"], title="x", interval=0.1)),
    fuzz("raildyn.animations.Animation.html", lambda: on(_movie())),
    fuzz(
        "raildyn.animations.Animation.save",
        lambda: on(_movie(), Path(tempfile.mkdtemp()) / "movie.html"),
    ),
    fuzz("raildyn.animations.record", lambda: call(_figure(), _draw, ["a", "b"], title="x", interval=0.1)),
    fuzz(
        "raildyn.animations.hunting_wheelset",
        lambda: call(
            Wheelset(yaw_stiffness=2e6, lateral_stiffness=1e6), 60.0, duration=0.2, window=0.1, frames=2
        ),
        accepts={"initial_displacement": SIGNED, "ws": DEFAULT},
    ),
    fuzz(
        "raildyn.animations.hunting_bogie",
        lambda: call(Bogie(), 80.0, duration=0.2, window=0.1, frames=2),
        accepts={"initial_displacement": SIGNED, "bogie": DEFAULT},
    ),
    fuzz(
        "raildyn.animations.bogie_curve_entry",
        lambda: call(
            Bogie(),
            20.0,
            Curve(radius=800.0, cant=0.05, transition_length=10.0, arc_length=8.0, straight=0.0),
            frames=2,
        ),
        accepts={"bogie": DEFAULT, "curve": DEFAULT},
    ),
    # speed None is the car's roll resonance speed
    fuzz(
        "raildyn.animations.rocking_car",
        lambda: call(RockingFreightCar(), 10.0, cycles=4, frames=2),
        accepts={"car": DEFAULT, "speed": DEFAULT},
    ),
    # the couplers may start centred (0) or bunched (negative)
    fuzz(
        "raildyn.animations.train_run_in",
        lambda: call(braking_model(5, 1), 2.0, 10.0, initial_extension=0.01, frames=2),
        # a train may start from rest
        accepts={"initial_extension": "zero negative tiny", "model": DEFAULT, "initial_speed": "zero tiny"},
    ),
    fuzz(
        "raildyn.animations.bridge_crossing",
        lambda: call(SimplySupportedBeam(20.0, 1.0e10, 1.0e4, modes=3), moving_mass(5000.0), 20.0, frames=2),
        # speed None is α = 0.3
        accepts={"beam": DEFAULT, "load": DEFAULT, "speed": DEFAULT},
    ),
]
