"""Sphinx hooks for the raildyn book.

* Docstrings use ``|x|`` for a magnitude; reStructuredText would read it as a
  substitution, so the bars are escaped outside literals.
* sphinx-thebe's settings script can reach a page twice, which the browser
  reports as an error; repeated inline scripts are dropped.
* sphinx-book-theme leaves pydata-sphinx-theme's colour mode empty, which its
  script reports as an error; the mode starts as "auto" (follow the system).
* The executed notebooks carry the kernel's widget state. Without a kernel the
  state is dead weight (hundreds of kB of PNG per page), and every raildyn widget
  already brings its own kernel-free HTML, so the state is left out of the pages.
"""

import re

_LITERAL = re.compile(r"(``.*?``)")


def _escape(line: str) -> str:
    if line.lstrip().startswith((">>>", "...", "+-", "| ")):  # doctests, tables, line blocks stay
        return line
    parts = _LITERAL.split(line)
    return "".join(p if p.startswith("``") else p.replace("|", r"\|") for p in parts)


def escape_bars(app, what, name, obj, options, lines):
    lines[:] = [_escape(line) for line in lines]


def drop_widget_state(app, pagename, templatename, context, doctree):
    metadata = getattr(app.env, "nb_metadata", {}).get(pagename, {})
    metadata.get("js_files", {}).pop("ipywidgets_state", None)


def drop_repeated_scripts(app, pagename, templatename, context, doctree):
    seen, kept = set(), []
    for script in context.get("script_files", []):
        # An inline script may come with filename None or "" for the same body.
        attributes = tuple(sorted(getattr(script, "attributes", {}).items()))
        key = (getattr(script, "filename", script) or "", attributes)
        if key not in seen:
            seen.add(key)
            kept.append(script)
    context["script_files"] = kept


def set_colour_mode(app, pagename, templatename, context, doctree):
    if not context.get("default_mode"):
        context["default_mode"] = "auto"


def setup(app):
    app.connect("autodoc-process-docstring", escape_bars)
    # Before myst-nb (priority 500) adds the page's scripts.
    app.connect("html-page-context", drop_widget_state, priority=400)
    app.connect("html-page-context", drop_repeated_scripts, priority=900)
    app.connect("html-page-context", set_colour_mode, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
