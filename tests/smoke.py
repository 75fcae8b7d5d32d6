"""The smoke test of an installed raildyn, run by an environment's own Python from a folder outside the
repository (tests/test_packaging.py runs it in a fresh environment holding the built wheel).

It imports every public module of the installed package, runs the command line's help, writes one
figure with its data, copies the chapter notebooks and reads the data files the models need, and prints
one line a check; any failure ends it with a traceback and a non-zero status.

Usage: ``python smoke.py WORKDIR``
"""

import importlib
import pkgutil
import subprocess
import sys
from pathlib import Path

import raildyn


def main(work: Path) -> None:
    """Run the checks, writing what they make under ``work``."""
    print("raildyn from", Path(raildyn.__file__).parent)
    public = sorted(
        m.name
        for m in pkgutil.walk_packages(raildyn.__path__, "raildyn.")
        if not any(part.startswith("_") for part in m.name.split(".")[1:])
    )
    for name in public:
        importlib.import_module(name)
    print("imported", len(public), "public modules")
    subprocess.run([sys.executable, "-m", "raildyn", "--help"], check=True, capture_output=True)
    print("help ran")
    figures = work / "figures"
    command = [sys.executable, "-m", "raildyn", "figures", "--only", "fig1.4", "--data", "--out", figures]
    subprocess.run(command, check=True, capture_output=True)
    print("figure written:", sorted(p.name for p in figures.iterdir()))
    notebooks = work / "notebooks"
    subprocess.run([sys.executable, "-m", "raildyn", "notebooks", notebooks], check=True, capture_output=True)
    print("notebooks copied:", len(list(notebooks.glob("*.ipynb"))))
    from raildyn.contact import worn_rail, worn_wheel  # the files the models read
    from raildyn.validation.measured import lerelva_strain

    print(
        "data read:",
        worn_wheel().lateral.size,
        "wheel points,",
        worn_rail().lateral.size,
        "rail points,",
        lerelva_strain().strain.shape,
        "strains",
    )


if __name__ == "__main__":
    main(Path(sys.argv[1]))
