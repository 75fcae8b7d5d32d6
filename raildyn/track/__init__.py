"""The track: its irregularities (chapter 3) and the geometry of its curves (chapter 8).

* :mod:`raildyn.track.deterministic` — jointed rail with cusp-shaped dipped
  joints (staggered or in phase), an isolated bump, sinusoids; with derivatives.
* :mod:`raildyn.track.spectra` — the FRA classes 1–6 (Hamid & Yang 1981) and the
  German low/high-disturbance spectra, one-sided per rad/m, with their band
  variances in closed form; a spectrum as a callable that names its component
  (:class:`~raildyn.track.spectra.TrackSpectrum`); the speed each FRA class allows.
* :mod:`raildyn.track.synthesis` — seeded samples along distance, a consistent
  two-rail sample, and the spectrum in time at speed V with the delays between axles.
* :mod:`raildyn.track.cant` — the cant of a curve: equilibrium cant, cant deficiency, unbalanced
  acceleration, balance speed, and the limits of curve geometry (the smallest radius, the
  largest cant), each defined once.
* :mod:`raildyn.track.curve` — a curve with clothoid transitions and cant ramps
  (:class:`~raildyn.track.curve.Curve`): curvature, cant, twist and plan along it.

Every spectrum follows the package convention (:mod:`raildyn.random_vibration`):
one-sided, per rad/m in space and per rad/s in time, variance = ∫₀^∞ S dΩ.
"""

from raildyn.track.cant import (
    CANT_GRADIENT_LIMIT,
    MAXIMUM_CANT,
    MINIMUM_RADIUS,
    TWIST_BASE,
    balance_speed,
    cant_deficiency,
    equilibrium_cant,
    speed_for_deficiency,
    unbalanced_acceleration,
)
from raildyn.track.curve import Curve
from raildyn.track.deterministic import (
    RAIL_LENGTH,
    JointedTrack,
    bump,
    dipped_joints,
    harmonic_amplitudes,
    jointed_track,
    passing_frequency,
    passing_speed,
    sinusoid,
)
from raildyn.track.spectra import (
    COMPONENTS,
    FRA_CLASSES,
    FRA_PARAMETERS,
    FRA_SPEED_LIMITS_MPH,
    GERMAN_LEVELS,
    GERMAN_PARAMETERS,
    TrackSpectrum,
    band_variance,
    fra_psd,
    fra_speed_limit,
    german_psd,
    track_psd,
    wavelength_band,
)
from raildyn.track.synthesis import (
    ComponentVariances,
    IrregularitySample,
    TwoRailIrregularity,
    axle_delays,
    axle_filter_wavelengths,
    excitation_csd,
    spatial_to_temporal,
    synthesize_irregularity,
    synthesize_track,
    temporal_psd,
)

__all__ = [
    "RAIL_LENGTH",
    "JointedTrack",
    "bump",
    "dipped_joints",
    "jointed_track",
    "passing_frequency",
    "passing_speed",
    "harmonic_amplitudes",
    "sinusoid",
    "COMPONENTS",
    "FRA_CLASSES",
    "FRA_PARAMETERS",
    "FRA_SPEED_LIMITS_MPH",
    "GERMAN_LEVELS",
    "GERMAN_PARAMETERS",
    "TrackSpectrum",
    "band_variance",
    "fra_psd",
    "fra_speed_limit",
    "german_psd",
    "track_psd",
    "wavelength_band",
    "ComponentVariances",
    "IrregularitySample",
    "TwoRailIrregularity",
    "axle_delays",
    "axle_filter_wavelengths",
    "excitation_csd",
    "spatial_to_temporal",
    "synthesize_irregularity",
    "synthesize_track",
    "temporal_psd",
    "CANT_GRADIENT_LIMIT",
    "MAXIMUM_CANT",
    "MINIMUM_RADIUS",
    "TWIST_BASE",
    "Curve",
    "balance_speed",
    "cant_deficiency",
    "equilibrium_cant",
    "speed_for_deficiency",
    "unbalanced_acceleration",
]
