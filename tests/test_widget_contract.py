"""The contract every raildyn widget keeps, checked for all chapters at once, without a browser.

* every control changes the picture, and the figure is updated in place (no new
  figure, no pyplot figure left open);
* the frame drawn on the cached background equals a full redraw, pixel for pixel;
* the kernel-free copy has one distinct frame per value of its grid (8–16 values
  of one slider, at most 32 frames over two controls) and starts at the control's default.

Chapter-specific checks (the numbers in a status line) stay in test_widgets_chNN.py.
"""

import functools
import importlib
import io
import pkgutil
import re

import ipywidgets
import matplotlib.pyplot as plt
import numpy as np
import pytest
from PIL import Image
from widget_helpers import widgets_of

import raildyn.widgets
from raildyn.widgets import (
    chapter01,
    chapter02,
    chapter03,
    chapter04,
    chapter05,
    chapter06,
    chapter07,
    chapter08,
    chapter08_safety,
    chapter09,
    chapter10,
    chapter11,
)
from raildyn.widgets._core import Recipe, _nearest

# For each factory: a new value for every control, each different from its default, in an order
# where each move changes the picture.
MOVES = {
    chapter01.free_vibration: dict(damping_ratio=1.4, natural_frequency=12.0, x0=-5.0, v0=100.0),
    chapter01.forced_response: dict(damping_ratio=0.5),
    chapter01.chain_modes: dict(
        dof=2, initial="mode 1 shape", mass_ratio=2.0, stiffness_ratio=0.5, damping_ratio=0.1
    ),
    chapter01.random_response: dict(frequency_hz=3.0, damping_ratio=0.3, seed=7),
    chapter02.scheme_response: dict(method="houbolt", dt_over_T=0.25, damping_ratio=0.05),
    chapter02.accuracy_chart: dict(method="central_difference", damping_ratio=0.1),
    chapter03.random_track: dict(
        track="FRA class 2", component="alignment", speed_kmh=160.0, shortest=3.0, longest=150.0, seed=4
    ),
    chapter03.jointed_rail: dict(half_width=3.5, depth_mm=12.0, arrangement="in_phase", speed_kmh=100.0),
    chapter03.dipped_joint: dict(speed_kmh=160.0, dip_mrad=14.0, unsprung_kg=1500.0),
    chapter04.hertz: dict(load_kn=150.0, wheel_radius_mm=400.0, rail_radius_mm=120.0),
    chapter04.creep_laws: dict(a_over_b=2.0, spin=1.0, friction=0.4, load_kn=60.0),
    chapter04.fastsim_patch: dict(xi_permille=3.0, eta_permille=-1.0, spin=0.5, friction=0.2),
    # A cone gives the same Δr(y) = 2λy on any rail and gauge, so the wheel changes last.
    chapter04.profiles: dict(rail="60E1 at 1:20", gauge_mm=1440.0, wheel="cone 1:20"),
    chapter04.wheel_on_rail: dict(shift_mm=7.0, rail="60E1 at 1:20", wheel="cone 1:40"),
    chapter05.klingel: dict(conicity=0.3, rolling_radius_mm=400.0, semi_wheelbase=1.0),
    chapter05.wheelset_roots: dict(conicity=0.3, yaw_stiffness=8.0, lateral_stiffness=3.0),
    chapter05.hunting_wheelset: dict(speed_kmh=250.0, phase_deg=90.0),
    chapter05.curved_wheelset: dict(
        radius=900.0, deficiency_mm=120.0, yaw_stiffness=10.0, lateral_stiffness=3.0
    ),
    chapter06.ride_quality: dict(track="German high", speed_kmh=160.0, seed=4),
    chapter06.rock_and_roll_widget: dict(speed_kmh=55.0, friction_kn=10.0, depth_mm=15.0),
    chapter06.wheel_unloading: dict(speed_kmh=26.0),
    chapter07.car_roots: dict(conicity=0.3, yaw_stiffness=20.0),
    chapter07.critical_curve: dict(yaw_stiffness=20.0, secondary_yaw_stiffness=1.0),
    chapter07.vehicle_comparison: dict(vehicle="locomotive", conicity=0.3),
    chapter07.bifurcation: dict(conicity=0.3, yaw_stiffness=2.0 * chapter07._K_PSI),  # a diagram a move
    chapter08.curving_plan: dict(radius=900.0, speed_kmh=100.0, cant_mm=50.0),
    chapter08.nadal_chart: dict(flange_angle=65.0, friction=0.2, radius=500.0, speed_kmh=90.0),
    chapter08.curve_entry_speed: dict(speed_kmh=120.0, quantity="offset"),
    chapter08.stiffness_tradeoff: dict(conicity=0.3, radius=900.0),
    chapter08_safety.safety_chart: dict(speed_kmh=140.0, radius=900.0, cant_mm=50.0, wind_kn=80.0),
    chapter09.string_lining: dict(radius=400.0, force_kn=-600.0),
    chapter09.braking_run_widget: dict(slack_mm=50.0, signal_speed=150.0, speed_kmh=40.0, cars=20),
    chapter10.moving_load_explorer: dict(speed_kmh=300.0, position=0.8, damping=0.02),
    chapter10.train_resonance: dict(coach_length=22.0, span=25.0, frequency_hz=5.0),
    chapter10.load_models: dict(speed_kmh=150.0),
    chapter10.track_receptance: dict(pad_mn=600.0, ballast_mn=80.0),
    chapter11.prediction_vs_measurement: dict(
        speed_kmh=70.0, scale=1.2, frequency_hz=10.0, damping=5.0, gauge=2
    ),
    chapter11.metrics_explorer: dict(gain=1.2, delay_ms=-30.0, noise=10.0),
    chapter11.sensitivity_bars: dict(output="frequency_hz", kind="total"),
}


def _chapter_modules():
    names = [m.name for m in pkgutil.iter_modules(raildyn.widgets.__path__) if m.name.startswith("chapter")]
    return [importlib.import_module(f"raildyn.widgets.{name}") for name in sorted(names)]


RECIPES = {
    f"{module.__name__.rsplit('.', 1)[1]}.{name}": value
    for module in _chapter_modules()
    for name, value in vars(module).items()
    if isinstance(value, Recipe)
}


FACTORIES = [pytest.param(f, id=f.__name__, marks=widgets_of(f.__module__)) for f in MOVES]
RECIPE_NAMES = [pytest.param(name, id=name, marks=widgets_of(name.split(".")[0])) for name in RECIPES]


def _pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)))


def test_every_widget_has_moves_here():
    factories = {f.__module__ + "." + f.__name__ for f in MOVES}
    assert len(factories) == len(RECIPES), "a widget recipe has no entry in MOVES (or the reverse)"


@functools.cache
def _moved(factory):
    """One widget, built and moved through its MOVES once: the two tests below read the same run
    (a chapter's tests share a process), so a widget is built and driven once, not twice."""
    before = plt.get_fignums()
    container, update = factory()
    image = container.children[-1]
    frames = [update()] + [update(**{name: value}) for name, value in MOVES[factory].items()]
    return container, image, frames, plt.get_fignums() == before


@pytest.mark.parametrize("factory", FACTORIES)
def test_each_control_changes_the_frame_in_place(factory):
    container, image, frames, no_pyplot_figure = _moved(factory)
    assert isinstance(container, ipywidgets.VBox)
    assert frames[0].startswith(b"\x89PNG"), "a frame is a PNG image"
    for name, before, after in zip(MOVES[factory], frames[:-1], frames[1:], strict=True):
        assert after != before, f"moving {name} did not change the picture"
    assert container.children[-1] is image, "the figure widget was rebuilt instead of updated"
    assert no_pyplot_figure, "a widget opened a pyplot figure"


@pytest.mark.parametrize("factory", FACTORIES)
def test_blitted_frame_equals_a_full_redraw(factory):
    container, _, frames, _ = _moved(factory)
    container.live.invalidate()
    assert np.array_equal(_pixels(frames[-1]), _pixels(container.live.render()))


@pytest.mark.parametrize("name", RECIPE_NAMES)
def test_static_copy_has_one_distinct_frame_per_grid_value(name):
    recipe = RECIPES[name]
    assert 1 <= len(recipe.static) <= 2, "one or two controls"
    # One slider: 8–16 values, enough to explore. A pair (such as spin and a/b, or wheel and rail,
    # whose every option is shown): at most 32 frames in all, to keep the page light.
    sizes = [len(values) for values in recipe.static.values()]
    numeric = all(isinstance(v, int | float) for values in recipe.static.values() for v in values)
    if len(sizes) == 1 and numeric:
        assert 8 <= sizes[0] <= 16
    else:
        assert min(sizes) >= 2 and np.prod(sizes) <= 32
    page = recipe.static_html()
    frames = re.search(r"var frames = (\[.*?\]), sizes", page).group(1).split(",")
    expected = int(np.prod([len(values) for values in recipe.static.values()]))
    assert len(frames) == expected
    assert len(set(frames)) == expected, "two grid values gave the same picture"
    for control, values in recipe.static.items():
        start = _nearest(values, recipe.defaults()[control])
        assert f'data-control="{control}" aria-label' in page
        assert re.search(rf'value="{start}" data-control="{control}"', page), (
            "the static slider starts at the default"
        )


@pytest.mark.parametrize("name", list(RECIPES))
def test_static_copy_opens_where_the_live_widget_does(name):
    # The page without a kernel first shows the frame of the live widget's starting values, not the
    # nearest grid value (chapter 10's explorer opened at 240 km/h against the live 250).
    recipe = RECIPES[name]
    defaults = recipe.defaults()
    for control, values in recipe.static.items():
        assert defaults[control] in list(values), (
            f"{name}: the grid of {control} {list(values)} lacks its starting value {defaults[control]}"
        )


def test_a_static_grid_without_the_starting_value_is_refused():
    recipe = RECIPES["chapter10.MOVING_LOAD_EXPLORER"]
    off = Recipe(recipe.controls, recipe.setup, recipe.figure, static={"speed_kmh": [60.0, 240.0, 300.0]})
    with pytest.raises(ValueError, match=r"static\['speed_kmh'\] must hold the control's starting value 250"):
        off.static_html()
