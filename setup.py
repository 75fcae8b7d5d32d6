"""Build hook: a wheel carries the chapter notebooks as package data (``raildyn/_notebooks``), so that
``python -m raildyn notebooks DIR`` copies them for a reader who installed raildyn with pip. Everything
else about the package is in pyproject.toml."""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py


class BuildWithNotebooks(build_py):
    """setuptools' build_py, then the notebooks copied from ``notebooks/`` into the built package."""

    def run(self):
        super().run()
        target = Path(self.build_lib, "raildyn", "_notebooks")
        target.mkdir(parents=True, exist_ok=True)
        for notebook in sorted(Path("notebooks").glob("*.ipynb")):
            shutil.copy2(notebook, target / notebook.name)


setup(cmdclass={"build_py": BuildWithNotebooks})
