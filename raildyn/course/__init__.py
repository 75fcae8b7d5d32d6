"""Answers a student can check and homework a lecturer can set (the course's tools).

* :func:`check` holds an answer to the expected value within a tolerance and, when it is off, says
  why if the slip is a common one: the sign, a factor 2π (hertz for radians a second), a unit
  (millimetres for metres, km/h for m/s, a mass for a weight, degrees for radians), a factor two
  (a peak-to-peak value for an amplitude), a square or a square root (a variance for an RMS value).
* :class:`Exercise` draws each student's own values of a numeric exercise from their id, always the
  same for the same id, and computes the answer with raildyn: a lecturer sets one exercise and every
  student meets different numbers.
* :func:`mark` and :func:`mark_csv` mark a class's answers (a CSV of student, exercise, answer), and
  ``python -m raildyn mark ANSWERS.csv KEY.py`` does so from the command line, KEY.py listing the
  exercises as ``EXERCISES``.
* :func:`check_matrices` holds the matrices a student derived (with
  :func:`raildyn.derivations.lagrange`) to a model's, entry by entry, and names the first entry that
  is off and the likely slip.
* :class:`SelfCheck` is a question that answers in the page itself, without a kernel: the static book,
  the lecture-room app and JupyterLab alike check a number (with :func:`check`'s slips) or a choice
  in the page's JavaScript.
* ``%load_ext raildyn.course`` makes a cell that opens with the line ``#| answer`` a worked answer: its
  output stays folded under "Show the answer" when the notebook is run, in JupyterLab as in the
  lecture-room app.

Where things are: :mod:`~raildyn.course.answers` (an answer and a derivation checked),
:mod:`~raildyn.course.homework` (variants and marks) and :mod:`~raildyn.course.page` (what the page
itself does: self-checks, folded answers).
"""

from raildyn.course.answers import Verdict, check, check_matrices
from raildyn.course.homework import Exercise, Mark, mark, mark_csv
from raildyn.course.page import SelfCheck
from raildyn.course.page import load_ipython_extension as load_ipython_extension  # %load_ext raildyn.course

__all__ = ["Exercise", "Mark", "SelfCheck", "Verdict", "check", "check_matrices", "mark", "mark_csv"]
