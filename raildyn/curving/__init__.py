"""Curving (book chapter 8): curve geometry, steady-state curving, wheel climb.

The package grows module by module; each public name is re-exported here.
"""

__all__: list[str] = []
