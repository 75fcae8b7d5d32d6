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


def test_static_grid_must_name_one_or_two_controls():
    from raildyn.widgets._static import frames_html

    with pytest.raises(ValueError, match="one or two controls"):
        frames_html(lambda **v: b"", {}, {}, alt="x")
