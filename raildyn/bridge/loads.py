"""Axle sequences: where a train's axles stand and what each presses on the rail (chapter 10).

A sequence is the moving-force model of a train: the axles at fixed distances behind the
leading one, each a constant vertical force. The design trains of EN 1991-2 and the coupled
vehicles of :mod:`raildyn.bridge.coupled` use the same shape.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from raildyn import _checks

__all__ = ["AxleSequence"]

_MAX_AXLES = 10_000  # a 2 km freight train has about 600


@dataclass(frozen=True, eq=False)  # arrays: compared by identity, not elementwise
class AxleSequence:
    """A train as constant axle forces at fixed spacings.

    Attributes
    ----------
    positions : ndarray, (a,)
        Distance of each axle behind the leading one, m: the first 0, then non-decreasing
        (at most 10 000 axles).
    loads : ndarray, (a,)
        Force of each axle on the rail, N (> 0, downwards).
    name : str
        What the sequence is, for legends.

    Examples
    --------
    Two bogies of two axles, 2.5 m apart in the bogie and 17.5 m between bogie centres:

    >>> train = AxleSequence([0.0, 2.5, 17.5, 20.0], [170e3] * 4, "coach")
    >>> train.length
    20.0
    """

    positions: np.ndarray
    loads: np.ndarray
    name: str = ""

    def __post_init__(self):
        x = _checks.array("positions", self.positions, ndim=1, low=0.0, allow_empty=False)
        if x.size > _MAX_AXLES:
            raise ValueError(f"positions must hold at most {_MAX_AXLES} axles, got {x.size}")
        if x[0] != 0.0 or np.any(np.diff(x) < 0.0):
            raise ValueError(
                f"positions must start at 0 (the leading axle) and never decrease, got {x[:8]}"
                + (" …" if x.size > 8 else "")
            )
        p = _checks.array("loads", self.loads, shape=x.shape, low=0.0, low_open=True)
        _checks.instance("name", self.name, str)
        x, p = x.copy(), p.copy()  # never freeze the caller's own arrays
        x.setflags(write=False)
        p.setflags(write=False)
        object.__setattr__(self, "positions", x)
        object.__setattr__(self, "loads", p)

    @property
    def length(self) -> float:
        """From the leading to the last axle, m."""
        return float(self.positions[-1])
