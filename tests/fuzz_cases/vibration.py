"""Fuzz registry: chapter 1 (vibration, random vibration), the shared plot helpers and the failure policy.

Sizes are the smallest that mean something: a two-mass chain, 11 times, 3 frequencies, records of
64 samples, so the whole part runs in a few seconds.
"""

from __future__ import annotations

import numpy as np
from fuzzing import call, fuzz, on

from raildyn import vibration as vib

M2 = np.diag([2.0, 1.0])
K2 = np.array([[300.0, -100.0], [-100.0, 100.0]])
C2 = 0.01 * K2
B2 = np.array([[1.0], [0.0]])
T = np.linspace(0.0, 1.0, 11)
F2 = np.vstack([np.sin(T), np.zeros(T.size)])
OMEGA = np.array([1.0, 5.0, 20.0])
W5 = np.array([0.0, 1.0, 2.0, 4.0, 8.0])
S5 = np.array([0.5, 1.0, 1.0, 0.5, 0.25])
RECORD = np.sin(0.7 * np.arange(64)) + 0.1 * np.cos(2.3 * np.arange(64))

#: Changes valid for a result dataclass: its fields hold whatever the model computes.
RESULT = "zero negative mm big"


def sdof():
    return vib.SDOF(1.0, 0.4, 100.0)


def flat(w):
    """A flat one-sided PSD, 0.01 per rad/s, evaluated on the array ``w``."""
    return np.full(np.shape(w), 0.01)


def axes():
    import matplotlib.pyplot as plt

    return plt.subplots()[1]


def free_vibration():
    return sdof().free_vibration(T, 0.01, 0.0)


def modes():
    return vib.modal_analysis(M2, K2)


def cmodes():
    return vib.complex_modes(M2, C2, K2)


def locus():
    return vib.root_locus(10.0, [0.0, 0.5, 1.0, 2.0])


ENTRIES = [
    # ------------------------------------------------------------------ SDOF
    fuzz(
        "raildyn.vibration.SDOF",
        lambda: call(1.0, 0.4, 100.0),
        accepts={"mass": "big mm", "stiffness": "big tiny mm", "damping": "zero big mm"},
    ),
    fuzz(
        "raildyn.vibration.SDOF.from_modal",
        lambda: call(10.0, 0.05, mass=2.0),
        accepts={"natural_frequency": "big mm", "mass": "big tiny mm", "damping_ratio": "zero big mm"},
    ),
    fuzz("raildyn.vibration.SDOF.roots", lambda: on(sdof())),
    fuzz(
        "raildyn.vibration.SDOF.free_response",
        lambda: on(sdof(), T, 0.01, 0.0),
        accepts={"x0": "zero negative big mm", "v0": "zero negative big", "t": "zero shape"},
    ),
    fuzz(
        "raildyn.vibration.SDOF.free_velocity",
        lambda: on(sdof(), T, 0.01, 0.1),
        accepts={"x0": "zero negative big mm", "v0": "zero negative big mm", "t": "zero shape"},
    ),
    fuzz("raildyn.vibration.SDOF.impulse_response", lambda: on(sdof(), T), accepts={"t": "zero shape"}),
    fuzz(
        "raildyn.vibration.SDOF.envelope",
        lambda: on(sdof(), T, 0.01, 0.1),
        accepts={"x0": "zero negative big mm", "v0": "zero negative big mm", "t": "zero shape"},
    ),
    fuzz(
        "raildyn.vibration.SDOF.decay_peaks",
        lambda: on(sdof(), 0.01, 0.1, count=3),
        accepts={"x0": "zero negative big mm", "v0": "zero negative big mm"},
    ),
    fuzz(
        "raildyn.vibration.SDOF.free_vibration",
        lambda: on(sdof(), T, 0.01, 0.1, peaks=2),
        accepts={"x0": "zero negative big mm", "v0": "zero negative big mm"},
    ),
    fuzz("raildyn.vibration.SDOF.receptance", lambda: on(sdof(), OMEGA), accepts={"omega": "zero shape"}),
    fuzz("raildyn.vibration.SDOF.base_frf", lambda: on(sdof(), OMEGA), accepts={"omega": "zero shape"}),
    fuzz(
        "raildyn.vibration.SDOF.transmissibility", lambda: on(sdof(), OMEGA), accepts={"omega": "zero shape"}
    ),
    fuzz(
        "raildyn.vibration.SDOF.forced_response",
        lambda: on(sdof(), T, np.sin(T), 0.01, 0.1),
        accepts={"force": "zero negative", "x0": "zero negative big mm", "v0": "zero negative big mm"},
    ),
    fuzz(
        "raildyn.vibration.SDOF.duhamel_response",
        lambda: on(sdof(), T, np.sin(T)),
        accepts={"force": "zero negative"},
    ),
    fuzz("raildyn.vibration.SDOF.state_space_matrices", lambda: on(sdof())),
    fuzz("raildyn.vibration.SDOF.to_control", lambda: on(sdof())),
    # ------------------------------------------------------------------ SDOF results and curves
    fuzz(
        "raildyn.vibration.DecayPeaks",
        lambda: call(np.array([0.0, 0.6]), np.array([0.01, 0.008])),
        accepts={"times": "zero", "values": RESULT},  # a result: it holds what decay_peaks computes
    ),
    fuzz(
        "raildyn.vibration.FreeVibration",
        lambda: call(T, np.cos(T), np.ones(T.size), vib.DecayPeaks(np.array([0.0]), np.array([1.0]))),
        accepts={"displacement": RESULT, "envelope": "zero"},  # a result: what free_vibration computes
    ),
    fuzz(
        "raildyn.vibration.FreeVibration.plot", lambda: on(free_vibration(), axes()), accepts={"ax": "none"}
    ),
    fuzz(
        "raildyn.vibration.RootLocus",
        lambda: call(10.0, np.array([0.0, 1.0]), [[10j, -10j], [-10.0, -10.0]]),
        accepts={
            "natural_frequency": "big tiny mm",
            "damping_ratios": "zero",
            "roots": RESULT,
        },  # a result: what root_locus computes
    ),
    fuzz(
        "raildyn.vibration.RootLocus.plot",
        lambda: on(locus(), axes(), normalised=True),
        accepts={"ax": "none"},
    ),
    fuzz(
        "raildyn.vibration.root_locus",
        lambda: call(10.0, np.array([0.0, 0.5, 1.0, 2.0])),
        accepts={"natural_frequency": "big mm", "damping_ratios": "zero"},
    ),
    fuzz(
        "raildyn.vibration.log_decrement",
        lambda: call(np.array([0.05, 0.3])),
        accepts={"damping_ratio": "zero shape"},
    ),
    fuzz(
        "raildyn.vibration.damping_ratio_from_decrement",
        lambda: call(np.array([0.3, 1.0])),
        accepts={"delta": "zero shape"},
    ),
    fuzz(
        "raildyn.vibration.decrement_from_peaks",
        lambda: call(12.0, 3.0, cycles=5),
        accepts={"first": "big tiny mm", "later": "big tiny mm"},
    ),
    fuzz(
        "raildyn.vibration.magnification_factor",
        lambda: call(np.array([0.0, 0.5, 2.0]), 0.25),
        accepts={"frequency_ratio": "zero shape", "damping_ratio": "zero big mm"},
    ),
    fuzz(
        "raildyn.vibration.phase_angle",
        lambda: call(np.array([0.0, 0.5, 2.0]), 0.25),
        accepts={"frequency_ratio": "zero shape", "damping_ratio": "zero big mm"},
    ),
    fuzz(
        "raildyn.vibration.transmissibility_ratio",
        lambda: call(np.array([0.0, 0.5, 2.0]), 0.25),
        accepts={"frequency_ratio": "zero shape", "damping_ratio": "zero big mm"},
    ),
    # ------------------------------------------------------------------ several degrees of freedom
    fuzz(
        "raildyn.vibration.ModalResult",
        lambda: call(np.array([7.0, 14.0]), np.array([[0.5, 0.5], [0.7, -0.7]])),
        accepts={
            "natural_frequencies": "zero",
            "mode_shapes": RESULT,
        },  # a result: what modal_analysis computes
    ),
    fuzz(
        "raildyn.vibration.ModalResult.modal_matrix",
        lambda: on(modes(), K2),
        accepts={"matrix": "zero negative"},
    ),
    fuzz(
        "raildyn.vibration.ComplexModes",
        lambda: call(
            *(np.real(getattr(cmodes(), f)) for f in ("eigenvalues", "mode_shapes")),
            np.array([1.0, 1.0, 2.0, 2.0]),
            np.array([0.1, 0.1, 0.2, 0.2]),
        ),  # fmt: skip
        # a result: what complex_modes computes (a negative damping ratio is an unstable mode)
        accepts={
            "eigenvalues": RESULT + " complex",  # complex: the eigenvalues' and shapes' own domain
            "mode_shapes": RESULT + " complex",
            "natural_frequencies": "zero",
            "damping_ratios": RESULT,
        },
    ),
    fuzz(
        "raildyn.vibration.ComplexModes.relative_phase",
        lambda: on(cmodes(), 1, 0),
        accepts={"coordinate": "zero", "reference": "zero"},
    ),
    fuzz("raildyn.vibration.ChainMatrices", lambda: call(M2, C2, K2), accepts={"*": RESULT}),  # a result
    fuzz(
        "raildyn.vibration.RayleighCoefficients",
        lambda: call(0.075, 0.025),
        accepts={"alpha": "big mm", "beta": "big mm", "*": RESULT},
    ),  # a result
    fuzz(
        "raildyn.vibration.RayleighCoefficients.damping_ratio",
        lambda: on(vib.RayleighCoefficients(0.075, 0.025), OMEGA),
        accepts={"omega": "shape"},
    ),
    fuzz(
        "raildyn.vibration.RayleighCoefficients.damping_matrix",
        lambda: on(vib.RayleighCoefficients(0.075, 0.025), M2, K2),
        accepts={"K": "zero"},
    ),
    fuzz(
        "raildyn.vibration.StateSpaceMatrices",
        lambda: call(
            np.array([[0.0, 1.0], [-100.0, -0.4]]),
            np.array([[0.0], [1.0]]),
            np.array([[1.0, 0.0]]),
            np.array([[0.0]]),
        ),  # fmt: skip
        accepts={"*": RESULT},  # a result: what state_space_matrices computes
    ),
    fuzz("raildyn.vibration.StateSpaceMatrices.to_control", lambda: on(sdof().state_space_matrices())),
    fuzz(
        "raildyn.vibration.chain_matrices",
        lambda: call([2.0, 1.0], [200.0, 100.0], dampings=[2.0, 1.0], grounded=True),
        accepts={"dampings": "zero none"},
    ),
    fuzz(
        "raildyn.vibration.uniform_chain_frequencies",
        lambda: call(3, 1.0, 100.0),
        accepts={"mass": "big tiny mm", "stiffness": "big tiny mm"},
    ),
    fuzz(
        "raildyn.vibration.rayleigh_coefficients",
        lambda: call(1.0, 3.0, 0.05, 0.02),
        accepts={
            "omega1": "big tiny mm",
            "omega2": "big tiny mm",
            "xi1": "zero big mm",
            "xi2": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.vibration.rayleigh_damping",
        lambda: call(M2, K2, 0.5, 0.01),
        accepts={"K": "zero", "alpha": "zero negative big mm", "beta": "zero negative big mm"},
    ),
    fuzz("raildyn.vibration.modal_analysis", lambda: call(M2, K2), accepts={"K": "zero"}),
    fuzz("raildyn.vibration.modal_damping_ratios", lambda: call(M2, C2, K2), accepts={"C": "zero"}),
    fuzz(
        "raildyn.vibration.modal_superposition",
        lambda: call(M2, K2, T, x0=[0.01, 0.0], v0=[0.0, 0.1], force=F2, damping_ratios=[0.02, 0.05]),
        accepts={
            "K": "zero",
            "x0": "zero negative none",
            "v0": "zero negative none",
            "force": "zero negative none",
            "damping_ratios": "zero none",
        },
    ),
    fuzz(
        "raildyn.vibration.first_order_matrix",
        lambda: call(M2, C2, K2),
        # a stack of matrices (one per speed) is documented; C and K may be any real matrices
        accepts={"M": "shape", "C": "shape zero negative", "K": "shape zero negative"},
    ),
    fuzz(
        "raildyn.vibration.complex_modes",
        lambda: call(M2, C2, K2),
        accepts={"C": "zero negative", "K": "zero negative"},
    ),
    fuzz(
        "raildyn.vibration.state_space_matrices",
        lambda: call(M2, C2, K2, B2, output="velocity"),
        accepts={"C": "zero negative", "K": "zero negative", "B": "zero negative"},
    ),
    fuzz(
        "raildyn.vibration.to_control",
        lambda: call(M2, C2, K2, B2, output="acceleration"),
        accepts={"C": "zero negative", "K": "zero negative", "B": "zero negative"},
    ),
    fuzz(
        "raildyn.vibration.frf_matrix",
        lambda: call(M2, C2, K2, OMEGA),
        accepts={"C": "zero negative", "K": "zero negative", "omega": "zero"},
    ),
    # ------------------------------------------------------------------ random vibration
    fuzz("raildyn.random_vibration.Spectrum", lambda: call(W5, S5), accepts={"psd": "zero shape"}),
    fuzz(
        "raildyn.random_vibration.SpectralLines",
        lambda: call(np.array([1.0, 2.0, 3.0]), np.array([0.01, 0.01, 0.02]), 1.0),
        accepts={"d_omega": "big tiny mm", "psd": "zero"},
    ),
    fuzz(
        "raildyn.random_vibration.cancellation_frequencies",
        lambda: call(0.1, 3),
        accepts={"delay": "big tiny mm"},
    ),
    fuzz(
        "raildyn.random_vibration.convert_psd",
        lambda: call(S5, from_sided="two", from_unit="Hz", to_sided="one", to_unit="rad/s"),
        accepts={"values": "zero shape"},
    ),
    fuzz(
        "raildyn.random_vibration.response_psd",
        lambda: call(np.array([1.0, 0.5, -0.2, 0.1, 0.0]), S5),
        accepts={"frf": "zero negative complex", "input_psd": "zero complex"},
    ),
    fuzz(
        "raildyn.random_vibration.delayed_input_csd",
        lambda: call(S5, W5, [0.0, 0.1]),
        accepts={"psd": "zero", "omega": "zero", "delays": "zero negative"},
    ),
    fuzz(
        "raildyn.random_vibration.delayed_mean_psd",
        lambda: call(S5, W5, [0.0, 0.1]),
        accepts={"psd": "zero", "omega": "zero", "delays": "zero negative"},
    ),
    fuzz("raildyn.random_vibration.mean_square", lambda: call(S5, W5), accepts={"psd": "zero"}),
    fuzz("raildyn.random_vibration.rms", lambda: call(S5, W5), accepts={"psd": "zero"}),
    fuzz(
        "raildyn.random_vibration.spectral_moments",
        lambda: call(S5, W5, orders=(0, 2, 4)),
        accepts={"psd": "zero", "orders": "zero"},
    ),
    fuzz("raildyn.random_vibration.zero_upcrossing_rate", lambda: call(S5, W5)),
    fuzz("raildyn.random_vibration.peak_rate", lambda: call(S5, W5)),
    fuzz("raildyn.random_vibration.irregularity_factor", lambda: call(S5, W5)),
    fuzz(
        "raildyn.random_vibration.sdof_white_noise_mean_square",
        lambda: call(1.0, 2.0, 4.0, 5.0, sided="two"),
        accepts={
            "mass": "big tiny mm",
            "damping": "big tiny mm",
            "stiffness": "big tiny mm",
            "psd_level": "zero big mm",
        },
    ),
    fuzz(
        "raildyn.random_vibration.synthesis_lines",
        lambda: call(flat, 0.01, 64, band=(10.0, 200.0)),
        accepts={"band": "none"},
    ),
    fuzz(
        "raildyn.random_vibration.synthesize",
        lambda: call(flat, 0.01, 64, 1, n_samples=2, band=(10.0, 200.0)),
        accepts={"rng": "zero none", "band": "none"},
    ),
    fuzz(
        "raildyn.random_vibration.welch_psd",
        lambda: call(RECORD, 0.01, nperseg=32),
        accepts={"dt": "big tiny mm", "x": "zero negative shape", "nperseg": "none"},
    ),
    # ------------------------------------------------------------------ plot helpers
    fuzz("raildyn.plots.axes_or_new", lambda: call(axes()), accepts={"ax": "none"}),
    fuzz(
        "raildyn.plots.time_history",
        lambda: call(T, np.cos(T), ax=axes(), envelope=np.exp(-T)),
        accepts={"x": "zero negative", "envelope": "zero none", "ax": "none"},
    ),
    fuzz(
        "raildyn.plots.frequency_curves",
        lambda: call(np.array([0.5, 1.0, 2.0]), {"a": np.array([1.0, 2.0, 0.5])}, ax=axes(), logy=True),
        accepts={"ax": "none"},
    ),
    fuzz(
        "raildyn.plots.movable_line",
        lambda: call(axes(), None, "curve", np.array([1.0, 2.0, 3.0]), np.array([1.0, 0.5, 2.0]), log=True),
        # any text names the line and labels the axes; y of any sign
        accepts={
            "ax": "none",
            "y": "zero negative",
            "label": "none",
            "color": "none",
            "key": "unknown",
            "xlabel": "empty unknown",
            "ylabel": "empty unknown",
        },
    ),
    fuzz(
        "raildyn.plots.spectrum",
        lambda: call(OMEGA, np.array([1.0, 0.1, 0.01]), ax=axes()),
        accepts={"psd": "zero", "ax": "none"},
    ),
    # ------------------------------------------------------------------ the plausible ranges
    fuzz(
        "raildyn.constants.PlausibleRange",
        lambda: call("a wheel's rolling radius", 0.1, 1.5, "m", "from the smallest wheels to the largest"),
        # any text describes a quantity; a range may start at 0 or below (a signed quantity), and a
        # wider one (×1000, 1e9 or 1e300 at the top) is still a range
        accepts={
            "what": "unknown",
            "unit": "unknown",
            "reason": "unknown",
            "low": "zero negative",
            "high": "mm big huge",
        },  # fmt: skip
    ),
    # ------------------------------------------------------------------ the failure policy
    fuzz(
        "raildyn.errors.SolverError",
        lambda: call("the state became non-finite", step=12, time=0.06),
        accepts={"step": "zero none", "time": "zero negative none big mm", "reason": "unknown"},
        skip={"partial": "holds whatever the failed run computed (NaN included): any object is valid"},
    ),
]
