"""What the bench measures, where, and how long it waits."""

from __future__ import annotations

from dataclasses import dataclass

from site_server import Link

from . import ROOT

SITE = ROOT / "site"
SUBPATH = "/workbook/"
BASELINE_PATH = "/baseline/"
STOCK_PATH = "/stock/"  # chapter 0 on the stock theme (stock_page.py)

# The tests' flags (tests/browser/conftest.py).
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--disable-component-update",
                 "--disable-sync", "--no-first-run", "--disable-quic"]
# Features of the full browser's own interface switched off, on top of Playwright's list (as Puppeteer does by
# default): the address bar's popup is a WebUI page that the full Chromium renders in a renderer of its own
# for the pages the bench opens, about 1 s of CPU on this 2-core machine that competed with the page measured.
BROWSER_UI_FEATURES_OFF = ("WebUIOmniboxPopup", "WebUIOmniboxAimPopup")
# Nothing listens on port 9 ("discard"): every request that is not to 127.0.0.1 fails.
DEAD_PROXY = {"server": "http://127.0.0.1:9", "bypass": "127.0.0.1"}
# What GitHub Pages sends.
CACHE_CONTROL = "max-age=600"

CH0, CH1, CH3 = "chapters/00-rotations-2d/", "chapters/01-transforms/", "chapters/03-ekf-predict/"
CH9 = "chapters/09-capstone/"
# One exercise of each checked kind: (page, id).
GRADED = {"derive": (CH0, "0.1"), "trace": (CH0, "0.3"), "debug": (CH3, "3.5"), "design": (CH1, "1.5"),
          "matrix": (CH3, "3.8"), "formula": (CH3, "3.9")}  # a 3x3 P⁻; F(1,3) as a formula in v, θ, dt
DERIVE_INPUT = "sqrt(2)/2"  # an expression (exercises the parser), graded incorrect

BUILD_ID = "0.5"
BUILD_PLAIN = (
    "import math\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = math.cos(theta), math.sin(theta)\n"
    "    return (c * x - s * y, s * x + c * y)\n"
)
BUILD_NUMPY = (
    "import numpy as np\n\n\n"
    "def rotate_2d(x, y, theta):\n"
    "    c, s = np.cos(theta), np.sin(theta)\n"
    "    return np.array([[c, -s], [s, c]]) @ np.array([x, y])\n"
)
BUILD_LOOP = "while True:\n    pass\n"
# Two of the "Code the robot" Builds, each with the bank's model solution: a typical one (1.7, on a page
# the bench visits anyway) and the heaviest (9.9, driven closed loop over every case).
BUILD_NEW_ID, BUILD_HEAVY_ID = "1.7", "9.9"

READY_TIMEOUT_MS = 90_000
GRADE_TIMEOUT_MS = 15_000
NUMPY_TIMEOUT_MS = 120_000


@dataclass(frozen=True)
class Profile:
    """A network and CPU to measure a first visit on.

    ``link``: None for the plain 127.0.0.1 server (no pacing, no gzip), else the
    emulated link (scripts/site_server.py). ``cpu_slowdown``: CDP
    Emulation.setCPUThrottlingRate on every page (Chromium applies it to the
    page's main thread only: it refuses it for worker targets). ``cpu_share``:
    run the whole browser in a CPU cgroup holding that share of one core
    (cpu_limit.py), which slows the workers too; CDP throttling is then not
    applied, and is the fallback where a cgroup cannot be made. ``runs``: the
    default run count (None: ``--runs``)."""

    name: str
    link: Link | None
    cpu_slowdown: float = 1.0
    cpu_share: float | None = None
    runs: int | None = None
    ready_timeout_ms: int = READY_TIMEOUT_MS
    precache_timeout_ms: int = 60_000


PROFILES = {
    "localhost": Profile("localhost", None),
    "10mbps": Profile("10mbps", Link("10mbps", 10e6, 40), runs=3, ready_timeout_ms=180_000,
                      precache_timeout_ms=120_000),
    # Issue 48's phone: 8 Mbps / 40 ms, and every browser process on a quarter of one core (CPU x4).
    "phone": Profile("phone", Link("phone", 8e6, 40), cpu_slowdown=4, cpu_share=0.25, runs=2,
                     ready_timeout_ms=400_000, precache_timeout_ms=400_000),
}
DEFAULT_PROFILES = "localhost,10mbps,phone"
