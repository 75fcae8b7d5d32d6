"""Old public names kept for one issue: each still works, and warns that it goes.

Issue 33 renamed public names so that a name says what it is: the plain ``Car`` was the lateral car
while the plain ``FreightCar`` and ``Locomotive`` were vertical models; ``moving_force`` (a beam's
response) and ``moving_forces`` (a load) differed by one letter; ``state_space`` meant a
``control.StateSpace`` on a linear model and a :class:`~raildyn.vibration.StateSpaceMatrices` in
chapter 1. The old names stay for one issue as deprecated aliases: reaching one gives the new object
and a ``DeprecationWarning`` that names the new name.

This is the one place for them: :data:`RENAMED` lists every old module attribute, which each module
(and each package that exported it) serves through :func:`module_getattr`, its PEP 562
``__getattr__``; :class:`renamed_method` is the old name of a method. The old names are absent from
``__all__``. Removing them, after one issue, is deleting this module and the lines that use it.

Part of the ground floor: it imports nothing of raildyn's.
"""

from __future__ import annotations

import warnings

#: Module → {old name: new name}, for every module attribute renamed by issue 33. A package that
#: exported the old name serves it too, so both import paths keep working.
RENAMED: dict[str, dict[str, str]] = {
    "raildyn.vehicles": {
        "Car": "LateralCar",
        "FreightCar": "VerticalFreightCar",
        "Locomotive": "VerticalLocomotive",
    },
    "raildyn.vehicles.lateral": {"Car": "LateralCar"},
    "raildyn.vehicles.freight": {"FreightCar": "VerticalFreightCar"},
    "raildyn.vehicles.locomotive": {"Locomotive": "VerticalLocomotive"},
    "raildyn.bridge": {"moving_force": "moving_force_response", "moving_forces": "moving_load"},
    "raildyn.bridge.beam": {"moving_force": "moving_force_response"},
    "raildyn.bridge.loads": {"moving_forces": "moving_load"},
    "raildyn.vibration": {"state_space": "state_space_matrices"},
    "raildyn.vibration.damped": {"state_space": "state_space_matrices"},
    "raildyn.vibration.mdof": {"state_space": "state_space_matrices"},
}


def warn(old: str, new: str, *, stacklevel: int = 3) -> None:
    """Warn that ``old`` is deprecated, naming ``new`` (a ``DeprecationWarning``).

    Parameters
    ----------
    old : str
        The old name, dotted as the caller reaches it (e.g. ``"raildyn.vehicles.Car"``).
    new : str
        The name to use instead.
    stacklevel : int
        As for :func:`warnings.warn`; the default points at the caller of the function that calls
        this one.
    """
    warnings.warn(f"{old} is deprecated; use {new}", DeprecationWarning, stacklevel=stacklevel)


def module_getattr(module: str, namespace: dict):
    """The ``__getattr__`` (PEP 562) of a module that keeps old names from :data:`RENAMED`.

    Parameters
    ----------
    module : str
        The module's ``__name__``; a key of :data:`RENAMED`.
    namespace : dict
        The module's ``globals()``, where each new name is looked up when an old one is reached.

    Returns
    -------
    callable
        ``__getattr__(name)``: for an old name, warns and returns the object of the new name; for
        any other name, raises ``AttributeError`` as a module without ``__getattr__`` would.

    Examples
    --------
    In a module that renamed ``old_name`` to ``new_name`` (with ``RENAMED[__name__] ==
    {"old_name": "new_name"}``)::

        __getattr__ = _deprecated.module_getattr(__name__, globals())
    """
    renamed = RENAMED[module]

    def __getattr__(name: str):
        if name in renamed:
            warn(f"{module}.{name}", renamed[name])
            return namespace[renamed[name]]
        raise AttributeError(f"module {module!r} has no attribute {name!r}")

    return __getattr__


class renamed_method:
    """A method's old name: calling it warns and calls the method of the new name.

    A descriptor rather than a ``def``, so that the old name is not one more public method for the
    API checks and the fuzz registry to hold: ``state_space = renamed_method("state_space_matrices")``
    in a class body.

    Parameters
    ----------
    new : str
        The name of the method to call instead.
    """

    def __init__(self, new: str):
        self.new = new
        self.old = ""

    def __set_name__(self, owner, name: str):
        self.old = f"{owner.__qualname__}.{name}"

    def __get__(self, instance, owner=None):
        if instance is None:
            return self
        method = getattr(instance, self.new)
        new = f"{type(instance).__qualname__}.{self.new}"

        def old(*args, **kwargs):
            warn(self.old, new)
            return method(*args, **kwargs)

        old.__doc__ = f"Deprecated: the old name of :meth:`{new}`, kept for one issue."
        return old
