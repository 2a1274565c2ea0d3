# Robotics Math Workbook — every step installs what it needs and is idempotent.
#   make serve   build the site and serve it at http://127.0.0.1:8000
#   make test    run the whole test suite (unit + browser)
#   make site    build the static site into site/
#   make bench   measure start-up and grading speed (writes bench-results/)

SHELL := /bin/bash
export NO_MKDOCS_2_WARNING := 1
.DELETE_ON_ERROR:

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
# pyodide-build's offline tools need Python 3.12 (GitHub: setup-python; here: pyenv).
PY312 ?= $(shell for p in python3.12 $$HOME/.pyenv/versions/3.12*/bin/python3.12; do $$p -c 'import sys; assert sys.version_info[:2] == (3, 12)' >/dev/null 2>&1 && { command -v $$p; break; }; done)
HOST ?= 127.0.0.1
PORT ?= 8000

PKG_SOURCES := $(shell find pyodide_pkg -name '*.py' -not -path '*/build/*') pyodide_pkg/pyproject.toml
JS_SOURCES := $(wildcard docs/assets/js/*.js)
DOCS_SOURCES := $(shell find docs -type f -not -path 'docs/assets/vendor/*' -not -path 'docs/assets/dist/*' -not -name '*.pyc')

.PHONY: serve site test test-unit test-browser bench deps browser clean dev

$(BIN)/.installed: requirements.txt pyodide_pkg/pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -r requirements.txt -e pyodide_pkg
	touch $@

node_modules/.installed: package.json package-lock.json
	npm ci --no-audit --no-fund --loglevel=error
	touch $@

# Optional: pyodide-build (lockfile add-wheels, py-compile) in a Python 3.12 venv of its own.
.venv-pyodide/.installed: requirements-pyodide-tools.txt
	@if [ -n "$(PY312)" ]; then \
	  test -x .venv-pyodide/bin/python || $(PY312) -m venv .venv-pyodide; \
	  .venv-pyodide/bin/python -m pip install --quiet --disable-pip-version-check -r requirements-pyodide-tools.txt; \
	else echo "note: no Python 3.12 found; the lock file is written without pyodide-build"; fi
	mkdir -p .venv-pyodide && touch $@

build/vendor.stamp: scripts/vendor.py scripts/pyodide-0.27.7.sha256 node_modules/.installed $(BIN)/.installed
	$(BIN)/python scripts/vendor.py
	mkdir -p build && touch $@

build/wheel.stamp: build/vendor.stamp scripts/build_wheel.py $(PKG_SOURCES) .venv-pyodide/.installed
	$(BIN)/python scripts/build_wheel.py
	touch $@

# The standard library cut in two: the core the worker starts with (what start-up and
# the grader import, found by running them in Node, plus the package) and the rest.
build/stdlib.stamp: build/wheel.stamp scripts/stdlib_probe.mjs scripts/split_stdlib.py scripts/sandbox_files.py
	node scripts/stdlib_probe.mjs
	$(BIN)/python scripts/split_stdlib.py
	$(BIN)/python scripts/sandbox_files.py  # the sandbox's Python: the core without the grading package
	touch $@

# The worker's memory snapshot: Node boots the vendored Pyodide with the package imported.
build/snapshot.stamp: build/stdlib.stamp scripts/build_snapshot.mjs
	node scripts/build_snapshot.mjs
	touch $@

build/bundle.stamp: scripts/bundle.mjs $(JS_SOURCES) node_modules/.installed
	node scripts/bundle.mjs
	mkdir -p build && touch $@

deps: $(BIN)/.installed node_modules/.installed

site/.stamp: build/vendor.stamp build/wheel.stamp build/stdlib.stamp build/snapshot.stamp build/bundle.stamp mkdocs.yml $(DOCS_SOURCES)
	$(BIN)/mkdocs build --strict --quiet
	touch $@

site: site/.stamp

serve: site
	@echo "Serving the workbook at http://$(HOST):$(PORT)/  (Ctrl-C stops)"
	$(BIN)/python -m http.server --bind $(HOST) --directory site $(PORT)

# Live-reloading server for authors (rebuilds pages on save).
dev: build/vendor.stamp build/wheel.stamp build/stdlib.stamp build/snapshot.stamp build/bundle.stamp
	$(BIN)/mkdocs serve -a $(HOST):$(PORT)

# A browser for the tests: Playwright's own where installed, else Debian's chromium.
browser: $(BIN)/.installed
	@if $(BIN)/python scripts/find_browser.py >/dev/null 2>&1; then :; \
	elif command -v apt-get >/dev/null; then \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo sudo ); \
	  $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq chromium >/dev/null; \
	else echo "no browser: run '$(BIN)/playwright install chromium'"; exit 1; fi
	@echo "browser: $$($(BIN)/python scripts/find_browser.py)"

test-unit: $(BIN)/.installed
	$(BIN)/python -m pytest tests/unit

test-browser: site browser
	$(BIN)/python -m pytest tests/browser

test: site browser
	$(BIN)/python -m pytest tests/unit
	$(BIN)/python -m pytest tests/browser

bench: site browser
	cd scripts && ../$(BIN)/python -m bench $(BENCH_ARGS)

clean:
	rm -rf site build docs/assets/vendor docs/assets/dist
