# raildyn: one command per job. Every target installs what it needs from nothing.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp
BOOK_HTML := book/_build/html
# matplotlib's font cache inside the venv: a cache shared across checkouts on one machine can be
# rewritten by another checkout's half-deleted venv and lose matplotlib's own fonts.
export MPLCONFIGDIR := $(CURDIR)/.venv/matplotlib
# Python's bytecode cache on for every process a target starts (the tests' workers, the book's kernels, the
# app's): where the machine switches it off (PYTHONDONTWRITEBYTECODE), each process compiles raildyn anew
# and pytest rewrites every test module's assertions anew, 4.5 s of each worker's collection.
unexport PYTHONDONTWRITEBYTECODE
# One BLAS thread a process, where processes already share the cores (the tests' workers, the book's
# kernels, the app's kernels, one a lecture-room page): OpenBLAS's threads wait for each other by
# spinning, so two of them in each of several busy processes burn the machine (chapter 2's notebook ran
# in 32 s beside two busy loops, 12 s on one thread; alone, 11 s either way).
ONE_BLAS_THREAD := OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1

.PHONY: book book-student pdf pdf-student test test-fast lab app bench figures lint clean chromium fe-libs debian install constraints

# A fresh virtual environment with the pinned ranges, raildyn installed editable
# so that the notebooks import the working tree; then its numba kernels compiled once into numba's
# cache (the __pycache__ folders beside the sources, which every later kernel, book build and Voilà loads),
# one process a core (24 s on 2 cores, 33 s in one). pip does not byte-compile what it installs
# (--no-compile): Python compiles a module when it is first imported and keeps it, so only the modules
# in use are compiled (the install from pip's cache: 39 s with pip's compiling, 19 s without; the first
# imports of a test session then compile for some 6 s once).
# What requirements.txt installs (raildyn editable with its "dev" extra; the ranges live in pyproject.toml),
# at the versions constraints.txt pins, so that every machine tests the same set, in two steps: raildyn with
# what it imports, then the extra's tools (scripts/extras.py lists them) while the kernels compile, which
# need only the first (pip unpacks on one core, the compilation takes both).
$(STAMP): requirements.txt pyproject.toml constraints.txt
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet --no-compile -c constraints.txt -e .
	$(PY) scripts/extras.py dev > $(VENV)/extras.txt
	$(PY) -m raildyn compile --jobs $(shell nproc) & compiling=$$!; \
	  $(PY) -m pip install --quiet --no-compile -c constraints.txt -r $(VENV)/extras.txt; installed=$$?; \
	  wait $$compiling && test $$installed = 0
	touch $@

install: $(STAMP)

## constraints: pin what .venv holds as the tested set, after an upgrade there (.venv/bin/pip install -U NAME,
## within pyproject.toml's ranges); tests/test_packaging.py checks the pins against the ranges
constraints:
	@test -x $(PY) || { echo "no $(VENV): make install first"; exit 1; }
	{ echo "# The tested set: make install pins these; make constraints writes them from the venv."; \
	  $(PY) -m pip list --format=freeze --exclude-editable | grep -v -i -E '^(pip|raildyn)=='; } > constraints.txt

## book: execute every notebook and build the HTML book (the README's main command)
# RAILDYN_PROGRESS=0: a page without a kernel would show a progress bar frozen at 0 %, so none is drawn.
# A rebuild runs only the notebooks whose code changed (Jupyter Book's execution cache) and rewrites only
# the pages that changed; scripts/book_cache.py empties the cache when raildyn's own files changed.
book: $(STAMP)
	$(PY) scripts/book_cache.py book/_build
	RAILDYN_PROGRESS=0 $(VENV)/bin/jupyter-book build . --config book/_config.yml --toc book/_toc.yml --path-output book
	@echo "The book is at $(abspath $(BOOK_HTML))/index.html"

## pdf: the whole book as one PDF (book/_build/raildyn.pdf), printed offline by headless chromium: the
## course with its worked answers, then the API reference as its appendix; page numbers, links inside the PDF
pdf: book chromium
	$(PY) scripts/book_pdf.py $(BOOK_HTML) book/_build/raildyn.pdf

## book-student: the student edition (book/_build/student/_build/html): the same book with every worked
## answer removed, built from the notebooks `make book` executed; pdf-student prints it (raildyn-student.pdf)
book-student: book
	$(PY) scripts/student_edition.py book/_build book/_build/student

pdf-student: book-student chromium
	$(PY) scripts/book_pdf.py book/_build/student/_build/html book/_build/raildyn-student.pdf

## test: the whole suite: unit, property, notebooks, book build (warnings are errors), browser
# One pytest-xdist worker a core (JOBS=N for another number, JOBS=0 for pytest's own process). The book's
# build starts once the checks of its validation page have run, in a process of its own
# (tests/background.py), and its printing and student edition follow it there, as the Binder environment
# does from the first test; the app's tests hold one worker, the other tests (a file at a time where they
# share a fixture) go to the workers as they come free, and the tests that read the book come last
# (tests/conftest.py).
JOBS ?= $(shell nproc)
PYTEST := $(PY) -m pytest --dist loadscope --no-loadscope-reorder
test:
	@$(MAKE) --no-print-directory -j2 $(STAMP) debian
	$(ONE_BLAS_THREAD) $(PYTEST) -n $(JOBS)

# Debian's packages of the suite, installed beside the Python environment (make test), one apt-get after
# the other: they share dpkg's lock.
debian:
	@$(MAKE) --no-print-directory chromium
	@$(MAKE) --no-print-directory fe-libs

# Debian's chromium for the browser tests; Playwright drives it, nothing is downloaded.
chromium:
	@if [ ! -x /usr/bin/chromium ]; then \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq chromium >/dev/null; \
	fi

# Debian's BLAS and LAPACK, which OpenSeesPy's Linux wheel links to (the bridge's finite-element cross-check).
fe-libs:
	@if ! dpkg -s libblas3 liblapack3 >/dev/null 2>&1; then \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi; \
	  $$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq libblas3 liblapack3 >/dev/null; \
	fi

## test-fast: the unit and property tests only
# No app, no book and no model run of seconds against its reference (the tests marked slow, which
# make test runs): one pytest-xdist worker a core (FAST_JOBS=N for another number).
FAST_JOBS ?= $(shell nproc)
test-fast: $(STAMP) fe-libs
	$(ONE_BLAS_THREAD) $(PYTEST) -n $(FAST_JOBS) -m "not slow"

## lab: JupyterLab on the notebooks
lab: $(STAMP)
	$(VENV)/bin/jupyter lab notebooks

## app: the notebooks as a web app (widgets only, code hidden) for a lecture room
# The page template is the project's (app/nbconvert/templates/raildyn: a citation or an equation link
# reads as text instead of leaving the page and stopping its widgets; nothing is fetched from another
# host); Voilà finds it on JUPYTER_PATH. tests/test_browser.py serves the app with these settings.
# A closed tab leaves its kernel running (the page's shutdown request is refused, voila#1458), so
# kernels no page has been connected to for ten minutes are shut down; an open page's never are.
# The list of notebooks is the server's own HTML page (--classic-tree): Voilà's default list is a
# JupyterLab application that sometimes drew nothing within 30 s in the tests, and needs twice the time.
APP_TEMPLATES := app
APP_OPTIONS := --template=raildyn --classic-tree --no-browser --Voila.ip=127.0.0.1 \
  --MappingKernelManager.cull_idle_timeout=600 --MappingKernelManager.cull_interval=60
app: $(STAMP)
	$(ONE_BLAS_THREAD) JUPYTER_PATH=$(CURDIR)/$(APP_TEMPLATES)$${JUPYTER_PATH:+:$$JUPYTER_PATH} $(VENV)/bin/voila notebooks $(APP_OPTIONS) --port=8866

## bench: widget and model timings against their baselines, same run
# One BLAS thread (ONE_BLAS_THREAD): on a shared 2-core machine, thread scheduling otherwise swings the
# matrix-heavy cases (raildyn and baseline alike) by more than the ratios measured.
bench: $(STAMP) fe-libs
	$(ONE_BLAS_THREAD) $(PY) benchmarks/run.py

## figures: write every registered book figure
figures: $(STAMP)
	$(PY) -m raildyn figures --out figures

## lint: ruff over the code (also part of make test)
lint: $(STAMP)
	$(VENV)/bin/ruff check raildyn tests benchmarks book/_ext notebooks scripts
	$(VENV)/bin/ruff format --check raildyn tests benchmarks book/_ext notebooks scripts

clean:
	rm -rf $(VENV) book/_build .pytest_cache figures
