"""ruff lints and formats the package, the tests, the benchmarks, the book's extension and the notebooks."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PATHS = ["raildyn", "tests", "benchmarks", "book/_ext", "notebooks", "scripts"]
RUFF = str(Path(sys.executable).parent / "ruff")


def test_ruff_check():
    proc = subprocess.run([RUFF, "check", *PATHS], cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_ruff_format():
    proc = subprocess.run([RUFF, "format", "--check", *PATHS], cwd=ROOT, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
