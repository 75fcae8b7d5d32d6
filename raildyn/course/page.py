"""The course on the page: questions that check themselves without a kernel
(:class:`~raildyn.course.SelfCheck`), and worked answers whose output stays folded when a notebook runs
(a cell that opens with ``#| answer``)."""

from __future__ import annotations

import hashlib
import html
import itertools
import json
import sys
from dataclasses import dataclass

from raildyn import _checks
from raildyn._progress import in_the_app
from raildyn.course.answers import SLIPS

__all__ = ["ANSWER_FOLD", "ANSWER_LINE", "SelfCheck"]


# The page's check of a number: the same rules as check() (the tolerance, then the sign, then SLIPS,
# then a square or a square root), in JavaScript so that the static book answers with no kernel.
_SELF_CHECK_JS = """(function () {
  const box = document.getElementById(%(id)s), spec = %(spec)s;
  const say = box.querySelector('.raildyn-selfcheck-verdict');
  const close = (a, b, rtol, atol) => Math.abs(a - b) <= atol + rtol * Math.abs(b);
  function verdict(a) {
    const e = spec.expected, r = spec.rtol, t = spec.atol;
    if (close(a, e, r, t)) return [true, 'right'];
    const sign = 'the sign is wrong: which way is the quantity positive?';
    if (e !== 0 && close(-a, e, r, t)) return [false, sign];
    for (const [factor, why] of spec.slips) {
      if (e !== 0 && close(a, factor * e, r, t * factor)) return [false, why];
      if (e !== 0 && close(-a, factor * e, r, t * factor)) return [false, why + ' (and the sign is wrong)'];
    }
    const square = 'the square of the answer: a variance where an RMS value was asked?';
    const root = 'the square root of the answer: an RMS value where a variance was asked?';
    if (e > 0 && a > 0 && close(a, e * e, r, t)) return [false, square];
    if (e > 0 && a > 0 && close(a * a, e, r, t)) return [false, root];
    return [false, 'not yet: check the method, not a unit'];
  }
  box.querySelector('button').addEventListener('click', () => {
    let right, why;
    if (spec.choices) {
      const picked = box.querySelector('input[type=radio]:checked');
      if (!picked) { say.textContent = 'Pick one first.'; return; }
      right = Number(picked.value) === spec.right;
      why = right ? 'right' : 'not that one: think again';
    } else {
      const typed = box.querySelector('input').value.trim();
      const a = Number(typed.replace(',', '.').replace('\\u2212', '-'));
      if (!Number.isFinite(a) || typed === '') { say.textContent = 'Type a number first.'; return; }
      [right, why] = verdict(a);
    }
    say.textContent = (right ? '\\u2713 ' : '\\u2717 ') + why + (right && spec.why ? ' ' + spec.why : '');
    say.dataset.right = right;
  });
})();"""

_SELF_CHECKS = itertools.count()


def _inline_math(text: str) -> str:
    """``text`` as HTML, each $…$ in it marked up as the book marks inline mathematics (a span of class
    "math" around \\(…\\)), which the book's MathJax and JupyterLab's both typeset."""
    parts = html.escape(text).split("$")
    if len(parts) % 2 == 0:
        raise ValueError(f"question must pair its $ signs (each formula between two), got {text!r:.80}")
    return "".join(
        f'<span class="math notranslate nohighlight">\\({p}\\)</span>' if i % 2 else p
        for i, p in enumerate(parts)
    )


@dataclass(frozen=True, repr=False)
class SelfCheck:
    """A question that checks its answer in the page: a number within a tolerance, or one choice of several.

    Displayed in a notebook (its ``_repr_html_``), it is a question, an answer box and a "Check"
    button; the check runs in the page's JavaScript, so it answers in the static book, in the
    lecture-room app and in JupyterLab alike, with no kernel. A number is held as :func:`check` holds
    it and a wrong one meets the same slips (the sign, 2π, a unit, a factor two).

    Attributes
    ----------
    question : str
        What is asked (not empty; HTML is escaped; a formula stands between two dollar signs, which
        the page's MathJax typesets).
    expected : float or None
        The right number, finite, in ``unit``; None for a choice.
    unit : str
        The unit the answer is asked in, shown beside the box (may be empty).
    rtol, atol : float
        The tolerance of a number, as for :func:`check`. Default 2 % and 0.
    choices : tuple of str
        For a choice: the options (at least two, different); empty for a number.
    right : int or None
        For a choice: the index of the right option.
    why : str
        Shown after a right answer: the reason in a sentence (may be empty).
    """

    question: str
    expected: float | None = None
    unit: str = ""
    rtol: float = 0.02
    atol: float = 0.0
    choices: tuple = ()
    right: int | None = None
    why: str = ""

    def __post_init__(self):
        if not isinstance(self.question, str) or not self.question.strip():
            raise ValueError(f"question must be a non-empty string, got {self.question!r}")
        _inline_math(self.question)
        for key in ("unit", "why"):
            if not isinstance(getattr(self, key), str):
                raise TypeError(f"{key} must be a string, got {type(getattr(self, key)).__name__}")
        _checks.scalar("rtol", self.rtol, low=0.0, high=1.0)
        _checks.nonnegative("atol", self.atol)
        if not isinstance(self.choices, tuple | list):
            raise TypeError(
                f"choices must be a tuple of strings (none for a number), got {self.choices!r:.60}"
            )
        if self.choices:
            choices = _checks.strings("choices", self.choices, unique=True)
            if len(choices) < 2:
                raise ValueError(f"choices must offer at least two options, got {len(choices)}")
            if self.expected is not None:
                raise ValueError(f"expected must be None for a choice, got {self.expected!r}")
            _checks.integer("right", self.right, low=0, high=len(choices) - 1)
        else:
            if self.expected is None:
                raise ValueError("expected must be a number for a question without choices, got None")
            _checks.scalar("expected", self.expected)
            if self.right is not None:
                raise ValueError(f"right must be None for a number (no choices), got {self.right!r}")

    def __repr__(self) -> str:  # the question only: a plain-text display must not give the answer away
        return f"SelfCheck({self.question!r})"

    def _repr_html_(self) -> str:
        tag = int(hashlib.sha256(self.question.encode()).hexdigest()[:7], 16)  # apart on one page too
        box = f"raildyn-selfcheck-{next(_SELF_CHECKS)}-{tag}"
        spec = {"rtol": self.rtol, "atol": self.atol, "why": self.why, "slips": SLIPS}
        if self.choices:
            spec |= {"choices": len(self.choices), "right": self.right}
            field_ = "".join(
                f'<label><input type="radio" name="{box}" value="{i}"> {html.escape(c)}</label><br>'
                for i, c in enumerate(self.choices)
            )
        else:
            spec["expected"] = float(self.expected)
            unit = f" {html.escape(self.unit)}" if self.unit else ""
            field_ = f'<input type="text" inputmode="decimal" size="12" aria-label="your answer">{unit} '
        script = _SELF_CHECK_JS % {"id": json.dumps(box), "spec": json.dumps(spec)}
        return (
            f'<div class="raildyn-selfcheck" id="{box}">'
            f"<p><b>Check yourself:</b> {_inline_math(self.question)}</p>"
            f"<p>{field_}<button>Check</button></p>"
            f'<p class="raildyn-selfcheck-verdict" aria-live="polite"></p><script>{script}</script></div>'
        )


#: What a folded answer's summary says (the page shows it; the answer's output is under it).
ANSWER_FOLD = "Show the answer"


def _math(latex: str) -> str:
    """A LaTeX output ($…$ or $$…$$, as sympy gives it) as the book marks displayed mathematics."""
    body = latex.strip().strip("$").strip()
    return f'<div class="math notranslate nohighlight">\\[{html.escape(body)}\\]</div>'


def _fold(items: list[dict]) -> str:
    """What an answer printed ({"text": …}) and displayed ({"data": mime bundle}), as HTML folded under
    :data:`ANSWER_FOLD`."""
    parts = []
    for item in items:
        data = item.get("data", {})
        if "text" in item:
            parts.append(f"<pre>{html.escape(item['text'])}</pre>" if item["text"].strip() else "")
        elif "text/html" in data:
            parts.append(data["text/html"])
        elif "image/png" in data:
            parts.append(f'<img src="data:image/png;base64,{data["image/png"]}" alt="the answer\'s figure">')
        elif "image/svg+xml" in data:
            parts.append(data["image/svg+xml"])
        elif "text/latex" in data:
            parts.append(_math(data["text/latex"]))
        else:
            parts.append(f"<pre>{html.escape(data.get('text/plain', ''))}</pre>")
    return f'<details class="raildyn-answer"><summary>{ANSWER_FOLD}</summary>{"".join(parts)}</details>'


def _run_recorded(shell, cell: str) -> tuple:
    """Run ``cell`` with IPython's own capture; returns (result, items, stderr), the items being what it
    printed ({"text": …}, first) and what it displayed ({"data": …}, in order)."""
    from IPython.utils.capture import capture_output

    # IPython's capture as it is: a stand-in for sys.stdout that also recorded the displays' order made
    # the lecture-room app lose widget models on a busy machine, so printed text comes first.
    with capture_output() as captured:
        result = shell.run_cell(cell, store_history=False, silent=False)
    items = [{"text": captured.stdout}] + [{"data": output.data} for output in captured.outputs]
    return result, items, captured.stderr


def _answer(line: str, cell: str) -> None:
    """``%%answer`` (what ``#| answer`` runs): run the cell, then show what it printed and drew folded.

    JupyterLab unfolds a cell's outputs whenever the cell runs, so a worked answer hidden by the
    notebook's metadata would show after "Run All"; folded in its own output it stays hidden until
    opened. An error is shown unfolded and fails the cell. The lecture-room app shows no answer
    (``raildyn._progress.in_the_app``), so there an answer is not worked out at all:
    nothing of it can reach the projector, and the page is ready sooner. (No other cell uses a name an
    answer defines: tests/test_course.py holds the notebooks to that.)
    """
    from IPython import get_ipython
    from IPython.display import HTML, display

    if line.strip():
        raise ValueError(f"%%answer takes no arguments, got {line.strip()!r}")
    if in_the_app():
        return
    result, items, errors = _run_recorded(get_ipython(), cell)
    sys.stderr.write(errors)  # a warning stays a warning (the tests make warnings errors)
    if not result.success:
        sys.stdout.write("".join(item.get("text", "") for item in items))  # the traceback, unfolded
        result.raise_error()
    widgets = [i for i in items if "application/vnd.jupyter.widget-view+json" in i.get("data", {})]
    display(HTML(_fold([i for i in items if i not in widgets])))
    for widget in widgets:  # a live widget cannot fold into HTML: it shows as it is
        display(widget["data"], raw=True)


#: The first line of a worked answer's cell: a comment, so that the cell stays Python (linted, parsed,
#: and run as plain code where the extension is not loaded), and all a collapsed cell shows of it.
ANSWER_LINE = "#| answer"


def _answer_cells(lines: list[str]) -> list[str]:
    """IPython input transformer: a cell that opens with :data:`ANSWER_LINE` runs as ``%%answer``."""
    if lines and lines[0].strip() == ANSWER_LINE:
        return ["%%answer\n", *lines[1:]]
    return lines


def load_ipython_extension(ipython) -> None:
    """``%load_ext raildyn.course``: a cell that opens with ``#| answer`` is a worked answer.

    Registers the cell magic ``%%answer`` (:func:`_answer`) and an input transformer that runs every
    cell whose first line is ``#| answer`` through it.
    """
    ipython.register_magic_function(_answer, magic_kind="cell", magic_name="answer")
    if _answer_cells not in ipython.input_transformers_cleanup:
        ipython.input_transformers_cleanup.append(_answer_cells)
