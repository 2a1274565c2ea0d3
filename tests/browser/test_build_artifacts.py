"""The built site's generated runtime files agree with each other and with the sources.

No browser needed, but the built site is (``make test`` builds it first).
"""

from __future__ import annotations

import base64
import gzip
import hashlib
import json
import struct
import zipfile
from pathlib import Path

SITE = Path(__file__).resolve().parents[2] / "site"
VENDOR = SITE / "assets/vendor/pyodide"


def lock() -> dict:
    return json.loads((VENDOR / "pyodide-lock.json").read_text())


def test_every_package_matches_its_lock_entry():
    """Pyodide refuses a package whose sha256 differs from the lock's."""
    for name, entry in lock()["packages"].items():
        assert hashlib.sha256((VENDOR / entry["file_name"]).read_bytes()).hexdigest() == entry["sha256"], name


def test_numpy_ships_compiled_with_a_true_record():
    """build_wheel.py compiles NumPy's modules once, so `import numpy` does not compile them in the page."""
    with zipfile.ZipFile(VENDOR / lock()["packages"]["numpy"]["file_name"]) as wheel:
        names = wheel.namelist()
        assert not [n for n in names if n.endswith(".py")]
        assert "numpy/__init__.pyc" in names
        (record,) = [n for n in names if n.endswith(".dist-info/RECORD")]
        rows = [line.split(",") for line in wheel.read(record).decode().splitlines()]
        assert sorted(row[0] for row in rows) == sorted(names)
        for path, digest, size in rows:
            if path == record:
                continue
            data = wheel.read(path)
            expected = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            assert (digest, int(size)) == (f"sha256={expected}", len(data)), path


def test_snapshot_was_made_from_the_wheel_the_site_ships():
    """The snapshot holds the grading package's code: a stale one would grade with old keys."""
    vendor = VENDOR
    info = json.loads((SITE.parent / "build/snapshot.json").read_text())
    lock = json.loads((vendor / "pyodide-lock.json").read_text())
    wheel = vendor / lock["packages"]["robotics-workbook"]["file_name"]
    assert info["wheel"] == wheel.name
    assert info["wheel_sha256"] == hashlib.sha256(wheel.read_bytes()).hexdigest()
    packed = gzip.decompress((vendor / "workbook.snapshot.gz").read_bytes())
    assert packed[:8] == b"WBSPARSE" and len(packed) == info["sparse_bytes"] < info["bytes"]
    total, runs = struct.unpack_from("<II", packed, 8)
    memory, data = bytearray(total), 16 + 8 * runs
    for i in range(runs):
        offset, length = struct.unpack_from("<II", packed, 16 + 8 * i)
        memory[offset:offset + length] = packed[data:data + length]
        data += length
    assert data == len(packed)
    assert hashlib.sha256(memory).hexdigest() == info["sha256"] and len(memory) == info["bytes"]
