"""Chapter 10 figures: the dynamic amplification of one moving force against α, a regular train's
resonance and its cancellation, and four models of one car crossing the same span.

The amplification comes from the closed form of :func:`raildyn.bridge.beam.moving_force_response`, the
coupled crossings from :func:`raildyn.bridge.coupled.crossing`; the curves are drawn by
:meth:`~raildyn.bridge.beam.MovingForceResponse.plot` and :meth:`~raildyn.bridge.coupled.BridgeCrossing.plot`,
which the chapter's widgets call too. None of them mirrors a numbered figure of the book.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from raildyn import plots
from raildyn.bridge import (
    AxleSequence,
    SimplySupportedBeam,
    codes,
    crossing,
    moving_force_response,
    moving_mass,
    sprung_mass,
    train,
    vehicle,
)
from raildyn.bridge.trains import regular_train
from raildyn.constants import GRAVITY
from raildyn.figures import new_figure, register
from raildyn.vehicles import VerticalCar

_SPAN, _EI, _MASS = 20.0, 1.0e10, 1.0e4  # m, N·m², kg/m: f₁ = 3.93 Hz (SimplySupportedBeam's defaults)


def _tuned(span: float, frequency_hz: float, damping_ratio: float, modes: int) -> SimplySupportedBeam:
    """A beam of 10 t/m whose EI gives the first frequency: f₁ = (π/(2L²))√(EI/m)."""
    EI = _MASS * (2 * frequency_hz * span**2 / np.pi) ** 2
    return SimplySupportedBeam(span, EI, _MASS, damping_ratio=damping_ratio, modes=modes)


@register(
    "fig10.daf_single_force",
    "The dynamic amplification of the midspan deflection of a simply supported beam under one constant "
    "force crossing it, against the speed parameter α = v/(2f₁L), for damping ratios of 0, 2 % and 5 % "
    "(closed form, ten modes). Undamped, the largest amplification, about 1.73, comes near α = 0.6 "
    "(Frýba 1972); damping lowers it a little. Below α ≈ 0.2 the ripples are the first mode's free "
    "vibration riding on the quasi-static deflection.",
    chapter=10,
)
def daf_single_force() -> Figure:
    alphas = np.linspace(0.005, 1.995, 400)  # 0.005 apart, off the undamped resonance α = 1
    fig = new_figure(figsize=(7.0, 4.0))
    ax = fig.subplots()
    for k, zeta in enumerate((0.0, 0.02, 0.05)):
        # The amplification depends on α and ζ alone (Frýba 1972): a span twice as long of the same
        # section meets α = 2 at 157 m/s, within raildyn.constants.MAXIMUM_SPEED (20 m: 314 m/s).
        beam = SimplySupportedBeam(2 * _SPAN, _EI, _MASS, damping_ratio=zeta, modes=10)
        alpha_speed = 2 * beam.frequencies_hz[0] * beam.span
        response = moving_force_response(beam, alphas * alpha_speed, 1.0e5)
        response.plot(ax, alpha_speed=alpha_speed, color=plots.COLORS[k], label=f"ζ = {100 * zeta:g} %")
        daf = response.amplification
        if zeta == 0.0:
            i = int(np.argmax(daf))
            ax.plot([alphas[i]], [daf[i]], "o", color=plots.COLORS[k], mfc="white")
            ax.annotate(
                f"{daf[i]:.3f} at α = {alphas[i]:.2f}",
                (alphas[i], daf[i]),
                xytext=(12, 6),
                textcoords="offset points",
                fontsize=8,
            )
    ax.axhline(1.0, color="0.6", lw=0.8)
    ax.set(xlim=(0.0, 2.0), ylim=(0.8, 1.85))
    ax.legend(loc="upper right", fontsize=8)
    return fig


@register(
    "fig10.train_resonance",
    "Ten articulated coaches of 18 m (eleven two-axle bogies, 170 kN an axle) crossing simply supported "
    "spans with f₁ = 4 Hz and 1 % damping: the largest midspan deflection over the static one against "
    "speed. On the 20 m span the resonances v = f₁d/i (dotted) build up, the first one to about eight "
    "times the static deflection; on the 27 m span, L/d = 1.5, each force leaves the first mode at rest "
    "at v = f₁d, and that resonance cancels.",
    chapter=10,
)
def train_resonance_figure() -> Figure:
    spacing, f1 = 18.0, 4.0
    axles = regular_train(10, spacing, 2.5, 170.0e3)
    speeds = np.geomspace(60.0, 420.0, 300) / 3.6
    fig = new_figure(figsize=(8.0, 4.0))
    ax = fig.subplots()
    for k, span in enumerate((20.0, 1.5 * spacing)):
        beam = _tuned(span, f1, 0.01, 3)
        moving_force_response(beam, speeds, axles, samples=3000).plot(
            ax, color=plots.COLORS[k], label=f"L = {span:g} m (L/d = {span / spacing:.2f})"
        )
    for i, v in enumerate(codes.resonance_speeds(f1, spacing, 4), start=1):
        ax.axvline(3.6 * v, color="0.5", ls=":", lw=1)
        ax.text(3.6 * v, 0.98, f" f₁d/{i}", transform=ax.get_xaxis_transform(), fontsize=8, va="top")
    ax.set_yscale("log")
    ax.set_yticks([1, 2, 5, 10], ["1", "2", "5", "10"])
    ax.set(xlim=(60.0, 420.0), ylabel="largest midspan deflection / static")
    ax.legend(loc="center right", fontsize=8)
    return fig


@register(
    "fig10.load_models",
    "The Manchester car in the vertical plane crossing a 20 m span (f₁ = 3.93 Hz, 1 % damping) at "
    "200 km/h, as moving forces, moving masses (each axle's load riding rigidly), Biggs's sprung masses "
    "(a quarter of the body and half a bogie above each wheelset, 1.0 Hz) and the full car: the midspan "
    "deflection against the leading axle's position (left) and the car body's vertical acceleration "
    "beside EN 1990's level for very good comfort (right). The forces, the sprung masses and the car "
    "agree within a few per cent; the moving masses, which add the car's whole mass rigidly to the "
    "beam's and so lower its frequency towards the bogies' resonance, differ most.",
    chapter=10,
)
def load_models_figure() -> Figure:
    car = VerticalCar()
    full = vehicle(car, 1813.0)
    gaps = np.diff(full.positions)
    quarter = sprung_mass(
        car.body_mass / 4 + car.bogie_mass / 2,
        1.0 / (1.0 / car.primary_stiffness + 2.0 / car.secondary_stiffness),
        car.secondary_damping / 2,
        1813.0,
    )
    models = {
        "moving forces": AxleSequence(full.positions, full.static_loads),
        "moving masses": train([moving_mass(w / GRAVITY) for w in full.static_loads], gaps),
        "sprung masses": train([quarter] * 4, gaps),
        "vertical car": full,
    }
    beam = SimplySupportedBeam(_SPAN, _EI, _MASS, damping_ratio=0.01, modes=3)
    speed = 200.0 / 3.6
    fig = new_figure(figsize=(11.0, 3.8))
    left, right = fig.subplots(1, 2)
    for k, (name, load) in enumerate(models.items()):
        run = crossing(beam, load, speed, free_time=10.0 / speed)
        run.plot(left, static=k == 0, color=plots.COLORS[k], label=f"{name}: {run.amplification:.3f}")
        if run.vehicle is not None:
            run.plot(right, quantity="body acceleration", color=plots.COLORS[k], label=name)
    left.set(ylabel="midspan deflection (mm)")
    left.legend(fontsize=8, title="amplification", title_fontsize=8)
    limit = codes.comfort_acceleration_limit("very good")
    for sign in (1, -1):
        right.axhline(sign * limit, color="0.4", ls="--", lw=1)
    right.text(1.0, limit, " EN 1990 b_v, very good comfort", va="bottom", fontsize=8)
    right.set(ylim=(-1.2, 1.4))
    right.legend(fontsize=8, loc="lower right")
    return fig
