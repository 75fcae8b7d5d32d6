"""Physical constants shared by every raildyn model: one value each, cited once.

* :data:`GRAVITY` — standard gravity g = 9.80665 m/s², the conventional value
  fixed by the 3rd CGPM (1901) and used by ISO 80000-3. It is chosen over the
  rounded 9.81 because it is a definition rather than a local measurement: the
  train's tonnage ratings (AAR, in short tons force) and the vehicles' weights
  then convert with the same number.
* :data:`STEEL_YOUNGS_MODULUS`, :data:`STEEL_POISSON_RATIO` — wheel and rail
  steel, E = 210 GPa and ν = 0.3 (Johnson 1985, *Contact Mechanics*; the values
  Kalker 1990 and most vehicle-dynamics codes use).
* :data:`STEEL_SHEAR_MODULUS` — G = E/(2(1 + ν)) = 80.8 GPa, the shear modulus
  that goes with them, so that Hertz's patch and Kalker's coefficients describe
  the same steel.
* :data:`MPH` — one mile per hour in m/s, 1609.344/3600 (the international mile of
  1959, exact), for sources in US units: the FRA's track-class speed limits, Davis's
  resistance formula.
"""

from __future__ import annotations

__all__ = ["GRAVITY", "MPH", "STEEL_POISSON_RATIO", "STEEL_SHEAR_MODULUS", "STEEL_YOUNGS_MODULUS"]

GRAVITY = 9.80665  # m/s², standard gravity (3rd CGPM, 1901; ISO 80000-3)
STEEL_YOUNGS_MODULUS = 2.1e11  # Pa (Johnson 1985)
STEEL_POISSON_RATIO = 0.3  # (Johnson 1985)
STEEL_SHEAR_MODULUS = STEEL_YOUNGS_MODULUS / (2.0 * (1.0 + STEEL_POISSON_RATIO))  # Pa, isotropic elasticity
MPH = 1609.344 / 3600  # m/s per mile per hour (international mile, 1959: exact)
