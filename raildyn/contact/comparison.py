"""The creep-force laws of chapter 4 side by side on one sweep of lateral creepage.

Kalker's linear theory, Carter's two-dimensional law (with Kalker's initial slope),
Vermeulen and Johnson's theory (with its own creep coefficients), the saturation of
Shen, Hedrick and Elkins (Kalker's forces, spin included), Polach's method and
FASTSIM, all for the same contact ellipse, load and friction: the chart of the
chapter's figure ``fig4.creep`` and of its creep-law widget, drawn by
:meth:`LateralCreepCurves.plot`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks
from raildyn._tables import Tabular
from raildyn.constants import STEEL_POISSON_RATIO, STEEL_SHEAR_MODULUS
from raildyn.contact.fastsim import fastsim
from raildyn.contact.johnson_vermeulen import johnson_vermeulen
from raildyn.contact.kalker import CreepCoefficients, creep_coefficients, kalker_linear
from raildyn.contact.polach import polach
from raildyn.contact.saturation import carter, shen_hedrick_elkins

__all__ = ["CREEP_LAWS", "LateralCreepCurves", "lateral_creep_curves"]

CREEP_LAWS = {
    "Kalker linear": "kalker_linear",
    "Carter (2-D)": "carter",
    "Johnson–Vermeulen": "johnson_vermeulen",
    "Shen–Hedrick–Elkins": "shen_hedrick_elkins",
    "Polach": "polach",
    "FASTSIM": "fastsim",
}
"""The laws compared, by label, with the field of :class:`LateralCreepCurves` that holds each."""

_STYLES = dict(zip(CREEP_LAWS, (":", "-", "-", "--", "-.", "o"), strict=True))


@dataclass(frozen=True)
class LateralCreepCurves(Tabular):
    """Lateral creep force against lateral creepage by every law of chapter 4 (no longitudinal creepage).

    Attributes
    ----------
    lateral : ndarray, shape (n,)
        Lateral creepages γ_y swept (dimensionless).
    spin : float
        Spin creepage φ, 1/m (Carter and Johnson–Vermeulen take none).
    normal_load : float
        N, N.
    friction : float
        μ.
    a, b : float
        Semi-axes of the contact ellipse, m.
    coefficients : CreepCoefficients
        Kalker's coefficients of the ellipse.
    kalker_linear, carter, johnson_vermeulen, shen_hedrick_elkins, polach, fastsim : ndarray, shape (n,)
        F_y of each law, N (the force of the rail on the wheel: negative for γ_y > 0).

    Every number is finite, and the curves are 1-D, non-empty and of the shape of ``lateral``.
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (
        ("lateral", "-"), ("kalker_linear", "N"), ("carter", "N"), ("johnson_vermeulen", "N"),
        ("shen_hedrick_elkins", "N"), ("polach", "N"), ("fastsim", "N"),
    )  # fmt: skip
    _scalars = (("spin", "1/m"), ("normal_load", "N"), ("friction", "-"), ("a", "m"), ("b", "m"))

    lateral: np.ndarray
    spin: float
    normal_load: float
    friction: float
    a: float
    b: float
    coefficients: CreepCoefficients
    kalker_linear: np.ndarray
    carter: np.ndarray
    johnson_vermeulen: np.ndarray
    shen_hedrick_elkins: np.ndarray
    polach: np.ndarray
    fastsim: np.ndarray

    def __post_init__(self):
        _checks.fields(self)
        for name in ("spin", "normal_load", "friction", "a", "b"):
            _checks.scalar(name, getattr(self, name))
        _checks.instance("coefficients", self.coefficients, CreepCoefficients)
        shape = np.shape(self.lateral)
        if len(shape) != 1 or shape[0] == 0:
            raise ValueError(f"lateral must be a non-empty 1-D array, got shape {shape}")
        for name in ("kalker_linear", *CREEP_LAWS.values()):
            if np.shape(getattr(self, name)) != shape:
                raise ValueError(
                    f"lateral and {name} must have one shape, got {shape} and {np.shape(getattr(self, name))}"
                )

    def normalised(self, label: str) -> np.ndarray:
        """−F_y/(μN) of one law: 1 at full sliding.

        Parameters
        ----------
        label : str
            One of the keys of :data:`CREEP_LAWS`, e.g. ``"Polach"``.

        Returns
        -------
        ndarray, shape (n,)
            Dimensionless.
        """
        _checks.choice("label", label, CREEP_LAWS)
        return -getattr(self, CREEP_LAWS[label]) / (self.friction * self.normal_load)

    def plot(self, ax=None, *, artists=None) -> dict:
        """Draw −F_y/(μN) of every law against γ_y in %; or move lines drawn before.

        Parameters
        ----------
        ax : matplotlib.axes.Axes, optional
            Where to draw; new axes on a new pyplot figure if None.
        artists : dict, optional
            The dict a previous call returned (same creepages): its lines take
            these curves (``set_ydata``) instead of drawing new ones.

        Returns
        -------
        dict
            One line per law, keyed by its label in :data:`CREEP_LAWS`.
        """
        if artists is not None:
            _checks.instance("artists", artists, dict, "dict returned by an earlier plot")
            for label in CREEP_LAWS:
                artists[label].set_ydata(self.normalised(label))
            return artists
        import matplotlib

        from raildyn import plots

        ax = plots.axes_or_new(ax)
        lines = {}
        every = max(1, self.lateral.size // 40)
        with matplotlib.rc_context(plots.STYLE):
            for i, label in enumerate(CREEP_LAWS):
                colour = "k" if label == "Kalker linear" else plots.COLORS[(i - 1) % len(plots.COLORS)]
                style = _STYLES[label]
                extra = {"ms": 3, "markevery": every} if style == "o" else {}
                (lines[label],) = ax.plot(
                    100 * self.lateral, self.normalised(label), style, color=colour, label=label, **extra
                )
            ax.axhline(1.0, color="0.5", lw=0.8)
            ax.set_ylim(0, 1.4)
            ax.set_xlabel("lateral creepage γ_y (%)")
            ax.set_ylabel("lateral creep force −F_y/(μN)")
            ax.legend(loc="lower right", ncol=2)
        return lines


def lateral_creep_curves(
    lateral,
    normal_load,
    friction,
    a,
    b,
    spin=0.0,
    shear_modulus=STEEL_SHEAR_MODULUS,
    poisson_ratio=STEEL_POISSON_RATIO,
) -> LateralCreepCurves:
    """Lateral creep force of every law of chapter 4 over a sweep of lateral creepage.

    Carter's law takes Kalker's f₂₂ as its initial slope, so it, SHE, Polach and
    FASTSIM start on the linear theory; Vermeulen and Johnson start on their own,
    steeper slope G a b C₂₂ (:func:`~raildyn.contact.johnson_vermeulen.johnson_vermeulen_coefficients`),
    and at zero spin that is all that parts them from SHE, whose saturation is their
    cubic. All saturate at μN except the linear theory.

    Parameters
    ----------
    lateral : array_like, shape (n,)
        γ_y, dimensionless, >= 0, at least one.
    normal_load : float
        N, N, in [1, 1e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "wheel_load").
    friction : float
        μ, in (0, 1] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "friction").
    a, b : float
        Semi-axes of the contact ellipse, m, each in [1e-5, 0.05] (:data:`~raildyn.constants.PLAUSIBLE_RANGES`
        "contact_semi_axis"), 0.1 <= a/b <= 10.
    spin : float
        φ, 1/m.
    shear_modulus : float
        G, Pa; :data:`raildyn.constants.STEEL_SHEAR_MODULUS` by default.
    poisson_ratio : float
        ν; :data:`raildyn.constants.STEEL_POISSON_RATIO` by default.

    Returns
    -------
    LateralCreepCurves
        F_y of each law (N); ``.plot(ax)`` draws them.

    Examples
    --------
    >>> c = lateral_creep_curves(np.linspace(0.0, 0.01, 5), 100e3, 0.3, 6e-3, 4e-3)
    >>> np.round(c.normalised("Shen–Hedrick–Elkins"), 3).tolist()
    [-0.0, 0.555, 0.854, 0.976, 1.0]
    """
    eta = _checks.array("lateral", lateral, ndim=1, low=0.0, allow_empty=False)
    load = _checks.plausible("normal_load", normal_load, "wheel_load")
    mu = _checks.friction("friction", friction)
    a = _checks.plausible("a", a, "contact_semi_axis")
    b = _checks.plausible("b", b, "contact_semi_axis")
    phi = _checks.scalar("spin", spin)
    f = creep_coefficients(a, b, shear_modulus, poisson_ratio)
    fy = {
        "kalker_linear": kalker_linear(0.0, eta, phi, f).fy,
        "carter": carter(eta, load, mu, f.f22),
        "johnson_vermeulen": johnson_vermeulen(0.0, eta, load, mu, a, b, shear_modulus, poisson_ratio).fy,
        "shen_hedrick_elkins": shen_hedrick_elkins(0.0, eta, phi, load, mu, f).fy,
        "polach": polach(0.0, eta, phi, load, mu, a, b, shear_modulus, poisson_ratio).fy,
        "fastsim": fastsim(0.0, eta, phi, load, mu, a, b, shear_modulus, poisson_ratio, fields=False).fy,
    }
    return LateralCreepCurves(
        lateral=eta,
        spin=phi,
        normal_load=load,
        friction=mu,
        a=a,
        b=b,
        coefficients=f,
        **{name: np.broadcast_to(np.asarray(v, dtype=float), eta.shape).copy() for name, v in fy.items()},
    )
