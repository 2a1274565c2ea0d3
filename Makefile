# Robotics Math Workbook — every step installs what it needs and is idempotent.
#   make serve    build the site and serve it at http://127.0.0.1:8000
#   make test     run the whole test suite (lint, then unit + browser)
#   make lint     ruff and mypy over the Python; ESLint and TypeScript's checker (tsc) over the JavaScript (any finding fails)
#   make typecheck  TypeScript's checker over the JavaScript's JSDoc types (checkJs; part of lint)
#   make site     build the static site into site/
#   make browser  find a Chromium for the tests, or install Debian's (says so first)
#   make bench    measure start-up and grading speed (writes bench-results/)
#   make lock     re-lock requirements/*.in into requirements/*.lock (with hashes)
#   make scorm    SCORM 1.2 and 2004 packages of the site for an LMS (writes dist/)
#
# One toolchain: Python 3.12 (the version Pyodide 0.27.7 runs; the build parses and
# compiles Python for it), Node 20+. Every output below lists all of its inputs;
# tests/unit/test_build_graph.py checks it with `make -n -W FILE`.

SHELL := /bin/bash
export NO_MKDOCS_2_WARNING := 1
.DELETE_ON_ERROR:

VENV := .venv
BIN := $(VENV)/bin
HOST ?= 127.0.0.1
PORT ?= 8000
# Python 3.12: PY312=/path/to/python3.12 overrides the search (PATH, pyenv, uv's own installs).
PY312 ?= $(shell for p in python3.12 $$HOME/.pyenv/versions/3.12*/bin/python3.12 $$HOME/.local/share/uv/python/cpython-3.12*/bin/python3.12; do \
  $$p -c 'import sys; assert sys.version_info[:2] == (3, 12)' >/dev/null 2>&1 && { command -v $$p; break; }; done)
PIP := $(BIN)/python -m pip --disable-pip-version-check --quiet
# uv installs the locks (the same hash checks as pip, downloads in parallel: 5 s against pip's 53 s on a
# fresh clone); it is itself installed from requirements/tools.lock, with hashes, by the venv's pip.
UV := build/tools/bin/uv
UV_INSTALL = $(UV) pip install --quiet --python $(BIN)/python --compile-bytecode --require-hashes --no-deps

# ---- Sources, by kind (recursive) ----------------------------------------------------
# sw.js is the service worker's template (docs/hooks/offline.py fills it in).
SW_TEMPLATE := docs/assets/js/sw.js
PKG_SOURCES := $(shell find pyodide_pkg/workbook pyodide_pkg/workbook_sandbox -type f \( -name '*.py' -o -name '*.json' \) -not -path '*/__pycache__/*') pyodide_pkg/pyproject.toml
JS_SOURCES := $(filter-out $(SW_TEMPLATE),$(shell find docs/assets/js -type f \( -name '*.js' -o -name '*.json' \)))
HOOKS := $(shell find docs/hooks -type f -name '*.py')
OVERRIDES := $(shell find docs/overrides -type f)
# The pages and everything MkDocs copies (Markdown, CSS); not the generated folders, not the JS sources (bundled).
PAGES := $(shell find docs -type f -not -path 'docs/assets/vendor/*' -not -path 'docs/assets/dist/*' \
  -not -path 'docs/assets/js/*' -not -path 'docs/hooks/*' -not -path 'docs/overrides/*' -not -name '*.pyc')

.PHONY: serve site lint typecheck test test-unit test-browser bench deps browser full-browser clean dev lock python312 scorm

# ---- Python 3.12 -------------------------------------------------------------------
# Where none is found, the first install says so and provides one with uv (`make python312`).
define CHECK_PYTHON
if [ -z "$(PY312)" ]; then \
  echo "This build needs Python 3.12 (what Pyodide 0.27.7 runs) and found none on PATH, in pyenv or from uv:"; \
  echo "installing uv from PyPI into build/uv, and CPython 3.12 with it (make python312). To use your own"; \
  echo "instead: apt-get install python3.12-venv (Ubuntu 24.04), or PY312=/path/to/python3.12."; \
  $(MAKE) --no-print-directory python312; fi
endef
# The Python 3.12 to make the venv with (after CHECK_PYTHON, in the same recipe).
PY312_NOW = py="$(PY312)"; [ -n "$$py" ] || py=$$(build/uv/bin/uv python find 3.12)

# Provides a CPython 3.12 through uv (a well-kept installer from PyPI; needs python3 with venv).
python312:
	python3 -m venv build/uv && build/uv/bin/python -m pip install --quiet --disable-pip-version-check 'uv==0.13.8'
	build/uv/bin/uv python install 3.12
	@echo "Python 3.12: $$(build/uv/bin/uv python find 3.12)"

# ---- Installed tools: from the locks only ------------------------------------------
# .serve: what building and serving need; .test: the test tools on top (same versions).
$(BIN)/.serve: requirements/serve.lock requirements/tools.lock pyodide_pkg/pyproject.toml
	@$(CHECK_PYTHON)
	@if [ -x $(BIN)/python ] && ! $(BIN)/python -c 'import sys; assert sys.version_info[:2] == (3, 12)' 2>/dev/null; then \
	  echo "$(VENV) is not Python 3.12: making it again"; rm -rf $(VENV); fi
	test -x $(BIN)/python || { $(PY312_NOW); $$py -m venv $(VENV); }
	rm -rf build/tools && $(PIP) install --require-hashes --no-deps --target build/tools -r requirements/tools.lock
	$(UV_INSTALL) -r requirements/serve.lock
	$(PIP) install --no-deps --no-build-isolation -e pyodide_pkg
	rm -f $(BIN)/.test
	touch $@

$(BIN)/.test: requirements/test.lock $(BIN)/.serve
	$(UV_INSTALL) -r requirements/test.lock
	touch $@

node_modules/.installed: package.json package-lock.json
	npm ci --no-audit --no-fund --loglevel=error
	touch $@

deps: $(BIN)/.serve node_modules/.installed

# Re-lock after editing requirements/*.in (with the uv that tools.lock pins).
lock: $(BIN)/.serve
	cd requirements && for lock in serve test tools; do \
	  ../$(UV) pip compile --quiet --generate-hashes --universal --python-version 3.12 $$lock.in -o $$lock.lock || exit 1; done

# ---- The runtime's files (docs/assets/vendor/, build/) -------------------------------
build/vendor.stamp: scripts/vendor.py scripts/pyodide-0.27.7.sha256 node_modules/.installed $(BIN)/.serve
	$(BIN)/python scripts/vendor.py
	mkdir -p build && touch $@

build/wheel.stamp: build/vendor.stamp scripts/build_wheel.py $(PKG_SOURCES)
	$(BIN)/python scripts/build_wheel.py
	touch $@

# The standard library cut in two: the core the worker starts with (what start-up and
# the grader import, found by running them in Node, plus the package; also compiled, for a plain
# start on a first visit) and the rest.
build/stdlib.stamp: build/wheel.stamp scripts/stdlib_probe.mjs scripts/split_stdlib.py scripts/chapter_modules.py scripts/sandbox_files.py $(PKG_SOURCES)
	node scripts/stdlib_probe.mjs
	$(BIN)/python scripts/split_stdlib.py
	$(BIN)/python scripts/sandbox_files.py  # the sandbox's Python: the core without the grading package
	touch $@

# The workers' memory snapshots: Node boots the vendored Pyodide with the package imported
# (the grader's), and with the sandbox's own Python and its runner (the sandbox's).
build/snapshot.stamp: build/stdlib.stamp scripts/build_snapshot.mjs
	node scripts/build_snapshot.mjs
	node scripts/build_snapshot.mjs --sandbox
	touch $@

# A student id's Unicode case folding, from the Python the grader runs (its unicodedata), so
# that the page (assignment-hash.js) folds ids as workbook/assignment.py does.
build/casefold.json: scripts/casefold_table.py $(BIN)/.serve
	$(BIN)/python scripts/casefold_table.py $@

# The page's JavaScript (esbuild); contract.js imports contract.json, the worker's boot
# module reads the sizes of the runtime files it loads (a real progress bar).
build/bundle.stamp: scripts/bundle.mjs $(JS_SOURCES) pyodide_pkg/workbook/contract.json build/casefold.json node_modules/.installed build/snapshot.stamp build/wheel.stamp
	node scripts/bundle.mjs
	mkdir -p build && touch $@

RUNTIME_STAMPS := build/vendor.stamp build/wheel.stamp build/stdlib.stamp build/snapshot.stamp build/bundle.stamp

# The hooks import the grading package (bank, contract); offline.py fills in the SW template;
# notices.py writes the licences and third-party notices page with scripts/notices.py.
NOTICES := scripts/notices.py LICENSE LICENSE-text.md
site/.stamp: $(RUNTIME_STAMPS) mkdocs.yml $(PAGES) $(HOOKS) $(OVERRIDES) $(SW_TEMPLATE) $(PKG_SOURCES) $(NOTICES)
	$(BIN)/mkdocs build --strict --quiet
	touch $@

site: site/.stamp

# scripts/serve.py says where it serves once it holds the port, says so when the port is taken
# (PORT=8001 make serve chooses another), and ends cleanly on Ctrl-C or SIGTERM (no "make: *** ... Terminated").
serve: site
	@$(BIN)/python scripts/serve.py $(HOST) $(PORT) site

# Live-reloading server for authors (rebuilds pages on save).
dev: $(RUNTIME_STAMPS)
	$(BIN)/mkdocs serve -a $(HOST):$(PORT)

# ---- SCORM packages (docs/teaching/scorm.md): the built site/ zipped for an LMS ----
# They zip site/ exactly as built, the same files `make test` tests (nothing is rebuilt for them): the
# whole book in each version, and one package per chapter and version in dist/chapters/ (written with them).
SCORM_ZIPS := dist/robotics-workbook-scorm12.zip dist/robotics-workbook-scorm2004.zip
$(SCORM_ZIPS) &: site/.stamp scripts/scorm_package.py $(wildcard scripts/scorm/*.j2)
	rm -rf dist/chapters
	$(BIN)/python scripts/scorm_package.py --site site --out dist --chapters

scorm: $(SCORM_ZIPS)

# ---- Tests ----------------------------------------------------------------------------
# $(call chromium,TARGET,THERE,PACKAGE,WHAT,FIND): where `find_browser.py THERE` finds none, install
# Debian's PACKAGE (WHAT, for the message) with apt-get (with sudo when not root), saying so first;
# then `find_browser.py FIND` must name one, else the target fails with what to do.
define chromium
	@if $(BIN)/python scripts/find_browser.py $(2) >/dev/null; then :; \
	elif command -v apt-get >/dev/null; then \
	  SUDO=$$( [ "$$(id -u)" = 0 ] || echo "sudo -n" ); \
	  echo "make $(1): installing Debian's $(4): $$SUDO apt-get install $(3)"; \
	  ( $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq $(3) >/dev/null ) || \
	    echo "make $(1): could not install it"; fi
	@$(BIN)/python scripts/find_browser.py $(5) >/dev/null || \
	  { echo "make $(1): no Chromium found: install one, or set WORKBOOK_CHROMIUM=/path/to/chrome"; exit 1; }
	@echo "$(1): $$($(BIN)/python scripts/find_browser.py $(5))"
endef

# A browser for the tests: a headless shell of Chromium (scripts/find_browser.py says why),
# Debian's or Playwright's own. Where there is none, this installs Debian's
# chromium-headless-shell, and says so first; if that cannot be done, a full
# Chromium already there is used instead (slower, the same results).
browser: $(BIN)/.test
	$(call chromium,browser,--shell,chromium-headless-shell,headless Chromium,)

# The bench measures the whole browser, as learners run it (not the tests' headless shell):
# Debian's chromium, installed the same way where there is none.
full-browser: $(BIN)/.test
	$(call chromium,full-browser,--full,chromium,Chromium,--full)

# The unit tests run on TEST_JOBS processes (pytest-xdist), one by one; the browser tests on
# BROWSER_JOBS, a file at a time (a file's tests share its fixtures), longest file first, and the
# tests of a file that declares SPREAD one by one (tests/browser/conftest.py). The unit tests keep
# both cores busy with two; the browser tests, two processes on two cores, left the CPU idle 14 % of
# the time (they wait on time limits, emulated links and the offline copy): three finished in
# 607 s instead of 670 s (the same 261 tests, on the same machine).
# Python may keep its compiled modules (and pytest its rewritten test modules) in __pycache__/ even
# where the environment sets PYTHONDONTWRITEBYTECODE: each test process then reads them instead of
# compiling every module again (about 2.5 s of each process's start).
TEST_JOBS ?= 2
BROWSER_JOBS ?= 3
PYTEST := env -u PYTHONDONTWRITEBYTECODE $(BIN)/python -m pytest
# The unit tests drive no browser: without Playwright's plugin, each process loads about 140
# modules fewer, which every native Build run's Restore (workbook_sandbox/restore.py) walks twice.
UNIT := $(PYTEST) -n $(TEST_JOBS) -p no:playwright tests/unit
BROWSER := $(PYTEST) -n $(BROWSER_JOBS) --dist loadgroup tests/browser

# Linter and type checker (ruff.toml, mypy.ini, eslint.config.mjs): fast, and first in `make test`.
LINT_PY := pyodide_pkg docs/hooks scripts tests
# TypeScript's checker over the JavaScript as it is (checkJs, JSDoc types; no build step, nothing emitted): the page's
# modules, the workers (WebWorker lib) and the service worker, each with the globals its context has
# (scripts/typecheck/); part of `lint`. assignment-hash.js imports the generated build/casefold.json.
TYPECHECK := page workers sw
typecheck: node_modules/.installed build/casefold.json
	@status=0; for c in $(TYPECHECK); do node_modules/.bin/tsc -p scripts/typecheck/$$c.json || status=1; done; exit $$status

lint: $(BIN)/.test node_modules/.installed typecheck
	$(BIN)/ruff check --quiet $(LINT_PY)
	$(BIN)/mypy
	node_modules/.bin/eslint --max-warnings 0 docs/assets/js tests/js

test-unit: $(BIN)/.test node_modules/.installed
	WORKBOOK_DRAW_SHARE=0.2 $(UNIT)

test-browser: site browser
	$(BROWSER)

test: lint site browser
	$(UNIT)
	$(BROWSER)

bench: site full-browser
	cd scripts && ../$(BIN)/python -m bench $(BENCH_ARGS)

clean:
	rm -rf site build docs/assets/vendor docs/assets/dist dist
