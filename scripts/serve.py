#!/usr/bin/env python3
"""Serve the built site (``make serve``) until Ctrl-C or a stop signal, then end quietly.

``python -m http.server`` dies of SIGTERM, and make then reports the recipe as failed
("make: *** [serve] Terminated"); here both Ctrl-C (SIGINT) and SIGTERM end the server
cleanly, with status 0. It says where it serves only once it holds the port: a port that
another server holds (or one it may not use) is said in a sentence, with the command that
chooses another, and it ends with status 1, without a traceback.

Usage: serve.py HOST PORT DIRECTORY
"""

from __future__ import annotations

import errno
import functools
import signal
import sys
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer


def _cannot_serve(host: str, port: int, err: OSError) -> str:
    other = 8001 if port != 8001 else 8002
    if err.errno == errno.EADDRINUSE:
        why = f"Port {port} on {host} is taken: another server (perhaps another `make serve`) is using it."
    elif err.errno == errno.EACCES:
        why = f"This user may not serve on port {port} (ports below 1024 need root)."
    elif err.errno == errno.EADDRNOTAVAIL:
        return (f"{host} is not an address of this machine ({err.strerror}). "
                "Choose another with HOST=, for example: HOST=127.0.0.1 make serve")
    else:
        why = f"The workbook cannot be served at {host}:{port}: {err.strerror or err}."
    return f"{why}\nChoose another port with PORT=, for example: PORT={other} make serve"


def main(host: str, port: str, directory: str) -> int:
    handler = functools.partial(SimpleHTTPRequestHandler, directory=directory)
    try:
        number = int(port)
        server = ThreadingHTTPServer((host, number), handler)
    except (ValueError, OverflowError):  # not a number, or none from 0 to 65535
        print(f"PORT={port} is not a port number: choose one from 1024 to 65535, for example PORT=8001 make serve",
              file=sys.stderr)
        return 1
    except OSError as err:
        print(_cannot_serve(host, number, err), file=sys.stderr)
        return 1
    with server:
        def stop(signum, frame):
            raise KeyboardInterrupt

        signal.signal(signal.SIGTERM, stop)
        print(f"Serving the workbook at http://{host}:{number}/  (Ctrl-C stops)", flush=True)
        try:
            server.serve_forever()
        except KeyboardInterrupt:
            print("\nStopped serving the workbook.", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
