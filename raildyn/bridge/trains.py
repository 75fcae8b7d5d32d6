"""Design trains as axle sequences: EN 1991-2's HSLM-A and trains of identical coaches (book chapter 10).

The ten universal trains HSLM-A1 … A10 of EN 1991-2 Annex E (Table E.4, Figure E.8) stand for
the articulated, conventional and regular high-speed trains that a bridge must carry: two power
cars, two end coaches and N intermediate coaches of length D sharing their bogies (of axle spacing
d, each axle P). Their resonance speeds n₀D/i sweep the range of real trains as D runs from 18 to
27 m.
"""

from __future__ import annotations

import numpy as np

from raildyn import _checks
from raildyn.bridge.loads import AxleSequence

__all__ = ["HSLM_A", "hslm", "regular_train"]

#: EN 1991-2 Table E.4: number → (N intermediate coaches, coach length D m, bogie axle spacing d m,
#: point force P kN). The same numbers define the trains of CALDINTAV (Nguyen Gia & Goicolea, UPM,
#: files ``trains/a01.def`` … ``a10.def``), whose axle positions the tests hold these trains to.
HSLM_A = {
    1: (18, 18.0, 2.0, 170.0),
    2: (17, 19.0, 3.5, 200.0),
    3: (16, 20.0, 2.0, 180.0),
    4: (15, 21.0, 3.0, 190.0),
    5: (14, 22.0, 2.0, 170.0),
    6: (13, 23.0, 2.0, 180.0),
    7: (13, 24.0, 2.0, 190.0),
    8: (12, 25.0, 2.5, 190.0),
    9: (11, 26.0, 2.0, 210.0),
    10: (11, 27.0, 2.0, 210.0),
}

# EN 1991-2 Figure E.8, the fixed dimensions (m): the power car's axles (two bogies of 3 m, centres
# 14 m apart); 3.525 m from its last axle to the end coach's first; from that axle to the centre of
# the first shared bogie, D − 1.7625 m. (As encoded in CALDINTAV's a01.def … a10.def, whose
# positions these reproduce.)
_POWER_CAR = np.array([0.0, 3.0, 14.0, 17.0])
_GAP = 3.525
_END_COACH = 1.7625


def hslm(number: int) -> AxleSequence:
    """HSLM-A1 … A10, EN 1991-2's high-speed load model A, as an axle sequence.

    The train, front to back (Annex E, Figure E.8, Table E.4): a power car (axles at 0, 3, 14 and
    17 m), 3.525 m, an end coach's free bogie (axles d apart), N + 1 shared (Jacobs) bogies at the
    regular spacing D, the first D − 1.7625 m behind the end coach's first axle, the rear end coach
    and power car mirrored. Every axle presses P. It has 2N + 14 axles and measures
    37.525 + (N + 2) D m from the first axle to the last.

    Parameters
    ----------
    number : int
        1 … 10.

    Returns
    -------
    AxleSequence
        Positions, m, behind the leading axle; loads, N.

    Examples
    --------
    >>> train = hslm(1)
    >>> train.positions.size, train.length, float(train.loads[0])
    (50, 397.525, 170000.0)
    """
    k = _checks.integer("number", number, low=1, high=10)
    N, D, d, P = HSLM_A[k]
    end_axle = _POWER_CAR[-1] + _GAP  # the front end coach's first axle
    centres = end_axle + D - _END_COACH + D * np.arange(N + 1)  # the shared bogies
    rear_axle = centres[-1] + D - _END_COACH  # the rear end coach's last axle
    positions = np.concatenate(
        [
            _POWER_CAR,
            [end_axle, end_axle + d],
            (centres[:, None] + [-d / 2, d / 2]).ravel(),
            [rear_axle - d, rear_axle],
            rear_axle + _GAP + _POWER_CAR,
        ]
    )
    return AxleSequence(positions, np.full(positions.size, P * 1e3), f"HSLM-A{k}")


def regular_train(
    coaches: int, coach_length, bogie_axle_spacing, axle_load, bogie_centres=None
) -> AxleSequence:
    """A train of identical coaches, as an axle sequence.

    Each coach is ``coach_length`` long, coupling to coupling. With ``bogie_centres`` None the
    coaches are articulated: one two-axle bogie at every joint, N + 1 bogies for N coaches, so the
    bogies repeat at exactly the coach length (the regular part of an HSLM train). Otherwise each
    coach has two bogies of its own, their centres ``bogie_centres`` apart and centred in the coach.

    Parameters
    ----------
    coaches : int
        N, in [1, 1000].
    coach_length : float
        D, m, in (0, 1000].
    bogie_axle_spacing : float
        d, m, in [0.01, 100] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "vehicle_length"): less than D
        for articulated coaches, less
        than ``bogie_centres`` otherwise.
    axle_load : float
        P, N, in [1, 2e6] (:data:`~raildyn.constants.PLAUSIBLE_RANGES` "axle_load"), the same on every axle.
    bogie_centres : float, optional
        a, m, between the two bogie centres of a coach: a + d ≤ D. None: articulated.

    Returns
    -------
    AxleSequence
        Positions, m, behind the leading axle; loads, N.

    Examples
    --------
    Two conventional coaches, 25 m long, bogie centres 17.5 m apart, bogies of 2.5 m:

    >>> regular_train(2, 25.0, 2.5, 170e3, bogie_centres=17.5).positions
    array([ 0. ,  2.5, 17.5, 20. , 25. , 27.5, 42.5, 45. ])
    """
    n = _checks.integer("coaches", coaches, low=1, high=1000)
    D = _checks.scalar("coach_length", coach_length, low=0.0, low_open=True, high=1000.0)
    d = _checks.plausible("bogie_axle_spacing", bogie_axle_spacing, "vehicle_length")
    P = _checks.plausible("axle_load", axle_load, "axle_load")
    if bogie_centres is None:
        if d >= D:
            raise ValueError(f"bogie_axle_spacing must be less than coach_length {D!r} m, got {d!r}")
        centres = D * np.arange(n + 1)
        name = f"{n} articulated coaches of {D:g} m"
    else:
        a = _checks.positive("bogie_centres", bogie_centres)
        if a + d > D or d >= a:
            raise ValueError(
                f"bogie_centres must exceed bogie_axle_spacing {d!r} m and leave the bogies inside the coach "
                f"(bogie_centres + bogie_axle_spacing ≤ coach_length {D!r} m), got {a!r}"
            )
        centres = (D * np.arange(n)[:, None] + [(D - a) / 2, (D + a) / 2]).ravel()
        name = f"{n} coaches of {D:g} m"
    positions = (centres[:, None] + [-d / 2, d / 2]).ravel()
    positions -= positions[0]
    return AxleSequence(positions, np.full(positions.size, P), name)
