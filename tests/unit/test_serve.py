"""`make serve` (scripts/serve.py): a taken port is said in a sentence with the way out, never a traceback.

The server runs as make runs it, in a process of its own, on ports the tests choose: one held by a
listening socket of the test's own (as another server would hold it), and a free one it serves on
until SIGTERM ends it.
"""

from __future__ import annotations

import select
import signal
import socket
import subprocess
import sys
import urllib.request
from pathlib import Path

SERVE = Path(__file__).resolve().parents[2] / "scripts" / "serve.py"


def _serve(*args: str, **kwargs) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, str(SERVE), *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, **kwargs)


def test_a_taken_port_is_said_with_how_to_choose_another(tmp_path):
    with socket.socket() as other:  # another server on the port
        other.bind(("127.0.0.1", 0))
        other.listen()
        port = other.getsockname()[1]
        run = _serve("127.0.0.1", str(port), str(tmp_path))
        out, err = run.communicate(timeout=60)
    assert run.returncode == 1
    assert "Traceback" not in err + out
    assert f"Port {port} on 127.0.0.1 is taken" in err
    assert "PORT=8001 make serve" in err
    assert "Serving the workbook" not in out  # it never claimed to serve


def test_a_port_that_is_no_number_is_said_too(tmp_path):
    for port in ("eighty", "70000"):
        run = _serve("127.0.0.1", port, str(tmp_path))
        _out, err = run.communicate(timeout=60)
        assert run.returncode == 1 and "Traceback" not in err
        assert f"PORT={port} is not a port number" in err


def test_a_free_port_serves_the_site_and_stops_cleanly(tmp_path):
    (tmp_path / "index.html").write_text("<p>the workbook</p>", encoding="utf-8")
    with socket.socket() as probe:  # a port free a moment ago (the server binds it next)
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    run = _serve("127.0.0.1", str(port), str(tmp_path))
    try:
        assert run.stdout is not None
        ready, _, _ = select.select([run.stdout], [], [], 60)  # a bound: a server that says nothing fails, not hangs
        said = run.stdout.readline() if ready else ""
        assert said.startswith(f"Serving the workbook at http://127.0.0.1:{port}/"), said + run.stderr.read()
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/index.html", timeout=30) as reply:
            assert reply.read() == b"<p>the workbook</p>"
    finally:
        run.send_signal(signal.SIGTERM)
        out, err = run.communicate(timeout=60)
    assert run.returncode == 0, err
    assert "Stopped serving the workbook." in out and "Traceback" not in err
