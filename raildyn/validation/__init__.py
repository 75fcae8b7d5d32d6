"""Validating models (book chapter 11): comparing predictions with measurements, identifying
parameters from records, and spreading uncertain parameters into the answer. The package grows
module by module.
"""

__all__: list[str] = []
