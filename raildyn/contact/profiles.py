"""The wheel and rail profiles of chapter 4: the conical wheel, S1002 and 60E1.

Each is a :class:`~raildyn.contact.geometry.WheelProfile` or
:class:`~raildyn.contact.geometry.RailProfile`, in the coordinates set out in
:mod:`raildyn.contact.geometry`, where the contact geometry of a profile pair is computed.

Sources: S1002 wheel, EN 13715 (the piecewise polynomial definition as
distributed by H. Netter, DLR); 60E1 (UIC60) rail head, EN 13674-1 (arcs R300
to x = ±10.228 mm, R80 to ±26.027 mm, R13, then a 1:20 flank). A measured worn wheel and rail are
read from files by :mod:`raildyn.contact.profile_files` (:func:`~raildyn.contact.profile_files.worn_wheel`).
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.contact.geometry import (  # noqa: F401  (all but the private ones and the profiles: see below)
    _CANT_MAX,
    _RADIUS_MAX,
    ContactGeometry,
    RailProfile,
    WheelProfile,
    _grid,
    contact_angles,
    contact_geometry,
    equivalent_conicity,
    rolling_radius_difference,
)

# WheelProfile, RailProfile and the contact geometry moved to raildyn.contact.geometry (issue 33); the
# ones this module does not use are imported only so that the old paths (raildyn.contact.profiles.X)
# keep working for one issue, then they go.

__all__ = [
    "conical_wheel",
    "s1002_wheel",
    "uic60_rail",
]


_MM = 1e-3
_STEP = 0.05e-3  # m; sampling of the profiles and of the contact search, refined by a parabola
_WIDTH = (1e-3, 0.5)  # m; a tread is ~0.14 m wide; 0.5 m bounds the cone's grid at 10,000 samples


def conical_wheel(slope, nominal_radius=0.46, *, width=0.13) -> WheelProfile:
    """A conical tread r(u) = r₀ + λu with no flange (book ch. 4, the coned wheel).

    Parameters
    ----------
    slope : float
        Conicity λ (e.g. 1/20 or 1/40), ≥ 0, with λ·width/2 < r₀ so that every radius is positive.
    nominal_radius : float
        r₀ (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
    width : float, keyword
        Lateral extent of the tread, centred on the tape circle (m), from 1 mm to 0.5 m (a
        tread is about 0.14 m wide).

    Returns
    -------
    WheelProfile
        Named "cone 1:N" (or "cylinder").

    Examples
    --------
    >>> conical_wheel(1 / 40).name
    'cone 1:40'
    """
    lam = _checks.nonnegative("slope", slope)
    r0 = _checks.plausible("nominal_radius", nominal_radius, "wheel_radius")
    w = _checks.scalar("width", width, low=_WIDTH[0], high=_WIDTH[1])
    if lam * w / 2 >= r0:
        raise ValueError(
            "slope * width / 2 must be < nominal_radius so that every radius is positive, got "
            f"slope = {slope!r}, width = {width!r} m and nominal_radius = {nominal_radius!r} m"
        )
    u = np.arange(-w / 2, w / 2 + _STEP / 2, _STEP)
    return WheelProfile(f"cone 1:{1 / lam:.0f}" if lam > 0 else "cylinder", u, r0 + lam * u, r0)


def _s1002_height_mm(s: np.ndarray) -> np.ndarray:
    """S1002 profile height F(s) (mm) above the tape circle, s (mm) positive towards the field side.

    Piecewise definition of EN 13715 (sections A–H), coefficients as distributed
    by H. Netter (DLR); valid for −70 ≤ s ≤ 60.
    """
    # fmt: off
    sec_b = [0.0, -3.358537058e-02, 1.565681624e-03, -2.810427944e-05, 5.844240864e-08,
             -1.562379023e-08, 5.309217349e-15, -5.957839843e-12, 2.646656573e-13]
    sec_c = [-4.320221063e+03, -1.038384026e+03, -1.065501873e+02, -6.051367875,
             -2.054332446e-01, -4.169739389e-03, -4.687195829e-05, -2.252755540e-07]
    # fmt: on
    with np.errstate(invalid="ignore"):
        f_a = 1.364323640 - 0.066666667 * s
        f_b = np.polynomial.polynomial.polyval(s, sec_b)
        f_c = np.polynomial.polynomial.polyval(s, sec_c)
        f_d = 16.446 - np.sqrt(13.0**2 - (s + 26.210665) ** 2)
        f_e = -93.576667419 - 2.747477419 * s
        f_f = 8.834924130 + np.sqrt(20.0**2 - (s + 58.558326413) ** 2)
        f_g = 16.0 + np.sqrt(12.0**2 - (s + 55.0) ** 2)
        f_h = 9.519259302 + np.sqrt(20.5**2 - (s + 49.5) ** 2)
    bounds = [-62.764705882, -49.662510381, -39.764473993, -38.426669071, -35.0, -26.0, 32.15796]
    return np.select(
        [s < bound for bound in bounds],
        [f_h, f_g, f_f, f_e, f_d, f_c, f_b],
        default=f_a,
    )


def s1002_wheel(nominal_radius=0.46) -> WheelProfile:
    """The S1002 wheel profile of EN 13715 (a worn-shape profile), u from −60 to 68 mm.

    The flange tip lies about 28 mm above the tape circle at u ≈ 55 mm; the
    back of the flange is 70 mm from the tape circle.

    Parameters
    ----------
    nominal_radius : float
        r₀, the radius at the tape circle (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "wheel_radius").

    Returns
    -------
    WheelProfile

    Examples
    --------
    >>> w = s1002_wheel()
    >>> round(float(1e3 * (w.radius.max() - w.nominal_radius)), 1)  # flange height, mm
    28.0
    """
    # The tread falls 2.6 mm below the tape circle at its field-side end: 10 mm keeps every radius > 0.
    r0 = _checks.plausible("nominal_radius", nominal_radius, "wheel_radius")
    u = np.arange(-60.0 * _MM, 68.0 * _MM + _STEP / 2, _STEP)
    return WheelProfile("S1002", u, r0 + _s1002_height_mm(-u / _MM) * _MM, r0)


def _uic60_head_mm(x: np.ndarray) -> np.ndarray:
    """Untilted 60E1 head height (mm, crown at 0) at |x| (mm) from the centre line."""
    x = np.abs(x)
    x1, x2 = 20.456 / 2, 52.053 / 2  # ends of the R300 and R80 arcs, EN 13674-1 (60E1)
    a1 = np.arcsin(x1 / 300.0)
    c2 = np.array([220.0 * np.sin(a1), -300.0 + 220.0 * np.cos(a1)])  # R80 centre, tangent to R300
    a2 = np.arcsin((x2 - c2[0]) / 80.0)
    p2 = c2 + 80.0 * np.array([np.sin(a2), np.cos(a2)])
    c3 = p2 - 13.0 * np.array([np.sin(a2), np.cos(a2)])  # R13 centre, tangent to R80
    a3 = np.arctan(20.0)  # the R13 arc ends where the flank's 1:20 line begins
    p3 = c3 + 13.0 * np.array([np.sin(a3), np.cos(a3)])
    with np.errstate(invalid="ignore"):
        z1 = -300.0 + np.sqrt(300.0**2 - x**2)
        z2 = c2[1] + np.sqrt(80.0**2 - (x - c2[0]) ** 2)
        z3 = c3[1] + np.sqrt(13.0**2 - (x - c3[0]) ** 2)
        z4 = p3[1] - 20.0 * (x - p3[0])
    return np.select([x <= x1, x <= x2, x <= p3[0]], [z1, z2, z3], default=z4)


def uic60_rail(inclination=1 / 40) -> RailProfile:
    """The 60E1 (UIC60) rail head, tilted towards the track centre.

    Parameters
    ----------
    inclination : float
        The cant as a slope (e.g. 1/40 or 1/20), in [0, 1/10]; 0 leaves the rail upright. Rails
        in track are canted 1:20 to 1:40, or not at all.

    Returns
    -------
    RailProfile

    Examples
    --------
    >>> uic60_rail(1 / 20).name
    '60E1 1:20'
    """
    cant = np.arctan(_checks.scalar("inclination", inclination, low=0.0, high=_CANT_MAX))
    x = np.linspace(-36.5, 36.5, 7301)  # mm, the head and its 1:20 flanks
    z = _uic60_head_mm(x)
    keep = z > -25.0  # the running surface and the upper flanks
    name = "60E1" + (f" 1:{1 / np.tan(cant):.0f}" if cant > 0 else " upright")
    return _tilted_rail(name, x[keep], z[keep], float(cant))


_GAUGE_DEPTH = 14.0  # mm; the gauge point lies 14 mm below the top of the rail (EN 13848-1)


def _tilted_rail(name: str, x: np.ndarray, z: np.ndarray, cant: float, *, where: str = "") -> RailProfile:
    """A :class:`RailProfile` from a densely sampled upright head section, tilted by ``cant``.

    ``x`` (mm, increasing, positive towards the gauge side) and ``z`` (mm, upwards) describe the
    head in the rail's own axes. The section is turned so that the gauge side goes down, resampled
    on the profiles' grid with the crown at height 0, and its gauge point found 14 mm below the top.
    Where the turn folds the section back on itself (a face steeper than the cant), only the part
    joined to the top is kept. ``where`` (e.g. a file name) starts the message if the tilted head
    does not reach 14 mm below its top on the gauge side.
    """
    u_t = x * np.cos(cant) + z * np.sin(cant)
    z_t = -x * np.sin(cant) + z * np.cos(cant)
    top = int(np.argmax(z_t))
    rising = np.diff(u_t) > 0
    first = top - int(np.argmin(rising[:top][::-1])) if top and not rising[:top].all() else 0
    last = top + int(np.argmin(rising[top:])) if not rising[top:].all() else u_t.size - 1
    u_t, z_t = u_t[first : last + 1], z_t[first : last + 1]
    u = np.arange(u_t.min(), u_t.max(), _STEP / _MM)
    z_u = np.interp(u, u_t, z_t) - z_t.max()
    gauge_side = u > u[np.argmax(z_u)]
    if not gauge_side.any() or z_u[gauge_side].min() > -_GAUGE_DEPTH:
        raise ValueError(
            f"{where}the rail head must reach {_GAUGE_DEPTH:g} mm below its top on the gauge side (where the "
            f"gauge is measured), got {-z_u[gauge_side].min() if gauge_side.any() else 0.0:.4g} mm"
        )
    face = u[gauge_side][np.argmin(np.abs(z_u[gauge_side] + _GAUGE_DEPTH))]  # gauge point 14 mm below the top
    return RailProfile(name, u * _MM, z_u * _MM, float(cant), float(face * _MM))
