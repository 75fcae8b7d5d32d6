"""Profiles read from two-column files: the round trip of the named profiles, the worn pair, the refusals."""

from __future__ import annotations

import numpy as np
import pytest

from raildyn.contact import (
    WORN_RAIL_FILE,
    WORN_WHEEL_FILE,
    check_pair,
    conical_wheel,
    contact_geometry,
    read_rail_profile,
    read_wheel_profile,
    s1002_wheel,
    uic60_rail,
    worn_rail,
    worn_wheel,
)
from raildyn.wheelset import profile_contact


def _write(path, u_mm, z_mm, *, sep=" ", header="# lateral_mm height_mm\n"):
    with open(path, "w") as f:
        f.write(header)
        for a, b in zip(u_mm, z_mm, strict=True):
            f.write(f"{a:.6f}{sep}{b:.6f}\n")
    return path


def _wheel_file(path, wheel, step_mm=0.5, **kwargs):
    """A wheel profile written as a gauge would measure it: every ``step_mm``, heights from any datum."""
    u = np.arange(wheel.lateral[0], wheel.lateral[-1], step_mm * 1e-3)
    h = (wheel.radius_at(u) - wheel.nominal_radius) * 1e3 + 5.0  # a datum 5 mm off the tape circle
    return _write(path, u * 1e3, h, **kwargs)


@pytest.fixture(scope="module")
def s1002_file(tmp_path_factory):
    return _wheel_file(tmp_path_factory.mktemp("profiles") / "s1002.txt", s1002_wheel())


@pytest.fixture(scope="module")
def rail_file(tmp_path_factory):
    """The upright 60E1 head written every 0.5 mm."""
    upright = uic60_rail(0.0)
    x = np.arange(upright.lateral[0], upright.lateral[-1], 0.5e-3)
    return _write(
        tmp_path_factory.mktemp("profiles") / "60e1.txt",
        x * 1e3,
        np.interp(x, upright.lateral, upright.height) * 1e3,
    )


# ----------------------------------------------------------------------------- the round trip


def test_a_wheel_read_back_from_its_points_is_the_wheel(s1002_file):
    # S1002 sampled every 0.5 mm and joined again by PCHIP, the datum removed. On the tread (slopes
    # under 1:2) the radius returns to within 2 µm: a cubic through 0.5 mm samples of arcs of 12 mm
    # radius or more errs by well under h²/(8R) = 2.6 µm. On the flange, where the height changes
    # 2.75 mm per mm laterally (the 70° flank), the same curve errs up to 25 µm vertically, which is
    # under 9 µm normal to the surface (× cos 70°).
    read = read_wheel_profile(s1002_file)
    named = s1002_wheel()
    assert read.nominal_radius == named.nominal_radius
    assert read.radius_at(0.0) == pytest.approx(0.46, abs=1e-12)
    tread, flange = np.linspace(-55e-3, 30e-3, 1701), np.linspace(30e-3, 50e-3, 401)
    assert np.max(np.abs(read.radius_at(tread) - named.radius_at(tread))) < 2e-6
    assert np.max(np.abs(read.radius_at(flange) - named.radius_at(flange))) < 25e-6
    # and the contact geometry of the pair follows: Δr within 5 µm over the treads
    y = np.linspace(-6e-3, 6e-3, 25)
    rail = uic60_rail(1 / 40)
    dr_read = contact_geometry(read, rail, y).rolling_radius_difference
    dr_named = contact_geometry(named, rail, y).rolling_radius_difference
    assert np.max(np.abs(dr_read - dr_named)) < 5e-6


def test_order_separators_and_comments_do_not_matter(tmp_path, s1002_file):
    lines = [line for line in s1002_file.read_text().splitlines(keepends=True) if not line.startswith("#")]
    text = "# reversed, comma-separated, with comments and blank lines\n\n"
    text += "".join(line.replace(" ", ", ").rstrip() + "  # a point\n" for line in reversed(lines))
    other = tmp_path / "reversed.csv"
    other.write_text(text)
    a, b = read_wheel_profile(s1002_file), read_wheel_profile(other)
    assert np.allclose(a.lateral, b.lateral, atol=1e-12) and np.allclose(a.radius, b.radius, atol=1e-12)


def test_a_rail_read_back_and_tilted_is_the_named_rail(rail_file):
    # The upright head sampled every 0.5 mm, tilted by the reader: over the running surface (to 26 mm
    # each side of the centre, where wheels touch) heights within 2 µm of the named rail (the PCHIP
    # error as above; the 1:20 flanks below, 20 mm of height per mm, are not resolved by 0.5 mm
    # samples), the gauge point within one grid step (0.05 mm).
    for slope in (1 / 40, 1 / 20):
        read, named = read_rail_profile(rail_file, inclination=slope), uic60_rail(slope)
        u = np.linspace(-26e-3, 26e-3, 3001)
        assert (
            np.max(
                np.abs(np.interp(u, read.lateral, read.height) - np.interp(u, named.lateral, named.height))
            )
            < 2e-6
        )
        assert read.gauge_face == pytest.approx(named.gauge_face, abs=0.051e-3)
        assert read.inclination == pytest.approx(named.inclination, rel=1e-12)


def test_a_profile_is_named_after_its_file(s1002_file, rail_file):
    assert read_wheel_profile(s1002_file).name == str(s1002_file)
    assert read_rail_profile(rail_file, name="new 60E1").name == f"new 60E1 ({rail_file})"


# ----------------------------------------------------------------------------- the worn pair


def test_the_worn_files_hold_the_source_points():
    # First and last points of the source (CONTACT test bank, worn_high_mileage.prw and site_b_hr.prr),
    # as the data README states: the wheel's (143.440840, -3.032591) → u = 70 − y; the rail's points
    # 11 and 472 of the source, (−36.898592, 35.832154) and (36.767956, 29.527173) → (−y, −z).
    wheel = np.loadtxt(WORN_WHEEL_FILE)
    rail = np.loadtxt(WORN_RAIL_FILE)
    assert wheel.shape == (638, 2) and rail.shape == (462, 2)
    assert tuple(wheel[0]) == pytest.approx((70.0 - 143.440840, -3.032591), abs=1e-9)
    assert tuple(wheel[-1]) == pytest.approx((70.0 - 3.934136, 26.511718), abs=1e-9)
    assert tuple(rail[0]) == (36.898592, -35.832154) and tuple(rail[-1]) == (-36.767956, -29.527173)


def test_the_worn_wheel_has_a_hollow_tread_and_a_high_flange():
    wheel = worn_wheel()
    h = lambda u: 1e3 * (wheel.radius_at(u) - wheel.nominal_radius)  # noqa: E731
    assert h(0.0) == 0.0
    assert h(-13e-3) < -0.2  # the hollow, 13 mm to the field side
    assert h(-59e-3) - h(-13e-3) > 1.2  # the false flange beyond it
    assert 35.0 < h(wheel.lateral[np.argmax(wheel.radius)]) < 35.5  # the flange tip, source's 35.33 mm


def test_the_worn_pair_runs_through_the_nonlinear_contact():
    wheel, rail = worn_wheel(), worn_rail()
    contact = profile_contact(wheel, rail, gauge=1.4351, tape_distance=1.4874)
    assert contact.flange_clearance == pytest.approx(
        check_pair(wheel, rail, gauge=1.4351, tape_distance=1.4874)
    )
    assert 0.010 < contact.flange_clearance < 0.02  # a worn gauge corner and a worn flange: a wide gap
    assert np.radians(60) < contact.flange_angle < np.radians(80)


@pytest.mark.parametrize("slope", [1 / 40, 1 / 20])
def test_check_pair_finds_the_clearance_profile_contact_finds(slope):
    wheel, rail = s1002_wheel(), uic60_rail(slope)
    assert check_pair(wheel, rail) == profile_contact(wheel, rail).flange_clearance


# ----------------------------------------------------------------------------- refusals name the file


def _lines(path, rows):
    path.write_text("# test profile\n" + "".join(f"{a} {b}\n" for a, b in rows))
    return path


GOOD = [(u, 0.05 * u) for u in np.arange(-20.0, 21.0, 1.0)]


def test_a_point_out_of_order_is_refused_with_its_line(tmp_path):
    rows = list(GOOD)
    rows[10] = (rows[8][0] - 0.5, 0.0)  # the 11th point steps back
    path = _lines(tmp_path / "turns_back.txt", rows)
    with pytest.raises(ValueError, match="strictly monotonic") as err:
        read_wheel_profile(path)
    assert str(path) in str(err.value) and "line 12" in str(err.value)  # the comment is line 1


def test_a_repeated_lateral_position_is_refused(tmp_path):
    rows = list(GOOD)
    rows[5] = (rows[4][0], 1.0)
    path = _lines(tmp_path / "repeated.txt", rows)
    with pytest.raises(ValueError, match="strictly monotonic") as err:
        read_rail_profile(path)
    assert str(path) in str(err.value) and "line 7" in str(err.value)


def test_a_gap_is_refused_with_where_it_is(tmp_path):
    rows = [r for r in GOOD if not 2.0 < r[0] < 5.0]  # 2 → 5 mm: a 3 mm gap
    path = _lines(tmp_path / "gap.txt", rows)
    with pytest.raises(ValueError, match="at most 2 mm apart") as err:
        read_wheel_profile(path)
    message = str(err.value)
    assert str(path) in message and "gap of 3 mm" in message and "lines 24 and 25" in message


def test_too_few_points_are_refused(tmp_path):
    path = _lines(tmp_path / "few.txt", GOOD[:9])
    with pytest.raises(ValueError, match="at least 10 points, got 9") as err:
        read_wheel_profile(path)
    assert str(path) in str(err.value)


@pytest.mark.parametrize("bad", ["1.0 abc", "1.0", "1.0 2.0 3.0", "nan 1.0", "1.0 inf"])
def test_a_line_that_is_not_two_numbers_is_refused(tmp_path, bad):
    path = tmp_path / "words.txt"
    path.write_text("# x z\n1.0 0.0\n" + bad + "\n")
    with pytest.raises(ValueError, match="line 3 must hold two finite numbers") as err:
        read_rail_profile(path)
    assert str(path) in str(err.value)


def test_a_missing_file_or_a_number_for_a_file_is_refused():
    with pytest.raises(ValueError, match="path must name an existing profile file.*no-such-file"):
        read_wheel_profile("no-such-file.txt")
    with pytest.raises(TypeError, match="path must be a file name"):
        read_rail_profile(3.0)


def test_a_wheel_that_misses_its_tape_circle_is_refused(tmp_path):
    path = _lines(tmp_path / "no_tape.txt", [(u + 25.0, 0.0) for u, _ in GOOD])
    with pytest.raises(ValueError, match="both sides of the tape circle") as err:
        read_wheel_profile(path)
    assert str(path) in str(err.value)


def test_a_rail_cut_above_its_gauge_point_is_refused(tmp_path):
    # A crown of radius 300 mm over ±30 mm falls only 1.5 mm: no gauge point 14 mm down.
    x = np.arange(-30.0, 30.5, 0.5)
    path = _write(tmp_path / "shallow.txt", x, -300.0 + np.sqrt(300.0**2 - x**2))
    with pytest.raises(ValueError, match="reach 14 mm below its top on the gauge side") as err:
        read_rail_profile(path)
    assert str(path) in str(err.value)


# ----------------------------------------------------------------------------- a pair that cannot run


@pytest.fixture(scope="module")
def cone_file(tmp_path_factory):
    return _wheel_file(tmp_path_factory.mktemp("profiles") / "cone.txt", conical_wheel(1 / 20, width=0.12))


def test_a_flange_that_never_touches_is_refused_naming_the_file(cone_file):
    wheel, rail = read_wheel_profile(cone_file), uic60_rail(1 / 40)
    with pytest.raises(ValueError, match="let a flange touch its rail within 20 mm") as err:
        profile_contact(wheel, rail)
    assert str(cone_file) in str(err.value)
    with pytest.raises(ValueError, match="let a flange touch its rail within 20 mm") as err:
        check_pair(wheel, rail)
    assert str(cone_file) in str(err.value) and "gauge 1.435 m" in str(err.value)


def test_a_gauge_too_wide_for_the_wheelset_is_refused(s1002_file):
    # 1.5 m gauge, UIC wheelset: each flange stands ~37 mm from its rail, never touching within 20 mm.
    with pytest.raises(ValueError, match="let a flange touch") as err:
        check_pair(read_wheel_profile(s1002_file), uic60_rail(1 / 40), gauge=1.5)
    assert str(s1002_file) in str(err.value) and "gauge 1.5 m" in str(err.value)


@pytest.mark.parametrize(("gauge", "tape"), [(1.40, 1.5), (1.435, 1.56)])
def test_wheels_riding_on_their_flanges_are_refused(s1002_file, gauge, tape):
    # A gauge 35 mm narrow, or tape circles 60 mm too far apart: the centred wheels stand on their flanges.
    with pytest.raises(ValueError, match="centred wheelset on its treads") as err:
        check_pair(read_wheel_profile(s1002_file), uic60_rail(1 / 40), gauge=gauge, tape_distance=tape)
    assert str(s1002_file) in str(err.value) and f"gauge {gauge:g} m" in str(err.value)


def test_wheels_off_the_rails_are_refused_naming_both_files(s1002_file, rail_file):
    # Tape circles 0.3 m further apart than the gauge: the treads hang beyond the rail heads.
    with pytest.raises(ValueError, match="put the wheels on the rails") as err:
        check_pair(read_wheel_profile(s1002_file), read_rail_profile(rail_file), tape_distance=1.8)
    assert (
        str(s1002_file) in str(err.value)
        and str(rail_file) in str(err.value)
        and "gauge 1.435 m" in str(err.value)
    )
