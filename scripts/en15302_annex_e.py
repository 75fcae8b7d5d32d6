"""Write the EN 15302 Annex E reference cases kept in ``raildyn/contact/data/`` (one run, output committed).

Source: the public transcription of EN 15302's Annex E in the repository
``criogenox/B_ECC-Equivalent-Conicity-Calculation`` on GitHub (MIT licence), commit 6e33d43 (6 December 2024),
folder ``src/main/resources/eqcon/mvnver/data/``: for each combination E1–E9,
``dr_ce_E<n>.dat`` holds the rolling-radius difference Δr (mm, one value a line) on a grid of
lateral shifts 0.1 mm apart, and ``ben_E<n>.dat`` the reference equivalent conicity (columns:
amplitude ŷ in mm, tan γ_e, then tolerance bounds). The grid of each Δr table is not in the
file: it is the one the repository's program assigns to each case (``Select.java``), written
out below as ``GRIDS``. Only the numbers are taken; nothing of the program's code.

The script reads both files of each case from the repository's git history and writes two
CSV files: ``en15302_annex_e_delta_r.csv`` (case, y in mm, Δr in mm) and
``en15302_annex_e_conicity.csv`` (case, ŷ in mm, tan γ_e), as the source gives them.

Usage::

    python scripts/en15302_annex_e.py --repo /path/to/B_ECC-Equivalent-Conicity-Calculation(.git)
        [--out raildyn/contact/data]
"""

from __future__ import annotations

import argparse
import io
import subprocess
from pathlib import Path

import numpy as np

SOURCE = "https://github.com/criogenox/B_ECC-Equivalent-Conicity-Calculation"
COMMIT = "6e33d43295fe6e90020d6c89ac338a901fbcaf54"
FOLDER = "src/main/resources/eqcon/mvnver/data"
# First and last shift (mm) of each case's Δr table, every 0.1 mm (the repository's Select.java).
GRIDS = {
    "E1": (-6.8, 6.8), "E2": (-6.8, 6.8), "E3": (-6.8, 6.8), "E4": (-7.1, 7.1), "E5": (-6.8, 6.8),
    "E6": (-6.9, 6.8), "E7": (-6.8, 6.7), "E8": (-7.1, 7.0), "E9": (-6.8, 6.8),
}  # fmt: skip


def _show(repo: Path, name: str) -> np.ndarray:
    text = subprocess.run(
        ["git", "-C", str(repo), "show", f"{COMMIT}:{FOLDER}/{name}"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    return np.loadtxt(io.StringIO(text), ndmin=2)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", type=Path, required=True, help="the repository's git directory")
    parser.add_argument("--out", type=Path, default=Path("raildyn/contact/data"))
    args = parser.parse_args()
    rows_dr, rows_ref = [], []
    for case, (first, last) in GRIDS.items():
        dr = _show(args.repo, f"dr_ce_{case}.dat").ravel()
        steps = round((last - first) / 0.1)
        if dr.size != steps + 1:
            raise SystemExit(
                f"{case}: {dr.size} values of Δr, but the grid {first}..{last} mm has {steps + 1}"
            )
        y = np.round(first + 0.1 * np.arange(steps + 1), 1)
        rows_dr += [f"{case},{yi:.1f},{di:.6f}" for yi, di in zip(y, dr, strict=True)]
        ref = _show(args.repo, f"ben_{case}.dat")
        rows_ref += [f"{case},{amp:.1f},{lam:.3f}" for amp, lam in ref[:, :2]]
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "en15302_annex_e_delta_r.csv").write_text(
        "case,y_mm,delta_r_mm\n" + "\n".join(rows_dr) + "\n"
    )
    (args.out / "en15302_annex_e_conicity.csv").write_text(
        "case,amplitude_mm,tan_gamma_e\n" + "\n".join(rows_ref) + "\n"
    )


if __name__ == "__main__":
    main()
