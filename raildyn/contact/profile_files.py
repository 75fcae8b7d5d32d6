"""Measured or worn wheel and rail profiles read from two-column text files, and a check of a pair.

A profile gauge (a MiniProf, a laser profilometer, a template traced on paper) gives a profile
as a list of points, lateral and vertical position in millimetres, one point a line. The readers
here turn such a file into the :class:`~raildyn.contact.geometry.WheelProfile` or
:class:`~raildyn.contact.geometry.RailProfile` that the contact geometry of
:mod:`raildyn.contact.geometry` reads, resampled on the same 0.05 mm grid as the named profiles
of :mod:`raildyn.contact.profiles`, and refuse a file whose points cannot describe a profile
(out of order, a gap, too few, not numbers) with the file's name, the line and the reason.
:func:`check_pair` then says whether a wheel and a rail, so read, make a wheelset that sits on
its rails at a given gauge, and returns the pair's flangeway clearance. One measured worn pair is
shipped in ``raildyn/contact/data`` (:func:`worn_wheel`, :func:`worn_rail`; its source and terms are
in that folder's README.md).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from raildyn import _checks
from raildyn.contact.geometry import RailProfile, WheelProfile, contact_geometry
from raildyn.contact.profiles import _CANT_MAX, _MM, _STEP, _tilted_rail

# Imported where used, to keep this module's import cheap (tests/test_imports.py):
# scipy.interpolate.PchipInterpolator

__all__ = [
    "WORN_RAIL_FILE",
    "WORN_WHEEL_FILE",
    "check_pair",
    "read_rail_profile",
    "read_wheel_profile",
    "worn_rail",
    "worn_wheel",
]

#: mm: the largest lateral step between two points of a profile file; a measuring gauge samples a
#: profile every 0.1 to 1 mm, and a contact patch is ~10 mm wide, so a step of 2 mm is a gap.
MAX_SPACING = 2.0
#: The fewest points a profile file may hold.
MIN_POINTS = 10
_FINE = 0.01  # mm; the smooth curve through a rail's points is sampled this finely before it is tilted


def _path(path) -> Path:
    """``path`` as a Path to an existing file (str or os.PathLike)."""
    if isinstance(path, bool) or not isinstance(path, str | os.PathLike):
        raise TypeError(f"path must be a file name (str or os.PathLike), got {type(path).__name__} {path!r}")
    p = Path(path)
    if not p.is_file():
        raise ValueError(f"path must name an existing profile file, got {str(path)!r} (no such file)")
    return p


def _points(path: Path, lateral: str, vertical: str) -> tuple[np.ndarray, np.ndarray]:
    """The (lateral, vertical) points of a profile file in mm, in increasing lateral order; checked."""
    rows, lines = [], []
    with path.open(encoding="utf-8", errors="replace") as text:
        for number, line in enumerate(text, start=1):
            body = line.split("#", 1)[0].strip()
            if not body:
                continue
            words = body.replace(",", " ").replace(";", " ").split()
            try:
                values = [float(w) for w in words]
            except ValueError:
                values = []
            if len(values) != 2 or not np.isfinite(values).all():
                raise ValueError(
                    f"{path}: line {number} must hold two finite numbers, {lateral} and {vertical} in mm, "
                    f"got {body[:60]!r}"
                )
            rows.append(values)
            lines.append(number)
    if len(rows) < MIN_POINTS:
        raise ValueError(f"{path}: a profile file must hold at least {MIN_POINTS} points, got {len(rows)}")
    x, z = np.array(rows).T
    step = np.diff(x)
    sign = 1.0 if step[0] > 0 else -1.0
    bad = np.flatnonzero(sign * step <= 0)
    if bad.size:
        k = int(bad[0]) + 1
        order = "increasing" if sign > 0 else "decreasing"
        raise ValueError(
            f"{path}: the {lateral} must be strictly monotonic (here {order} from the first line), but line "
            f"{lines[k]} gives {x[k]:g} mm after {x[k - 1]:g} mm at line {lines[k - 1]}"
        )
    gaps = np.flatnonzero(np.abs(step) > MAX_SPACING)
    if gaps.size:
        k = int(gaps[0])
        raise ValueError(
            f"{path}: the points must be at most {MAX_SPACING:g} mm apart laterally, but lines {lines[k]} "
            f"and "
            f"{lines[k + 1]} ({x[k]:g} and {x[k + 1]:g} mm) leave a gap of {abs(step[k]):g} mm"
        )
    return (x, z) if sign > 0 else (x[::-1], z[::-1])


def _name(path: Path, name) -> str:
    """The profile's label: the file's path, after ``name`` if given (so every message names the file)."""
    return str(path) if name is None else f"{name} ({path})"


def read_wheel_profile(path, *, nominal_radius=0.46, name=None) -> WheelProfile:
    """Read a measured or worn wheel profile from a two-column text file.

    **Format.** One point a line: the lateral position and the height of the wheel's surface,
    both in millimetres, as a profile gauge exports them (MiniProf and the like: lateral,
    vertical, mm), separated by spaces, tabs, a comma or a semicolon. Text after ``#`` is a
    comment; blank lines are skipped. The lateral coordinate u is measured from the tape circle
    (the rolling circle where the wheel's diameter is measured, 70 mm from the back of the
    flange on a UIC wheel), positive towards the flange; the height is measured outwards from
    the axle (a larger radius is higher: the flange tip is some 28 to 35 mm above the tread),
    from any datum: the reader takes the radius at u = 0 to be ``nominal_radius``. A gauge that
    measures from the back of the flange gives x = (tape-circle distance) − u. The points
    run in increasing or decreasing u, strictly (a point that turns back is refused), at most
    2 mm apart, at least 10 of them, and they must reach u = 0. They are joined by a
    monotone piecewise-cubic curve (PCHIP: no overshoot between points) and resampled every
    0.05 mm.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    nominal_radius : float, keyword
        r₀, the wheel's radius at the tape circle (m), in [0.1, 1.5]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_radius").
    name : str, optional
        A label; the profile's name is ``"name (path)"``, or the path alone, so that every
        message about the profile names its file.

    Returns
    -------
    WheelProfile

    Raises
    ------
    ValueError
        Naming the file and the line: a line that is not two numbers, lateral coordinates not
        strictly monotonic, a gap over 2 mm, fewer than 10 points, no point on either side of
        the tape circle.

    Examples
    --------
    The worn wheel shipped with raildyn, then the check that it sits on worn rails at the gauge
    of the track it was measured on (:func:`check_pair`, which returns the flangeway clearance):

    >>> wheel = read_wheel_profile(WORN_WHEEL_FILE, nominal_radius=0.444)
    >>> rail = read_rail_profile(WORN_RAIL_FILE, inclination=1 / 40)
    >>> round(1e3 * check_pair(wheel, rail, gauge=1.4351, tape_distance=1.4874), 2)  # mm
    15.0
    """
    from scipy.interpolate import PchipInterpolator

    p = _path(path)
    r0 = _checks.plausible("nominal_radius", nominal_radius, "wheel_radius")
    u, h = _points(p, "lateral positions u", "heights")
    if not u[0] < 0.0 < u[-1]:
        raise ValueError(
            f"{p}: the wheel profile must reach both sides of the tape circle u = 0 (its lateral origin), "
            f"got u from {u[0]:g} to {u[-1]:g} mm"
        )
    curve = PchipInterpolator(u, h)
    step = _STEP / _MM
    grid = (
        np.arange(np.ceil(u[0] / step - 1e-9), np.floor(u[-1] / step + 1e-9) + 1) * step
    )  # u = 0 on the grid
    radius = r0 + (curve(grid) - curve(0.0)) * _MM
    return WheelProfile(_name(p, name), grid * _MM, radius, r0)


def read_rail_profile(path, *, inclination=1 / 40, name=None) -> RailProfile:
    """Read a measured or worn rail head profile from a two-column text file.

    **Format.** One point a line: the lateral position and the height of the rail head, both in
    millimetres, as a profile gauge standing on the rail exports them (lateral, vertical, mm),
    separated by spaces, tabs, a comma or a semicolon; text after ``#`` is a comment, blank
    lines are skipped. The section is in the rail's own axes, upright (the gauge sits on the
    rail, so the rail's inclination in the track is not in the file): the lateral coordinate is
    positive towards the gauge side (the track centre), from any origin (the rail's centre line
    is usual), and the height is upwards, from any datum. The points run in increasing or
    decreasing lateral order, strictly, at most 2 mm apart, at least 10 of them, and the gauge
    side must reach 14 mm below the top, where the gauge is measured. They are joined by a
    monotone piecewise-cubic curve (PCHIP), tilted by ``inclination`` towards the track centre,
    and resampled every 0.05 mm with the crown at height 0; where the tilt turns a face past
    the vertical, the head is kept down to that point.

    Parameters
    ----------
    path : str or os.PathLike
        The file.
    inclination : float, keyword
        The rail's cant in the track as a slope (1/40, 1/20, or 0 for upright rails), in
        [0, 1/10].
    name : str, optional
        A label; the profile's name is ``"name (path)"``, or the path alone.

    Returns
    -------
    RailProfile

    Raises
    ------
    ValueError
        Naming the file and the line: a line that is not two numbers, lateral coordinates not
        strictly monotonic, a gap over 2 mm, fewer than 10 points, a gauge side that does not
        reach 14 mm below the top.

    Examples
    --------
    >>> rail = read_rail_profile(WORN_RAIL_FILE, inclination=1 / 40)
    >>> round(1e3 * float(rail.height.min()), 1) <= -14.0  # reaches the gauge point
    True
    """
    from scipy.interpolate import PchipInterpolator

    p = _path(path)
    cant = float(np.arctan(_checks.scalar("inclination", inclination, low=0.0, high=_CANT_MAX)))
    x, z = _points(p, "lateral positions", "heights")
    fine = np.linspace(x[0], x[-1], int(np.ceil((x[-1] - x[0]) / _FINE)) + 1)
    return _tilted_rail(_name(p, name), fine, PchipInterpolator(x, z)(fine), cant, where=f"{p}: ")


_TREAD_LIMIT = np.radians(40.0)  # a contact steeper than 40° is on the flange (profile_contact takes e here)
_REACH = 0.02  # m; the flange must touch within 20 mm of the centre
_SCAN = 2.5e-4  # m; the step of the scan outwards from the centre (profile_contact's tables take it too)


def check_pair(wheel: WheelProfile, rail: RailProfile, *, gauge=1.435, tape_distance=1.5) -> float:
    """Check that a wheelset of this wheel sits on two rails of this rail at a gauge; its flangeway clearance.

    The wheelset, centred, must stand on both rails (:func:`~raildyn.contact.geometry.contact_geometry`
    finds each contact inside both profiles) and on its treads: a centred contact beyond the
    steepest point of the flange's flank (on the flange tip), or one that passes 40° within
    0.5 mm of the centre, means that the flanges ride on the rail heads (the tape circles too far
    apart, or the gauge too narrow). Shifted sideways in steps of 0.25 mm, one of its contacts must pass 40°,
    the jump to the flange, within 20 mm (a wider gap means that the gauge is too wide for the
    wheelset, or the wheel has no flange): the last shift before that is the flangeway clearance
    e, as :func:`raildyn.wheelset.profile_contact` finds it.

    Parameters
    ----------
    wheel : WheelProfile
        The wheel profile (both sides); e.g. from :func:`read_wheel_profile`.
    rail : RailProfile
        The rail profile (both sides); e.g. from :func:`read_rail_profile`.
    gauge : float, keyword
        Track gauge (m), between the gauge points 14 mm below the rail tops, > 0; 1.435 m is
        standard gauge (56.5 in in North America).
    tape_distance : float, keyword
        Distance between the two tape circles (m), > 0: the wheelset's back-to-back distance
        plus twice the tape circle's distance from the flange back (1.360 + 2 × 0.070 = 1.5 m
        for UIC wheelsets).

    Returns
    -------
    float
        The flangeway clearance e (m), > 0.

    Raises
    ------
    ValueError
        Naming both profiles (so a profile read from a file names its file), the gauge and the
        tape distance, and what is wrong.

    Examples
    --------
    >>> from raildyn.contact.profiles import s1002_wheel, uic60_rail
    >>> round(1e3 * check_pair(s1002_wheel(), uic60_rail(1 / 40)), 2)  # mm
    6.5
    """
    _checks.instance("wheel", wheel, WheelProfile)
    _checks.instance("rail", rail, RailProfile)
    g = _checks.positive("gauge", gauge)
    t = _checks.positive("tape_distance", tape_distance)
    pair = f"the {wheel.name!r} wheel on the {rail.name!r} rail at gauge {g:.6g} m, tape distance {t:.6g} m"
    y = np.arange(0.0, _REACH + _SCAN / 2, _SCAN)
    try:
        sides = [contact_geometry(wheel, rail, s, gauge=g, tape_distance=t) for s in (y, -y)]
    except ValueError as err:
        raise ValueError(f"gauge and tape_distance must put the wheels on the rails: {pair}: {err}") from None
    steep = (sides[0].contact_angle[0] > _TREAD_LIMIT) | (sides[1].contact_angle[1] > _TREAD_LIMIT)
    slope = np.gradient(wheel.radius, wheel.lateral)
    flank = int(np.argmax(slope))  # the steepest point of the flange's flank; beyond it lies the flange tip
    on_tip = slope[flank] > np.tan(_TREAD_LIMIT) and sides[0].wheel_position[0, 0] > wheel.lateral[flank]
    if on_tip or steep[:3].any():  # within 0.5 mm of the centre: no room on the treads (as profile_contact)
        raise ValueError(
            f"gauge and tape_distance must set the centred wheelset on its treads: {pair} touches at "
            f"u = {1e3 * sides[0].wheel_position[0, 0]:.1f} mm on the wheel, at "
            f"{np.degrees(sides[0].contact_angle[0, 0]):.1f}°, "
            + ("beyond the flange's flank" if on_tip else "and passes 40° within 0.5 mm of the centre")
            + " (the flanges ride on the rail heads)"
        )
    if not steep.any():
        raise ValueError(
            f"gauge and tape_distance must let a flange touch its rail within {1e3 * _REACH:g} mm of the "
            "centre: "
            f"{pair} reaches no contact steeper than 40° (the gauge too wide, or a wheel with no flange)"
        )
    return float(y[int(np.argmax(steep)) - 1])


# ---------------------------------------------------------------- the measured worn pair shipped

_DATA = Path(__file__).resolve().parent / "data"
# The two paths are where raildyn is installed: the API page states what they are, not the build's path.
#: The worn wheel's file (format of :func:`~raildyn.contact.profile_files.read_wheel_profile`), in
#: raildyn's ``contact/data`` folder.
#:
#: :meta hide-value:
WORN_WHEEL_FILE = _DATA / "worn_wheel_na_heavy_haul.txt"
#: The worn rail's file (format of :func:`~raildyn.contact.profile_files.read_rail_profile`), in
#: raildyn's ``contact/data`` folder.
#:
#: :meta hide-value:
WORN_RAIL_FILE = _DATA / "worn_rail_na_heavy_haul.txt"


def worn_wheel(nominal_radius=0.444) -> WheelProfile:
    """A worn wheel: high mileage, hollow tread, measured on a North American heavy-haul railway.

    Read from :data:`WORN_WHEEL_FILE` (source: the CONTACT program's test bank, courtesy of
    K. Oldknow, Apache License 2.0; see ``raildyn/contact/data/README.md``). Its tread is worn
    hollow (the hollow's bottom 13 mm from the tape circle towards the field side, a false flange
    rising 1.3 mm above it 46 mm further out) and its flange tip stands 35 mm above the tape
    circle. The tape circle is taken 70 mm from the back of the flange; the source's own case puts
    the flange backs 1347.4 mm apart at a gauge of 1435.1 mm, so the pair runs with
    ``gauge=1.4351`` and ``tape_distance=1.4874`` (1.3474 + 2 × 0.070 m), e.g. on :func:`worn_rail`.

    Parameters
    ----------
    nominal_radius : float
        r₀, the radius at the tape circle (m), in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "wheel_radius"); 0.444 m, the source's case (a 36 in freight wheel, worn).

    Returns
    -------
    WheelProfile
        Named after its file.

    Examples
    --------
    >>> w = worn_wheel()
    >>> round(float(1e3 * (w.radius.max() - w.nominal_radius)), 1)  # flange tip above the tape circle, mm
    35.4
    """
    return read_wheel_profile(WORN_WHEEL_FILE, nominal_radius=nominal_radius, name="worn wheel")


def worn_rail(inclination=1 / 40) -> RailProfile:
    """A worn rail head: the high rail of a curve on a North American heavy-haul railway, measured.

    Read from :data:`WORN_RAIL_FILE` (the same source and terms as :func:`worn_wheel`). Its gauge
    corner is worn to a near-vertical face and its crown lies about 16 mm towards the field side.

    Parameters
    ----------
    inclination : float
        The cant as a slope, in [0, 1/10]; 1/40, the cant of North American track.

    Returns
    -------
    RailProfile
        Named after its file.

    Examples
    --------
    >>> round(1e3 * check_pair(worn_wheel(), worn_rail(), gauge=1.4351, tape_distance=1.4874), 2)  # mm
    15.0
    """
    return read_rail_profile(WORN_RAIL_FILE, inclination=inclination, name="worn rail")
