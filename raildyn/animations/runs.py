"""Motion in section, along the train and along the span, from the models' own runs: the rocking freight
car (chapter 6), the train's run-in (chapter 9) and the car crossing the bridge (chapter 10).

Each function runs the model (:func:`raildyn.vehicles.rocking_runs.rocking_run`,
:func:`raildyn.train.longitudinal.simulate`, :func:`raildyn.bridge.coupled.crossing`), picks evenly
spaced times of the run and moves one picture to the state at each, the run's own numbers below it.
Where a motion is too small to see at the picture's scale (the roll, the slack, the deflection), it is
drawn exaggerated by a round factor that the picture states.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks, diagrams, plots, train
from raildyn.animations import _frames
from raildyn.animations.player import Animation, record
from raildyn.bridge import AxleSequence, MovingLoad, SimplySupportedBeam, crossing, sprung_mass
from raildyn.vehicles import RockingFreightCar, rocking_run

# Imported where used, to keep this module's import cheap: matplotlib

__all__ = ["bridge_crossing", "rocking_car", "train_run_in"]

_BODY_WIDTH = 3.05  # m: the width the body is drawn at in section, a drawing size (the run does not use it)


def rocking_car(
    car: RockingFreightCar | None = None,
    speed: float | None = None,
    *,
    cycles: int = 12,
    frames: int = 40,
) -> Animation:
    """The freight car rocking on staggered joints, in section: its own run, the last two rail lengths.

    :func:`raildyn.vehicles.rocking_runs.rocking_run` runs the car over staggered dipped joints for ``cycles``
    rail lengths at ``speed``; the frames cover the last two rail lengths, in its steady window. The
    body is drawn in section seen from behind, rolled about its centre plate by the run's roll (times
    the factor the picture states) on the two spring nests; each wheel of the leading wheelset stands
    on its rail with a bar of its load (the run's wheel loads, the static load marked), red and marked
    lifted when the load is zero. Below: the roll and the leading wheels' loads over the run.

    Parameters
    ----------
    car : raildyn.vehicles.RockingFreightCar, optional
        Default :class:`~raildyn.vehicles.RockingFreightCar` (the loaded 286K hopper).
    speed : float, optional
        V, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]; default the car's roll resonance
        speed (:meth:`~raildyn.vehicles.rocking.RockingFreightCar.roll_resonance_speed`).
    cycles : int
        Rail lengths run, in [4, 1000].
    frames : int
        In [2, 400].

    Returns
    -------
    Animation
    """
    import matplotlib

    car = (
        RockingFreightCar()
        if car is None
        else _checks.instance("car", car, RockingFreightCar, "raildyn.vehicles.RockingFreightCar")
    )
    n = _frames.frame_count(frames)
    V = car.roll_resonance_speed() if speed is None else _checks.speed("speed", speed)
    run = rocking_run(car, V, cycles=cycles)
    t, roll = run.t, run.roll
    loads = run.wheel_loads[:, 0, :] / run.static_wheel_load  # the leading wheelset's, over Q₀
    period = 2 * run.rail_length / run.speed
    pick = _frames.picks(t, max(t[-1] - period, t[0]), t[-1], n)
    factor = _frames.exaggeration(np.abs(roll[pick]).max(), np.radians(15.0))
    a, r = car.half_rail_spacing, car.wheel_radius
    plate = car.centre_plate_height
    top = 2 * car.cg_height_above_rail - plate  # a body whose centre of gravity is at mid-height
    nests = 1.0  # m: the spring nests either side, under the side frames
    fig, (ax, ax_run) = _frames.figure(heights=(2.4, 1.0))
    with matplotlib.rc_context({**plots.STYLE, "axes.grid": False}):
        for side in (-1.0, 1.0):
            ax.plot([side * a - 0.04, side * a + 0.04], [0.0, 0.0], color="0.3", lw=3)
        ax.plot([-2.2, 2.2], [-0.05, -0.05], color="0.5", lw=0.8)
        (body,) = ax.fill([], [], facecolor="0.88", edgecolor="black", lw=0.9, zorder=2)
        springs = [ax.plot([], [], color="black", lw=0.9)[0] for _ in range(2)]
        # the wheels seen from behind, left (the left rail's, j = 0) of the picture first
        wheels = [
            ax.fill(
                [side * a - 0.07, side * a + 0.07, side * a + 0.07, side * a - 0.07],
                [0.0, 0.0, 2 * r, 2 * r],
                facecolor="0.7",
                edgecolor="black",
                lw=0.8,
                zorder=3,
            )[0]
            for side in (-1.0, 1.0)
        ]
        ax.plot([-a, a], [r, r], color="black", lw=2.0, zorder=2.5)  # the axle
        bars = [ax.bar([s * (a + 0.35)], [0.0], width=0.16, bottom=0.0, color="0.5")[0] for s in (-1.0, 1.0)]
        for s in (-1.0, 1.0):
            ax.plot([s * (a + 0.35) - 0.12, s * (a + 0.35) + 0.12], [0.5, 0.5], color="0.35", lw=0.8, ls=":")
        lifted = [
            ax.text(s * (a + 0.35), 1.1, "", ha="center", size=7, color=plots.COLORS[1]) for s in (-1, 1)
        ]
        ax.text(
            -2.3,
            top + 0.25,
            f"roll drawn × {factor:g}; bars: wheel load (dotted: static)",
            size=7,
            color="0.35",
        )
        ax.set_xlim(-2.4, 2.4)
        ax.set_ylim(-0.2, top + 0.45)
        ax.set_aspect("equal", adjustable="box")
        ax.set_axis_off()
    cursor = _frames.trace(
        ax_run,
        t,
        {"roll (mrad)": 1e3 * roll, "left Q/Q₀ × 10": 10 * loads[:, 0], "right Q/Q₀ × 10": 10 * loads[:, 1]},
        ylabel="",
        window=(t[pick[0]], t[-1]),
    )

    def draw(i: int) -> None:
        k = pick[i]
        angle = factor * roll[k]
        outline = np.array(
            [
                (-_BODY_WIDTH / 2, plate),
                (_BODY_WIDTH / 2, plate),
                (_BODY_WIDTH / 2, top),
                (-_BODY_WIDTH / 2, top),
            ]
        )
        body.set_xy(_turn(outline, angle, (0.0, plate)))
        for side, spring in zip((-1.0, 1.0), springs, strict=True):
            foot = (side * nests, 0.5 * r + 0.15)
            head = _turn(np.array([(side * nests, plate)]), angle, (0.0, plate))[0]
            spring.set_data(*_zigzag(foot, head).T)
        for j, (wheel, bar, note) in enumerate(zip(wheels, bars, lifted, strict=True)):
            off = loads[k, j] <= 0.0
            wheel.set_facecolor(plots.COLORS[1] if off else "0.7")
            bar.set_height(0.5 * loads[k, j])
            note.set_text("lifted" if off else "")
        cursor.set_xdata([t[k]])

    labels = [
        f"t = {t[k]:.2f} s, V = {3.6 * run.speed:.1f} km/h, roll {np.degrees(roll[k]):+.2f}°" for k in pick
    ]
    title = f"the freight car rocking at {3.6 * run.speed:.1f} km/h, in section"
    moving = [body, *springs, *wheels, *bars, *lifted, cursor]
    return record(fig, draw, labels, title=title, moving=moving)


def _turn(points: np.ndarray, angle: float, centre) -> np.ndarray:
    """Points turned by ``angle`` (rad) about ``centre``, clockwise as drawn: seen from behind, the
    left side (left of the picture) rises, as a positive roll of the run lifts it."""
    c, s = np.cos(angle), np.sin(angle)
    centre = np.asarray(centre, float)
    # the row vectors' form of the rotation by −angle: x' = x c + y s, y' = −x s + y c
    return (points - centre) @ np.array([[c, -s], [s, c]]) + centre


def _zigzag(p0, p1, coils: int = 4, width: float = 0.12) -> np.ndarray:
    """A spring's zigzag from ``p0`` to ``p1``."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    along = np.linspace(0.0, 1.0, 2 * coils + 3)
    side = np.zeros_like(along)
    side[1:-1:2], side[2:-1:2] = width / 2, -width / 2
    side[[1, -2]] = 0.0
    d = p1 - p0
    normal = np.array([-d[1], d[0]]) / np.hypot(*d)
    return p0 + along[:, None] * d + side[:, None] * normal


def train_run_in(
    model: train.TrainModel | None = None,
    duration: float = 40.0,
    initial_speed: float = 20.0,
    *,
    initial_extension: float = 0.0125,
    frames: int = 40,
) -> Animation:
    """The train's run-in under braking: each car's place along the train and the coupler forces.

    :func:`raildyn.train.longitudinal.simulate` runs the train for ``duration`` seconds from
    ``initial_speed``, its couplers starting at ``initial_extension``. Each frame draws the cars as
    boxes along the train, each shifted by how far it has closed up on the front vehicle since the
    start (times the factor the picture states, so that millimetres of slack show on a train of a
    kilometre and more) and coloured by the force in the coupler behind it; below, the coupler
    forces against the distance behind the front at that instant.

    Parameters
    ----------
    model : raildyn.train.TrainModel, optional
        Default chapter 9's: ``train.braking_model(100, 2, slack=0.025, propagation_speed=250.0)``.
    duration : float
        s, in [1, 600].
    initial_speed : float
        m/s, in [0, 200].
    initial_extension : float
        As for :func:`raildyn.train.longitudinal.simulate`.
    frames : int
        In [2, 400].

    Returns
    -------
    Animation
    """
    model = (
        train.braking_model(100, 2, slack=0.025, propagation_speed=250.0)
        if model is None
        else _checks.instance("model", model, train.TrainModel, "raildyn.train.TrainModel")
    )
    T = _checks.scalar("duration", duration, low=1.0, high=600.0)
    V0 = _checks.scalar("initial_speed", initial_speed, low=0.0, high=200.0)
    n = _frames.frame_count(frames)
    run = train.simulate(model, T, V0, initial_extension=initial_extension, samples=max(401, 4 * n))
    x = run.position  # (vehicles, times)
    closing = (x - x[:, :1]) - (x[:1] - x[:1, :1])  # each car's shift since the start, against the front's
    ahead = run.coupler_offsets
    # m: each vehicle's front behind the train's front, and its length (the last one's as the one before)
    place = np.concatenate([[0.0], ahead])
    lengths = np.diff(
        np.concatenate([place, [place[-1] + (ahead[-1] - ahead[-2] if ahead.size > 1 else 20.0)]])
    )
    pick = _frames.picks(run.t, 0.0, run.t[-1], n)
    end = place[-1] + lengths[-1]
    factor = _frames.exaggeration(np.abs(closing).max(), 0.04 * end)
    force = run.coupler_force / 1e3  # kN
    biggest = max(np.abs(force).max(), 1.0)
    import matplotlib
    from matplotlib.collections import PolyCollection

    fig, (ax, ax_force) = _frames.figure(heights=(0.8, 2.0), size=(6.4, 3.0))
    cmap = matplotlib.colormaps["RdBu_r"]  # as the run's own wave plot (TrainRun.plot_wave)
    with matplotlib.rc_context(plots.STYLE):
        cars = PolyCollection([], edgecolors="0.3", linewidths=0.3, cmap=cmap)
        cars.set_clim(-biggest, biggest)
        ax.add_collection(cars)
        ax.set_xlim(-0.05 * end, 1.02 * end)
        ax.set_ylim(-0.2, 2.2)
        ax.set_axis_off()
        ax.text(
            -0.05 * end,
            2.2,
            f"← front; closing up on the front drawn × {factor:g}; colour: force behind (blue: compression)",
            size=7,
            color="0.35",
            va="top",
        )
        (line,) = ax_force.plot(ahead, force[:, 0], color=plots.COLORS[0], lw=1.2)
        ax_force.axhline(0.0, color="0.5", lw=0.6)
        ax_force.set_xlim(-0.05 * end, 1.02 * end)
        ax_force.set_ylim(-1.05 * biggest, 1.05 * biggest)
        ax_force.set_xlabel("distance behind the front (m)", fontsize=8)
        ax_force.set_ylabel("coupler force (kN)", fontsize=8)
        ax_force.tick_params(labelsize=7)
        ax_force.grid(alpha=0.3)
    rear_force = np.vstack([force, np.zeros((1, force.shape[1]))])  # the last vehicle has no coupler behind

    def draw(i: int) -> None:
        k = pick[i]
        front = place - factor * closing[:, k]  # a car that closes up moves towards the front
        cars.set_verts(
            [
                [(f, 0.0), (f, 1.0), (f + 0.92 * L, 1.0), (f + 0.92 * L, 0.0)]
                for f, L in zip(front, lengths, strict=True)
            ]
        )
        cars.set_array(rear_force[:, k])
        line.set_ydata(force[:, k])

    labels = [f"t = {run.t[k]:.1f} s, front at {run.speed[0, k]:.1f} m/s" for k in pick]
    return record(fig, draw, labels, title="the train's run-in under braking", moving=[cars, line])


def bridge_crossing(
    beam: SimplySupportedBeam | None = None,
    load: MovingLoad | AxleSequence | None = None,
    speed: float | None = None,
    *,
    frames: int = 40,
) -> Animation:
    """The car crossing the bridge: the beam bent as the coupled run finds it, the load moving on it.

    :func:`raildyn.bridge.coupled.crossing` runs the load over the beam, coupled; each frame bends the beam
    of :class:`~raildyn.diagrams.structures.BeamLoad` to the run's deflection w(x, t) = Σ φᵢ(x) bᵢ(t) from its
    modal coordinates (times the factor the picture states) and puts the load (its leading axle) at
    x = vt; below, the midspan deflection over the run. The frames run from the leading axle's
    arrival until the last axle leaves.

    Parameters
    ----------
    beam : raildyn.bridge.SimplySupportedBeam, optional
        Default chapter 10's light span: 20 m, EI = 10¹⁰ N·m², 10⁴ kg/m, 1 % damping, 5 modes.
    load : raildyn.bridge.MovingLoad or raildyn.bridge.AxleSequence, optional
        Default a sprung mass (8000 kg on a spring tuned to the beam's first mode, over a 1500 kg wheel).
    speed : float, optional
        v, m/s, in (0, :data:`~raildyn.constants.MAXIMUM_SPEED`]; default α = 0.3 (v = 0.6 f₁ L).
    frames : int
        In [2, 400].

    Returns
    -------
    Animation
    """
    beam = (
        SimplySupportedBeam(20.0, 1.0e10, 1.0e4, damping_ratio=0.01, modes=5)
        if beam is None
        else _checks.instance("beam", beam, SimplySupportedBeam, "raildyn.bridge.SimplySupportedBeam")
    )
    f1 = float(beam.frequencies_hz[0])
    if load is None:
        load = sprung_mass(8000.0, 8000.0 * (2 * np.pi * f1) ** 2, 0.0, 1500.0)
    _checks.instance("load", load, (MovingLoad, AxleSequence), "raildyn.bridge.MovingLoad or AxleSequence")
    v = 0.6 * f1 * beam.span if speed is None else _checks.speed("speed", speed)
    n = _frames.frame_count(frames)
    run = crossing(beam, load, v)
    on = run.time <= beam.span / v  # while the leading axle is on the span
    pick = _frames.picks(run.time, 0.0, run.time[on][-1], n)
    fig, (ax, ax_run) = _frames.figure(heights=(2.0, 1.0))
    drawn = diagrams.beam_load(beam, sprung=isinstance(load, MovingLoad) and load.system is not None, ax=ax)
    shapes = beam.mode_shapes(drawn.points)  # (modes, 101)
    w = run.modal[:, 0, :] @ shapes  # (k, 101), m, downwards
    factor = _frames.exaggeration(np.abs(w).max(), beam.span / 14)
    ax.text(
        0.0, 1.0, f"deflection drawn × {factor:g}", transform=ax.transAxes, size=7, color="0.35", va="top"
    )
    cursor = _frames.trace(ax_run, run.time, {"midspan w (mm)": 1e3 * run.deflection}, ylabel="w (mm)")

    def draw(i: int) -> None:
        k = pick[i]
        drawn.update(min(v * run.time[k], beam.span), factor * w[k])
        cursor.set_xdata([run.time[k]])

    labels = [f"t = {run.time[k]:.3f} s, x = {v * run.time[k]:.1f} m, v = {v:.1f} m/s" for k in pick]
    title = f"a load crossing a {beam.span:g} m span at {v:.1f} m/s"
    return record(fig, draw, labels, title=title, moving=_frames.artists(drawn.artists, cursor))
