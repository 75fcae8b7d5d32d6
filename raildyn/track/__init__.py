"""Track irregularities (chapter 3): deterministic inputs, random spectra, samples and the view in time.

* :mod:`raildyn.track.deterministic` — jointed rail with cusp-shaped dipped
  joints (staggered or in phase), an isolated bump, sinusoids; with derivatives.
* :mod:`raildyn.track.spectra` — the FRA classes 1–6 (Hamid & Yang 1981) and the
  German low/high-disturbance spectra, one-sided per rad/m, with their band
  variances in closed form; a spectrum as a callable that names its component
  (:class:`~raildyn.track.spectra.TrackSpectrum`); the speed each FRA class allows.
* :mod:`raildyn.track.synthesis` — seeded samples along distance, a consistent
  two-rail sample, and the spectrum in time at speed V with the delays between axles.

Every spectrum follows the package convention (:mod:`raildyn.random_vibration`):
one-sided, per rad/m in space and per rad/s in time, variance = ∫₀^∞ S dΩ.
"""

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
]
