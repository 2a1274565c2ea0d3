"""Serve the built site on 127.0.0.1 as a GitHub Pages project site would.

One server for the browser tests (``tests/browser/conftest.py``) and the bench
(``scripts/bench``):

- ``site/`` under the sub-path ``/workbook/`` (other folders can be mounted
  under other sub-paths, e.g. the bench's baseline page); everything else 404s;
- ``sitemap.xml`` rewritten to this server's own address: mkdocs-material's
  instant navigation follows only the absolute URLs it lists;
- wasm and JavaScript MIME types, quiet logs, and a client that goes away
  mid-response (a test ended) is not an error;
- every response is logged with its path, status and the bytes written to the
  socket (headers included), for the bench.

Off by default, so that the tests are unaffected: ``cache_control`` (GitHub
Pages sends ``max-age=600``), HTTP/1.1 keep-alive, and a ``Link`` that emulates
one network link shared by everything the browser fetches (page, worker,
service worker): a token bucket for the bandwidth, a round trip per request,
and gzip as GitHub Pages applies it.

    with SiteServer(Path("site")) as server:
        print(server.url)          # http://127.0.0.1:PORT/workbook/
"""

from __future__ import annotations

import functools
import gzip
import http.server
import mimetypes
import re
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import urlsplit

SUBPATH = "/workbook/"

# GitHub Pages compresses text types and wasm; archives are left as they are.
GZIP_TYPES = ("text/", "application/javascript", "application/json", "application/xml", "image/svg+xml",
              "application/wasm", "application/manifest+json")
NO_GZIP_SUFFIXES = (".gz", ".whl", ".zip", ".png", ".jpg", ".jpeg", ".woff", ".woff2", ".ico")
_GZIP_CACHE: dict[tuple[str, int, int], bytes] = {}  # (path, mtime, size) -> gzip body, for every server
_GZIP_LOCK = threading.Lock()
CHUNK = 16 * 1024  # bytes per write on an emulated link: connections interleave at this grain


@dataclass(frozen=True)
class Link:
    """One emulated network link: bandwidth in bits per second, round-trip time in ms."""

    name: str
    bandwidth_bps: float
    rtt_ms: float
    gzip: bool = True


class TokenBucket:
    """Bandwidth shared by every connection: each write waits for its bytes' tokens.

    Tokens accrue at ``rate`` bytes per second up to ``burst`` bytes; a write of n
    bytes takes n tokens, waiting (outside the lock) for any it lacks. Writers
    queue in order of arrival, so concurrent responses share the link.
    """

    def __init__(self, bytes_per_s: float, burst: int = CHUNK):
        self.rate, self.burst = float(bytes_per_s), burst
        self.lock = threading.Lock()
        self.free_at = time.monotonic()  # when the link has sent everything reserved so far

    def take(self, n: int) -> None:
        with self.lock:
            now = time.monotonic()
            start = max(self.free_at, now - self.burst / self.rate)  # an idle link has at most `burst` saved
            self.free_at = start + n / self.rate
            wait = self.free_at - now
        if wait > 0:
            time.sleep(wait)


class _Writer:
    """The socket's file: counts what is written, and paces it on an emulated link."""

    def __init__(self, raw, handler):
        self._raw, self._handler = raw, handler

    def write(self, data):
        bucket = self._handler.server_state.bucket
        view = memoryview(data)
        if bucket is None:
            n = self._raw.write(data)
            self._handler.count(len(data) if n is None else n)
            return n
        for i in range(0, len(view), CHUNK):
            piece = view[i:i + CHUNK]
            bucket.take(len(piece))
            self._raw.write(piece)
            self._raw.flush()
            self._handler.count(len(piece))
        return len(view)

    def flush(self):
        return self._raw.flush()

    def __getattr__(self, name):
        return getattr(self._raw, name)


class _Handler(http.server.SimpleHTTPRequestHandler):
    # RUF012 would have it a ClassVar, but typeshed declares extensions_map an instance attribute.
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, ".wasm": "application/wasm",  # noqa: RUF012
                      ".js": "text/javascript", ".mjs": "text/javascript", ".json": "application/json",
                      ".whl": "application/octet-stream", ".zip": "application/zip", ".svg": "image/svg+xml",
                      ".xml": "application/xml"}

    def __init__(self, *args, server_state: SiteServer, **kwargs):
        self.server_state = server_state
        super().__init__(*args, **kwargs)

    # -- bookkeeping ----------------------------------------------------------
    def setup(self):
        super().setup()
        self.wfile = _Writer(self.wfile, self)  # type: ignore[assignment]  # (writes through, counting)
        self._entry = None

    def count(self, n: int) -> None:
        if self._entry is not None:
            self.server_state._add_bytes(self._entry, n)

    def handle_one_request(self):
        self._entry, self._gzip_body, self._waited = None, None, False
        try:
            super().handle_one_request()
        finally:
            if self._entry is not None:
                self.server_state._finish(self._entry)

    def handle(self):
        try:
            super().handle()
        except (ConnectionResetError, BrokenPipeError, ConnectionAbortedError):
            pass  # the browser went away mid-response (a test ended): not an error

    def log_message(self, *args):  # quiet
        pass

    def send_response(self, code, message=None):
        if self._entry is None:
            self._entry = self.server_state._start(urlsplit(self.path).path, code)
        link = self.server_state.link
        if link is not None and not self._waited:
            self._waited = True
            time.sleep(link.rtt_ms / 1000)  # the request's way there and the first byte's way back
        super().send_response(code, message)

    # -- what is served -------------------------------------------------------
    def translate_path(self, path):
        p = urlsplit(path).path
        for prefix, folder in self.server_state.mounts.items():
            if p.startswith(prefix):
                rel = p[len(prefix):]
                if prefix == SUBPATH:
                    return super().translate_path("/" + rel)
                rel = rel or "index.html"
                return str(Path(folder) / rel.lstrip("/"))
        return str(self.server_state.site / "__not_found__")

    def end_headers(self):
        if self.server_state.cache_control:
            self.send_header("Cache-Control", self.server_state.cache_control)
        super().end_headers()

    def do_GET(self):
        if urlsplit(self.path).path == SUBPATH + "sitemap.xml":
            self._send_sitemap()
            return
        super().do_GET()

    def _send_sitemap(self):
        """As if deployed at this address: absolute URLs built from this server's host."""
        text = (self.server_state.site / "sitemap.xml").read_text()
        found = re.search(r"<loc>(.*?)</loc>", text)
        if found:
            text = text.replace(found.group(1), f"http://{self.headers['Host']}{SUBPATH}")
        body = text.encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/xml")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    # gzip: send_head of the base class sends the headers; swap the length and
    # add the encoding on the way, then write the cached compressed body.
    def send_head(self):
        self._gzip_body = None
        link = self.server_state.link
        if link is not None and link.gzip and "gzip" in self.headers.get("Accept-Encoding", ""):
            path = Path(self.translate_path(self.path))
            if path.is_dir() and urlsplit(self.path).path.endswith("/"):
                path = path / "index.html"  # what the base class serves for a folder
            if path.is_file() and gzippable(path):
                self._gzip_body = self.server_state.gzipped(path)
        return super().send_head()

    def send_header(self, keyword, value):
        if self._gzip_body is not None and keyword.lower() == "content-length":
            super().send_header("Content-Encoding", "gzip")
            super().send_header("Vary", "Accept-Encoding")
            value = str(len(self._gzip_body))
        super().send_header(keyword, value)

    def copyfile(self, source, outputfile):
        if self._gzip_body is not None:
            outputfile.write(self._gzip_body)
        else:
            super().copyfile(source, outputfile)


def gzippable(path: Path) -> bool:
    """Whether GitHub Pages would gzip this file (by its type; archives never)."""
    if path.name.lower().endswith(NO_GZIP_SUFFIXES):
        return False
    ctype = _Handler.extensions_map.get(path.suffix.lower()) or mimetypes.guess_type(path.name)[0] or ""
    return ctype.startswith(GZIP_TYPES)


class SiteServer:
    """The site on 127.0.0.1:PORT (a free port) in a background thread.

    ``mounts`` maps other sub-paths (``"/baseline/"``) to folders. ``log`` holds
    one dict per response: ``path``, ``status``, ``bytes`` (on the wire),
    ``start``/``end`` (``time.time()``, comparable with the page's
    ``performance.timeOrigin``) and ``writes`` ([time, bytes] per write).
    """

    def __init__(self, site: Path, *, mounts: dict[str, Path] | None = None, cache_control: str | None = None,
                 keep_alive: bool = False, link: Link | None = None):
        self.site = Path(site)
        self.mounts = {SUBPATH: self.site, **(mounts or {})}
        self.cache_control, self.link = cache_control, link
        self.bucket = TokenBucket(link.bandwidth_bps / 8) if link else None
        self.lock = threading.Lock()
        self.log: list[dict] = []
        handler = type("Handler", (_Handler,), {"protocol_version": "HTTP/1.1" if keep_alive else "HTTP/1.0"})
        self.httpd = http.server.ThreadingHTTPServer(
            ("127.0.0.1", 0), functools.partial(handler, directory=str(self.site), server_state=self))
        self.httpd.daemon_threads = True
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)
        self.thread.start()
        self.origin = f"http://127.0.0.1:{self.httpd.server_address[1]}"
        self.url = self.origin + SUBPATH

    def __enter__(self) -> SiteServer:
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        self.httpd.shutdown()
        self.httpd.server_close()

    def gzipped(self, path: Path) -> bytes:
        """The file gzipped (level 6, as common web servers), cached in memory per file."""
        st = path.stat()
        key = (str(path), st.st_mtime_ns, st.st_size)
        with _GZIP_LOCK:
            body = _GZIP_CACHE.get(key)
        if body is None:
            body = gzip.compress(path.read_bytes(), compresslevel=6, mtime=0)
            with _GZIP_LOCK:
                _GZIP_CACHE[key] = body
        return body

    def precompress(self) -> int:
        """Gzip every file a link would compress now (not while a page waits); returns how many."""
        count = 0
        for folder in self.mounts.values():
            for path in Path(folder).rglob("*"):
                if path.is_file() and gzippable(path):
                    self.gzipped(path)
                    count += 1
        return count

    # -- the log ----------------------------------------------------------------
    def _start(self, path: str, status: int) -> dict:
        entry = {"path": path, "status": int(status), "bytes": 0, "start": time.time(), "end": None, "writes": []}
        with self.lock:
            self.log.append(entry)
        return entry

    def _add_bytes(self, entry: dict, n: int) -> None:
        with self.lock:
            entry["bytes"] += n
            entry["writes"].append((time.time(), n))

    def _finish(self, entry: dict) -> None:
        with self.lock:
            entry["end"] = time.time()

    def mark(self) -> int:
        """A position in the log; ``since(mark)`` returns what came after it."""
        with self.lock:
            return len(self.log)

    def since(self, mark: int) -> list[dict]:
        with self.lock:
            return [dict(e, writes=list(e["writes"])) for e in self.log[mark:]]

    def wait_quiet(self, quiet_s: float = 1.0, timeout_s: float = 15.0) -> bool:
        """Wait (at most `timeout_s`) until no byte has been written for `quiet_s`
        and no response is in progress; True if it got quiet."""
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            with self.lock:
                busy = any(e["end"] is None for e in self.log[-50:])
                last = max((e["writes"][-1][0] if e["writes"] else e["start"] for e in self.log[-50:]), default=0.0)
            if not busy and time.time() - last >= quiet_s:
                return True
            time.sleep(0.1)
        return False
