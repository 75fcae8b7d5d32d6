"""The rocking freight car's coordinates, in the order of its kernel's arrays.

Apart from :mod:`raildyn.vehicles.rocking` (which publishes them as ``LABELS``), its analysis and its
compiled kernel, so that each of the three can name them without importing another: importing the car
must not load the kernel (numba; tests/test_imports.py), and the kernel must not import the car back.
"""

from __future__ import annotations

__all__ = ["LABELS"]

LABELS = (
    ("body z", "body θ", "body φ", "body y")
    + tuple(f"bolster {i} {c}" for i in (1, 2) for c in ("z", "φ", "y"))
    + tuple(f"wheelset {j} {c}" for j in (1, 2, 3, 4) for c in ("z", "φ"))
)
