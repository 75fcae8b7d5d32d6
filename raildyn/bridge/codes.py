"""Design-code formulas for railway bridges under moving trains (book chapter 10).

The impact allowances that practice applies to the static load, beside which the dynamic
amplification that :mod:`raildyn.bridge.beam` computes can be read:

* AREMA's impact for steel spans (American Railway Engineering and Maintenance-of-Way
  Association, Manual for Railway Engineering, ch. 15, art. 1.3.5), the rule of the Chu,
  Garg & Dhar (1979) impact studies on which the book's chapter 10 draws;
* EN 1991-2 §6.4.5's dynamic factors Φ₂ and Φ₃, and its Annex C factor for real trains;
* EN 1990 Annex A2's limits on the deck's vertical acceleration and on the passengers'
  comfort;
* the resonance speeds of a regularly spaced train, v = n₀d/i (Yang, Yau & Hsu 1997;
  EN 1991-2 §6.4.6.4), and the spans at which a resonance cancels.

Inputs are SI; a formula written in feet converts inside.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks

__all__ = [
    "arema_impact_factor",
    "cancellation_spans",
    "comfort_acceleration_limit",
    "deck_acceleration_limit",
    "en1991_dynamic_factor",
    "en1991_real_train_factor",
    "resonance_speeds",
]

FOOT = 0.3048  # m, exactly (international foot)

#: EN 1990 A2.4.4.2.1(4)P, recommended values: peak deck acceleration, m/s².
DECK_ACCELERATION_LIMITS = {"ballasted": 3.5, "direct": 5.0}

#: EN 1990 Table A2.9 (A2.4.4.3.2): car-body vertical acceleration b_v by level of comfort, m/s².
COMFORT_ACCELERATION_LIMITS = {"very good": 1.0, "good": 1.3, "acceptable": 2.0}


def _lengths(name, value):
    """A length or an array of lengths of a bridge, m, each in [1, 2000] (``PLAUSIBLE_RANGES["span"]``):
    returned as an array with its shape."""
    arr = _checks.array(name, value)
    if arr.size == 0:
        raise ValueError(f"{name} must not be empty, got an array of shape {arr.shape}")
    return _checks.plausible_array(name, arr, "span")


def _out(arr):
    """A float for a 0-d array, else the array."""
    return float(arr) if arr.ndim == 0 else arr


def arema_impact_factor(span, girder_spacing=None):
    """AREMA's impact on a steel span under rolling stock without hammer blow, as a fraction of the live load.

    The vertical effect, with L the span in feet (AREMA Manual, ch. 15, art. 1.3.5; the rule Chu,
    Garg & Dhar 1979 compare their computed impact with)::

        I_v = 40 − 3L²/1600 percent    for L < 80 ft,
        I_v = 16 + 600/(L − 30) percent for L ≥ 80 ft,

    (the two meet at 28 % at 80 ft), and the rocking effect, a couple of 20 % of the wheel loads
    acting up on one rail and down on the other, 5 ft apart, taken by girders S ft apart::

        I_r = 100/S percent.

    The rocking term is the Manual's rule as a practitioner states it (20 % of the live load times
    5 ft over S: H. Swanson, Eng-Tips thread 115832, "AREMA steel structures load combination"); the
    vertical formulas follow the Manual as Chu, Garg & Dhar (1979) use it — the Manual's own text
    was not at hand to check them against (they meet continuously at 80 ft, as they should).

    Parameters
    ----------
    span : float or array_like
        L, m (each in [1, 2000], :data:`~raildyn.constants.PLAUSIBLE_RANGES` "span"), the span centre to
        centre of bearings.
    girder_spacing : float, optional
        S, m (> 0), between the centres of the girders or stringers; None leaves the rocking
        term out.

    Returns
    -------
    float or ndarray
        I = (I_v + I_r)/100, the impact as a fraction of the static live load (the dynamic factor
        is 1 + I); the shape of ``span``.

    Examples
    --------
    A 20 m (65.6 ft) span with girders 2 m (6.56 ft) apart:

    >>> round(arema_impact_factor(20.0, 2.0), 4)
    0.4717
    """
    L = _lengths("span", span) / FOOT
    vertical = np.where(L < 80.0, 40.0 - 3.0 * L**2 / 1600.0, 16.0 + 600.0 / np.maximum(L - 30.0, 50.0))
    rocking = 0.0
    if girder_spacing is not None:
        S = _checks.plausible("girder_spacing", girder_spacing, "span") / FOOT
        rocking = 100.0 / S
    return _out((vertical + rocking) / 100.0)


def en1991_dynamic_factor(determinant_length, maintenance: str = "careful"):
    """EN 1991-2's dynamic factor Φ for the static load models 71, SW/0 and SW/2 (§6.4.5.2).

    For carefully maintained track (eq. 6.4)::

        Φ₂ = 1.44/(√L_Φ − 0.2) + 0.82,  1.00 ≤ Φ₂ ≤ 1.67,

    and for standard maintenance (eq. 6.5)::

        Φ₃ = 2.16/(√L_Φ − 0.2) + 0.73,  1.00 ≤ Φ₃ ≤ 2.00.

    For a short determinant length the formula passes its upper bound (and further down its pole at
    L_Φ = 0.04 m): the bound is returned there.

    Parameters
    ----------
    determinant_length : float or array_like
        L_Φ, m (each in [1, 2000], :data:`~raildyn.constants.PLAUSIBLE_RANGES` "span"), from EN 1991-2
        Table 6.2 (for a simply supported main girder,
        its span).
    maintenance : {"careful", "standard"}
        The track maintenance: Φ₂ or Φ₃.

    Returns
    -------
    float or ndarray
        Φ, the factor on the static load effects; the shape of ``determinant_length``.

    Examples
    --------
    >>> round(en1991_dynamic_factor(20.0), 4), round(en1991_dynamic_factor(20.0, "standard"), 4)
    (1.1571, 1.2356)
    """
    L = _lengths("determinant_length", determinant_length)
    kind = _checks.choice("maintenance", maintenance, ("careful", "standard"))
    a, b, top = (1.44, 0.82, 1.67) if kind == "careful" else (2.16, 0.73, 2.00)
    root = np.sqrt(L) - 0.2
    reach = a / (top - b)  # √L_Φ − 0.2 below this: the formula exceeds its upper bound
    phi = np.where(root > reach, a / np.maximum(root, reach) + b, top)
    return _out(np.clip(phi, 1.0, top))


def en1991_real_train_factor(speed, determinant_length, frequency_hz, maintenance: str = "careful") -> float:
    """EN 1991-2 Annex C's dynamic factor for a real train: 1 + φ′ + ½φ″ (careful) or 1 + φ′ + φ″.

    With K = v/(2 L_Φ n₀) (eq. C.3)::

        φ′ = K/(1 − K + K⁴) for K < 0.76,  φ′ = 1.325 for K ≥ 0.76    (eq. C.2),
        φ″ = (α/100)[56 e^{−(L_Φ/10)²} + 50 (L_Φ n₀/80 − 1) e^{−(L_Φ/20)²}] ≥ 0  (eq. C.4),

    α = v/22 for v ≤ 22 m/s and 1 above (the track irregularities' share), and the factor is
    1 + φ′ + ½φ″ for carefully maintained track, 1 + φ′ + φ″ for standard maintenance (eq. C.1).
    φ′ is the dynamic response of a perfect track, φ″ that of its irregularities.

    Parameters
    ----------
    speed : float
        v, m/s, in [0, :data:`~raildyn.constants.MAXIMUM_SPEED`] (200 m/s; the annex is written for speeds
        up to 200 km/h, 55.6 m/s, where no
        dynamic analysis is asked for; beyond, φ′ stays at its plateau).
    determinant_length : float
        L_Φ, m, in (0, 1e5].
    frequency_hz : float
        n₀, the first natural bending frequency of the unloaded bridge, Hz (> 0).
    maintenance : {"careful", "standard"}
        The track maintenance.

    Returns
    -------
    float
        1 + φ, the factor on the static load effects of the real train.

    Examples
    --------
    A 20 m span at 4 Hz crossed at 40 m/s (K = 0.25):

    >>> round(en1991_real_train_factor(40.0, 20.0, 4.0), 4)
    1.3367
    """
    v = _checks.speed("speed", speed, low_open=False)
    L = float(_lengths("determinant_length", _checks.scalar("determinant_length", determinant_length)))
    n0 = _checks.positive("frequency_hz", frequency_hz)
    kind = _checks.choice("maintenance", maintenance, ("careful", "standard"))
    K = v / (2.0 * L * n0)
    phi1 = K / (1.0 - K + K**4) if K < 0.76 else 1.325
    alpha = v / 22.0 if v <= 22.0 else 1.0
    phi2 = max(
        alpha
        / 100.0
        * (56.0 * np.exp(-((L / 10.0) ** 2)) + 50.0 * (L * n0 / 80.0 - 1.0) * np.exp(-((L / 20.0) ** 2))),
        0.0,
    )
    return float(1.0 + phi1 + (0.5 if kind == "careful" else 1.0) * phi2)


def deck_acceleration_limit(track: str = "ballasted") -> float:
    """The largest peak vertical deck acceleration EN 1990 allows, m/s² (A2.4.4.2.1(4)P).

    Recommended values: 3.5 m/s² for ballasted track (beyond it the ballast loses its grip) and
    5.0 m/s² for direct-fastened track, each for frequencies up to the larger of 30 Hz, 1.5 times
    the first mode's frequency and the third mode's.

    Parameters
    ----------
    track : {"ballasted", "direct"}
        The track on the deck.

    Returns
    -------
    float
        γ_bt or γ_df, m/s².

    Examples
    --------
    >>> deck_acceleration_limit("ballasted"), deck_acceleration_limit("direct")
    (3.5, 5.0)
    """
    return DECK_ACCELERATION_LIMITS[_checks.choice("track", track, DECK_ACCELERATION_LIMITS)]


def comfort_acceleration_limit(level: str = "very good") -> float:
    """The car body's vertical acceleration for a level of passenger comfort, m/s² (EN 1990 Table A2.9).

    Recommended values of b_v (A2.4.4.3.2): 1.0 m/s² for a very good level of comfort, 1.3 good,
    2.0 acceptable.

    Parameters
    ----------
    level : {"very good", "good", "acceptable"}
        The level of comfort.

    Returns
    -------
    float
        b_v, m/s².

    Examples
    --------
    >>> comfort_acceleration_limit("good")
    1.3
    """
    return COMFORT_ACCELERATION_LIMITS[_checks.choice("level", level, COMFORT_ACCELERATION_LIMITS)]


def resonance_speeds(frequency_hz, spacing, count: int = 3) -> np.ndarray:
    """The speeds at which a train of regularly spaced axles drives a mode at resonance, m/s.

    Each axle passes a point of the bridge every d/v seconds; when i such passes fit one period of
    the mode, every axle adds to the motion the one before it left: v_i = n₀ d / i, i = 1, 2, …
    (Yang, Yau & Hsu 1997; EN 1991-2 §6.4.6.4 writes the same as n₀ times the wavelength d/i).

    Parameters
    ----------
    frequency_hz : float
        n₀, the mode's frequency, Hz (> 0).
    spacing : float
        d, the regular spacing of the axle groups (the coach length), m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length").
    count : int
        How many speeds, i = 1 … count, in [1, 1000].

    Returns
    -------
    ndarray, (count,)
        v_i, m/s, falling.

    Examples
    --------
    A 4 Hz span under an 18 m spacing:

    >>> resonance_speeds(4.0, 18.0)
    array([72., 36., 24.])
    """
    n0 = _checks.positive("frequency_hz", frequency_hz)
    d = _checks.plausible("spacing", spacing, "vehicle_length")
    i = np.arange(1, _checks.integer("count", count, low=1, high=1000) + 1)
    return n0 * d / i


def cancellation_spans(spacing, order: int = 1, count: int = 3) -> np.ndarray:
    """The spans at which the i-th resonance of a regular axle train cancels, m.

    One force crossing an undamped simply supported span at α = v/(2 f₁ L) leaves the first mode
    vibrating with the amplitude (Q/ω²)·2α/(1 − α²)·|cos(π/(2α))|, Q = 2P/(mL): from the mode's
    response under sin(πvt/L) while the force is on (Frýba 1972, ch. 1), evaluated at its exit
    t = L/v. It vanishes at α = 1/(2k + 1), k = 1, 2, … (α = 1 is the resonance of the single
    force, where the limit is finite). At the i-th resonance of a train of spacing d,
    v = f₁ d/i, so α = d/(2 i L), and every axle then leaves nothing behind when::

        L/d = (2k + 1)/(2i),  k = 1, 2, …

    (the cancellation of Yang, Yau & Hsu 1997, derived here as above).

    Parameters
    ----------
    spacing : float
        d, the regular axle spacing, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "vehicle_length").
    order : int
        i, the resonance (1: v = f₁d), in [1, 1000].
    count : int
        How many spans, k = 1 … count, in [1, 1000].

    Returns
    -------
    ndarray, (count,)
        L, m, rising.

    Examples
    --------
    The first resonance of an 18 m spacing cancels on spans of 1.5, 2.5 and 3.5 spacings:

    >>> cancellation_spans(18.0)
    array([27., 45., 63.])
    """
    d = _checks.plausible("spacing", spacing, "vehicle_length")
    i = _checks.integer("order", order, low=1, high=1000)
    k = np.arange(1, _checks.integer("count", count, low=1, high=1000) + 1)
    return d * (2 * k + 1) / (2 * i)
