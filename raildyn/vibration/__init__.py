"""Linear vibration of single- and multi-degree-of-freedom systems (book chapter 1).

The deterministic half of chapter 1 of Garg & Dukkipati (1984), as functions a
notebook can call:

* the single-degree-of-freedom oscillator ``m x'' + c x' + k x = F(t)`` (eq. 1.3):
  its free response in every damping regime, characteristic roots and their
  locus (Fig. 1.4), logarithmic decrement (eq. 1.17), harmonic and base-excited
  response, and the exact response to a sampled force;
* several degrees of freedom: the undamped eigenproblem with mass-normalised
  modes, modal superposition, Rayleigh (proportional) damping, complex modes of
  the first-order form when damping is not proportional, state-space matrices
  and the frequency-response matrix.

Linear-system tools that python-control already has (transfer functions, Bode
plots, pole-zero maps) are reached through ``to_control`` rather than written
again. SI units throughout: m, kg, s, N, rad/s.
"""

from raildyn import _deprecated
from raildyn.vibration.mdof import (
    ChainMatrices,
    ComplexModes,
    ModalResult,
    RayleighCoefficients,
    StateSpaceMatrices,
    chain_matrices,
    complex_modes,
    first_order_matrix,
    frf_matrix,
    modal_analysis,
    modal_damping_ratios,
    modal_superposition,
    rayleigh_coefficients,
    rayleigh_damping,
    state_space_matrices,
    to_control,
    uniform_chain_frequencies,
)
from raildyn.vibration.sdof import (
    SDOF,
    DecayPeaks,
    FreeVibration,
    RootLocus,
    damping_ratio_from_decrement,
    decrement_from_peaks,
    log_decrement,
    magnification_factor,
    phase_angle,
    root_locus,
    transmissibility_ratio,
)

__all__ = [
    "SDOF",
    "ChainMatrices",
    "ComplexModes",
    "DecayPeaks",
    "FreeVibration",
    "ModalResult",
    "RayleighCoefficients",
    "RootLocus",
    "StateSpaceMatrices",
    "chain_matrices",
    "complex_modes",
    "damping_ratio_from_decrement",
    "decrement_from_peaks",
    "first_order_matrix",
    "frf_matrix",
    "log_decrement",
    "magnification_factor",
    "modal_analysis",
    "modal_damping_ratios",
    "modal_superposition",
    "phase_angle",
    "rayleigh_coefficients",
    "rayleigh_damping",
    "root_locus",
    "state_space_matrices",
    "to_control",
    "transmissibility_ratio",
    "uniform_chain_frequencies",
]

# The old names of issue 33 (raildyn._deprecated.RENAMED): each warns and gives the new object;
# they go after one issue.
__getattr__ = _deprecated.module_getattr(__name__, globals())
