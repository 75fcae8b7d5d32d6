"""Linear vehicles driven by the track: FRFs and response spectra (chapter 6).

Every vehicle here is a linear model of the one protocol
(:class:`raildyn.linear_model.LinearModel`), whose system is

    M q'' + C(V) q' + K q = G_K w(t) + G_C w'(t),

q the body coordinates, w the track inputs under its wheels (rail heights,
alignment or cross-level, :data:`raildyn.linear_model.INPUT_KINDS`). Input j is
the track met at distance s_j behind the leading axle: w_j(t) = z(t − τ_j) with
τ_j = s_j/V, z the track's irregularity under the leading axle. The speed V is
given once, to each function here, and reaches both the delays and the creep
damping of the lateral models.

* :func:`track_frf` — H(ω) = Σ_j a_j H_j(ω) e^{−iωτ_j}: from the track met by the
  leading axle to the output;
* :func:`response_spectrum` — response PSD and RMS for spatial track spectra at
  speed V, one per irregularity component, the components independent
  (:func:`raildyn.track.synthesis.excitation_csd` and
  :func:`raildyn.random_vibration.response_psd`). Each spectrum says which component
  it describes (a :class:`raildyn.track.spectra.TrackSpectrum` names its own; a plain callable
  needs ``component=``), and a component the vehicle has no input for is refused;
* :func:`rms_over_speeds` — the RMS of :func:`response_spectrum` at many speeds;
* :func:`~raildyn.vehicles.time_domain.time_response` — the history over a track profile, in
  :mod:`raildyn.vehicles.time_domain`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from raildyn import _checks, plots
from raildyn import random_vibration as rv
from raildyn import track as _track
from raildyn._tables import Tabular
from raildyn.constants import MAXIMUM_FREQUENCY
from raildyn.linear_model import INPUT_KINDS, LinearSystem
from raildyn.vehicles._shared import _earlier_artists, _steady_system, _vehicle

# Moved to raildyn.vehicles.time_domain (issue 33): imported here so that the old paths
# (raildyn.vehicles.response.X) keep working for one issue; then this goes.
from raildyn.vehicles.time_domain import PeriodicProfile, TimeResponse, periodic_profile, time_response  # noqa: F401

# Imported where used, to keep this module's import cheap (tests/test_imports.py): matplotlib

__all__ = [
    "ResponseSpectrum",
    "response_spectrum",
    "rms_over_speeds",
    "track_frf",
]


def _rail_weights(system: LinearSystem, component: str, source: str = "component") -> np.ndarray:
    """a_j: how an irregularity of the given component reaches each input.

    An input of the same kind takes it whole; a rail-height input takes a vertical
    irregularity whole and a cross-level Δz as ±Δz/2 on the left/right rail. A component
    that reaches no input (the vertical car has no alignment input, the lateral car no
    rail height) is refused, naming ``source``, the caller's parameter that gave it: its
    response would be a zero that says nothing.
    """
    _checks.choice(source, component, INPUT_KINDS)
    weights = _weights(system, component)
    if not np.any(weights):
        allowed = [kind for kind in INPUT_KINDS if np.any(_weights(system, kind))]
        what = (
            f"component {component!r} is"
            if source == "component"
            else f"psd describes the {component!r} component,"
        )
        raise ValueError(
            f"{what} not an input of this vehicle (its inputs are {sorted(set(system.input_kinds))}): "
            f"its response would be zero; allowed components: {allowed}"
        )
    return weights


def _weights(system: LinearSystem, component: str) -> np.ndarray:
    """a_j of :func:`_rail_weights`, zeros included."""
    kinds = np.array(system.input_kinds)
    weights = (kinds == component).astype(float)
    if component == "cross_level":  # left − right = c: the left rail at +c/2, the right at −c/2
        weights += np.where(kinds == "vertical", 0.5 * system.input_rails, 0.0)
    return weights


def _omega(omega, *, positive: bool) -> np.ndarray:
    """A non-empty 1-D grid of circular frequencies in [0, MAXIMUM_FREQUENCY] rad/s, > 0 if ``positive``."""
    w = _checks.array("omega", omega, ndim=1, low=0.0, low_open=positive, allow_empty=False)
    if w.max() > MAXIMUM_FREQUENCY:
        raise ValueError(
            f"omega must be at most {MAXIMUM_FREQUENCY:g} rad/s (rigid-body models of motions below some "
            "100 Hz), "
            f"got {w.max()!r}"
        )
    return w


def track_frf(vehicle, omega, speed, output="body z", derivative: int = 0, component: str = "vertical"):
    """H(ω) = Σ_j a_j H_j(ω) e^{−iωτ_j}: from the track under the leading axle to the output.

    a_j is 1 for an input of the component's kind, and ±1/2 on the left/right
    rail for a cross-level met by rail-height inputs.

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
    omega : array_like, (n_ω,)
        rad/s, in [0, 1e6] (rigid-body models of motions below some 100 Hz), not empty.
    speed : float
        V, m/s, in [0.001, :data:`~raildyn.constants.MAXIMUM_SPEED`] and below the critical speed of a lateral
        model.
    output : str, (str, float) or array_like
        See :meth:`raildyn.linear_model.LinearSystem.output_vector`.
    derivative : {0, 1, 2}
        Output in m, m/s or m/s² per m of track.
    component : {"vertical", "alignment", "cross_level"}
        The irregularity; one the vehicle has an input for (the vertical car takes only
        "vertical", the lateral car "alignment" and "cross_level").

    Returns
    -------
    ndarray, complex, (n_ω,)

    Raises
    ------
    ValueError
        If the vehicle has no input for ``component`` (the FRF would be a zero that says nothing).
    """
    system, V = _steady_system(vehicle, speed)
    w = _omega(omega, positive=False)
    Hj = system.axle_frf(w, V, output, derivative)
    tau = _track.axle_delays(system.input_positions, V)
    return _delayed_sum(Hj, _rail_weights(system, component), w, tau)


def _delayed_sum(Hj, weights, omega, delays) -> np.ndarray:
    """Σ_j a_j H_j(ω) e^{−iωτ_j}: each input met τ_j after the leading axle; ``delays`` (q,) or (n_V, q)."""
    phase = np.exp(-1j * omega[:, None] * delays[..., None, :])  # (..., n_ω, q)
    return np.einsum("kj,j,...kj->...k", Hj, weights, phase)


@dataclass(frozen=True)
class ResponseSpectrum(Tabular):
    """A response spectrum at one speed.

    Attributes
    ----------
    omega : ndarray, (n_ω,)
        rad/s, > 0, not empty.
    psd : ndarray, (n_ω,)
        One-sided PSD of the output, (output unit)²/(rad/s), ≥ 0.
    rms : float
        √∫S dω over the grid, in the output unit, ≥ 0.
    speed : float
        m/s, in [0.001, :data:`~raildyn.constants.MAXIMUM_SPEED`].
    """

    # The table of to_csv and to_pandas (raildyn._tables): columns and scalars with their units.
    _columns = (("omega", "rad/s"), ("psd", "(output unit)²/(rad/s)"))
    _scalars = (("rms", "output unit"), ("speed", "m/s"))

    omega: np.ndarray
    psd: np.ndarray
    rms: float
    speed: float

    def __post_init__(self):
        w = _checks.array("omega", self.omega, ndim=1, low=0.0, low_open=True, allow_empty=False)
        object.__setattr__(self, "omega", w)
        object.__setattr__(self, "psd", _checks.array("psd", self.psd, shape=w.shape, low=0.0))
        object.__setattr__(self, "rms", _checks.nonnegative("rms", self.rms))
        object.__setattr__(self, "speed", _checks.speed("speed", self.speed, low=1.0e-3, low_open=False))

    @property
    def frequency_hz(self) -> np.ndarray:
        """The grid in Hz."""
        return self.omega / (2 * np.pi)

    @property
    def psd_per_hz(self) -> np.ndarray:
        """The one-sided PSD per Hz, (unit)²/Hz, the form ride standards plot."""
        return rv.convert_psd(self.psd, from_sided="one", from_unit="rad/s", to_unit="Hz")

    def plot(self, ax=None, *, artists: dict | None = None, label: str | None = None, color=None) -> dict:
        """Draw the PSD per Hz against frequency in Hz, on a logarithmic axis.

        Parameters
        ----------
        ax : matplotlib Axes, optional
            Axes to draw on; new ones by default. Ignored when ``artists`` is given.
        artists : dict, optional
            The artists an earlier call returned: they are moved to this spectrum.
        label : str, optional
            Legend entry.
        color : optional
            Line colour; the house palette's first by default.

        Returns
        -------
        dict
            The artists: ``line``.
        """
        import matplotlib

        floor = 1e-12  # (unit)²/Hz: a logarithmic axis cannot show a zero
        y = np.maximum(self.psd_per_hz, floor)
        if artists is not None:
            _earlier_artists(artists, ("line",))["line"].set_data(self.frequency_hz, y)
            return artists
        ax = plots.axes_or_new(ax)
        with matplotlib.rc_context(plots.STYLE):
            (line,) = ax.semilogy(self.frequency_hz, y, color=plots.COLORS[0] if color is None else color,
                                  label=label)  # fmt: skip
            ax.set_xlabel("frequency (Hz)")
            ax.set_ylabel(r"PSD ((m/s$^2$)$^2$/Hz)")
        return {"line": line}


def _spectra(psd, component) -> dict:
    """{component: (S(Ω), the caller's parameter that named the component)} from the arguments.

    ``psd`` is one spectrum or a mapping {component: S} of independent components. A
    :class:`raildyn.track.spectra.TrackSpectrum` names its own component; a plain callable needs
    ``component``. A spectrum whose component is not stated, a ``component`` that contradicts
    the spectrum's own, and the gauge (no vehicle here has a gauge input) are refused. Each S
    is wrapped so that what it returns is checked where it is used: finite, ≥ 0, shaped like Ω.
    """
    if isinstance(psd, Mapping):
        if component is not None:
            raise ValueError(f"component must be None when psd is a mapping of components, got {component!r}")
        if not psd:
            raise ValueError("psd must hold at least one spectrum, got an empty mapping")
        for name, S in psd.items():
            if name not in INPUT_KINDS:
                raise ValueError(f"psd must map components {INPUT_KINDS} to spectra; got the key {name!r}")
            own = _own_component(S)
            if own is not None and own != name:
                raise ValueError(
                    f"psd[{name!r}] is a spectrum of the {own!r} component, not of {name!r}: key each "
                    f"spectrum by its own component"
                )
        entries = {name: (f"psd[{name!r}]", S, "psd") for name, S in psd.items()}
    else:
        own = _own_component(psd)
        if component is not None:
            _checks.choice("component", component, INPUT_KINDS)
        if own is None and component is None:
            _checks.function("psd", psd)
            raise ValueError(
                "psd does not say which irregularity it describes: give component= one of "
                f"{list(INPUT_KINDS)}, or pass a spectrum that names its own (raildyn.track.track_psd), "
                f"got {psd!r:.80}"
            )
        if own is not None and component is not None and own != component:
            raise ValueError(
                f"component {component!r} contradicts psd, a spectrum of the {own!r} component: "
                f"give component={own!r} or leave it out"
            )
        if own is not None and own not in INPUT_KINDS:
            raise ValueError(
                f"psd is a spectrum of the {own!r} component, which no vehicle model takes as an input; "
                f"allowed components: {list(INPUT_KINDS)}"
            )
        name, source = (own, "psd") if component is None else (component, "component")
        entries = {name: ("psd", psd, source)}
    return {
        name: (_checked_spectrum(label, _checks.function(label, S)), source)
        for name, (label, S, source) in entries.items()
    }


def _inputs_for(system: LinearSystem, psd, component) -> dict:
    """:func:`_spectra`, each component checked, before any work, to reach an input of ``system``."""
    spectra = _spectra(psd, component)
    for name, (_, source) in spectra.items():
        _rail_weights(system, name, source)
    return spectra


def _own_component(spectrum) -> str | None:
    """The component a spectrum names itself (a :class:`raildyn.track.spectra.TrackSpectrum`), else None."""
    return spectrum.component if isinstance(spectrum, _track.TrackSpectrum) else None


def _checked_spectrum(label: str, spectrum: Callable) -> Callable:
    """S(Ω) whose values are checked where they are used: finite, ≥ 0 and shaped like Ω."""

    def checked(Omega):
        return _checks.returned(label, spectrum(Omega), shape=np.shape(Omega), low=0.0)

    return checked


def response_spectrum(
    vehicle,
    psd,
    speed,
    omega,
    output="body z",
    derivative: int = 2,
    component: str | None = None,
) -> ResponseSpectrum:
    """Response PSD and RMS of an output for spatial track spectra S(Ω) (m²/(rad/m)) at speed V.

    For each irregularity component the inputs' cross-spectral matrix comes from
    :func:`raildyn.track.synthesis.excitation_csd` and the response from
    :func:`raildyn.random_vibration.response_psd`; the components (vertical
    profile, alignment, cross-level) are taken as independent processes, so
    their response PSDs add.

    Parameters
    ----------
    vehicle : LinearModel or LinearSystem
    psd : TrackSpectrum, callable or mapping
        S(Ω), one-sided, m²/(rad/m): a :class:`raildyn.track.spectra.TrackSpectrum` (from
        :func:`raildyn.track.spectra.track_psd`), which names its component; a plain callable of
        the irregularity named by ``component``; or a mapping {component: S} of
        independent components. Each S takes an array of Ω (rad/m) and returns finite
        values ≥ 0 of the same shape.
    speed : float
        V, m/s, in [0.001, :data:`~raildyn.constants.MAXIMUM_SPEED`] and below the critical speed of a lateral
        model.
    omega : array_like
        rad/s, in (0, 1e6] (rigid-body models of motions below some 100 Hz), not empty.
    output : str, (str, float) or array_like
        See :meth:`raildyn.linear_model.LinearSystem.output_vector`.
    derivative : {0, 1, 2}
        Displacement, velocity or acceleration of the output.
    component : {"vertical", "alignment", "cross_level"}, optional
        With a single ``psd``: the component it describes. Required for a plain callable;
        for a :class:`~raildyn.track.spectra.TrackSpectrum`, it may only repeat the spectrum's own.

    Returns
    -------
    ResponseSpectrum

    Raises
    ------
    ValueError
        If a spectrum returns a non-finite or negative value, or an array not shaped like its Ω;
        if the component of a plain callable is not given, or ``component`` contradicts the
        spectrum's own; if the vehicle has no input for a component (the vertical car has no
        alignment or cross-level input, the lateral car no rail height): its response would be
        a zero that says nothing.

    Examples
    --------
    >>> from raildyn import track
    >>> from raildyn.vehicles import MANCHESTER_CAR
    >>> w = np.linspace(1.0, 60.0, 200)
    >>> spec = response_spectrum(MANCHESTER_CAR, track.track_psd("fra", "alignment", 4), 30.0, w, "body y")
    >>> bool(spec.rms > 0)
    True
    """
    system, V = _steady_system(vehicle, speed)
    w = _omega(omega, positive=True)
    return _response_spectrum(system, _inputs_for(system, psd, component), V, w, output, derivative)


def _response_spectrum(system, spectra, V, w, output, derivative) -> ResponseSpectrum:
    """:func:`response_spectrum` for checked arguments (the spectra from :func:`_spectra`)."""
    Hj = system.axle_frf(w, V, output, derivative)
    S = np.zeros(w.size)
    for name, (spectrum, source) in spectra.items():
        H = Hj * _rail_weights(system, name, source)[None, :]
        S_in = _track.excitation_csd(spectrum, w, system.input_positions, V)
        S = S + rv.response_psd(H, S_in)
    return ResponseSpectrum(w, S, float(np.sqrt(rv.mean_square(S, w))), V)


def rms_over_speeds(
    vehicle, psd, speeds, omega, output="body z", derivative: int = 2, component: str | None = None
) -> np.ndarray:
    """The RMS of :func:`response_spectrum` at each speed, from one batched FRF solve where it can.

    A vehicle without creep damping (the vertical cars) has axle FRFs that do not
    depend on speed: only the delays and the temporal spectrum S(ω/V)/V do, so a
    speed costs one weighted sum over the grid. A lateral model's FRFs are solved
    again at each speed.

    Parameters
    ----------
    vehicle, psd, omega, output, derivative, component
        As for :func:`response_spectrum`.
    speeds : array_like, (n_V,)
        m/s, each in [0.001, :data:`~raildyn.constants.MAXIMUM_SPEED`] and below the critical speed of a
        lateral model; not empty.

    Returns
    -------
    ndarray, (n_V,)
        RMS of the output at each speed, in its unit.

    Raises
    ------
    ValueError
        As for :func:`response_spectrum`.
    """
    system = _vehicle(vehicle)
    V = _checks.speeds("speeds", speeds, low=1.0e-3, low_open=False)
    w = _omega(omega, positive=True)
    spectra = _inputs_for(system, psd, component)
    if np.any(system.C1):
        steady = (_steady_system(system, v, "speeds") for v in V)
        return np.array(
            [_response_spectrum(sys_v, spectra, v, w, output, derivative).rms for sys_v, v in steady]
        )
    Hj = system.axle_frf(w, V[0], output, derivative)  # (n_ω, q), the same at every speed
    tau = _track.axle_delays(system.input_positions, 1.0)[None, :] / V[:, None]  # (n_V, q), s
    S = np.zeros((V.size, w.size))
    for name, (spectrum, source) in spectra.items():
        H = _delayed_sum(Hj, _rail_weights(system, name, source), w, tau)  # (n_V, n_ω)
        S = S + np.abs(H) ** 2 * np.asarray(spectrum(w[None, :] / V[:, None])) / V[:, None]
    return np.sqrt(np.trapezoid(S, w, axis=1))
