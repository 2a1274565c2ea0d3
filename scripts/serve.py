#!/usr/bin/env python3
"""Serve the built site (``make serve``) until Ctrl-C or a stop signal, then end quietly.

``python -m http.server`` dies of SIGTERM, and make then reports the recipe as failed
("make: *** [serve] Terminated"); here both Ctrl-C (SIGINT) and SIGTERM end the server
cleanly, with status 0.

Usage: serve.py HOST PORT DIRECTORY
"""

from __future__ import annotations

import functools
import signal
import sys
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer


def main(host: str, port: str, directory: str) -> int:
    handler = functools.partial(SimpleHTTPRequestHandler, directory=directory)
    with ThreadingHTTPServer((host, int(port)), handler) as server:
        def stop(signum, frame):
            raise KeyboardInterrupt

        signal.signal(signal.SIGTERM, stop)
        try:
            server.serve_forever()
        except KeyboardInterrupt:
            print("\nStopped serving the workbook.", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
