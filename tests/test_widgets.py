"""Chapter widgets driven without a browser: every control changes the picture, in place."""

import ipywidgets
import pytest

from raildyn.widgets import chapter01


def test_reset_restores_the_first_frame():
    container, update = chapter01.forced_response()
    start = update()
    update(damping_ratio=0.7)
    reset = next(
        w
        for row in container.children[:-1]
        for w in getattr(row, "children", [])
        if isinstance(w, ipywidgets.Button)
    )
    reset.click()
    assert container.children[-1].value == start


def test_update_rejects_unknown_control():
    _, update = chapter01.forced_response()
    with pytest.raises(ValueError, match="unknown control"):
        update(zeta=0.3)


def test_free_vibration_status_reports_the_decrement():
    container, update = chapter01.free_vibration()
    update(damping_ratio=0.1)
    status = container.children[-2].children[-1].value
    # δ read off the curve and 2πξ/√(1−ξ²) = 0.6315 for ξ = 0.1 must both be printed.
    assert "0.6315" in status and "underdamped" in status


def test_display_bundle_carries_the_kernel_free_html():
    container, _ = chapter01.forced_response()
    bundle = container._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert 'class="raildyn-static"' in bundle["text/html"]


def test_the_app_draws_no_kernel_free_frames(monkeypatch):
    # The lecture-room app shows the live view only: its kernels skip the frames (seconds a page).
    container, _ = chapter01.forced_response()
    drawn = []
    container.static = lambda: drawn.append(1) or "<div></div>"
    monkeypatch.setenv("VOILA_KERNEL_ID", "k")
    bundle = container._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert "text/html" not in bundle and not drawn
    monkeypatch.delenv("VOILA_KERNEL_ID")
    assert container._repr_mimebundle_()["text/html"] == "<div></div>" and drawn == [1]


def test_only_the_kernel_free_copy_runs_the_recipes_preparation():
    # Work for the whole grid (chapter 7's bifurcation diagrams, as one batch) is done for the frames
    # without a kernel, once and before them; the live widget draws one value at a time without it.
    from raildyn.widgets import Recipe
    from raildyn.widgets._core import slider

    calls = []

    def setup(live, status):
        (line,) = live.axes[0, 0].plot([0.0, 1.0], [0.0, 0.0])
        live.animate(line)

        def redraw(values):
            calls.append(values["a"])
            line.set_ydata([0.0, values["a"]])

        return redraw

    recipe = Recipe(lambda: {"a": slider("a", 0.5, 0.0, 1.0, 0.5)}, setup, {"figsize": (2.0, 1.5), "dpi": 40},
                    static={"a": [0.0, 0.5, 1.0]}, prepare=lambda: calls.append("prepare"))  # fmt: skip
    recipe.build()
    assert calls and "prepare" not in calls
    calls.clear()
    recipe.static_html()
    assert calls[0] == "prepare" and calls.count("prepare") == 1 and {0.0, 0.5, 1.0} <= set(calls)
    with pytest.raises(TypeError, match="prepare"):
        Recipe(lambda: {}, setup, prepare="batch")


def test_static_grid_must_name_one_or_two_controls():
    from raildyn.widgets._static import frames_html

    with pytest.raises(ValueError, match="one or two controls"):
        frames_html(lambda **v: b"", {}, {}, alt="x")


def test_the_widget_machinery_refuses_bad_input_by_name():
    from raildyn.widgets import LiveFigure, Recipe, assemble
    from raildyn.widgets._core import slider

    with pytest.raises(ValueError, match=r"nrows must be an integer in \[1, 10\]"):
        LiveFigure(0)
    with pytest.raises(ValueError, match="figsize must be at most 40.0 inches"):
        LiveFigure(figsize=(100.0, 3.0))
    with pytest.raises(TypeError, match="dpi must be an integer"):
        LiveFigure(dpi=80.5)
    controls = {"a": slider("a", 0.5, 0.0, 1.0, 0.5)}
    with pytest.raises(TypeError, match="controls must be a mapping of names to ipywidgets controls"):
        assemble({"a": 0.5}, LiveFigure(), lambda v: None)
    with pytest.raises(TypeError, match="live must be a LiveFigure"):
        assemble(controls, None, lambda v: None)
    with pytest.raises(TypeError, match="redraw must return None"):
        assemble(controls, LiveFigure(), lambda v: [v["a"]])
    with pytest.raises(TypeError, match="setup must be a callable"):
        Recipe(lambda: controls, None)
    with pytest.raises(ValueError, match="static must map one or two control names"):
        Recipe(lambda: controls, lambda live, status: lambda v: None, static={"a": []})


def test_a_recipe_checks_what_its_callables_return_when_it_uses_them():
    from raildyn.widgets import Recipe
    from raildyn.widgets._core import slider

    def controls():
        return {"a": slider("a", 0.5, 0.0, 1.0, 0.5)}

    with pytest.raises(TypeError, match="controls must return a dict of ipywidgets controls"):
        Recipe(lambda: [0.5], lambda live, status: lambda v: None).build()
    with pytest.raises(TypeError, match="setup must return the redraw function"):
        Recipe(controls, lambda live, status: None).build()
    with pytest.raises(ValueError, match=r"static names controls \['b'\]"):
        Recipe(controls, lambda live, status: lambda v: None, static={"b": [1.0]}).defaults()
