"""The Jupyter Book builds from the repository root with zero warnings (-W -n --keep-going)."""

import re

import pytest


@pytest.mark.slow
def test_book_builds_without_warnings(built_book):
    proc, html = built_book
    log = proc.stdout + proc.stderr
    assert proc.returncode == 0, log[-6000:]
    # -W already turns Sphinx warnings into a failed build; this also catches ones printed without it.
    # The executing kernel's own start-up notice (transport encryption) is not the book's.
    warnings = [line for line in log.splitlines() if "WARNING" in line and "[IPKernelApp]" not in line]
    assert not warnings, "\n".join(warnings)
    assert (html / "index.html").exists()


@pytest.mark.slow
def test_book_has_chapter_one_with_offline_mathjax(built_book):
    _, html = built_book
    page = (html / "notebooks" / "01_analysis_of_dynamic_systems.html").read_text(encoding="utf-8")
    assert "_static/mathjax/tex-chtml.js" in page, "MathJax is not the bundled copy"
    assert (html / "_static" / "mathjax" / "tex-chtml.js").exists()
    remote = re.findall(r'<(?:script|link|img)[^>]*(?:src|href)="(https?://[^"]+)"', page)
    assert not remote, f"the page loads from the network: {remote}"
    assert "Logarithmic decrement" in page or "logarithmic decrement" in page
    assert page.count("<img") >= 4, "the executed notebook's figures are missing"


@pytest.mark.slow
def test_no_progress_bar_is_left_frozen_on_a_page(built_book):
    _, html = built_book
    for page in (html / "notebooks").glob("*.html"):
        assert "0%|" not in page.read_text(encoding="utf-8"), f"{page.name} shows a progress bar stuck at 0 %"


@pytest.mark.slow
def test_book_links_its_repository_and_its_issues(built_book):
    # A course reports errata where the book's buttons point: both come from repository.url.
    import yaml

    _, html = built_book
    config = yaml.safe_load((html.parents[1] / "_config.yml").read_text(encoding="utf-8"))
    url = config["repository"]["url"]
    page = (html / "book" / "intro.html").read_text(encoding="utf-8")
    assert f'href="{url}"' in page, "no repository button"
    assert f'href="{url}/issues' in page, "no issues button"
