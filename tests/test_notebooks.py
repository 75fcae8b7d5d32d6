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
    # (conftest.STRICT, an IPython start-up file); its executed copy is read here rather than run a
    # second time.
    proc, _ = built_book
    executed = ROOT / "book" / "_build" / "jupyter_execute" / "notebooks" / path.name
    assert executed.exists(), f"{path.name} was not executed by the book build:\n{proc.stderr[-3000:]}"
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
