"""Measure how fast the workbook starts and grades, next to a baseline.

Run by ``make bench`` (after ``make site``); docs/performance.md explains the
numbers. It serves a copy of ``site/`` on 127.0.0.1 under a sub-path, as GitHub
Pages serves a project site (``Cache-Control: max-age=600``, ``Last-Modified``;
``scripts/site_server.py``, the browser tests' server too), drives headless
Chromium with Playwright (the tests' browser and flags; every request not to
127.0.0.1 fails through a dead proxy), and writes ``bench-results/latest.json``,
a timestamped copy, and a table to stdout.

- Each run starts a fresh browser with an empty profile of its own (cold), then
  revisits in it (warm: HTTP cache, code cache and service worker as a returning
  learner has them). Playwright's off-the-record ``new_context()`` is not used:
  its in-memory cache refuses the 10 MB pyodide.asm.wasm, and its request
  routing would turn the HTTP cache off.
- Times are taken inside the page (``performance.now()``, zero at the navigation
  start; MutationObservers on the contract's runtime and state attributes), so
  Playwright's own overhead is not in them. Bytes are counted by the server.
- The BASELINE is a blank page that calls ``loadPyodide()`` on the main thread
  with stock Pyodide 0.27.7 files and the site's lock file, loads the same
  package and imports ``workbook.api``: the way many Pyodide exercise sites start.

- NETWORK PROFILES (``--profiles localhost,10mbps,phone``, each NAME or
  NAME:RUNS): ``localhost`` is the plain server above and runs every phase;
  ``10mbps`` (10 Mbps, 40 ms RTT) and ``phone`` (8 Mbps, 40 ms RTT, and the
  whole browser, workers included, on a quarter of one core: a CPU cgroup,
  cpu_limit.py; CDP's main-thread throttling where no cgroup can be made) put
  one emulated link in front of everything the browser fetches (a shared token
  bucket, a round trip per response, gzip as GitHub Pages applies it) and
  measure a first visit only. On every profile, a first visit of ours, of the
  baseline and of the STOCK PAGE (chapter 0's Markdown on the stock theme,
  stock_page.py), rotating which goes first: time to ready, bytes on the wire
  before ready and in all (until the service worker has stored the site), files
  sent twice, largest contentful paint, total blocking time (to ready, and to
  load + 5 s beside the stock page's), and the first grade and first Build run
  right after ready (first_visit.py).

    cd scripts && ../.venv/bin/python -m bench [--runs N] [--profiles localhost,10mbps:3,phone:2]
                                               [--checks 50] [--budget 2400]

``BENCH_RUNS`` in the environment sets the default for ``--runs`` (so does
``make bench BENCH_RUNS=7``).

Modules: ``__main__`` (options, order of work), ``config`` (pages, timeouts,
profiles), ``phases`` and ``first_visit`` (what each phase does in the
browser), ``browser`` (browsers, visits, waits), ``pagejs`` and ``js/`` (the
in-page instrumentation), ``records`` (server log and page records to numbers),
``report`` and ``network_report`` (metrics, targets, tables, files),
``baseline`` (the bare loadPyodide page), ``stock_page`` (the theme alone),
``cpu_limit`` (the phone's CPU), ``environment`` (machine, git,
snapshot, the native parser worst case).
"""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = ROOT / "scripts"
# This checkout's package and scripts first (a worktree must not measure another's).
for _p in (str(ROOT / "pyodide_pkg"), str(SCRIPTS)):
    if _p not in sys.path:
        sys.path.insert(0, _p)
