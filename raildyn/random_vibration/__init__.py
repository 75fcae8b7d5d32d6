"""Random vibration: spectra, response spectra, mean squares and sample functions (chapter 1).

The random part of Garg & Dukkipati's chapter 1: a stationary process described
by its power spectral density (PSD), the response PSD of a linear system, mean
squares by integration over frequency, several correlated inputs through a
cross-spectral matrix (two axles meeting the same track a time d/V apart), and
sample functions synthesized from a PSD for time-domain simulation.

The PSD convention of raildyn
-----------------------------
Every PSD in raildyn is **one-sided, per rad/s** in time (**per rad/m** in
space), so that the variance of a zero-mean process is

    σ² = ∫₀^∞ S(ω) dω.

Sources use other forms; with ω = 2πf (and Ω = 2πn in space, n in cycles/m):

* two-sided, on (−∞, ∞), per rad/s:  S₂(ω) = S(ω)/2, because the even S₂ covers
  each frequency twice (Newland 1993, ch. 5);
* one-sided per Hz:  S_Hz(f) df = S(ω) dω, so S_Hz(f) = 2π S(ω);
* two-sided per Hz:  S_Hz,2(f) = π S(ω).

:func:`convert_psd` converts the density *values* between these forms; the
frequency axis is converted separately by ω = 2πf (Ω = 2πn in space). A spatial
track spectrum S(Ω) per rad/m seen at speed V becomes the temporal spectrum
S(Ω)/V at ω = VΩ (the same change of variables, with dΩ = dω/V).

Cross-spectra
-------------
For inputs x_j(t) the cross-spectral matrix used here is

    S_jk(ω) = 2 · (1/2π) ∫ E[x_j(t+τ) x_k(t)] e^{−iωτ} dτ      (ω ≥ 0),

i.e. S_jk ∝ E[X_j X_k*] in terms of Fourier amplitudes. With it the response
y = H x of a linear system has S_y = H S_x Hᴴ, the usual matrix form. Texts that
define the cross-correlation as E[x_j(t) x_k(t+τ)] (e.g. Newland 1993, ch. 3 and
ch. 7) obtain the complex conjugate (= transpose) of this matrix and write the
response as H* S Hᵀ; the diagonal, and every response PSD, is the same.

Where things are
----------------
Every public name is imported here, ``raildyn.random_vibration.X``; the code is in
:mod:`~raildyn.random_vibration.spectra` (one PSD: conversion, mean square, moments, rates),
:mod:`~raildyn.random_vibration.response` (a linear system's response, delayed inputs) and
:mod:`~raildyn.random_vibration.synthesis` (sample functions from a PSD, the PSD of a record).

References
----------
* D. E. Newland, *An Introduction to Random Vibrations, Spectral and Wavelet
  Analysis*, 3rd ed., Longman, 1993.
* S. H. Crandall and W. D. Mark, *Random Vibration in Mechanical Systems*,
  Academic Press, 1963.
* M. Shinozuka and C.-M. Jan, "Digital simulation of random processes and its
  applications", *J. Sound Vib.* 25(1), 111–128, 1972.
* S. O. Rice, "Mathematical analysis of random noise", *Bell Syst. Tech. J.* 23,
  282–332 (1944) and 24, 46–156 (1945).
* P. D. Welch, "The use of fast Fourier transform for the estimation of power
  spectra", *IEEE Trans. Audio Electroacoust.* 15(2), 70–73, 1967.
"""

from raildyn.random_vibration.response import (
    cancellation_frequencies,
    delayed_input_csd,
    delayed_mean_psd,
    response_psd,
    sdof_white_noise_mean_square,
)
from raildyn.random_vibration.spectra import (
    convert_psd,
    irregularity_factor,
    mean_square,
    peak_rate,
    rms,
    spectral_moments,
    zero_upcrossing_rate,
)
from raildyn.random_vibration.synthesis import SpectralLines, Spectrum, synthesis_lines, synthesize, welch_psd

__all__ = [
    "SpectralLines",
    "Spectrum",
    "cancellation_frequencies",
    "convert_psd",
    "response_psd",
    "delayed_input_csd",
    "delayed_mean_psd",
    "mean_square",
    "rms",
    "spectral_moments",
    "zero_upcrossing_rate",
    "peak_rate",
    "irregularity_factor",
    "sdof_white_noise_mean_square",
    "synthesis_lines",
    "synthesize",
    "welch_psd",
]
