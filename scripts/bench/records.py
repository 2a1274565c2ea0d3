"""Turning raw records (the server's log, the page's long tasks) into numbers."""

from __future__ import annotations

import statistics
from urllib.parse import urlsplit

OUR_CODE = ("/workbook/assets/dist/", "/workbook/assets/js/", "/workbook/assets/vendor/pyodide/")


def summary(values: list[float]) -> dict | None:
    values = [v for v in values if v is not None]
    if not values:
        return None
    return {"median": statistics.median(values), "min": min(values), "max": max(values), "n": len(values),
            "values": [round(v, 3) for v in values]}


def percentile(values: list[float], q: float) -> float:
    """Nearest-rank percentile."""
    s = sorted(values)
    k = max(0, min(len(s) - 1, int(-(-q * len(s) // 100)) - 1))
    return s[k]


def net_summary(entries: list[dict]) -> dict:
    """Bytes and requests of a stretch of the server's log (SiteServer.since)."""
    by_status: dict[str, int] = {}
    for e in entries:
        by_status[str(e["status"])] = by_status.get(str(e["status"]), 0) + 1
    biggest = sorted(entries, key=lambda e: -e["bytes"])[:8]
    total = sum(e["bytes"] for e in entries)
    sw_check = sum(e["bytes"] for e in entries if e["path"].endswith("/sw.js"))  # the browser's update check
    return {"bytes": total, "requests": len(entries), "by_status": by_status,
            "bytes_without_sw_update_check": total - sw_check,
            "largest": [{"path": e["path"], "status": e["status"], "bytes": e["bytes"]} for e in biggest]}


def bytes_before(entries: list[dict], epoch_s: float) -> int:
    """Bytes written to the wire up to a moment (``time.time()`` seconds)."""
    return sum(n for e in entries for t, n in e["writes"] if t <= epoch_s)


def fetched_twice(entries: list[dict]) -> list[dict]:
    """Paths whose body was sent more than once (200s; a 304 revalidation sends none)."""
    counts: dict[str, list[int]] = {}
    for e in entries:
        if e["status"] == 200:
            counts.setdefault(e["path"], []).append(e["bytes"])
    return [{"path": p, "times": len(b), "bytes": sum(b)} for p, b in sorted(counts.items()) if len(b) > 1]


def attribute_long_tasks(snap: dict, until_ms: float, page_url: str) -> dict:
    """Long tasks (> 50 ms) before `until_ms`, each with the scripts of the long
    animation frame it falls in (the Long Animation Frames API names the source URL)."""
    tasks = [t for t in snap["longtasks"] if t["start"] <= until_ms]
    out = []
    for t in tasks:
        t_end = t["start"] + t["duration"]
        scripts = []
        for frame in snap["loaf"]:
            for s in frame["scripts"]:
                s_end = s["start"] + s["duration"]
                if s["start"] < t_end and s_end > t["start"] and s["duration"] > 0:
                    scripts.append(s)
        scripts.sort(key=lambda s: -s["duration"])
        top = scripts[0] if scripts else None
        src = (top or {}).get("sourceURL") or ""
        path = urlsplit(src).path
        if top is None:
            owner = "unknown"
        elif path.startswith(OUR_CODE) or (src.split("#")[0] == page_url.split("#")[0] and page_url.startswith("http")):
            owner = "ours"  # our bundle or the inline start-up script in our HTML
        elif path.startswith("/workbook/"):
            owner = "site (theme/vendor)"
        elif not src:
            owner = "no source URL"  # e.g. a browser or bench observer callback
        else:
            owner = "other"
        out.append({"start": round(t["start"], 1), "duration": round(t["duration"], 1), "owner": owner,
                    "top_script": {k: top.get(k) for k in ("sourceURL", "sourceFunctionName", "invoker", "invokerType",
                                                           "duration")} if top else None,
                    "longtask_attribution": t["attribution"]})
    durations = [t["duration"] for t in tasks]
    return {"count": len(tasks), "total_ms": round(sum(durations), 1), "max_ms": round(max(durations, default=0), 1),
            "ours_over_50ms": sum(1 for t in out if t["owner"] == "ours"), "tasks": out,
            "api_errors": [e for e in (snap.get("longtaskError"), snap.get("loafError")) if e]}


def total_blocking_time(snap: dict, until_ms: float) -> float:
    """Sum over the main thread's long tasks that start before `until_ms` of (duration - 50 ms)."""
    return round(sum(max(0.0, t["duration"] - 50) for t in snap["longtasks"] if t["start"] <= until_ms), 1)


def largest_contentful_paint(snap: dict) -> float | None:
    """The last 'largest-contentful-paint' entry's time (ms from navigation start)."""
    return snap["lcp"][-1]["start"] if snap.get("lcp") else None


def fmt(v, unit):
    if v is None:
        return "-"
    if unit == "B":
        return f"{v / 1e6:.2f} MB" if v >= 1e5 else f"{v:.0f} B"
    if unit == "x":
        return f"{v:.2f}x"
    if unit == "n":
        return f"{v:.0f}"
    return f"{v:.0f} ms" if v >= 100 else f"{v:.1f} ms"
