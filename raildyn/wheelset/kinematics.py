"""Klingel's kinematic oscillation of a free coned wheelset and of a rigid two-axle bogie (book chapter 5).

The wavelength of a coned wheelset rolling without slip
(:func:`~raildyn.wheelset.kinematic_wavelength`), of two wheelsets held parallel in a rigid bogie
(:func:`~raildyn.wheelset.rigid_bogie_wavelength`), and both paths along the track
(:func:`~raildyn.wheelset.kinematic_oscillation`). Also the one bound on a conicity and a
centred contact angle that the rest of :mod:`raildyn.wheelset` checks against. SI units: m, rad.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._checks import positive, scalar

__all__ = ["KinematicOscillation", "kinematic_oscillation", "kinematic_wavelength", "rigid_bogie_wavelength"]

_MAX_ANGLE = 0.5  # rad (29°), the largest conicity and centred contact angle: tread contact


def kinematic_wavelength(rolling_radius, half_gauge, conicity) -> float:
    """Klingel's wavelength of a free coned wheelset rolling without slip, m.

    L = 2π √(r₀ a / λ) (Klingel 1883; Garg & Dukkipati 1984, ch. 5).

    Parameters
    ----------
    rolling_radius : float
        Centred rolling radius r₀, m, in [0.1, 1.5] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "wheel_radius").
    half_gauge : float
        Half the lateral distance between the two contact points a, m, in [0.15, 1.1]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "half_gauge").
    conicity : float
        Equivalent conicity λ, dimensionless, in (0, 0.5] (real wheels run below about 0.5).

    Returns
    -------
    float
        L, m.

    Examples
    --------
    >>> round(kinematic_wavelength(0.46, 0.75, 0.05), 3)
    16.505
    """
    r0, a, lam = _coned_wheelset(rolling_radius, half_gauge, conicity)
    return float(2.0 * np.pi * np.sqrt(r0 * a / lam))


def _coned_wheelset(rolling_radius, half_gauge, conicity) -> tuple[float, float, float]:
    """The checked r₀, a and λ > 0 of the kinematic formulas, each in its plausible range."""
    r0 = _checks.plausible("rolling_radius", rolling_radius, "wheel_radius")
    a = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    lam = scalar("conicity", conicity, low=0.0, low_open=True, high=_MAX_ANGLE)
    return r0, a, lam


def rigid_bogie_wavelength(rolling_radius, half_gauge, conicity, semi_wheelbase) -> float:
    """Kinematic wavelength of two wheelsets held rigidly parallel in a bogie, m.

    L = 2π √(r₀ a / λ · (1 + b²/a²)), with b the half wheelbase (Wickens 2003,
    ch. 2): the rigid frame forces each wheelset to slide laterally as it yaws,
    which lengthens the wave.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m), a (m) and λ, as for :func:`kinematic_wavelength`.
    semi_wheelbase : float
        b, half the distance between the two axles, m, in [0.01, 100]
        (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length").

    Returns
    -------
    float
        L, m.

    Examples
    --------
    >>> round(rigid_bogie_wavelength(0.46, 0.75, 0.05, 1.28), 3)
    32.647
    """
    b = _checks.plausible("semi_wheelbase", semi_wheelbase, "vehicle_length")
    a = _checks.plausible("half_gauge", half_gauge, "half_gauge")
    # √(1 + (b/a)²) as a hypotenuse, which stays finite for any finite b/a
    return kinematic_wavelength(rolling_radius, half_gauge, conicity) * float(np.hypot(1.0, b / a))


@dataclass(frozen=True)
class KinematicOscillation:
    """Klingel's kinematic oscillation of a free wheelset and of two wheelsets held in a rigid bogie.

    Attributes
    ----------
    wavelength : float
        Of the free wheelset, 2π√(r₀a/λ), m (> 0).
    rigid_bogie_wavelength : float
        Of the rigid bogie, 2π√(r₀a/λ · (1 + b²/a²)), m (> 0).
    """

    wavelength: float
    rigid_bogie_wavelength: float

    def __post_init__(self):
        positive("wavelength", self.wavelength)
        positive("rigid_bogie_wavelength", self.rigid_bogie_wavelength)

    def plot(self, ax=None, *, artists: dict | None = None, distance=None, amplitude: float = 5.0) -> dict:
        """Draw both paths, y = A sin(2πx/L), against the distance along the track.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to these wavelengths.
        distance : array_like, optional
            x, m (1-D, at least two, strictly increasing); 0 to 60 m by default (with ``artists``: the
            distances drawn first).
        amplitude : float
            A, mm (> 0).

        Returns
        -------
        dict
            The artists: ``free`` and ``bogie``.
        """
        import matplotlib

        from raildyn import plots

        amplitude = positive("amplitude", amplitude)
        if distance is not None:
            distance = _checks.increasing("distance", distance)
            if distance.size < 2:
                raise ValueError(f"distance must hold at least two distances, got {distance.size}")
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict of the artists an earlier call returned")
            x = artists["free"].get_xdata()
        else:
            x = np.linspace(0.0, 60.0, 1200) if distance is None else distance
        paths = {
            "free": amplitude * np.sin(2 * np.pi * x / self.wavelength),
            "bogie": amplitude * np.sin(2 * np.pi * x / self.rigid_bogie_wavelength),
        }
        if artists is not None:
            for name, y in paths.items():
                artists[name].set_ydata(y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (free,) = ax.plot(x, paths["free"], color=plots.COLORS[0], label="free wheelset (Klingel)")
            (bogie,) = ax.plot(x, paths["bogie"], "--", color=plots.COLORS[1], label="rigid bogie")
            ax.set_xlim(x[0], x[-1])
            ax.set_xlabel("distance along the track $x$ (m)")
            ax.set_ylabel("lateral displacement $y$ (mm)")
        return {"free": free, "bogie": bogie}


def kinematic_oscillation(rolling_radius, half_gauge, conicity, semi_wheelbase) -> KinematicOscillation:
    """Both kinematic wavelengths at once: :func:`kinematic_wavelength` and :func:`rigid_bogie_wavelength`.

    Parameters
    ----------
    rolling_radius, half_gauge, conicity : float
        r₀ (m), a (m) and λ.
    semi_wheelbase : float
        b, m.

    Returns
    -------
    KinematicOscillation

    Examples
    --------
    >>> k = kinematic_oscillation(0.46, 0.75, 0.15, 1.28)
    >>> round(k.wavelength, 2), round(k.rigid_bogie_wavelength, 2)
    (9.53, 18.85)
    """
    return KinematicOscillation(
        kinematic_wavelength(rolling_radius, half_gauge, conicity),
        rigid_bogie_wavelength(rolling_radius, half_gauge, conicity, semi_wheelbase),
    )
