"""The :class:`Assembler`: a :class:`~raildyn.linear_model.LinearSystem` built element by element.

Part of :mod:`raildyn.linear_model` (see its docstring); import the names from there.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from raildyn import _checks
from raildyn.linear_model._system import LinearSystem

__all__ = ["Assembler"]


_MAX_INPUTS = 10_000


class Assembler:
    """Builds a :class:`LinearSystem` element by element.

    Parameters
    ----------
    labels : sequence of str
        Names of the coordinates (at least one, each once, none empty).
    n_inputs : int
        Number of track inputs q, in [0, 10 000] (one per wheel of a long train is far fewer).

    Examples
    --------
    Two masses on springs, the lower one on the track:

    >>> asm = Assembler(["body z", "wheel z"], n_inputs=1)
    >>> asm.mass("body z", 1000.0); asm.mass("wheel z", 100.0)
    >>> asm.element({"body z": 1.0, "wheel z": -1.0}, 1e5, 2e3)
    >>> asm.element({"wheel z": 1.0}, 1e7, inputs={0: 1.0})
    >>> asm.system().GK[:, 0]
    array([       0., 10000000.])
    """

    def __init__(self, labels: Sequence[str], n_inputs: int = 0):
        self.labels = list(_checks.strings("labels", labels, unique=True))
        n = len(self.labels)
        if n == 0:
            raise ValueError("labels must name at least one coordinate, got an empty sequence")
        q = _checks.integer("n_inputs", n_inputs, low=0, high=_MAX_INPUTS)
        self.M = np.zeros((n, n))
        self.C0 = np.zeros((n, n))
        self.C1 = np.zeros((n, n))
        self.K = np.zeros((n, n))
        self.GK = np.zeros((n, q))
        self.GC = np.zeros((n, q))
        self.KW = np.zeros((q, q))  # the inputs' own block, known while every input enters by an element
        self.CW = np.zeros((q, q))
        self.input_block_known = True
        self.wheelsets: list = []

    def index(self, label: str) -> int:
        """Position of a coordinate.

        Parameters
        ----------
        label : str
            One of the labels.

        Returns
        -------
        int
        """
        return self.labels.index(_checks.choice("label", label, self.labels))

    def vector(self, terms: dict) -> np.ndarray:
        """g with g·q = Σ coefficient · coordinate.

        Parameters
        ----------
        terms : dict of str to float
            Label → finite coefficient.

        Returns
        -------
        ndarray, (n,)
        """
        return self._vector(terms, "terms")

    def _vector(self, terms, name: str) -> np.ndarray:
        """:meth:`vector`, its messages naming ``name`` (the caller's parameter)."""
        _checks.instance(name, terms, dict, "dict of label to coefficient")
        g = np.zeros(len(self.labels))
        for label, value in terms.items():
            i = self.labels.index(_checks.choice(f"{name} key", label, self.labels))
            g[i] += _checks.scalar(f"{name}[{label!r}]", value)
        return g

    def mass(self, label: str, value: float) -> None:
        """Add a mass (kg) or inertia (kg·m²) on one coordinate.

        Parameters
        ----------
        label : str
            One of the labels.
        value : float
            > 0.
        """
        i = self.index(label)
        self.M[i, i] += _checks.positive("value", value)

    def element(self, body: dict, stiffness, damping=0.0, inputs: dict | None = None) -> None:
        """A spring and damper on d = Σ body coefficients · q − Σ input coefficients · w.

        Parameters
        ----------
        body : dict of str to float
            Coefficients of the coordinates in the deflection.
        stiffness, damping : float
            N/m and N·s/m (per radian for rotations), each ≥ 0 (a negative stiffness, such
            as gravity's, enters through :meth:`block`).
        inputs : dict of int to float, optional
            Coefficients of the track inputs in the deflection (input index in [0, q − 1]).
        """
        g = self._vector(body, "body")
        k = _checks.nonnegative("stiffness", stiffness)
        c = _checks.nonnegative("damping", damping)
        h = np.zeros(self.GK.shape[1])
        if inputs is not None:
            _checks.instance("inputs", inputs, dict, "dict of input index to coefficient or None")
            for j, value in inputs.items():
                h[self._input("inputs key", j)] += _checks.scalar(f"inputs[{j!r}]", value)
        self.K += k * np.outer(g, g)
        self.C0 += c * np.outer(g, g)
        self.GK += k * np.outer(g, h)
        self.GC += c * np.outer(g, h)
        self.KW += k * np.outer(h, h)
        self.CW += c * np.outer(h, h)

    def _input(self, name: str, j) -> int:
        """A track input index in [0, q − 1]."""
        q = self.GK.shape[1]
        if q == 0:
            raise ValueError(f"{name}: this assembly has no track inputs (n_inputs = 0), got {j!r}")
        return _checks.integer(name, j, low=0, high=q - 1)

    def block(self, labels: Sequence[str], *, C1=None, K=None) -> None:
        """Add a block of creep damping C₁ (N) and stiffness (N/m) on some coordinates.

        Parameters
        ----------
        labels : sequence of str
            The coordinates of the block's rows and columns, each once.
        C1, K : array_like, (k, k), optional
            Finite, of either sign (creep and gravity terms).
        """
        rows = [
            self.labels.index(_checks.choice("labels", s, self.labels))
            for s in _checks.strings("labels", labels, unique=True)
        ]
        k = len(rows)
        C1 = None if C1 is None else _checks.array("C1", C1, shape=(k, k))
        K = None if K is None else _checks.array("K", K, shape=(k, k))
        idx = np.ix_(rows, rows)
        if C1 is not None:
            self.C1[idx] += C1
        if K is not None:
            self.K[idx] += K

    def track_force(self, label: str, j: int, stiffness: float, damping: float = 0.0) -> None:
        """Add G_K[label, j] (N/m) and G_C[label, j] (N·s/m): a force on one coordinate per unit of input j.

        Parameters
        ----------
        label : str
            One of the labels.
        j : int
            Index of the track input, in [0, q − 1].
        stiffness, damping : float
            N/m and N·s/m per unit input, finite, of either sign.
        """
        i = self.index(label)
        j = self._input("j", j)
        self.GK[i, j] += _checks.scalar("stiffness", stiffness)
        self.GC[i, j] += _checks.scalar("damping", damping)
        self.input_block_known = False  # a force with no element: the reaction on the input is not known

    def system(self, **inputs) -> LinearSystem:
        """The assembled :class:`LinearSystem`.

        Parameters
        ----------
        **inputs
            ``input_positions``, ``input_kinds``, ``input_rails``, ``gravity_load``.

        Returns
        -------
        LinearSystem
        """
        known = self.input_block_known
        return LinearSystem(
            self.M, self.C0, self.C1, self.K, self.GK, self.GC, tuple(self.labels),
            wheelsets=tuple(self.wheelsets), input_stiffness=self.KW if known else None,
            input_damping=self.CW if known else None, **inputs,
        )  # fmt: skip
