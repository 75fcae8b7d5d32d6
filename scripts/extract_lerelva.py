"""Make the decimated extract of the Lerelva bridge strain record kept in ``raildyn/validation/data/``.

Source: Tor Holm Slettebak, master's thesis repository ``torholmslettebak/master2016`` on GitHub,
commit 7f6deef (2017-02-22), folder ``code/makeStrainHistory/train/``. The repository grants no
licence; the extract is kept for teaching and research, with attribution (see the data README).

Of the two records the snapshot holds, ``1603161045.txt`` has a train passage (an NSB class 92
unit, train 3 of the thesis, towards Heimdal); ``1603161026.txt`` holds only the quiet bridge.
The script reads the raw text (time, then three strain channels at 1024 Hz), keeps the
window around the passage, low-pass filters and decimates by 4 to 256 Hz with
:func:`scipy.signal.decimate` (an order-8 Chebyshev type I filter run forwards and
backwards, so without phase shift; cut-off 0.8 × 128 Hz), and stores float32 arrays in an
``.npz`` file.

Usage::

    python scripts/extract_lerelva.py [--repo /path/to/master2016(.git)] [--out raildyn/validation/data]
"""

from __future__ import annotations

import argparse
import io
import subprocess
from pathlib import Path

import numpy as np
from scipy import signal

SOURCE = "https://github.com/torholmslettebak/master2016"
COMMIT = "7f6deef903a761072921aa759edb2293ca109bfb"
FOLDER = "code/makeStrainHistory/train"
RUN = "1603161045"
RATE = 1024.0  # Hz, the readme's sampling rate (the file header says the same)
FACTOR = 4  # 1024 Hz -> 256 Hz
WINDOW = (12.0, 22.0)  # s of the raw record: the passage (about 15.0-17.5 s) with quiet either side
CHANNELS = ("midspan", "towards Trondheim (1 m)", "towards Heimdal (1 m)")


def read_raw(repo: Path, run: str) -> np.ndarray:
    """The raw record as an (n, 4) array: time (s) and the three strain channels, from the git history."""
    text = subprocess.run(
        ["git", "-C", str(repo), "show", f"{COMMIT}:{FOLDER}/{run}.txt"],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    return np.loadtxt(io.StringIO(text), comments="#")


def extract(raw: np.ndarray) -> dict:
    """The window, filtered and decimated; arrays ready for ``np.savez_compressed``."""
    t = raw[:, 0]
    steps = np.diff(t)
    assert np.allclose(steps, 1.0 / RATE, rtol=1e-9, atol=0.0), "the raw record is not sampled at 1024 Hz"
    strain = raw[:, 1:4].T
    decimated = signal.decimate(strain, FACTOR, ftype="iir", axis=1, zero_phase=True)
    t_dec = t[::FACTOR]
    keep = (t_dec >= WINDOW[0]) & (t_dec < WINDOW[1])
    return {
        "start": np.float64(t_dec[keep][0]),
        "rate": np.float64(RATE / FACTOR),
        "strain": decimated[:, keep].astype(np.float32),
        "channels": np.array(CHANNELS),
        "source": np.array(f"{SOURCE} @ {COMMIT[:7]}: {FOLDER}/{RUN}.txt"),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repo", default="/work/.mirror/torholmslettebak+master2016/repo", type=Path)
    parser.add_argument("--out", default=Path(__file__).resolve().parents[1] / "raildyn/validation/data")
    args = parser.parse_args()
    data = extract(read_raw(args.repo, RUN))
    out = Path(args.out) / f"lerelva_{RUN}.npz"
    np.savez_compressed(out, **data)
    print(f"wrote {out} ({out.stat().st_size} bytes, {data['strain'].shape[1]} samples at {data['rate']} Hz)")


if __name__ == "__main__":
    main()
