"""Results out as tables: the one place a result's arrays become named columns, a CSV or a DataFrame.

A result dataclass that holds arrays along a common axis (time, speed, frequency, position...)
inherits :class:`Tabular` and declares its columns and their units; ``table()``, ``to_csv(path)``
and ``to_pandas()`` come from here and nowhere else. It sits on the ground floor with
:mod:`raildyn._checks`: it imports nothing of raildyn, so every chapter's results may use it.

Conventions, the same for every result:

* a column is named ``"field (unit)"``, e.g. ``"t (s)"``; a dimensionless quantity has the unit
  ``-`` (written ``"damping_ratios (-)"``), so that every name carries its unit in parentheses;
* a field of more than one axis gives one column for each entry across the row axis, named by
  the result's own coordinate labels where it carries them (``"frequencies_hz[wheelset y] (Hz)"``),
  or the values of the other axis where they are numbers (``"deflection[speeds=20.0] (m)"``), else
  by its index (``"x[0] (m)"``, ``"wheel_loads[0][1] (N)"``);
* a complex field gives two columns, its real and imaginary parts (``"eigenvalues[0].real
  (rad/s)"``);
* the result's scalars (a critical speed, a resonance speed) are no columns: they go in the
  DataFrame's ``attrs`` and in the CSV's leading comment lines ``# name (unit) = value``, under
  the same ``"name (unit)"`` keys;
* the CSV holds every number to full precision (the shortest text that reads back to the same
  float), so that it reads back exactly; a flag is written 1 or 0 (the DataFrame keeps it a bool).

pandas is imported inside :meth:`Tabular.to_pandas` only: importing a model module never
imports it.
"""

from __future__ import annotations

import csv
import itertools
import os
from pathlib import Path
from typing import ClassVar

import numpy as np

#: The unit of a dimensionless column (a ratio, a fraction, a flag, a count).
DIMENSIONLESS = "-"


def _cell(value) -> str:
    """A number as the shortest text that reads back to the same value (booleans as 1 and 0); text
    as it is."""
    if isinstance(value, (str, np.str_)):
        return str(value)
    if isinstance(value, (bool, np.bool_)):
        return "1" if value else "0"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    return repr(float(value))


class Tabular:
    """Mixin of a result dataclass: its arrays as a table of named columns with units.

    A subclass declares, as tuples of pairs (immutable, so that no instance can change them):
    ``_columns``, (field name, unit) in column order, the first being the row axis (the time,
    the speeds...), its units copied from the class's "Attributes"; ``_scalars``, (field name,
    unit) for the scalars that go with the table; ``_labels``, (field name, name of the
    attribute holding the labels of that field's columns); and ``_by_row``, the fields stored
    with the row axis last, shape (n, m) against m rows (every other field has its row axis
    first). A field that is None (an optional array not computed) gives no column; a field of
    text (a status per row) gives a column of text.

    Examples
    --------
    >>> from raildyn.vibration import modal_analysis
    >>> modes = modal_analysis([[1.0, 0.0], [0.0, 2.0]], [[300.0, -100.0], [-100.0, 100.0]])
    >>> modes.table()[0]
    ['natural_frequencies (rad/s)', 'mode_shapes[0] (kg^(−1/2))', 'mode_shapes[1] (kg^(−1/2))']
    """

    _columns: ClassVar[tuple[tuple[str, str], ...]] = ()
    _scalars: ClassVar[tuple[tuple[str, str], ...]] = ()
    _labels: ClassVar[tuple[tuple[str, str], ...]] = ()
    _by_row: ClassVar[tuple[str, ...]] = ()

    def table(self) -> tuple[list[str], list[np.ndarray]]:
        """The result's arrays as named columns of one length.

        Returns
        -------
        names : list of str
            One name for each column, ``"field (unit)"``, or ``"field[label] (unit)"`` for an
            entry of a field of more than one axis.
        columns : list of ndarray
            The columns, each 1-D and of the row axis' length, in the order of ``names``.
        """
        names: list[str] = []
        columns: list[np.ndarray] = []
        rows = None
        for field, unit in self._columns:
            value = getattr(self, field)
            if value is None:
                continue
            value = np.atleast_1d(np.asarray(value))
            if field in self._by_row:
                value = np.moveaxis(value, -1, 0)
            if rows is None:
                rows = value.shape[0]
            if value.shape[0] != rows:
                # The declaration, not the caller, is wrong: no user input reaches this.
                raise ValueError(f"{type(self).__name__}.{field} has shape {value.shape}, not {rows} rows")
            for name, column in self._split(field, unit, value):
                names.append(name)
                columns.append(column)
        return names, columns

    def _split(self, field: str, unit: str, value: np.ndarray):
        """(name, column) for each column of one field: each entry across its trailing axes, and the
        real and imaginary parts of a complex one."""
        if value.ndim == 1:
            parts = [(field, value)]
        else:
            flat = value.reshape(value.shape[0], -1)
            source = dict(self._labels).get(field)
            labels = None if source is None else getattr(self, source)
            if labels is not None and len(labels) == flat.shape[1] and value.ndim == 2:
                # a number alone does not say what it is: "deflection[speeds=20.0]", not "deflection[20.0]"
                tags = [label if isinstance(label, str) else f"{source}={label}" for label in labels]
            else:
                tags = [
                    "][".join(map(str, index)) for index in itertools.product(*map(range, value.shape[1:]))
                ]
            parts = [(f"{field}[{tag}]", flat[:, j]) for j, tag in enumerate(tags)]
        for name, column in parts:
            if np.iscomplexobj(column):
                yield f"{name}.real ({unit})", column.real
                yield f"{name}.imag ({unit})", column.imag
            else:
                yield f"{name} ({unit})", column

    def _scalar_items(self) -> dict[str, object]:
        """``"name (unit)"`` → value, for each of the result's scalars."""
        return {f"{field} ({unit})": getattr(self, field) for field, unit in self._scalars}

    def to_csv(self, path) -> Path:
        """Write the table to a CSV file: scalars as comment lines, a header row, then the rows.

        The file starts with one line ``# name (unit) = value`` for each scalar of the result,
        then the column names (:meth:`table`), then one row for each entry of the row axis. The
        numbers are written to full precision, so that ``numpy.loadtxt(path, delimiter=",",
        skiprows=1)`` (comments are skipped) reads back exactly the result's arrays. pandas is not
        needed.

        Parameters
        ----------
        path : str or os.PathLike
            The file to write (replaced if it exists); its folder must exist.

        Returns
        -------
        pathlib.Path
            The file written.
        """
        return write_csv(path, *self.table(), notes=self._scalar_items())

    def to_pandas(self):
        """The table as a pandas DataFrame, the scalars in its ``attrs``.

        Returns
        -------
        pandas.DataFrame
            One column for each name of :meth:`table`, one row for each entry of the row axis;
            ``attrs`` maps ``"name (unit)"`` to each scalar of the result.

        Raises
        ------
        ImportError
            When pandas is not installed (``to_csv`` needs no pandas).
        """
        try:
            import pandas as pd  # deferred: a heavy library that a model module never imports
        except ImportError as error:
            raise ImportError(
                f"{type(self).__name__}.to_pandas needs pandas: install it (pip install pandas), "
                "or write the table with to_csv(path), which does not"
            ) from error
        names, columns = self.table()
        frame = pd.DataFrame(dict(zip(names, columns, strict=True)))
        frame.attrs.update(self._scalar_items())
        return frame


def write_csv(path, names: list[str], columns, notes: dict[str, object] | None = None) -> Path:
    """Write columns to a CSV file: ``notes`` as comment lines ``# key = value``, a header row, the rows.

    The one CSV writer of raildyn (a result's :meth:`Tabular.to_csv`, a figure's data): numbers to full
    precision, flags as 1 and 0, text as it is.

    Parameters
    ----------
    path : str or os.PathLike
        The file to write (replaced if it exists); its folder must exist.
    names : list of str
        The column names, the header row.
    columns : sequence of sequences
        The columns, one for each name, all of one length.
    notes : dict, optional
        Lines written before the header, ``# key = value``.

    Returns
    -------
    pathlib.Path
        The file written.
    """
    if isinstance(path, bool) or not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a file name (str or os.PathLike), got {type(path).__name__} {path!r}")
    target = Path(path)
    if not str(path) or target.is_dir():
        raise ValueError(f"path must name a file, got the folder {str(path)!r}")
    if not target.parent.is_dir():
        raise ValueError(
            f"path must be in an existing folder, got {str(path)!r}: {str(target.parent)!r} does not exist"
        )
    with target.open("w", newline="", encoding="utf-8") as file:
        for key, value in (notes or {}).items():
            file.write(f"# {key} = {_cell(value)}\n")
        writer = csv.writer(file)
        writer.writerow(names)
        writer.writerows(zip(*([_cell(v) for v in column] for column in columns), strict=True))
    return target
