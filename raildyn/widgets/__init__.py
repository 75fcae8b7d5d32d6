"""Interactive widgets: thin user interfaces over the raildyn models, one module per chapter.

Every widget factory builds its controls and its figure once and returns
``(container, update)``. ``container`` is an ipywidgets box to display;
``update(**values)`` sets any of the named controls, recomputes, redraws the
existing figure in place and returns the new frame as PNG bytes, so tests and
benchmarks drive a widget without a browser. Importing this package imports
ipywidgets; the model modules never do.
"""

from raildyn.widgets._core import LiveFigure, Recipe, assemble

__all__ = ["LiveFigure", "Recipe", "assemble"]
