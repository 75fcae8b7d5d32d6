"""Chapter 4 widgets: the Hertz ellipse, creep laws side by side, the FASTSIM patch, profile geometry,
and the wheel on its rail in section.

Each factory returns ``(container, update)`` (see :mod:`raildyn.widgets`). The
models are in :mod:`raildyn.contact` (steel of :mod:`raildyn.constants`); this
module turns control values (kN, mm, ‰) into SI model calls and moves the artists.
"""

from __future__ import annotations

import functools
import math

import ipywidgets as widgets
import numpy as np

from raildyn import contact, plots
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.widgets._core import Recipe, slider

__all__ = ["creep_laws", "fastsim_patch", "hertz", "profiles", "wheel_on_rail"]


# ---------------------------------------------------------------- Hertz ellipse and pressure


def _hertz_controls():
    return {
        "load_kn": slider("wheel load N (kN)", 100.0, 10.0, 200.0, 5.0, fmt=".0f"),
        "wheel_radius_mm": slider("wheel rolling radius (mm)", 460.0, 300.0, 600.0, 10.0, fmt=".0f"),
        "rail_radius_mm": slider("rail crown radius (mm)", 300.0, 80.0, 600.0, 10.0, fmt=".0f"),
    }


def _hertz_setup(live, status):
    ax_e, ax_p = live.axes[0]
    t = np.linspace(0, 2 * np.pi, 200)
    (ellipse,) = ax_e.plot(np.cos(t), np.sin(t), color=plots.COLORS[0])
    ax_e.set_xlim(-12, 12)
    ax_e.set_ylim(-9, 9)
    ax_e.set_aspect("equal")
    ax_e.set_xlabel("x, rolling direction (mm)")
    ax_e.set_ylabel("y, across the rail (mm)")
    s = np.linspace(-1, 1, 201)
    (p_x,) = ax_p.plot(s, s, color=plots.COLORS[0], label="along x (y = 0)")
    (p_y,) = ax_p.plot(s, s, color=plots.COLORS[1], ls="--", label="along y (x = 0)")
    ax_p.set_xlim(-12, 12)
    ax_p.set_ylim(0, 2000)
    ax_p.set_xlabel("distance from the centre (mm)")
    ax_p.set_ylabel("pressure p (MPa)")
    ax_p.legend(loc="upper right")
    live.animate(ellipse, p_x, p_y)

    def redraw(v):
        c = contact.hertz_contact(
            v["load_kn"] * 1e3, v["wheel_radius_mm"] * 1e-3, math.inf, v["rail_radius_mm"] * 1e-3
        )
        ellipse.set_data(1e3 * c.a * np.cos(t), 1e3 * c.b * np.sin(t))
        p_x.set_data(1e3 * c.a * s, 1e-6 * c.pressure(c.a * s, 0.0))
        p_y.set_data(1e3 * c.b * s, 1e-6 * c.pressure(0.0, c.b * s))
        status.value = (
            f"a_c = {1e3 * c.a:.2f} mm, b_c = {1e3 * c.b:.2f} mm, a_c/b_c = {c.a_over_b:.3f} · θ = "
            f"{math.degrees(c.theta):.1f}°, m = {c.m:.3f}, n = {c.n:.3f} · "
            f"p₀ = {1e-6 * c.peak_pressure:.0f} MPa"
            f" · u_N = {1e6 * c.approach:.1f} µm · k = {1e-9 * c.stiffness:.2f} kN/µm"
        )

    return redraw


HERTZ = Recipe(
    _hertz_controls,
    _hertz_setup,
    {"nrows": 1, "ncols": 2, "figsize": (9.0, 3.4)},
    static={"rail_radius_mm": [80.0, 120.0, 160.0, 200.0, 250.0, 300.0, 400.0, 500.0, 600.0]},
    title="Hertz contact ellipse and pressure of a conical wheel on a rail head",
)


def hertz():
    """Hertz ellipse (left) and the pressure along its axes (right) for a conical tread on a rail.

    Controls: wheel load (kN), wheel rolling radius and rail crown radius (mm).
    The status line gives the semi-axes a_c, b_c, θ, Hertz's m and n, p₀, the approach u_N and the
    linearized normal stiffness.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return HERTZ.build()


# ---------------------------------------------------------------- creep laws side by side


def _creep_controls():
    return {
        "a_over_b": slider("a_c/b_c", 1.0, 0.2, 5.0, 0.05),
        "spin": slider("spin φ (1/m)", 0.0, 0.0, 2.0, 0.05),
        "friction": slider("friction μ", 0.3, 0.1, 0.6, 0.01),
        "load_kn": slider("wheel load N (kN)", 100.0, 20.0, 200.0, 5.0, fmt=".0f"),
    }


def _ellipse(load, a_over_b):
    """Semi-axes a_c, b_c in the ratio a_c/b_c with the area of Hertz's circle for radius-460-mm bodies."""
    c = contact.hertz_contact(load, 0.46, 0.46, math.inf)  # circle: a = b
    size = math.sqrt(c.a * c.b)
    return size * math.sqrt(a_over_b), size / math.sqrt(a_over_b)


def _creep_curves(load, a_over_b, friction, spin, eta):
    a, b = _ellipse(load, a_over_b)
    return contact.lateral_creep_curves(eta, load, friction, a, b, spin=spin)


def _creep_setup(live, status):
    (ax,) = live.axes[0]
    eta = np.linspace(0.0, 0.01, 81)
    lines = _creep_curves(100e3, 1.0, 0.3, 0.0, eta).plot(ax)  # the default controls
    ax.set_xlim(0, 1.0)
    live.animate(*lines.values())

    def redraw(v):
        load, mu = v["load_kn"] * 1e3, v["friction"]
        curves = _creep_curves(load, v["a_over_b"], mu, v["spin"], eta)
        curves.plot(artists=lines)
        a, b, f = curves.a, curves.b, curves.coefficients
        jv = contact.johnson_vermeulen_coefficients(a / b, STEEL_POISSON_RATIO).c22
        status.value = (
            f"a_c = {1e3 * a:.2f} mm, b_c = {1e3 * b:.2f} mm · Kalker's f₂₂ = {f.f22 / 1e6:.2f} MN "
            f"(Johnson–Vermeulen's {STEEL_SHEAR_MODULUS * a * b * jv / 1e6:.2f} MN), "
            f"f₂₃ = {f.f23 / 1e3:.2f} kN m · μN = {mu * load / 1e3:.1f} kN "
            "(Carter and Johnson–Vermeulen take no spin)"
        )

    return redraw


CREEP_LAWS = Recipe(
    _creep_controls,
    _creep_setup,
    {"nrows": 1, "ncols": 1, "figsize": (7.5, 4.2)},
    static={"spin": [0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0], "a_over_b": [0.3, 1.0, 3.0]},
    title="Lateral creep force against lateral creepage for six theories",
)


def creep_laws():
    """Lateral creep force against creepage for Kalker linear, Carter, JV, SHE, Polach and FASTSIM.

    Controls: a_c/b_c, spin φ (1/m), friction μ and wheel load (kN); the ellipse
    area is that of Hertz's circular contact for 460 mm radii in both directions. Forces are
    shown as −F_y/(μN), so the saturation level is 1. The status line gives Kalker's f₂₂ and
    Johnson and Vermeulen's own, which is all that parts their curve from SHE's at zero spin.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return CREEP_LAWS.build()


# ---------------------------------------------------------------- FASTSIM traction over the patch


def _patch_controls():
    return {
        "xi_permille": slider("γ_x (‰)", 1.0, -5.0, 5.0, 0.1, fmt=".1f"),
        "eta_permille": slider("γ_y (‰)", 0.5, -5.0, 5.0, 0.1, fmt=".1f"),
        "spin": slider("spin φ (1/m)", 0.0, -2.0, 2.0, 0.05),
        "friction": slider("friction μ", 0.3, 0.1, 0.6, 0.01),
    }


_PATCH = {"load": 100e3, "a": 6e-3, "b": 4e-3, "n": 16}


def _patch(xi_permille, eta_permille, spin, friction):
    n = _PATCH["n"]
    return contact.fastsim(
        xi_permille * 1e-3, eta_permille * 1e-3, spin, _PATCH["load"], friction, _PATCH["a"], _PATCH["b"],
        n_x=n, n_y=n,
    )  # fmt: skip


def _patch_setup(live, status):
    ax_f, ax_s = live.axes[0]
    n = _PATCH["n"]
    a_mm, b_mm = 1e3 * _PATCH["a"], 1e3 * _PATCH["b"]
    patch = _patch(1.0, 0.5, 0.0, 0.3).plot_patch(ax_f)  # the default controls
    ax_f.set_xlim(-1.15 * a_mm, 1.15 * a_mm)
    ax_f.set_ylim(-1.3 * b_mm, 1.3 * b_mm)
    x_line = np.linspace(-a_mm, a_mm, n)
    (bound_up,) = ax_s.plot(x_line, x_line, color="0.5", lw=1, label="±μp_z")
    (bound_dn,) = ax_s.plot(x_line, x_line, color="0.5", lw=1)
    (trac_x,) = ax_s.plot(x_line, x_line, "o-", ms=3, color=plots.COLORS[0], label="p_x")
    (trac_y,) = ax_s.plot(x_line, x_line, "s-", ms=3, color=plots.COLORS[2], label="p_y")
    ax_s.set_xlim(-a_mm, a_mm)
    ax_s.set_ylim(-800, 800)
    ax_s.set_xlabel("x along the centre strip (mm)")
    ax_s.set_ylabel("traction (MPa)")
    ax_s.legend(loc="lower left", ncol=3)
    live.animate(patch["stick"], patch["slip"], patch["arrows"], bound_up, bound_dn, trac_x, trac_y)

    def redraw(v):
        r = _patch(v["xi_permille"], v["eta_permille"], v["spin"], v["friction"])
        r.plot_patch(artists=patch)
        mid = n // 2
        xs = 1e3 * r.x[mid]
        bound = 1e-6 * v["friction"] * r.pz[mid]
        bound_up.set_data(xs, bound)
        bound_dn.set_data(xs, -bound)
        trac_x.set_data(xs, 1e-6 * r.px[mid])
        trac_y.set_data(xs, 1e-6 * r.py[mid])
        status.value = (
            f"F_x = {r.fx / 1e3:.1f} kN, F_y = {r.fy / 1e3:.1f} kN, M_z = {r.mz:.1f} N m · "
            f"|F|/μN = {r.friction_utilisation:.3f} · adhesion on "
            f"{100 * r.adhesion_fraction:.0f} % of the area"
        )

    return redraw


FASTSIM_PATCH = Recipe(
    _patch_controls,
    _patch_setup,
    {"nrows": 1, "ncols": 2, "figsize": (9.5, 3.6)},
    static={"xi_permille": [-3.0, -1.0, 0.0, 0.3, 0.6, 1.0, 1.5, 2.0, 3.0, 5.0]},
    title="FASTSIM traction over the contact ellipse, with the adhesion and slip zones",
)


def fastsim_patch():
    """Traction over the contact ellipse by FASTSIM with its adhesion (blue) and slip (red) cells.

    N = 100 kN, a_c = 6 mm, b_c = 4 mm. Controls: γ_x and γ_y (‰), spin φ (1/m),
    friction μ. Right: the traction along the centre strip against the
    traction bound ±μp_z; the adhesion zone is where the traction stays inside.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return FASTSIM_PATCH.build()


# ---------------------------------------------------------------- profile geometry

_WHEELS = {
    "cone 1:20": lambda: contact.conical_wheel(1 / 20),
    "cone 1:40": lambda: contact.conical_wheel(1 / 40),
}
_WHEELS["S1002"] = contact.s1002_wheel
_RAILS = {"60E1 at 1:40": 1 / 40, "60E1 at 1:20": 1 / 20}
_SHIFTS = np.linspace(-10e-3, 10e-3, 121)  # 1/6 mm steps: fine for Δr, fast for a slider
_AMPLITUDES = np.linspace(0.5e-3, 10e-3, 39)


@functools.lru_cache(maxsize=16)
def _geometry(wheel_name: str, rail_name: str, gauge_mm: float) -> contact.ContactGeometry:
    wheel = _WHEELS[wheel_name]()
    rail = contact.uic60_rail(_RAILS[rail_name])
    return contact.contact_geometry(wheel, rail, _SHIFTS, gauge=gauge_mm * 1e-3)


def _profile_controls():
    return {
        "wheel": widgets.Dropdown(options=list(_WHEELS), value="S1002", description="wheel"),
        "rail": widgets.Dropdown(options=list(_RAILS), value="60E1 at 1:40", description="rail"),
        "gauge_mm": widgets.Dropdown(
            options=[1432.0, 1435.0, 1437.0, 1440.0], value=1435.0, description="gauge"
        ),
    }


def _profile_setup(live, status):
    ax_r, ax_d, ax_l = live.axes[0]
    start = _geometry("S1002", "60E1 at 1:40", 1435.0)  # the default controls
    dr = start.plot_rolling_radius_difference(ax_r, color=plots.COLORS[0])
    ax_r.set_xlim(-10, 10)
    ax_r.set_ylim(-20, 20)
    ang = start.plot_contact_angle(ax_d, color=plots.COLORS[1])
    ax_d.set_xlim(-10, 10)
    ax_d.set_ylim(0, 75)
    lam = start.plot_equivalent_conicity(_AMPLITUDES, ax_l, color=plots.COLORS[2])
    ax_l.set_xlim(0, 10)
    ax_l.set_ylim(0, 0.6)
    live.animate(*dr.values(), *ang.values(), *lam.values())

    def redraw(v):
        g = _geometry(v["wheel"], v["rail"], float(v["gauge_mm"]))
        g.plot_rolling_radius_difference(artists=dr)
        g.plot_contact_angle(artists=ang)
        g.plot_equivalent_conicity(_AMPLITUDES, artists=lam)
        conicity = lam["equivalent_conicity"].get_ydata()
        i3 = int(np.argmin(np.abs(_AMPLITUDES - 3e-3)))
        harmonic = contact.harmonic_conicity(g.shift, g.rolling_radius_difference, _AMPLITUDES[i3])[0]
        status.value = (
            f"λ_e(3 mm) = {conicity[i3]:.3f} (EN 15302; first harmonic {harmonic:.3f}) · largest contact "
            f"angle {np.degrees(g.contact_angle[0]).max():.1f}°"
        )

    return redraw


PROFILES = Recipe(
    _profile_controls,
    _profile_setup,
    {"nrows": 1, "ncols": 3, "figsize": (10.0, 3.3)},
    static={"wheel": list(_WHEELS), "rail": list(_RAILS)},
    title="Rolling-radius difference, contact angle and equivalent conicity of wheel–rail pairs",
)


def profiles():
    """Δr(y), the left contact angle and the equivalent conicity for a chosen wheel, rail and gauge.

    Controls: the wheel (1:20 and 1:40 cones, S1002), the 60E1 rail's
    inclination and the track gauge (mm). The conicity is EN 15302's; the status line
    gives it at 3 mm beside the first-harmonic value, and the largest contact angle.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return PROFILES.build()


# ---------------------------------------------------------------- the wheel on its rail, in section

# mm: the kernel-free frames, past the S1002 wheel's jump to its flange (6.5 mm on the 1:40 rail) each way
_SECTION_SHIFTS = [float(v) for v in np.arange(-7.0, 7.5, 1.0)]
_SECTION_WINDOW = (-45.0, 45.0)  # mm across each rail head, about its crown


@functools.lru_cache(maxsize=4)
def _section_pair(wheel_name: str, rail_name: str):
    return _WHEELS[wheel_name](), contact.uic60_rail(_RAILS[rail_name])


def _section_controls():
    return {
        "shift_mm": slider("lateral shift y (mm)", 0.0, -10.0, 10.0, 0.25, fmt=".2f"),
        "wheel": widgets.Dropdown(options=list(_WHEELS), value="S1002", description="wheel"),
        "rail": widgets.Dropdown(options=list(_RAILS), value="60E1 at 1:40", description="rail"),
    }


def _section(wheel, rail, g, side: int):
    """The rail head and the wheel above it on one side, in that rail's coordinates (mm): (u, z) of the
    rail, (u, z) of the wheel lowered on to it, the contact point, and the wheel's tread gap.

    The wheel's point u_w lies above the rail's u_w − (u_w* − u_r*) (the contact's own pair of points), at
    r₀ − r(u_w) ∓ φu_w (the wheelset's roll, left/right), lowered until it touches at the contact.
    """
    u_w, u_r = g.wheel_position[side, 0], g.rail_position[side, 0]
    rail_z = rail.height
    wheel_u = wheel.lateral - (u_w - u_r)
    roll = -g.roll[0] if side == 0 else g.roll[0]
    wheel_z = wheel.nominal_radius - wheel.radius + roll * wheel.lateral
    touch = np.interp(u_r, rail.lateral, rail_z)
    wheel_z += touch - np.interp(u_w, wheel.lateral, wheel_z)
    # the gap along the tread (the wheel's side of its flange root), to show the second contact coming
    on_rail = (wheel_u > rail.lateral[0]) & (wheel_u < rail.lateral[-1]) & (wheel.lateral < 0.0)
    gap = wheel_z[on_rail] - np.interp(wheel_u[on_rail], rail.lateral, rail_z)
    return rail.lateral, rail_z, wheel_u, wheel_z, (u_r, touch), float(gap.min()) if gap.size else np.nan


def _section_setup(live, status):
    axes = live.axes[0]
    lines = []
    for k, ax in enumerate(axes):
        ax.set_xlabel("across the rail head (mm), towards the track centre →" if k == 0 else
                      "← towards the track centre, across the rail head (mm)")  # fmt: skip
        ax.set_ylabel("height (mm)")
        ax.set_xlim(*_SECTION_WINDOW) if k == 0 else ax.set_xlim(_SECTION_WINDOW[1], _SECTION_WINDOW[0])
        ax.set_ylim(-25.0, 35.0)
        ax.set_aspect("equal", adjustable="box")
        ax.set_title("left wheel" if k == 0 else "right wheel")
        (rail_line,) = ax.plot([], [], color=plots.COLORS[0], label="rail 60E1")
        (wheel_line,) = ax.plot([], [], color=plots.COLORS[1], label="wheel")
        (point,) = ax.plot([], [], "o", color=plots.COLORS[3], label="contact")
        (normal,) = ax.plot([], [], "-", color=plots.COLORS[3], linewidth=1.0)
        lines.append((rail_line, wheel_line, point, normal))
    axes[0].legend(loc="upper left", fontsize="small")
    live.animate(*(a for group in lines for a in group))

    def redraw(v):
        wheel, rail = _section_pair(v["wheel"], v["rail"])
        y = 1e-3 * float(v["shift_mm"])
        g = contact.contact_geometry(wheel, rail, [y])
        words = []
        for side, (rail_line, wheel_line, point, normal) in enumerate(lines):
            u_rail, z_rail, u_wheel, z_wheel, (u_c, z_c), gap = _section(wheel, rail, g, side)
            rail_line.set_data(1e3 * u_rail, 1e3 * z_rail)
            wheel_line.set_data(1e3 * u_wheel, 1e3 * z_wheel)
            point.set_data([1e3 * u_c], [1e3 * z_c])
            angle = g.contact_angle[side, 0]
            # the contact normal, 12 mm long, leaning towards the track centre by the contact angle
            normal.set_data(1e3 * u_c + np.array([0.0, 12.0 * np.sin(angle)]),
                            1e3 * z_c + np.array([0.0, 12.0 * np.cos(angle)]))  # fmt: skip
            where = "flange" if angle > _FLANGE_ANGLE else "tread"
            words.append(
                f"{'left' if side == 0 else 'right'}: {where}, r = {1e3 * g.rolling_radius[side, 0]:.2f} mm, "
                f"ϑ = {np.degrees(angle):.1f}°"
                + (f", tread {1e3 * gap:.2f} mm clear" if where == "flange" else "")
            )
        status.value = (
            f"y = {1e3 * y:.2f} mm · Δr = {1e3 * g.rolling_radius_difference[0]:.2f} mm · roll "
            f"{1e3 * g.roll[0]:.2f} mrad · " + " · ".join(words)
        )

    return redraw


_FLANGE_ANGLE = math.radians(40.0)  # a contact steeper than this is on the flange (profile_contact's rule)

WHEEL_ON_RAIL = Recipe(
    _section_controls,
    _section_setup,
    {"nrows": 1, "ncols": 2, "figsize": (10.0, 3.8)},
    static={"shift_mm": _SECTION_SHIFTS},
    title="A wheelset's two wheels on their rails in section, the contact points moving as it shifts",
)


def wheel_on_rail():
    """Both wheels on their rails in section, with their contact points, as the wheelset shifts.

    Controls: the lateral shift y (mm), the wheel (1:20 and 1:40 cones, S1002) and the 60E1
    rail's inclination. Each panel draws the rail head and the wheel lowered on to it, with the
    wheelset's roll, the contact point and its normal; on a new S1002 wheel the contact runs
    smoothly over the tread, then jumps to the flange root. The status line gives each contact's
    radius and angle, the tread's clearance once the flange touches, Δr and the roll.

    Returns
    -------
    container : ipywidgets.VBox
        The controls and the figure, to display.
    update : callable
        ``update(**values)`` sets controls, redraws and returns the PNG frame.
    """
    return WHEEL_ON_RAIL.build()
