"""Fuzz registry: the bridges beyond the simple span, the design codes and the design trains (chapter 10)."""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn.bridge.continuous import ContinuousBeam
from raildyn.bridge.sleepers import DiscreteTrack
from raildyn.bridge.track import LayeredTrack
from raildyn.bridge.winkler import WinklerBeam

CONTINUOUS = ContinuousBeam((20.0, 25.0), 1.0e10, 1.0e4, modes=4)
RAIL = WinklerBeam(6.4e6, 60.34, 5.0e7, 2.0e4)
SHORT = dict(bays=8, quiet_bays=2)  # a small discrete track: cheap fuzz runs


def _matrices():
    m = DiscreteTrack(**SHORT).matrices
    return m.mass, m.damping, m.stiffness, m.deflection, m.sleepers, m.sleeper_nodes


ENTRIES = [
    fuzz(
        "raildyn.bridge.continuous.ContinuousBeam",
        lambda: call((20.0, 25.0), 1.0e10, 1.0e4, 0.02, 4),
        accepts={"flexural_rigidity": "big mm", "damping_ratio": "zero"},
    ),
    fuzz(
        "raildyn.bridge.continuous.ContinuousBeam.mode_shapes",
        lambda: on(CONTINUOUS, [0.0, 5.0, 50.0], derivative=1),
        accepts={"x": "zero negative", "derivative": "zero"},  # off the beam: 0; derivative 0: φ
    ),
    fuzz(
        "raildyn.bridge.continuous.ContinuousBeam.static_deflection",
        lambda: on(CONTINUOUS, 10.0, [0.0, 5.0, 30.0], 1.0e5),
        accepts={
            "force_position": "zero",  # on the end support: no deflection
            "at": "zero negative",  # on a support or off the beam: 0
            "force": "zero negative big mm",
        },
    ),
    # ------------------------------------------------------------------ Winkler
    fuzz(
        "raildyn.bridge.winkler.WinklerBeam",
        lambda: call(6.4e6, 60.34, 5.0e7, 2.0e4),
        accepts={
            "flexural_rigidity": "big mm",
            "mass_per_length": "mm",
            "foundation_modulus": "big tiny mm",
            "damping": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.bridge.winkler.WinklerBeam.static_deflection",
        lambda: on(RAIL, [0.0, 1.0, 2.0], 1.0e5),
        accepts={"x": "zero negative", "force": "zero negative big mm"},  # any position; a force either way
    ),
    fuzz(
        "raildyn.bridge.winkler.WinklerBeam.steady_deflection",
        lambda: on(RAIL, [-1.0, 0.0, 1.0], 150.0, 1.0e5),
        accepts={
            "x": "zero negative",
            "speed": "zero",
            "force": "zero negative big mm",
        },  # at rest: Hetényi's
    ),
    fuzz(
        "raildyn.bridge.winkler.WinklerBeam.receptance",
        lambda: on(RAIL, [0.0, 100.0, 1000.0]),
        accepts={"frequencies": "zero mm big"},  # at rest, or any frequency of the damped beam
    ),
    # ------------------------------------------------------------------ the track as a structure
    fuzz(
        "raildyn.bridge.track.beam_receptance",
        lambda: call(6.4e6, np.array([5.0e7, -2.0e7 + 1.0e6j])),
        # any finite support stiffness: above the cut-off s < 0; a list of numbers is an array
        accepts={"flexural_rigidity": "big mm", "dynamic_stiffness": "negative mm big list tiny"},
    ),
    fuzz(
        "raildyn.bridge.track.LayeredTrack",
        lambda: call(),
        accepts={
            "rail_flexural_rigidity": "big mm",
            "rail_mass": "mm",
            "pad_stiffness": "big tiny mm",
            "pad_loss_factor": "zero mm",
            "sleeper_mass": "big tiny mm",
            "ballast_stiffness": "big tiny mm",
            "ballast_loss_factor": "zero mm",
        },
    ),
    fuzz(
        "raildyn.bridge.track.LayeredTrack.receptance",
        lambda: on(LayeredTrack(), [0.0, 100.0, 1000.0]),
        accepts={"frequencies": "zero mm big list"},
    ),
    fuzz("raildyn.bridge.track.LayeredTrack.resonances", lambda: on(LayeredTrack())),
    fuzz(
        "raildyn.bridge.track.TrackResonances",
        lambda: call(48.6, 198.7, 457.4),
        accepts={"*": "big mm tiny", "antiresonance": "inf big mm tiny", "rail_on_pads": "inf big mm tiny"},
        infinite=("antiresonance", "rail_on_pads"),  # a single peak: no dip and no second peak, +inf
    ),
    fuzz(
        "raildyn.bridge.track.LayeredTrack.plot_receptance",
        lambda: on(LayeredTrack(), [10.0, 100.0, 1000.0]),
        accepts={"frequencies": "mm big list", "label": "none", "color": "none"},
    ),
    fuzz(
        "raildyn.bridge.track.LayeredTrack.support_stiffness",
        lambda: on(LayeredTrack(), [0.0, 100.0, 1000.0]),
        accepts={"frequencies": "zero mm big list"},
    ),
    fuzz(
        "raildyn.bridge.sleepers.DiscreteTrack",
        lambda: call(**SHORT),
        accepts={
            "rail_flexural_rigidity": "big mm",
            "rail_mass": "mm",
            "rail_shear_stiffness": "big tiny mm",
            "rail_rotary_inertia": "zero big tiny mm",
            "pad_stiffness": "big",  # 1e9 N/m: a stiff pad, in range
            "pad_damping": "zero big tiny mm",
            "sleeper_mass": "big tiny mm",
            "ballast_stiffness": "big tiny mm",
            "ballast_damping": "zero big tiny mm",
            "quiet_bays": "zero",  # no quiet layers: free ends
            "quiet_rate": "zero big tiny mm",
        },
    ),
    fuzz(
        "raildyn.bridge.sleepers.DiscreteTrack.receptance",
        lambda: on(DiscreteTrack(**SHORT), [0.0, 100.0, 1000.0], position=1.0),
        accepts={
            "frequencies": "zero mm big list",
            "position": "zero tiny none",
        },  # 0: the end; None: the middle
    ),
    fuzz(
        "raildyn.bridge.sleepers.DiscreteTrack.point",
        lambda: on(DiscreteTrack(**SHORT), 1.0),
        accepts={"position": "zero tiny"},
    ),
    fuzz("raildyn.bridge.sleepers.DiscreteTrack.resonances", lambda: on(DiscreteTrack(**SHORT))),
    fuzz(
        "raildyn.bridge.sleepers.DiscreteTrack.plot_receptance",
        lambda: on(DiscreteTrack(**SHORT), [10.0, 100.0, 1000.0], position=1.0),
        accepts={
            "frequencies": "mm big list",
            "position": "zero tiny none",
            "label": "none",
            "color": "none",
        },
    ),
    fuzz(
        "raildyn.bridge.sleepers.DiscreteResonances",
        lambda: call(33.1, 440.0, 1314.2),
        accepts={"*": "big mm tiny", "rail_on_pads": "inf big mm tiny"},
        infinite=("rail_on_pads",),  # no second peak below the pinned–pinned one: +inf
    ),
    fuzz(
        "raildyn.bridge.sleepers.TrackMatrices",
        lambda: call(*_matrices()),
        accepts={
            "mass": "big tiny huge mm",  # any positive diagonal
            "damping": "zero big tiny huge mm",
            "stiffness": "big tiny huge mm",
        },
    ),
    fuzz(
        "raildyn.bridge.sleepers.TrackMatrices.dense",
        lambda: on(DiscreteTrack(**SHORT).matrices, "stiffness"),
    ),
    # ------------------------------------------------------------------ codes
    fuzz(
        "raildyn.bridge.codes.arema_impact_factor",
        lambda: call(20.0, 2.0),
        accepts={"span": "list", "girder_spacing": "none mm"},  # spans as an array; None: no rocking term
    ),
    fuzz(
        "raildyn.bridge.codes.en1991_dynamic_factor",
        lambda: call(20.0, "careful"),
        accepts={"determinant_length": "list"},  # an array of lengths
    ),
    fuzz(
        "raildyn.bridge.codes.en1991_real_train_factor",
        lambda: call(40.0, 20.0, 4.0, "careful"),
        accepts={"frequency_hz": "big tiny mm", "speed": "zero"},  # at rest: 1
    ),
    fuzz("raildyn.bridge.codes.deck_acceleration_limit", lambda: call("ballasted")),
    fuzz("raildyn.bridge.codes.comfort_acceleration_limit", lambda: call("good")),
    fuzz(
        "raildyn.bridge.codes.resonance_speeds",
        lambda: call(4.0, 18.0, 3),
        accepts={"frequency_hz": "big tiny mm"},
    ),
    fuzz("raildyn.bridge.codes.cancellation_spans", lambda: call(18.0, 1, 3)),
    # ------------------------------------------------------------------ trains
    fuzz("raildyn.bridge.trains.hslm", lambda: call(3)),
    fuzz(
        "raildyn.bridge.trains.regular_train",
        lambda: call(5, 20.0, 2.5, 1.5e5, bogie_centres=15.0),
        accepts={"bogie_centres": "none"},  # None: articulated coaches
    ),
]
