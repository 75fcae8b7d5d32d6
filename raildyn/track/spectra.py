"""Random track irregularity spectra: the US FRA six classes and the German low/high-disturbance spectra.

Every function here returns a spectrum in the raildyn convention: **one-sided,
per rad/m**, so that the variance of the irregularity is σ² = ∫₀^∞ S(Ω) dΩ with
the spatial circular frequency (wavenumber) Ω = 2π/λ in rad/m. Irregularities
are in metres, spectra in m²/(rad/m).

FRA classes 1–6 (Hamid & Yang 1981)
-----------------------------------
With k = 0.25, the class parameters A_v, A_a (cm²·rad/m), the corner Ω_c and
Ω_s (rad/m):

* vertical profile   S_v(Ω) = k A_v Ω_c² / [Ω² (Ω² + Ω_c²)]
* alignment          S_a(Ω) = k A_a Ω_c² / [Ω² (Ω² + Ω_c²)]
* cross-level        S_c(Ω) = 4 k A_v Ω_c² / [(Ω² + Ω_c²)(Ω² + Ω_s²)]
* gauge              S_g(Ω) = 4 k A_v Ω_c² / [(Ω² + Ω_c²)(Ω² + Ω_s²)]

in cm²/(rad/m). This is the form and table in which Garg & Dukkipati (1984,
ch. 3) and most later texts (e.g. Zhai 2020, ch. 2) quote the FRA spectra of
Hamid & Yang (1981); TTB-2D (Cantero 2022, ``A04_Options.m``, citing Berawi
2013) codes the same k, A_v and Ω_c. Where sources differ:

* **units** — the table is in cm² (A in cm²·rad/m); raildyn converts to m²
  (× 10⁻⁴). Tables in in²/(cycle/ft) with wavenumbers in cycles/ft also
  circulate; they are not used here.
* **one- or two-sided** — the cm²/(rad/m) table is used, as its sources use it,
  as a one-sided density over Ω ≥ 0 (TTB-2D halves it to build a two-sided
  spectrum before its inverse FFT, which confirms its one-sided reading). The
  values are passed through :func:`raildyn.random_vibration.convert_psd` from
  that declared form, so a source in another form is one argument away.
* **the factor k** — texts call k a "safety factor" between 0.25 and 1; the
  tabulated A values are meant with k = 0.25, which raildyn uses by default
  (keyword ``k`` to change it).

German spectra (ORE B176 / DB)
------------------------------
With Ω_c, Ω_r, Ω_s in rad/m and A_v, A_a, A_g in m·rad (= m²·rad/m):

* vertical profile   S_v(Ω) = A_v Ω_c² / [(Ω² + Ω_r²)(Ω² + Ω_c²)]
* alignment          S_a(Ω) = A_a Ω_c² / [(Ω² + Ω_r²)(Ω² + Ω_c²)]
* cross-level        S_c(Ω) = (A_v/a²) Ω_c² Ω² / [(Ω² + Ω_r²)(Ω² + Ω_c²)(Ω² + Ω_s²)]
* gauge              S_g(Ω) = A_g Ω_c² Ω² / [(Ω² + Ω_r²)(Ω² + Ω_c²)(Ω² + Ω_s²)]

in m²/(rad/m) for S_v, S_a, S_g and rad²/(rad/m) for the cross-level *angle*
S_c, a being half the distance between the rails' contact points (0.75 m; field ``b``).
raildyn returns the cross-level as the height difference between the rails,
2a × the angle, so its spectrum is (2a)² S_c = 4 A_v Ω_c² Ω²/[…] and a drops
out. The gauge spectrum is already a length (no a). The low/high-disturbance
values are those quoted by Zhai (2020, ch. 2) and by Guo et al. (2012; A_v,
Ω_c, Ω_r also coded in TTB-2D); they are used one-sided per rad/m as those
sources use them. A_g (5.32e-8 low, 1.032e-7 high) is Zhai's value; the one
retrievable copy we found is an open-source Python implementation of these
spectra (its repository could not be identified) that codes every German
parameter with the values below, the same formulas and the same one-sided
m²/(rad/m) reading; Zhai remains the only primary source for A_g that we know of.

References
----------
* A. Hamid and T.-L. Yang, "Analytical descriptions of track geometry
  variations", *Transportation Research Record* 838, 19–26, 1981.
* V. K. Garg and R. V. Dukkipati, *Dynamics of Railway Vehicle Systems*,
  Academic Press, 1984, ch. 3.
* W. Zhai, *Vehicle–Track Coupled Dynamics: Theory and Applications*,
  Springer, 2020, ch. 2.
* W. W. Guo, H. Xia, G. De Roeck and K. Liu, "Integral model for
  train-track-bridge interaction on the Sesia viaduct", *Computers & Structures*
  112–113, 205–216, 2012.
* D. Cantero, "TTB-2D: Train–Track–Bridge interaction simulation tool for
  Matlab", *SoftwareX* 20, 101253, 2022 (code: ``A04_Options.m``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn import random_vibration as rv
from raildyn.constants import MPH

__all__ = [
    "COMPONENTS",
    "FRA_CLASSES",
    "GERMAN_LEVELS",
    "FRA_PARAMETERS",
    "FRA_SPEED_LIMITS_MPH",
    "GERMAN_PARAMETERS",
    "fra_speed_limit",
    "fra_psd",
    "german_psd",
    "track_psd",
    "TrackSpectrum",
    "band_variance",
    "wavelength_band",
]

COMPONENTS = ("vertical", "alignment", "cross_level", "gauge")
FRA_CLASSES = (1, 2, 3, 4, 5, 6)
GERMAN_LEVELS = ("low", "high")

_CM2 = 1.0e-4  # m² per cm²
FRA_K = 0.25  # Hamid & Yang (1981) as quoted by Garg & Dukkipati (1984) and coded by TTB-2D (Cantero 2022)
# The form in which the sources give the spectra (module docstring): one-sided, per rad/m.
_SOURCE_FORM = {"from_sided": "one", "from_unit": "rad/m"}


@dataclass(frozen=True)
class FRAParameters:
    """Parameters of one FRA track class (Hamid & Yang 1981).

    Attributes
    ----------
    A_v, A_a : float
        Roughness parameters of profile and alignment, cm²·rad/m (as tabulated).
    omega_c, omega_s : float
        Corner wavenumbers, rad/m.
    """

    A_v: float
    A_a: float
    omega_c: float
    omega_s: float


# fmt: off
# Hamid & Yang (1981), table as quoted by Garg & Dukkipati (1984, ch. 3) and Zhai (2020, ch. 2).
# A_v for every class and Ω_c = 0.8245 rad/m also in TTB-2D, A04_Options.m (Cantero 2022, citing Berawi 2013).
FRA_PARAMETERS = {
    #        A_v (cm²·rad/m)  A_a (cm²·rad/m)  Ω_c (rad/m)  Ω_s (rad/m)
    1: FRAParameters(1.2107, 3.3634, 0.8245, 0.6046),
    2: FRAParameters(1.0181, 1.2107, 0.8245, 0.9308),
    3: FRAParameters(0.6816, 0.4128, 0.8245, 0.8520),
    4: FRAParameters(0.5376, 0.3027, 0.8245, 1.1312),
    5: FRAParameters(0.2095, 0.0762, 0.8245, 0.8209),
    6: FRAParameters(0.0339, 0.0339, 0.8245, 0.4380),
}
# fmt: on


#: The highest speed each FRA class of track allows, mph, for "freight" and "passenger" trains: 49 CFR
#: 213.9(a) for classes 1–5; 49 CFR 213.307(a) for class 6, 110 mph for any train (freight only on the
#: conditions of its note 1; the same 110 mph for both stood in 213.9 when Hamid & Yang fitted the spectra).
FRA_SPEED_LIMITS_MPH = {
    1: {"freight": 10.0, "passenger": 15.0},
    2: {"freight": 25.0, "passenger": 30.0},
    3: {"freight": 40.0, "passenger": 60.0},
    4: {"freight": 60.0, "passenger": 80.0},
    5: {"freight": 80.0, "passenger": 90.0},
    6: {"freight": 110.0, "passenger": 110.0},
}
_SERVICES = ("freight", "passenger")


def fra_speed_limit(track_class: int, service: str = "passenger") -> float:
    """The highest speed an FRA class of track allows (49 CFR 213.9(a), 213.307(a)), m/s.

    A track's spectrum describes track kept to its class, and the class is what permits a
    speed: a vehicle run on class-4 track faster than class 4 allows is run on track that
    would not be kept so. :data:`FRA_SPEED_LIMITS_MPH` holds the limits in mph.

    Parameters
    ----------
    track_class : int
        FRA class 1 (worst) to 6 (best).
    service : {"passenger", "freight"}
        The kind of train.

    Returns
    -------
    float
        The maximum operating speed, m/s (> 0).

    Examples
    --------
    >>> round(3.6 * fra_speed_limit(4), 1)  # 80 mph
    128.7
    >>> round(3.6 * fra_speed_limit(4, "freight"), 1)  # 60 mph
    96.6
    """
    c = _checks.integer("track_class", track_class, low=min(FRA_CLASSES), high=max(FRA_CLASSES))
    service = _checks.choice("service", service, _SERVICES)
    return FRA_SPEED_LIMITS_MPH[c][service] * MPH


@dataclass(frozen=True)
class GermanParameters:
    """Parameters of a German track spectrum.

    Attributes
    ----------
    A_v, A_a, A_g : float
        Roughness parameters of profile, alignment and gauge, m·rad (= m²·rad/m).
    omega_c, omega_r, omega_s : float
        Corner wavenumbers, rad/m.
    b : float
        a, half the distance between the contact points of the two rails, m (the notation's a;
        the field keeps its name).
    """

    A_v: float
    A_a: float
    A_g: float
    omega_c: float
    omega_r: float
    omega_s: float
    b: float


# fmt: off
# Zhai (2020, ch. 2); A_v (low), Ω_c and Ω_r also in Guo et al. (2012) as coded in TTB-2D (Cantero 2022).
# Every value, A_g included, also in an open-source implementation of these spectra (see the module notes).
GERMAN_PARAMETERS = {
    #                  A_v (m·rad) A_a (m·rad) A_g (m·rad) Ω_c     Ω_r     Ω_s (rad/m)  b (m)
    "low": GermanParameters(4.032e-7, 2.119e-7, 5.32e-8, 0.8246, 0.0206, 0.4380, 0.75),
    "high": GermanParameters(1.080e-6, 6.125e-7, 1.032e-7, 0.8246, 0.0206, 0.4380, 0.75),
}
# fmt: on


_SPECTRA = ("fra", "german")
# The sources call k a "safety factor" between 0.25 and 1 (module docstring): k is taken in (0, 1].
_K_MAX = 1.0


def _component(value) -> str:
    return _checks.choice("component", value, COMPONENTS)


def _wavenumber(value) -> np.ndarray:
    """Wavenumbers Ω > 0 in rad/m (every spectrum here is unbounded or undefined at Ω = 0)."""
    arr = _checks.array("wavenumber", value, allow_empty=False)
    if np.any(arr <= 0):
        bad = arr[arr <= 0].flat[0]
        raise ValueError(
            f"wavenumber must be > 0 rad/m everywhere (the spectra grow without bound as Ω → 0), got {bad!r}"
        )
    return arr


def _fra_class(value, name: str = "track_class") -> FRAParameters:
    """The parameters of FRA class ``value`` (1–6); ``name`` is the caller's parameter."""
    return FRA_PARAMETERS[_checks.integer(name, value, low=min(FRA_CLASSES), high=max(FRA_CLASSES))]


def _german_level(value, name: str = "level") -> GermanParameters:
    return GERMAN_PARAMETERS[_checks.choice(name, value, GERMAN_LEVELS)]


def _k(value) -> float:
    return _checks.scalar("k", value, low=0.0, low_open=True, high=_K_MAX)


def _family(spectrum, grade, name: str = "spectrum"):
    """The checked family name and the parameters of its ``grade`` (an FRA class or a German level).

    ``name`` is the caller's parameter for the family.
    """
    spectrum = _checks.choice(name, spectrum, _SPECTRA)
    if spectrum == "fra":
        return spectrum, _fra_class(grade, "grade")
    return spectrum, _german_level(grade, "grade")


def fra_psd(component: str, track_class: int, wavenumber, *, k: float = FRA_K) -> np.ndarray:
    """One-sided PSD of an FRA track class (Hamid & Yang 1981), per rad/m.

    Parameters
    ----------
    component : {"vertical", "alignment", "cross_level", "gauge"}
        Vertical profile, alignment (lateral), cross-level (height difference
        between the rails) or gauge (lateral distance between the rails, minus
        its nominal value).
    track_class : int
        FRA class 1 (worst) to 6 (best).
    wavenumber : array_like
        Spatial circular frequency Ω = 2π/λ, rad/m, > 0; any shape, not empty.
    k : float
        Scale factor of the sources (module docstring), 0 < k <= 1 (the range the
        texts give this "safety factor"), default 0.25.

    Returns
    -------
    ndarray
        S(Ω) in m²/(rad/m), one-sided: σ² = ∫₀^∞ S dΩ. Same shape as ``wavenumber``.

    Examples
    --------
    >>> s = fra_psd("vertical", 4, [0.8245])  # at Ω = Ω_c: k A_v / (2 Ω_c²) cm²/(rad/m)
    >>> bool(np.isclose(s[0], 0.25 * 0.5376e-4 / (2 * 0.8245**2)))
    True
    """
    component = _component(component)
    p = _fra_class(track_class)
    k = _k(k)
    w = _wavenumber(wavenumber)
    wc2 = p.omega_c**2
    # Ω² overflows above 1e154 rad/m, where S is 0 to double precision, and underflows below 1e-154.
    with np.errstate(over="ignore", under="ignore", divide="ignore"):
        w2 = w**2
        if component in ("vertical", "alignment"):
            A = p.A_v if component == "vertical" else p.A_a
            s_cm2 = k * A * wc2 / (w2 * (w2 + wc2))
        else:
            s_cm2 = 4.0 * k * p.A_v * wc2 / ((w2 + wc2) * (w2 + p.omega_s**2))
    if not np.all(np.isfinite(s_cm2)):  # S grows as Ω⁻² towards Ω = 0: beyond double precision
        bad = float(w[~np.isfinite(s_cm2)].flat[0])
        raise ValueError(
            f"wavenumber must be large enough that S(Ω), which grows as 1/Ω² towards 0, stays finite "
            f"(above about 1e-150 rad/m, a wavelength of 6e150 m), got {bad!r}"
        )
    return rv.convert_psd(_CM2 * s_cm2, **_SOURCE_FORM, to_unit="rad/m")


def german_psd(component: str, level: str, wavenumber) -> np.ndarray:
    """One-sided PSD of the German low- or high-disturbance track spectrum, per rad/m.

    Parameters
    ----------
    component : {"vertical", "alignment", "cross_level", "gauge"}
        Vertical profile, alignment, cross-level as the height difference
        between the rails (2a × the cross-level angle of the source), or gauge.
    level : {"low", "high"}
        Low or high disturbance.
    wavenumber : array_like
        Ω = 2π/λ, rad/m, > 0; any shape, not empty.

    Returns
    -------
    ndarray
        S(Ω) in m²/(rad/m), one-sided.

    Examples
    --------
    Far below Ω_r the profile spectrum is flat at A_v Ω_c²/(Ω_r² Ω_c²) = A_v/Ω_r²:

    >>> s = german_psd("vertical", "low", [1e-5])
    >>> bool(np.isclose(s[0], 4.032e-7 / 0.0206**2, rtol=1e-6))
    True
    """
    component = _component(component)
    p = _german_level(level)
    w = _wavenumber(wavenumber)
    wc2, wr2 = p.omega_c**2, p.omega_r**2
    # Ω² overflows above 1e154 rad/m, where S is 0 to double precision, and underflows below 1e-154.
    with np.errstate(over="ignore", under="ignore", divide="ignore"):
        w2 = w**2
        base = wc2 / ((w2 + wr2) * (w2 + wc2))
        # Ω²/(Ω² + Ω_s²) as 1/(1 + Ω_s²/Ω²): 1, not inf/inf, where Ω² overflows; 0 where it underflows.
        high_pass = 1.0 / (1.0 + p.omega_s**2 / w2)
    if component == "vertical":
        s = p.A_v * base
    elif component == "alignment":
        s = p.A_a * base
    elif component == "cross_level":
        angle = (p.A_v / p.b**2) * base * high_pass
        s = (2.0 * p.b) ** 2 * angle
    else:
        s = p.A_g * base * high_pass
    return rv.convert_psd(s, **_SOURCE_FORM, to_unit="rad/m")


@dataclass(frozen=True)
class TrackSpectrum:
    """A track irregularity spectrum S(Ω) that knows what it describes.

    Built by :func:`track_psd`; called like a function of the wavenumber. A vehicle's response
    (:func:`raildyn.vehicles.response.response_spectrum`) reads ``component`` from it, so a spectrum of the
    alignment cannot be taken for a vertical profile.

    Attributes
    ----------
    family : {"fra", "german"}
        The source: FRA classes (Hamid & Yang 1981) or the German spectra.
    component : {"vertical", "alignment", "cross_level", "gauge"}
        The irregularity it describes, as for :func:`fra_psd`.
    grade : int or str
        FRA class 1–6, or German level ``"low"`` or ``"high"``.

    Examples
    --------
    >>> psd = TrackSpectrum("fra", "alignment", 4)
    >>> psd.component
    'alignment'
    >>> bool(np.isclose(psd([0.5])[0], fra_psd("alignment", 4, [0.5])[0]))
    True
    """

    family: str
    component: str
    grade: int | str

    def __post_init__(self):
        family, _ = _family(self.family, self.grade, "family")
        object.__setattr__(self, "family", family)
        object.__setattr__(self, "component", _component(self.component))
        if family == "fra":  # numpy integers as Python ints, so equal spectra compare equal
            object.__setattr__(self, "grade", int(self.grade))

    def __call__(self, wavenumber) -> np.ndarray:
        """S(Ω): the one-sided PSD, m²/(rad/m), at wavenumbers Ω (rad/m, > 0, any shape, not empty)."""
        if self.family == "fra":
            return fra_psd(self.component, self.grade, wavenumber)
        return german_psd(self.component, self.grade, wavenumber)


def track_psd(spectrum: str, component: str, grade) -> TrackSpectrum:
    """The spectrum S(Ω) as a callable that names its component, for the synthesis, response and widgets.

    The arguments are checked now, not at the first call.

    Parameters
    ----------
    spectrum : {"fra", "german"}
        The family: FRA classes (Hamid & Yang 1981) or the German spectra.
    component : {"vertical", "alignment", "cross_level", "gauge"}
        As for :func:`fra_psd`.
    grade : int or str
        FRA class 1–6, or German level ``"low"`` or ``"high"``.

    Returns
    -------
    TrackSpectrum
        S(Ω): wavenumbers (rad/m, > 0) to the one-sided PSD, m²/(rad/m); its ``component``,
        ``family`` and ``grade`` say what it describes.

    Examples
    --------
    >>> psd = track_psd("fra", "vertical", 4)
    >>> bool(np.isclose(psd(np.array([0.5]))[0], fra_psd("vertical", 4, [0.5])[0]))
    True
    >>> psd.component
    'vertical'
    """
    spectrum = _checks.choice("spectrum", spectrum, _SPECTRA)
    _family(spectrum, grade)
    return TrackSpectrum(spectrum, _component(component), grade)


def wavelength_band(band) -> tuple[float, float]:
    """Check a wavelength band and return the matching wavenumber band (2π/L_max, 2π/L_min).

    A band is a pair (low, high) wherever raildyn takes one, so this conversion
    returns the pair itself, ready to pass on as ``band``.

    Parameters
    ----------
    band : (float, float)
        (L_min, L_max), the shortest and longest wavelengths L_w, m, 0 < L_min < L_max.

    Returns
    -------
    (float, float)
        (Ω_low, Ω_high), rad/m.

    Examples
    --------
    >>> [round(w, 4) for w in wavelength_band((1.524, 304.8))]
    [0.0206, 4.1228]
    """
    return _wavenumber_band(band, "band")


def _wavenumber_band(band, name: str) -> tuple[float, float]:
    """:func:`wavelength_band` for the caller's parameter ``name``."""
    lo, hi = _checks.interval(name, band, unit="m")
    return 2.0 * np.pi / hi, 2.0 * np.pi / lo


def _int_inv_w2(w):  # ∫ dΩ/Ω²
    return -1.0 / w


def _int_lorentz(w, a):  # ∫ dΩ/(Ω² + a²)
    return np.arctan(w / a) / a


def _int_two_lorentz(w, a, b):
    """∫ dΩ/((Ω² + a²)(Ω² + b²)), by partial fractions; the double pole a = b by its limit."""
    if abs(b - a) <= 1e-6 * max(a, b):
        return w / (2 * a**2 * (w**2 + a**2)) + np.arctan(w / a) / (2 * a**3)
    return (_int_lorentz(w, a) - _int_lorentz(w, b)) / (b**2 - a**2)


def _int_three(w, a, b, c):
    """∫ Ω² dΩ/((Ω² + a²)(Ω² + b²)(Ω² + c²)) for distinct a, b, c, by partial fractions in Ω²."""
    total = 0.0
    for p, q, r in ((a, b, c), (b, a, c), (c, a, b)):
        # residue of u/((u+p²)(u+q²)(u+r²)) at u = −p²
        total = total + (-(p**2)) / ((q**2 - p**2) * (r**2 - p**2)) * _int_lorentz(w, p)
    return total


def band_variance(spectrum: str, component: str, grade, band, *, k: float = FRA_K) -> float:
    """Variance ∫ S(Ω) dΩ over a wavenumber band, in closed form (m²).

    Parameters
    ----------
    spectrum : {"fra", "german"}
        The family of spectra.
    component : str
        As for :func:`fra_psd` / :func:`german_psd`.
    grade : int or str
        FRA class 1–6, or German level "low"/"high".
    band : (omega_lo, omega_hi)
        Wavenumbers in rad/m, 0 < omega_lo < omega_hi (use :func:`wavelength_band`
        to convert from wavelengths).
    k : float
        The FRA scale factor, 0 < k <= 1, as for :func:`fra_psd` (checked, but not
        used, for the German spectra).

    Returns
    -------
    float
        σ² over the band, m². The antiderivatives follow from partial fractions
        of the rational spectra (module docstring).

    Examples
    --------
    >>> var = band_variance("fra", "vertical", 4, wavelength_band((1.524, 304.8)))
    >>> round(1e3 * var**0.5, 1)  # RMS in mm
    25.0
    """
    spectrum, p = _family(spectrum, grade)
    component = _component(component)
    k = _k(k)
    lo, hi = _checks.interval("band", band, unit="rad/m")

    def F(w):  # antiderivative of S in m²
        if spectrum == "fra":
            wc = p.omega_c
            if component in ("vertical", "alignment"):
                A = p.A_v if component == "vertical" else p.A_a
                # Ω_c²/(Ω²(Ω²+Ω_c²)) = 1/Ω² − 1/(Ω²+Ω_c²)
                return k * A * _CM2 * (_int_inv_w2(w) - _int_lorentz(w, wc))
            return 4 * k * p.A_v * _CM2 * wc**2 * _int_two_lorentz(w, wc, p.omega_s)
        if component in ("vertical", "alignment"):
            A = p.A_v if component == "vertical" else p.A_a
            return A * p.omega_c**2 * _int_two_lorentz(w, p.omega_r, p.omega_c)
        A = 4 * p.A_v if component == "cross_level" else p.A_g  # (2b)² A_v/b² for the cross-level
        return A * p.omega_c**2 * _int_three(w, p.omega_r, p.omega_c, p.omega_s)

    return float(F(hi) - F(lo))
