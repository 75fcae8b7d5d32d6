"""The figure registry and the ``python -m raildyn figures`` command."""

import csv
import dataclasses

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
    with pytest.raises(ValueError, match=r"id must be one of \['fig1.4', .*got 'fig99.1'"):
        figures.make("fig99.1")
    with pytest.raises(TypeError, match="id must be a string"):
        figures.show(1.4)


def test_command_line_writes_every_figure(tmp_path, capsys, monkeypatch):
    # The command's part is one file per registered figure, named by its id: each figure's own drawing
    # is test_each_figure_builds's, so here every figure draws a quick stand-in (the real ones take 40 s).
    def quick():
        fig = figures.new_figure(figsize=(3, 2))
        fig.subplots().plot([0, 1], [0, 1])
        return fig

    for fid, spec in list(figures.REGISTRY.items()):
        monkeypatch.setitem(figures.REGISTRY, fid, dataclasses.replace(spec, draw=quick))
    assert main(["figures", "--out", str(tmp_path)]) == 0
    written = sorted(p.stem for p in tmp_path.glob("*.png"))
    assert written == sorted(figures.REGISTRY)
    assert all((tmp_path / f"{fid}.png").stat().st_size > 1_000 for fid in written)


def _read_table(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def test_each_figures_data_is_written_beside_it_as_drawn(tmp_path, monkeypatch):
    # A stand-in that draws one of each kind the tables read: a line, a scatter, bars, a colour map with
    # its bar, a filled contour map; the table must give back exactly the numbers drawn.
    x = np.linspace(0.0, 2.0, 7)
    grid = np.arange(6.0).reshape(2, 3)

    def drawn():
        fig = figures.new_figure(figsize=(6, 2))
        a, b, c = fig.subplots(1, 3)
        a.plot(x, x**2, label="square")
        a.scatter([1.0, 2.0], [3.0, 4.0])
        a.set(xlabel="speed (m/s)", ylabel="force (kN)", title="one")
        b.bar([1.0, 2.0], [5.0, 6.0], width=0.5)
        fig.colorbar(c.pcolormesh([0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 2.0], grid), ax=c, label="stress (MPa)")
        c.contourf([0.0, 1.0, 2.0], [0.0, 1.0], grid[:, :3], levels=[0.0, 2.5, 5.0])
        return fig

    spec = figures.REGISTRY["fig1.4"]
    monkeypatch.setitem(figures.REGISTRY, "fig1.4", dataclasses.replace(spec, draw=drawn))
    assert main(["figures", "--out", str(tmp_path), "--only", "fig1.4", "--data"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig1.4.csv", "fig1.4.png"]
    rows = _read_table(tmp_path / "fig1.4.csv")
    line = [r for r in rows if r["series"] == "square"]
    assert [float(r["x"]) for r in line] == list(x) and [float(r["y"]) for r in line] == list(x**2)
    labels = {(r["panel"], r["x label"], r["y label"]) for r in line}
    assert labels == {("1: one", "speed (m/s)", "force (kN)")}
    scatter = [(float(r["x"]), float(r["y"])) for r in rows if r["series"].startswith("points")]
    assert scatter == [(1.0, 3.0), (2.0, 4.0)]
    bars = [(float(r["x"]), float(r["y"])) for r in rows if r["panel"] == "2"]
    assert bars == [(1.0, 5.0), (2.0, 6.0)]  # each bar's centre and top
    cells = [r for r in rows if r["series"].startswith("map")]
    assert [float(r["value"]) for r in cells] == list(grid.ravel())
    assert [(float(r["x"]), float(r["y"])) for r in cells[:2]] == [(0.5, 0.5), (1.5, 0.5)]  # cell centres
    assert {r["value label"] for r in cells} == {"stress (MPa)"}
    bands = {float(r["value"]) for r in rows if r["series"].startswith("level")}
    assert bands == {0.0, 2.5}  # each filled band's outline, at its lower level
    assert not any(r["panel"] == "4" for r in rows)  # the colour bar is not a panel


def test_a_real_figures_table_holds_its_curves(tmp_path):
    fig = figures.make("fig1.4")
    written = figures.save_all(tmp_path, ids="fig1.4", data=True, progress=False)
    (path,) = [p for p in written if p.suffix == ".csv"]
    rows = _read_table(path)
    drawn = sum(len(line.get_xdata()) for ax in fig.axes for line in ax.get_lines() if line.get_visible())
    assert len(rows) >= drawn > 0
    with pytest.raises(TypeError, match="data must be True or False, got 'yes'"):
        figures.save_all(tmp_path, ids="fig1.4", data="yes")


def test_command_line_lists(capsys):
    assert main(["figures", "--list"]) == 0
    assert "fig1.4 (book Fig. 1.4)" in capsys.readouterr().out


def test_show_gives_a_captioned_picture_for_notebooks():
    bundle = figures.show("fig1.4")._repr_mimebundle_()
    assert bundle["image/png"] and "book Fig. 1.4" in bundle["text/html"]
    assert bundle["text/html"].count("<img") == 1


def test_save_all_writes_the_chosen_ids_format_by_format_into_a_new_directory(tmp_path):
    out = tmp_path / "new" / "dir"  # created with its parents
    written = figures.save_all(out, formats=("png", "svg"), ids=["fig1.5", "fig1.4"], progress=False)
    # in the order asked for, figure by figure and format by format
    assert written == [out / "fig1.5.png", out / "fig1.5.svg", out / "fig1.4.png", out / "fig1.4.svg"]
    assert all(path.stat().st_size > 1_000 for path in written)


def test_register_refuses_an_id_registered_twice():
    with pytest.raises(ValueError, match="'fig1.4' is registered already"):
        figures.register("fig1.4", "again", chapter=1, book_figure="1.4")
    assert figures.REGISTRY["fig1.4"].caption != "again"


def test_only_a_mirror_of_a_book_figure_has_an_id_like_its_number():
    # An id of the form figN.M claims to be book Fig. N.M: it must say so, and nothing else may claim it.
    for id_, book_figure in (("fig3.9", None), ("fig3.9", "3.8"), ("fig3.track", "3.9")):
        with pytest.raises(ValueError, match="disagree"):
            figures.register(id_, "a figure", chapter=3, book_figure=book_figure)
    honest = {k for k, spec in figures.REGISTRY.items() if spec.book_figure is not None}
    assert honest == {"fig1.4", "fig1.5"}
    assert all(k == f"fig{figures.REGISTRY[k].book_figure}" for k in honest)


def test_a_figure_spec_is_checked_when_it_is_made():
    draw = figures.new_figure
    with pytest.raises(ValueError, match=r"chapter must be an integer in \[1, 11\]"):
        figures.register("fig12.1", "no such chapter", chapter=12)
    with pytest.raises(ValueError, match="book_figure must be a figure number such as '1.4'"):
        figures.FigureSpec("fig1.x", "caption", "one", 1, draw)
    with pytest.raises(ValueError, match="id must be a file name"):
        figures.FigureSpec("../fig", "caption", None, 1, draw)
    with pytest.raises(TypeError, match="draw must be a callable"):
        figures.FigureSpec("fig1.x", "caption", None, 1, None)
    with pytest.raises(TypeError, match="figure must be a matplotlib.figure.Figure"):
        figures.FigureView(figures.REGISTRY["fig1.4"], "a picture")


def test_make_checks_what_a_draw_function_returns():
    figures.REGISTRY["fig1.none"] = figures.FigureSpec("fig1.none", "draws nothing", None, 1, lambda: None)
    try:
        with pytest.raises(TypeError, match="draw function of figure 'fig1.none' must return a matplotlib"):
            figures.make("fig1.none")
    finally:
        del figures.REGISTRY["fig1.none"]


def test_save_all_refuses_bad_arguments_before_writing(tmp_path):
    out = tmp_path / "never"
    with pytest.raises(TypeError, match="out must be a str or pathlib.Path"):
        figures.save_all(None, ids=["fig1.4"])
    with pytest.raises(ValueError, match=r"ids must be one of \[.*got 'abc'"):
        figures.save_all(out, ids="abc")
    with pytest.raises(TypeError, match="ids must be a string or an iterable of strings"):
        figures.save_all(out, ids=1.0)
    with pytest.raises(ValueError, match="ids must name at least one"):
        figures.save_all(out, ids=[])
    with pytest.raises(ValueError, match=r"formats must be one of \[.*got 'abc'"):
        figures.save_all(out, formats="abc", ids=["fig1.4"])
    with pytest.raises(TypeError, match="progress must be True or False"):
        figures.save_all(out, ids=["fig1.4"], progress="no")
    assert not out.exists()
    assert figures.save_all(out, formats="svg", ids="fig1.4", progress=False) == [out / "fig1.4.svg"]


def test_new_figure_is_constrained_and_takes_figure_arguments():
    fig = figures.new_figure(figsize=(4.0, 3.0))
    assert isinstance(fig, Figure) and fig.get_layout_engine() is not None
    assert tuple(fig.get_size_inches()) == (4.0, 3.0)
    with pytest.raises(TypeError, match=r"unknown keyword\(s\) \['figsise'\]"):
        figures.new_figure(figsise=(4.0, 3.0))


def test_the_registry_exports_what_notebooks_and_plug_ins_use():
    # notebooks call show/make; the chNN plug-ins register and draw on new_figure
    assert {
        "REGISTRY",
        "FigureSpec",
        "FigureView",
        "make",
        "new_figure",
        "register",
        "save_all",
        "show",
    } <= set(figures.__all__)


def test_chapter_eight_figures_are_registered_without_book_numbers():
    for fid in ("fig8.curving_plan", "fig8.nadal_limit", "fig8.curve_entry"):
        spec = figures.REGISTRY[fid]
        assert spec.chapter == 8 and spec.book_figure is None and spec.caption


def test_nadal_limit_figure_puts_the_cars_quotients_under_nadals_curves():
    from raildyn.curving import climb, quasi_static_curving
    from raildyn.track import speed_for_deficiency
    from raildyn.vehicles import LateralCar

    ax = figures.make("fig8.nadal_limit").axes[0]
    curves, markers = ax.lines[:3], ax.lines[3:]
    for line, mu in zip(curves, (0.1, 0.3, 0.5), strict=True):
        delta = np.radians(line.get_xdata())
        np.testing.assert_allclose(line.get_ydata(), climb.nadal_limit(delta, mu), rtol=1e-12)
    speed = speed_for_deficiency(300.0, 0.1, 0.1)
    state = quasi_static_curving(LateralCar().nonlinear(), speed, 300.0, 0.1, flange_angle=np.radians(70.0))
    assert markers[-1].get_xdata()[0] == 70.0
    assert markers[-1].get_ydata()[0] == pytest.approx(state.derailment_quotient[0, 1], rel=1e-12)
    # every marker below the lowest limit (μ = 0.5) at 70°
    assert max(m.get_ydata()[0] for m in markers) < climb.nadal_limit(np.radians(70.0), 0.5)


def test_a_caption_names_what_the_figure_shows_with_its_number_not_its_id():
    # "Figure fig7.root_locus." read as a file name; a caption reads "Figure 7.1. <what it shows>".
    import re

    for fid, spec in figures.REGISTRY.items():
        same = [s.id for s in figures.REGISTRY.values() if s.chapter == spec.chapter]
        html = figures.FigureView(spec, figures.new_figure())._repr_mimebundle_()["text/html"]
        caption = re.search(r"<figcaption>(.*)</figcaption>", html).group(1)
        assert caption.startswith(f"Figure {spec.chapter}.{same.index(fid) + 1}"), caption[:40]
        assert fid not in caption and not re.search(r"\bfig\d+\.\w", caption), caption[:60]
        assert spec.caption.split(" (")[0][:20] in caption.replace("&#x27;", "'")


def test_each_notebook_shows_its_chapters_figures_in_their_numbered_order():
    # A chapter's figures are numbered in the order they are registered; the notebook shows them in
    # that order, from the first, so that Figure 7.2 follows Figure 7.1 on the page.
    import re
    from pathlib import Path

    import nbformat

    shown_anywhere = set()
    for path in sorted((Path(__file__).resolve().parents[1] / "notebooks").glob("*.ipynb")):
        chapter = int(path.name[:2])
        code = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "code")
        shown = re.findall(r'(?:figures\.show\(|REGISTRY\[)"(fig[^"]+)"', code)
        registered = [s.id for s in figures.REGISTRY.values() if s.chapter == chapter]
        assert shown == registered[: len(shown)], f"{path.name} shows {shown}, numbered {registered}"
        shown_anywhere.update(shown)
    assert len(shown_anywhere) >= 27
