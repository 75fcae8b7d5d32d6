"""Fuzz registry: the figure registry (raildyn.figures) and the widgets (raildyn.widgets)."""

from __future__ import annotations

import functools
import tempfile
from pathlib import Path

from fuzzing import call, fuzz, on

from raildyn import figures
from raildyn.widgets import LiveFigure, Recipe, chapter06
from raildyn.widgets._core import slider

OUT = Path(tempfile.gettempdir()) / "raildyn-fuzz-figures"  # save_all writes here, never into the tree
CHEAP = ("fig1.4", "fig9.tractive_effort")  # two figures drawn in a few hundredths of a second each

# The figure functions and recipes below are stored by what the fuzz test builds, not run at once.
_STORED = "returns-nan returns-negative returns-shape"


def _draw():
    fig = figures.new_figure(figsize=(2.0, 1.5))
    fig.subplots().plot([0.0, 1.0], [0.0, 1.0])
    return fig


def _live():
    return LiveFigure(1, 1, figsize=(2.0, 1.5), dpi=40)


def _line_on(live):
    (line,) = live.axes[0, 0].plot([0.0, 1.0], [0.0, 1.0])
    return line


def _controls():
    return {"a": slider("a", 0.5, 0.0, 1.0, 0.5)}


def _setup(live, status):
    line = live.animate(_line_on(live))

    def redraw(values):
        line.set_ydata([0.0, values["a"]])

    return redraw


def _recipe():
    # the static grid holds the control's starting value 0.5, as Recipe.static_html requires
    return Recipe(
        _controls, _setup, {"figsize": (2.0, 1.5), "dpi": 40}, static={"a": [0.0, 0.5, 1.0]}, title="t"
    )


def _redraw(values):
    return None


def _prepare():
    return None


@functools.lru_cache(maxsize=1)
def _ride():
    return chapter06.ride_run("FRA class 4", 200.0, 1)


def _factory(target):
    return fuzz(target, lambda: call())  # no arguments: only the unknown keyword applies


ENTRIES = [
    # ----------------------------------------------------------------- the figure registry
    fuzz(
        "raildyn.figures.FigureSpec",
        lambda: call("fig1.4", "A figure for the fuzz test.", "1.4", 1, _draw),
        # a new id is what a spec is for; book_figure may be None; draw is stored and only called
        # by figures.make, which checks what it returns
        accepts={"id": "unknown", "book_figure": "none", "draw": _STORED},
    ),
    fuzz("raildyn.figures.FigureView", lambda: call(figures.REGISTRY["fig1.4"], figures.new_figure())),
    fuzz("raildyn.figures.make", lambda: call("fig1.4")),
    fuzz("raildyn.figures.show", lambda: call("fig9.tractive_effort")),
    fuzz("raildyn.figures.new_figure", lambda: call(figsize=(2.0, 1.5))),
    fuzz(
        "raildyn.figures.register",
        lambda: call("fuzz.new", "A figure for the fuzz test.", chapter=3),
        accepts={"id": "unknown"},  # any id not registered yet
    ),
    fuzz(
        "raildyn.figures.save_all",
        lambda: call(OUT, formats=("png",), ids=CHEAP, progress=False),
        accepts={"out": "string"},  # any folder name: the fuzz test runs in a temporary folder
        skip={
            "ids": "None (valid, the default) writes all 20-odd figures, about 25 s, beyond the time limit; "
            "its other bad values are checked in tests/test_figures.py",
        },
    ),
    # ----------------------------------------------------------------- the widget machinery
    fuzz("raildyn.widgets.LiveFigure", lambda: call(1, 2, figsize=(4.0, 1.5), dpi=40)),
    fuzz("raildyn.widgets.LiveFigure.animate", lambda: (lambda live: on(live, _line_on(live)))(_live())),
    fuzz("raildyn.widgets.LiveFigure.invalidate", lambda: on(_live())),
    fuzz("raildyn.widgets.LiveFigure.render", lambda: on(_live())),
    fuzz("raildyn.widgets.LiveFigure.refresh", lambda: on(_live())),
    fuzz(
        "raildyn.widgets.Recipe",
        lambda: call(
            _controls,
            _setup,
            {"figsize": (2.0, 1.5), "dpi": 40},
            static={"a": [0.0, 0.5, 1.0]},
            prepare=_prepare,
        ),
        # controls and setup are stored, and called by build, static_html and defaults, which check
        # what they return; what prepare returns is not used
        accepts={"controls": _STORED, "setup": _STORED, "prepare": _STORED + " none"},
    ),
    fuzz("raildyn.widgets.Recipe.build", lambda: on(_recipe())),
    fuzz("raildyn.widgets.Recipe.defaults", lambda: on(_recipe())),
    fuzz("raildyn.widgets.Recipe.static_html", lambda: on(_recipe())),
    fuzz("raildyn.widgets.assemble", lambda: call(_controls(), _live(), _redraw, columns=2)),
    # ----------------------------------------------------------------- the chapters' widgets
    *(
        _factory(f"raildyn.widgets.{name}")
        for name in (
            "chapter01.chain_modes",
            "chapter01.forced_response",
            "chapter01.free_vibration",
            "chapter01.random_response",
            "chapter02.accuracy_chart",
            "chapter02.scheme_response",
            "chapter03.dipped_joint",
            "chapter03.jointed_rail",
            "chapter03.random_track",
            "chapter04.creep_laws",
            "chapter04.fastsim_patch",
            "chapter04.hertz",
            "chapter04.profiles",
            "chapter04.wheel_on_rail",
            "chapter05.curved_wheelset",
            "chapter05.hunting_wheelset",
            "chapter05.klingel",
            "chapter05.wheelset_roots",
            "chapter06.ride_quality",
            "chapter06.rock_and_roll_widget",
            "chapter06.wheel_unloading",
            "chapter07.bifurcation",
            "chapter07.car_roots",
            "chapter07.critical_curve",
            "chapter07.vehicle_comparison",
            "chapter09.braking_run_widget",
            "chapter09.string_lining",
        )
    ),
    fuzz(
        "raildyn.widgets.chapter06.ride_run", lambda: call("FRA class 4", 200.0, 1), accepts={"seed": "zero"}
    ),
    fuzz(
        "raildyn.vehicles.RideRun",  # the widget module re-exports it for one issue
        lambda: call(
            _ride().spectrum, _ride().frequency_domain, _ride().t, _ride().acceleration, _ride().time_domain
        ),
        accepts={"acceleration": "zero negative"},  # any acceleration history
    ),
    fuzz(
        "raildyn.widgets.chapter09.braking_run",
        lambda: call(1, 25.0, 250.0, 72.0),
        accepts={"speed_kmh": "tiny", "slack_mm": "zero"},  # couplers without slack
    ),
]
