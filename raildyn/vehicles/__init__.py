"""Vehicle models: the lateral bogie and car of chapter 7 (and, next, the vertical models of chapter 6).

Every public name is importable from ``raildyn.vehicles``.
"""

from raildyn.vehicles.lateral import MANCHESTER_CAR, Bogie, Car

__all__ = ["MANCHESTER_CAR", "Bogie", "Car"]
