"""Every chapter notebook runs top to bottom with no error, no warning and nothing on stderr.

The book build executes them (once, strict: see ``tests/conftest.py``); these tests read what it ran.
"""

import re
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


def test_there_are_notebooks():
    assert NOTEBOOKS, "notebooks/ holds no .ipynb"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_stored_without_outputs(path):
    nb = nbformat.read(path, as_version=4)
    with_outputs = [
        i for i, c in enumerate(nb.cells) if c.cell_type == "code" and (c.outputs or c.execution_count)
    ]
    assert not with_outputs, f"{path.name}: cells {with_outputs} carry outputs; strip them before committing"


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs_clean(path, built_book):
    # The book build executes every notebook once, in a kernel where any warning is an error
    # (tests/background.py's STRICT, an IPython start-up file); its executed copy is read here rather than
    # run a second time.
    proc, _ = built_book
    executed = ROOT / "book" / "_build" / "jupyter_execute" / "notebooks" / path.name
    assert executed.exists(), (
        f"{path.name} was not executed by the book build:\n{(proc.stdout + proc.stderr)[-3000:]}"
    )
    nb = nbformat.read(executed, as_version=4)
    source = nbformat.read(path, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert len(code) == sum(c.cell_type == "code" for c in source.cells), f"{path.name}: cells missing"
    assert all(c.execution_count for c in code if c.source.strip()), f"{path.name}: not every cell ran"
    for index, cell in enumerate(nb.cells):
        for output in cell.get("outputs", []):
            assert output.output_type != "error", f"{path.name} cell {index}: {output.get('ename')}"
            if output.output_type == "stream":
                assert output.name != "stderr", f"{path.name} cell {index} wrote to stderr:\n{output.text}"


_ROLE = re.compile(r"\{(cite|eq|ref|numref|doc)(:\w+)?\}`")
_CITE = re.compile(r"\]\(cite:([^)\s]+)\)")
_EQ = re.compile(r"\]\(eq:([^)\s]+)\)")
_LABEL = re.compile(r"\$\$\s*\((eq-[\w-]+)\)")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_citations_read_as_text_outside_the_book(path):
    # JupyterLab and Voilà show a MyST role as raw markup ("{cite}`kalker1967`"); notebooks link
    # instead ([Kalker 1967](cite:kalker1967)), and the book turns the links into its roles.
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    from raildyn_book import load_bib

    bib = load_bib()
    text = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "markdown")
    assert not _ROLE.findall(text), f"{path.name}: MyST roles that JupyterLab shows raw"
    unknown = {k for keys in _CITE.findall(text) for k in keys.split(",") if k not in bib}
    assert not unknown, f"{path.name}: citations of keys no .bib holds: {unknown}"
    labels = {
        l for nb in NOTEBOOKS for c in nbformat.read(nb, as_version=4).cells for l in _LABEL.findall(c.source)
    }
    assert not set(_EQ.findall(text)) - labels, f"{path.name}: links to equations no notebook labels"


def _answer_cells(nb) -> list[int]:
    """Indices of the code cells that answer a question: every code cell after the "Exercises"
    heading, and every code cell that follows a question (**1.**, **a.**) elsewhere."""
    out, in_exercises = [], False
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "markdown" and re.match(r"#+ Exercises", cell.source):
            in_exercises = True
        elif cell.cell_type == "markdown" and re.match(r"#+ ", cell.source):
            in_exercises = in_exercises and not re.match(r"#+ Summary", cell.source)
        previous = nb.cells[i - 1].source if i else ""
        question = re.search(r"^\*\*(\d+|[a-z])\.\*\*", previous, flags=re.M)
        if cell.cell_type == "code" and (in_exercises or question):
            out.append(i)
    return out


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_answers_are_hidden_in_jupyterlab_and_in_the_book(path):
    # JupyterLab honours the cell's "jupyter" metadata, the book its hide-cell tag: the answer's code and
    # its output stay folded under the question until the reader opens them.
    nb = nbformat.read(path, as_version=4)
    answers = _answer_cells(nb)
    assert len(answers) >= 5, f"{path.name}: {len(answers)} answered exercises, at least five wanted"
    for i in answers:
        meta = nb.cells[i].metadata
        assert "hide-cell" in meta.get("tags", []), f"{path.name}: answer cell {i} not tagged hide-cell"
        assert meta.get("jupyter") == {"source_hidden": True, "outputs_hidden": True}, (
            f"{path.name}: answer cell {i} shows in JupyterLab"
        )


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_no_answer_prints_unhidden_in_the_built_book(path, built_book):
    proc, html = built_book
    assert proc.returncode == 0, (proc.stdout + proc.stderr)[-4000:]
    page = (html / "notebooks" / f"{path.stem}.html").read_text(encoding="utf-8")
    # The book renders an answer cell as a container whose whole content, code and output, is one
    # folded <details> block; nothing of it is printed before the fold.
    cells = re.findall(r'<div class="cell tag_hide-cell[^"]*">\s*(<[^>]*>)', page)
    answers = _answer_cells(nbformat.read(path, as_version=4))
    assert len(cells) == len(answers), f"{path.name}: {len(cells)} folded cells for {len(answers)} answers"
    unfolded = [opening for opening in cells if not re.match(r'<details class="[^"]*\bhide\b', opening)]
    assert not unfolded, f"{path.name}: answer cells whose content is not folded: {unfolded[:3]}"


def test_no_line_of_inline_mathematics_starts_like_a_list_item():
    # Markdown reads a line that starts with "+ " or "- " as a list item even inside $...$, and the
    # mathematics is then left as raw TeX (the printed book showed it; the browser test did not).
    found = []
    for path in NOTEBOOKS:
        for i, cell in enumerate(nbformat.read(path, as_version=4).cells):
            if cell.cell_type != "markdown":
                continue
            paragraph = []
            for line in cell.source.split("\n"):
                if not line.strip():
                    paragraph = []
                    continue
                text = re.sub(r"\$\$.*?\$\$", "", "\n".join(paragraph), flags=re.S)
                inline_open = text.count("$$") % 2 == 0 and text.replace("$$", "").count("$") % 2 == 1
                if inline_open and re.match(r"\s{0,3}[+*-]\s", line):
                    found.append(f"{path.name} cell {i}: {line[:60]!r}")
                paragraph.append(line)
    assert not found, "\n".join(found)


COLAB = re.compile(
    r'if "google\.colab" in sys\.modules:\n    if importlib\.util\.find_spec\("raildyn"\) is None:'
)


def _colab_cell(path):
    nb = nbformat.read(path, as_version=4)
    return next(c for c in nb.cells if c.cell_type == "code")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_colab_installs_raildyn_first_and_nothing_else_does(path, monkeypatch):
    import subprocess

    import yaml

    cell = _colab_cell(path)
    assert COLAB.search(cell.source), f"{path.name}: the first code cell is not the Colab installer"
    assert "remove-cell" in cell.metadata.get("tags", []), f"{path.name}: the installer shows in the book"
    url = yaml.safe_load((ROOT / "book" / "_config.yml").read_text())["repository"]["url"]
    assert f"git+{url}" in cell.source, f"{path.name}: the installer does not install from {url}"
    # Every chapter's installer is the same cell.
    assert cell.source == _colab_cell(NOTEBOOKS[0]).source
    # Outside Colab (here, in the book, under Voilà) the cell runs and installs nothing.
    monkeypatch.setattr(subprocess, "check_call", lambda *a, **k: pytest.fail("installed outside Colab"))
    exec(compile(cell.source, path.name, "exec"), {})


def _on_colab(monkeypatch, *, raildyn_installed: bool, widgets_version: str | None):
    """Run the installer as Colab would: a google.colab module whose output records the widget manager
    switched on, pip and the compile recorded instead of run, and the ipywidgets the session had loaded."""
    import importlib.util
    import subprocess
    import types

    calls, enabled = [], []
    colab = types.ModuleType("google.colab")
    colab.output = types.SimpleNamespace(enable_custom_widget_manager=lambda: enabled.append(True))
    monkeypatch.setitem(sys.modules, "google", types.ModuleType("google"))
    monkeypatch.setitem(sys.modules, "google.colab", colab)
    monkeypatch.setattr(subprocess, "check_call", lambda args, **k: calls.append(args[2:]))
    found = importlib.util.find_spec

    def find_spec(name, *args):
        return None if name == "raildyn" and not raildyn_installed else found(name, *args)

    monkeypatch.setattr(importlib.util, "find_spec", find_spec)
    if widgets_version is None:
        monkeypatch.delitem(sys.modules, "ipywidgets", raising=False)
    else:
        monkeypatch.setitem(sys.modules, "ipywidgets", types.SimpleNamespace(__version__=widgets_version))
    source = _colab_cell(NOTEBOOKS[0]).source
    exec(compile(source, "colab", "exec"), {})
    return calls, enabled


def test_on_colab_the_installer_installs_compiles_and_switches_on_the_widget_manager(monkeypatch):
    calls, enabled = _on_colab(monkeypatch, raildyn_installed=False, widgets_version=None)
    install = ["pip", "install", "-q", "git+https://github.com/raildyn/raildyn"]
    assert calls == [install, ["raildyn", "compile"]]
    assert enabled == [True]


def test_on_colab_a_second_run_installs_nothing_and_still_switches_on_the_manager(monkeypatch):
    calls, enabled = _on_colab(monkeypatch, raildyn_installed=True, widgets_version="8.1.5")
    assert calls == [] and enabled == [True]


def test_on_colab_a_session_that_loaded_ipywidgets_7_is_told_to_restart(monkeypatch):
    # Colab has shipped ipywidgets 7.7; the install puts 8 in its place, which a running session cannot load.
    with pytest.raises(SystemExit, match="Restart the session"):
        _on_colab(monkeypatch, raildyn_installed=False, widgets_version="7.7.1")
