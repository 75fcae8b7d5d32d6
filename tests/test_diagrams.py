"""raildyn.diagrams: every schematic draws on given axes and on new ones, returns its artists, leaves
matplotlib's defaults alone, carries the notation's symbols, scales with its model's lengths, refuses bad
input by name; the moving schematics (the hunting wheelset and the bogie in plan, the beam's moving load)
move the artists they drew.

Geometry is measured from the returned artists' data (polygon vertices, line data), so a test that
doubles a length and finds the picture doubled tests the drawing, not the code that wrote it.
"""

from __future__ import annotations

import dataclasses

import matplotlib
import matplotlib.pyplot as plt
import numpy as np
import pytest

from raildyn.bridge import SimplySupportedBeam
from raildyn.diagrams import (
    BeamLoad,
    BogiePlan,
    WheelsetPlan,
    beam_load,
    bogie_plan,
    car_plan,
    car_side,
    coupler_chain,
    oscillator_model,
    rigid_body_freedoms,
    truck_schematic,
    wheelset_plan,
    wheelset_section,
)
from raildyn.train import DraftGear, make_consist
from raildyn.vehicles import Bogie, LateralCar, ThreePieceTruck, VerticalCar
from raildyn.vibration import SDOF
from raildyn.wheelset import Wheelset

CONSIST = make_consist("1 SD40-2 + 3 loaded hopper")

# name → (draw(ax), the symbols its texts must carry)
SECTION = ["$r_0$", "$a$", r"$\lambda$", "$y$"]
CASES = {
    "oscillator": (
        lambda ax: oscillator_model(SDOF(1000.0, 2000.0, 4e5), ax=ax),
        ["$m$", "$k$", "$c$", "$F(t)$", "$x(t)$", r"$\xi$"],
    ),
    "rigid body": (
        lambda ax: rigid_body_freedoms(ax=ax),
        ["$x$", "$z$", r"$\theta_x$", r"$\theta_y$", r"$\theta_z$"],
    ),
    "rigid body, planar": (lambda ax: rigid_body_freedoms(True, ax=ax), ["$x$", r"$\theta_z$"]),
    "wheelset section": (lambda ax: wheelset_section(Wheelset(), 0.004, exaggerate=5.0, ax=ax), SECTION),
    "wheelset plan": (
        lambda ax: wheelset_plan(Wheelset(), 0.003, 0.002, exaggerate=20.0, ax=ax),
        ["$y$", r"$\psi$", "$V$", "$a$"],
    ),
    "bogie plan": (lambda ax: bogie_plan(Bogie(), ax=ax), ["$k_y$", r"$k_\psi$", "$b$", "$a$", "$V$"]),
    "car side": (
        lambda ax: car_side(VerticalCar(), ax=ax),
        ["$l$", "$b$", "$z_c$", r"$\theta_c$", "$k_s$, $c_s$", "$k_p$, $c_p$"],
    ),
    "car plan": (
        lambda ax: car_plan(LateralCar(), 0.002, exaggerate=10.0, ax=ax),
        ["$l$", "$b$", r"$\psi$", "$V$"],
    ),
    "three-piece truck": (
        lambda ax: truck_schematic(ThreePieceTruck(), ax=ax),
        ["$b$", "$d$", "$a$", "$r_0$", "$k_w$", r"$\psi_b$"],
    ),
    "coupler chain": (lambda ax: coupler_chain(CONSIST, ax=ax), ["$e$", "$x_0$", r"$\Delta x_0$", "$V$"]),
    "beam, force": (
        lambda ax: beam_load(SimplySupportedBeam(), 6.0, ax=ax),
        ["$L$", "$x = Vt$", "$P$", "$V$"],
    ),
    "beam, sprung mass": (
        lambda ax: beam_load(SimplySupportedBeam(), 6.0, sprung=True, ax=ax),
        ["$M_v$", "$k_v$, $c_v$", "$m_w$", "$L$"],
    ),
}


def _artists(result) -> dict:
    return result.artists if isinstance(result, WheelsetPlan | BeamLoad) else result


def _flat(obj):
    """Every artist in a nested dict/list of artists."""
    if isinstance(obj, dict):
        for v in obj.values():
            yield from _flat(v)
    elif isinstance(obj, list | tuple):
        for v in obj:
            yield from _flat(v)
    else:
        yield obj


def _texts(ax) -> str:
    return " | ".join(t.get_text() for t in ax.texts)


def _centre(polygon) -> np.ndarray:
    return polygon.get_xy()[:-1].mean(axis=0)


@pytest.mark.parametrize("name", sorted(CASES))
def test_draws_on_given_axes_returns_artists_and_keeps_rcparams(name):
    draw, symbols = CASES[name]
    before = dict(matplotlib.rcParams)
    fig, ax = plt.subplots()
    artists = list(_flat(_artists(draw(ax))))
    assert artists and all(a.axes is ax for a in artists if hasattr(a, "axes"))
    assert plt.get_fignums() == [fig.number]  # drew there, made no other figure
    assert not ax.axison and ax.get_aspect() == 1.0  # no frame, equal aspect
    text = _texts(ax)
    missing = [s for s in symbols if s not in text]
    assert not missing, f"{name}: labels lack {missing}; found {text}"
    assert dict(matplotlib.rcParams) == before


@pytest.mark.parametrize("name", sorted(CASES))
def test_draws_on_new_axes(name):
    draw, _ = CASES[name]
    before = dict(matplotlib.rcParams)
    artists = list(_flat(_artists(draw(None))))
    assert len(plt.get_fignums()) == 1
    assert artists and artists[0].axes is plt.gcf().axes[0]
    assert dict(matplotlib.rcParams) == before


def test_wheelset_section_scales_with_half_gauge_and_rolls_as_a_cone():
    ws = Wheelset()
    x1 = wheelset_section(ws)["contacts"].get_xdata()
    # 1.4 times the 0.75 m default: 1.05 m, within the plausible half gauges (broadest gauges)
    x2 = wheelset_section(ws.replace(half_gauge=1.4 * ws.half_gauge))["contacts"].get_xdata()
    np.testing.assert_allclose(np.diff(x2), 1.4 * np.diff(x1), rtol=1e-12)
    # a cone on knife-edge rails shifted by y rolls by λy/a (left end up): the drawn centre line
    # leans by the drawn λ times the drawn y over a (closed form, exact in the drawing's algebra)
    y, k = 0.004, 3.0  # λk = 0.45: below the 0.5 at which the drawn cone's slope stops growing
    line = wheelset_section(ws, y, exaggerate=k)["centre_line"]
    (x0, x1_), (z0, z1) = line.get_xdata(), line.get_ydata()
    roll = np.arctan2(-(x1_ - x0), z1 - z0)
    assert roll == pytest.approx(-(ws.conicity * k) * (y * k) / ws.half_gauge, rel=1e-12)
    # the wheelset moved left (picture left) by the drawn y; its axle's centre stays at r₀ above the rails
    axle = _centre(wheelset_section(ws, y, exaggerate=k)["axle"])
    np.testing.assert_allclose(axle, [-y * k, ws.rolling_radius], atol=1e-12)


def test_wheelset_section_radius_is_the_model_r0():
    ws = Wheelset(rolling_radius=0.6)
    assert _centre(wheelset_section(ws)["axle"])[1] == pytest.approx(0.6)


def test_wheelset_plan_scales_and_moves_in_place():
    ws = Wheelset()
    for factor in (1.0, 1.4):  # 1.4 × 0.75 m: the broadest plausible half gauge is 1.1 m
        plan = wheelset_plan(ws.replace(half_gauge=factor * ws.half_gauge))
        left, right = (_centre(w) for w in plan.artists["wheels"])
        assert abs(left[1] - right[1]) == pytest.approx(2 * factor * ws.half_gauge)
    plt.close("all")
    fig, ax = plt.subplots()
    plan = wheelset_plan(ws, ax=ax)
    children = list(ax.get_children())
    axle = plan.artists["axle"]
    np.testing.assert_allclose(_centre(axle), [0.0, 0.0], atol=1e-12)
    y, psi, k = 0.004, 0.01, 10.0
    plan = WheelsetPlan(ws, exaggerate=k, ax=ax)
    children = list(ax.get_children())
    moved = plan.update(y, psi)
    assert moved is plan.artists
    assert list(ax.get_children()) == children  # the same artists, no new one
    assert plt.get_fignums() == [fig.number]
    np.testing.assert_allclose(_centre(plan.artists["axle"]), [0.0, y * k], atol=1e-12)
    # the axle turned by the drawn ψ: its long side (across the track) leans back by ψ k
    corners = plan.artists["axle"].get_xy()[:4]
    across = corners[2] - corners[1]
    assert np.arctan2(-across[0], across[1]) == pytest.approx(psi * k, rel=1e-12)
    heading = plan.artists["heading"]
    assert np.arctan2(np.diff(heading.get_ydata()), np.diff(heading.get_xdata()))[0] == pytest.approx(psi * k)
    assert plan.artists["y"].get_visible() and plan.artists["psi_head"].get_visible()
    plan.update(0.0, 0.0)
    assert not plan.artists["y"].get_visible()
    assert list(ax.get_children()) == children


def test_bogie_plan_scales_with_semi_wheelbase():
    bogie = Bogie()
    for factor in (1.0, 2.0):
        art = bogie_plan(bogie.replace(semi_wheelbase=factor * bogie.semi_wheelbase))
        front, rear = (_centre(ws[0]) for ws in art["wheelsets"])
        assert front[0] - rear[0] == pytest.approx(2 * factor * bogie.semi_wheelbase)
        assert len(art["lateral_springs"]) == len(art["longitudinal_springs"]) == 4


def test_car_side_and_plan_scale_with_bogie_spacing():
    car = VerticalCar()
    for factor in (1.0, 1.5):
        art = car_side(dataclasses.replace(car, semi_bogie_spacing=factor * car.semi_bogie_spacing))
        front, rear = (_centre(b) for b in art["bogies"])
        assert front[0] - rear[0] == pytest.approx(2 * factor * car.semi_bogie_spacing)
        wheels = sorted(_centre(w)[0] for w in art["wheels"])
        assert wheels[1] - wheels[0] == pytest.approx(2 * car.semi_wheelbase)
    lateral = LateralCar()
    for factor in (1.0, 1.5):
        art = car_plan(lateral.replace(semi_bogie_spacing=factor * lateral.semi_bogie_spacing))
        front, rear = (_centre(b) for b in art["bogies"])
        assert front[0] - rear[0] == pytest.approx(2 * factor * lateral.semi_bogie_spacing)
    # the body turns by the drawn ψ about its centre
    corners = car_plan(lateral, 0.003, exaggerate=10.0)["body"].get_xy()[:4]
    assert np.arctan2(*(corners[1] - corners[0])[::-1]) == pytest.approx(0.03)


def test_truck_scales_with_side_frame_spacing_and_wheelbase():
    truck = ThreePieceTruck()
    for factor in (1.0, 2.0):
        changed = dataclasses.replace(
            truck,
            side_frame_spacing=factor * truck.side_frame_spacing,
            semi_wheelbase=factor * truck.semi_wheelbase,
        )
        art = truck_schematic(changed)
        upper, lower = (_centre(f) for f in art["plan"]["side_frames"])
        assert abs(upper[1] - lower[1]) == pytest.approx(2 * factor * truck.side_frame_spacing)
        front, rear = (_centre(w) for w in art["wheels"])
        assert front[0] - rear[0] == pytest.approx(2 * factor * truck.semi_wheelbase, rel=1e-3)


def test_coupler_chain_boxes_are_the_vehicles_lengths_and_slack_scales():
    art = coupler_chain(CONSIST, vehicles=3)
    widths = [np.ptp(b.get_xy()[:, 0]) for b in art["boxes"]]
    np.testing.assert_allclose(widths, CONSIST.length[:3], rtol=1e-12)
    longer = CONSIST.with_vehicle(0, length=2 * float(CONSIST.length[0]))
    assert np.ptp(coupler_chain(longer)["boxes"][0].get_xy()[:, 0]) == pytest.approx(2 * CONSIST.length[0])
    gaps = []
    for slack in (0.02, 0.04):
        arrow, _ = coupler_chain(CONSIST, DraftGear(slack=slack))["slack"][0]
        (x0, _), (x1, _) = arrow._posA_posB
        gaps.append(abs(x1 - x0))
    assert gaps[1] == pytest.approx(2 * gaps[0])
    assert len(coupler_chain(CONSIST, vehicles=50)["boxes"]) == len(CONSIST)  # no more than the consist holds


def test_oscillator_grows_with_mass_and_draws_zero_damping_dashed():
    small = oscillator_model(SDOF(1000.0, 2000.0, 4e5))["mass"].get_xy()
    big = oscillator_model(SDOF(8000.0, 2000.0, 4e5))["mass"].get_xy()
    assert np.ptp(big[:, 0]) == pytest.approx(2 * np.ptp(small[:, 0]))  # the cube root of 8
    assert oscillator_model(SDOF(1000.0, 0.0, 4e5))["damper"].get_linestyle() == "--"


@pytest.mark.parametrize("sprung", [False, True])
def test_beam_load_moves_in_place_and_bends_under_the_load(sprung):
    beam = SimplySupportedBeam(span=30.0)
    fig, ax = plt.subplots()
    drawn = beam_load(beam, 0.0, sprung=sprung, ax=ax)
    x, w = drawn.artists["beam"].get_data()
    assert x[0] == 0.0 and x[-1] == pytest.approx(30.0)  # the span L, to scale
    np.testing.assert_allclose(w, 0.0, atol=1e-12)  # a load on the support bends nothing
    children = list(ax.get_children())
    for at in (7.5, 22.5, 15.0):
        drawn.update(at)
        x, w = drawn.artists["beam"].get_data()
        # closed forms, the point-load deflection of a simply supported beam over P L³/(48 EI), drawn
        # L/14 deep at most: at the load 16 a² b²/L⁴; deepest sqrt((L² − a²)/3) from the support
        # farther from the load, a the shorter of the load's distances to the supports
        a, b = min(at, 30.0 - at), max(at, 30.0 - at)
        assert np.interp(at, x, w) == pytest.approx(-30.0 / 14 * 16 * a**2 * b**2 / 30.0**4, rel=1e-9)
        deepest = np.sqrt((30.0**2 - a**2) / 3)
        expected = 30.0 - deepest if at < 15.0 else deepest
        assert x[np.argmin(w)] == pytest.approx(expected, abs=0.3)  # the drawn grid's step: 0.3 m
        if not sprung:
            (_, _), (xa, za) = drawn.artists["load"]._posA_posB
            assert xa == pytest.approx(at) and za == pytest.approx(np.interp(at, x, w))
    # closed form: under a midspan load the drawn sag is L/14 (P L³/(48 EI), normalised)
    assert -w.min() == pytest.approx(30.0 / 14, rel=1e-9)
    assert list(ax.get_children()) == children and plt.get_fignums() == [fig.number]


def test_beam_scales_with_span():
    spans = [
        np.ptp(beam_load(SimplySupportedBeam(span=s), 0.0).artists["beam"].get_xdata()) for s in (10.0, 20.0)
    ]
    assert spans[1] == pytest.approx(2 * spans[0])


BAD = [
    (lambda: oscillator_model("abc"), TypeError, "sdof"),
    (lambda: rigid_body_freedoms("yes"), TypeError, "planar"),
    (lambda: wheelset_section(None), TypeError, "ws"),
    (lambda: wheelset_section(Wheelset(), np.nan), ValueError, "y"),
    (lambda: wheelset_section(Wheelset(), 0.3), ValueError, "y"),
    (lambda: wheelset_section(Wheelset(), exaggerate=0.0), ValueError, "exaggerate"),
    (lambda: wheelset_section(Wheelset(), ax="abc"), TypeError, "ax"),
    (lambda: wheelset_plan(Wheelset(), 0.0, 1.0), ValueError, "psi"),
    (lambda: wheelset_plan(Wheelset(), 0.0, 0.0).update(0.0, np.inf), ValueError, "psi"),
    (lambda: wheelset_plan(Wheelset()).update("abc", 0.0), TypeError, "y"),
    (lambda: bogie_plan(Wheelset()), TypeError, "bogie"),
    (lambda: car_side(LateralCar()), TypeError, "car"),
    (lambda: car_plan(VerticalCar()), TypeError, "car"),
    (lambda: car_plan(LateralCar(), psi=0.5), ValueError, "psi"),
    (lambda: truck_schematic(Bogie()), TypeError, "truck"),
    (lambda: coupler_chain(CONSIST, vehicles=0), ValueError, "vehicles"),
    (lambda: coupler_chain(CONSIST, vehicles=2.0), TypeError, "vehicles"),
    (lambda: coupler_chain(CONSIST, gear="abc"), TypeError, "gear"),
    (lambda: coupler_chain([1, 2]), TypeError, "consist"),
    (lambda: beam_load(SimplySupportedBeam(), -1.0), ValueError, "position"),
    (lambda: beam_load(SimplySupportedBeam(), 5.0).update(21.0), ValueError, "position"),
    (lambda: beam_load(SimplySupportedBeam(), 5.0, sprung=1), TypeError, "sprung"),
    (lambda: beam_load(Wheelset(), 5.0), TypeError, "beam"),
]


@pytest.mark.parametrize("case", range(len(BAD)))
def test_bad_input_is_refused_by_name(case):
    call, error, name = BAD[case]
    with pytest.raises(error, match=rf"\b{name}\b"):
        call()


# The figure sizes the chapters draw each schematic at (a label is set in points, the drawing in metres,
# so whether a label clears the drawing depends on the size).
NOTEBOOK_SIZES = {
    "oscillator": (4.0, 3.4),
    "rigid body": (4.5, 3.6),
    "rigid body, planar": (4.5, 3.6),
    "wheelset section": (5.0, 3.8),
    "wheelset plan": (5.0, 3.8),
    "bogie plan": (7.0, 4.0),
    "car side": (9.0, 3.4),
    "car plan": (10.0, 3.2),
    "three-piece truck": (7.0, 4.6),
    "coupler chain": (9.0, 2.2),
    "beam, force": (7.0, 2.2),
    "beam, sprung mass": (7.0, 2.2),
}


def _label_clashes(ax) -> list[str]:
    """Labels that sit on the drawing: a label whose box crosses the outline of a body (a filled polygon)
    without lying wholly inside a body drawn above it (a name written on its body, "bolster", is fine),
    and labels that overlap each other."""
    from matplotlib.patches import Polygon

    ax.figure.canvas.draw()
    renderer = ax.figure.canvas.get_renderer()
    bodies = [p for p in ax.patches if isinstance(p, Polygon) and p.get_visible() and p.get_fill()]
    texts = [t for t in ax.texts if t.get_visible() and t.get_text().strip()]
    boxes = [t.get_window_extent(renderer) for t in texts]
    clashes = []
    for text, box in zip(texts, boxes, strict=True):
        crossed, holders = [], []
        for body in bodies:
            outline = body.get_path().transformed(body.get_transform())
            if all(outline.contains_point(corner) for corner in box.corners()):
                holders.append(body.get_zorder())
            elif outline.intersects_bbox(box, filled=True):
                crossed.append(body.get_zorder())
        if crossed and not (holders and max(holders) > max(crossed)):
            clashes.append(f"{text.get_text()!r} on a body's outline")
    for i in range(len(texts)):
        for j in range(i + 1, len(texts)):
            if boxes[i].overlaps(boxes[j]):
                clashes.append(f"{texts[i].get_text()!r} on {texts[j].get_text()!r}")
    return clashes


@pytest.mark.parametrize("name", sorted(CASES))
def test_labels_stand_clear_of_the_drawing_at_the_chapters_size(name):
    # Chapter 6's truck had "side frame" and "wedge" written across its wheels.
    assert set(NOTEBOOK_SIZES) == set(CASES)
    fig, ax = plt.subplots(figsize=NOTEBOOK_SIZES[name])
    try:
        CASES[name][0](ax)
        assert not _label_clashes(ax), _label_clashes(ax)
    finally:
        plt.close(fig)


def test_chapter_six_truck_labels_stand_clear():
    from raildyn.vehicles import LOADED_FREIGHT_CAR

    fig, ax = plt.subplots(figsize=NOTEBOOK_SIZES["three-piece truck"])
    try:
        truck_schematic(LOADED_FREIGHT_CAR.truck, ax=ax)
        assert not _label_clashes(ax), _label_clashes(ax)
    finally:
        plt.close(fig)


def test_bogie_plan_moves_frame_and_wheelsets_in_place():
    # Each wheelset's centre moves by its y times the exaggeration, the frame's pivot by the frame's; the
    # springs follow; the artists are the same objects.
    bogie = Bogie()
    plan = BogiePlan(bogie, exaggerate=10.0)
    before = {id(a) for a in plan.artists["lateral_springs"] + plan.artists["frame"]}
    springs = [line.get_xydata().copy() for line in plan.artists["lateral_springs"]]
    moved = plan.update((0.002, 0.0), ((0.004, 0.0), (-0.003, 0.0)))
    assert moved is plan.artists
    assert {id(a) for a in moved["lateral_springs"] + moved["frame"]} == before
    front, rear = (_centre(ws[0]) for ws in moved["wheelsets"])
    assert front == pytest.approx((bogie.semi_wheelbase, 0.04))
    assert rear == pytest.approx((-bogie.semi_wheelbase, -0.03))
    assert _centre(moved["frame"][-1])[1] == pytest.approx(0.02, abs=1e-3)  # the pivot's circle
    assert any(
        not np.allclose(a, line.get_xydata())
        for a, line in zip(springs, moved["lateral_springs"], strict=True)
    )
    with pytest.raises(ValueError, match="wheelsets"):
        plan.update((0.0, 0.0), ((0.1, 0.0), (0.0, 0.0)))  # 1 m drawn: beyond a quarter of the gauge


def test_beam_load_draws_the_deflection_it_is_given():
    beam = SimplySupportedBeam()
    drawn = beam_load(beam, 5.0)
    shape = 0.3 * np.sin(np.pi * drawn.points / beam.span)
    x, w = drawn.update(5.0, shape)["beam"].get_data()
    np.testing.assert_allclose(w, -shape)  # drawn downwards
    with pytest.raises(ValueError, match="deflection"):
        drawn.update(5.0, shape[:-1])
