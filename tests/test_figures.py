"""The figure registry and the ``python -m raildyn figures`` command."""

import numpy as np
import pytest
from matplotlib.figure import Figure

from raildyn import figures
from raildyn.__main__ import main


def test_chapter_one_figures_are_registered_with_book_numbers():
    assert figures.REGISTRY["fig1.4"].book_figure == "1.4"
    assert figures.REGISTRY["fig1.5"].book_figure == "1.5"


@pytest.mark.parametrize("fid", sorted(figures.REGISTRY))
def test_each_figure_builds(fid):
    fig = figures.make(fid)
    assert isinstance(fig, Figure) and fig.axes


def test_fig_1_5_marks_peaks_one_damped_period_apart():
    fig = figures.make("fig1.5")
    peaks = next(line for line in fig.axes[0].lines if line.get_marker() == "s")
    t, x = peaks.get_data()
    # ξ = 0.1, ω_n = 2π: T_d = 1/√(1−0.01) s and x1/x2 = exp(δ) with δ = 2π·0.1/√0.99.
    assert t[1] - t[0] == pytest.approx(1 / np.sqrt(0.99), rel=1e-9)
    assert np.log(x[0] / x[1]) == pytest.approx(2 * np.pi * 0.1 / np.sqrt(0.99), rel=1e-9)


def test_unknown_figure_id():
    with pytest.raises(ValueError, match="unknown figure id"):
        figures.make("fig99.1")


def test_command_line_writes_every_figure(tmp_path, capsys):
    assert main(["figures", "--out", str(tmp_path)]) == 0
    written = sorted(p.stem for p in tmp_path.glob("*.png"))
    assert written == sorted(figures.REGISTRY)
    assert all((tmp_path / f"{fid}.png").stat().st_size > 10_000 for fid in written)


def test_command_line_lists(capsys):
    assert main(["figures", "--list"]) == 0
    assert "fig1.4 (book Fig. 1.4)" in capsys.readouterr().out


def test_show_gives_a_captioned_picture_for_notebooks():
    bundle = figures.show("fig1.4")._repr_mimebundle_()
    assert bundle["image/png"] and "book Fig. 1.4" in bundle["text/html"]
    assert bundle["text/html"].count("<img") == 1
