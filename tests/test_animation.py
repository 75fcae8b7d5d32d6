"""The animations of raildyn.animations: each built from its model's own run, its frames moving, its page
light and offline, and bad input refused.

Each animation is built once here, with few frames, and shared by the checks (a run costs a second or
two); the sizes at the defaults' frame counts are measured in ``test_the_defaults_stay_within_the_budget``.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from raildyn import animations
from raildyn.bridge import SimplySupportedBeam
from raildyn.stability import simulate
from raildyn.train import braking_model
from raildyn.vehicles import Bogie, RockingFreightCar
from raildyn.wheelset import NonlinearWheelset, WheelRailContact, Wheelset

FEW = 6  # frames: enough to see the motion change, cheap to draw
BUILDS = {
    "hunting_wheelset": lambda: animations.hunting_wheelset(frames=FEW, duration=1.5, window=0.4),
    "hunting_bogie": lambda: animations.hunting_bogie(frames=FEW, duration=1.5, window=0.4),
    "bogie_curve_entry": lambda: animations.bogie_curve_entry(frames=FEW),
    "rocking_car": lambda: animations.rocking_car(frames=FEW, cycles=6),
    "train_run_in": lambda: animations.train_run_in(braking_model(20, 1), 20.0, frames=FEW),
    "bridge_crossing": lambda: animations.bridge_crossing(frames=FEW),
}
# Bytes of HTML per frame, base64 included: a frame of 410 × 230 px at 32 colours is 4–9 kB of PNG, so 36
# frames of the heaviest (the hunting plans, with their traces) make 400 kB. The first frame is there twice
# (in the picture, for a page read without JavaScript, and in the script).
PER_FRAME = 12_000


@pytest.fixture(scope="module", params=sorted(BUILDS))
def built(request):
    return request.param, BUILDS[request.param]()


def test_every_frame_differs_from_the_one_before(built):
    name, movie = built
    assert len(movie.frames) == FEW
    assert all(a != b for a, b in zip(movie.frames, movie.frames[1:], strict=False)), name
    assert len(set(movie.labels)) == FEW, f"{name}: the frames' labels repeat: {movie.labels}"


def test_the_player_is_offline_and_light(built):
    name, movie = built
    page = movie.html()
    assert not re.search(r"https?://", page), f"{name}: the player names a web address"
    assert page.count("data:image/png;base64,") == 2  # the first frame in the <img>, the rest in the script
    assert 'data-action="play"' in page and 'data-control="frame"' in page and "data-label" in page
    assert movie.size == len(page.encode()) <= PER_FRAME * (FEW + 1), f"{name}: {movie.size} bytes"


def test_the_defaults_stay_within_the_budget():
    # The chapter's own animation at its default frame count: 36 frames of the hunting wheelset.
    movie = animations.hunting_wheelset()
    assert len(movie.frames) == 36
    assert movie.size <= 400_000, f"{movie.size} bytes"


def test_the_hunting_wheelset_is_drawn_from_its_own_run():
    # The frames are the run's samples: the animation's last label is the run's last time, and the run
    # (the same call to simulate) has settled on a cycle of a few millimetres, which the plan draws.
    ws = Wheelset(yaw_stiffness=2.0e6, lateral_stiffness=1.0e6)
    run = simulate(NonlinearWheelset(ws, WheelRailContact()), 60.0, [0.008, 0.0, 0.0, 0.0], 1.5)
    movie = animations.hunting_wheelset(ws, 60.0, duration=1.5, window=0.4, frames=FEW)
    assert movie.labels[-1].startswith(f"t = {run.t[-1]:.3f} s")
    assert 0.002 < np.abs(run.states[0, run.t > 1.1]).max() < 0.02


def test_save_writes_a_page_that_holds_the_player(tmp_path):
    movie = BUILDS["bridge_crossing"]()
    page = movie.save(tmp_path / "crossing.html").read_text(encoding="utf-8")
    assert page.startswith("<!DOCTYPE html>") and '<div class="raildyn-animation"' in page
    assert page.count("data:image/png;base64,") == 2


@pytest.mark.parametrize(
    ("call", "error", "word"),
    [
        (lambda: animations.hunting_wheelset(Bogie()), TypeError, "ws"),
        (lambda: animations.hunting_wheelset(frames=1), ValueError, "frames"),
        (lambda: animations.hunting_wheelset(duration=1.0, window=2.0), ValueError, "window"),
        (lambda: animations.hunting_wheelset(initial_displacement=0.0), ValueError, "initial_displacement"),
        (lambda: animations.hunting_bogie(Wheelset()), TypeError, "bogie"),
        (lambda: animations.bogie_curve_entry(curve=600.0), TypeError, "curve"),
        (lambda: animations.rocking_car(RockingFreightCar(), -3.0), ValueError, "speed"),
        (lambda: animations.train_run_in(duration=0.0), ValueError, "duration"),
        (lambda: animations.bridge_crossing(SimplySupportedBeam(), load="car"), TypeError, "load"),
        (lambda: animations.Animation([b"x", b"y"], ["a", "b"], title="t"), ValueError, "frames"),
        (lambda: animations.Animation([b"\x89PNG\r\n\x1a\n"] * 2, ["a"], title="t"), ValueError, "labels"),
        (lambda: animations.record(None, print, ["a", "b"], title="t"), TypeError, "figure"),
    ],
)
def test_bad_input_is_refused_naming_the_parameter(call, error, word):
    with pytest.raises(error, match=rf"\b{word}\b"):
        call()
