"""raildyn: the interactive companion to Garg & Dukkipati, *Dynamics of Railway Vehicle Systems* (1984).

The models of each chapter live in their own module (``raildyn.vibration`` for
chapter 1, ``raildyn.random_vibration`` for its random part, and so on); the
widgets in ``raildyn.widgets`` are thin user interfaces over them and are only
imported when asked for, so importing a model never pulls in ipywidgets.

The package itself exports no names (``__all__`` is empty): import the chapter's
module. ``raildyn.__version__`` gives the version.
"""

__all__: list[str] = []

__version__ = "0.1.0"
