"""The app's icon, drawn from code: a two-link robot arm on the theme's indigo.

One drawing (:data:`SHAPES`, in a 512-unit square) gives the SVG icon and the PNG icons the
web app manifest lists (``app.py``): ``any`` icons on a rounded square, and a ``maskable``
one whose drawing sits inside the middle 80 % circle that a launcher's mask always keeps.
The PNGs are rasterised here (coverage from each shape's signed distance: smooth edges
without supersampling) and encoded with zlib: no imaging library.

>>> png = icon_png(16, maskable=False)
>>> png[:8] == PNG_SIGNATURE, int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
(True, 16, 16)
"""

from __future__ import annotations

import math
import struct
import zlib

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
UNITS = 512
BACKGROUND = "#3f51b5"  # the theme's indigo (mkdocs.yml: primary indigo)
INK = "#ffffff"
ACCENT = "#ff7043"  # deep orange, the theme's accent
RADIUS = 96  # the rounded square of the "any" icons
MASKABLE_SCALE = 0.72  # the drawing within the safe zone (a circle of 0.8 x the width)

# (kind, colour, geometry): a base plate, two links (capsules: x0, y0, x1, y1, half width)
# and the joints (circles: x, y, r), the end effector in the accent colour.
SHAPES = (
    ("box", INK, (104, 392, 408, 428, 14)),
    ("capsule", INK, (168, 372, 236, 196, 30)),
    ("capsule", INK, (236, 196, 376, 250, 24)),
    ("circle", INK, (168, 372, 44)),
    ("circle", BACKGROUND, (168, 372, 18)),
    ("circle", INK, (236, 196, 38)),
    ("circle", BACKGROUND, (236, 196, 14)),
    ("circle", ACCENT, (384, 254, 30)),
)


def _rgb(colour: str) -> tuple[int, int, int]:
    return int(colour[1:3], 16), int(colour[3:5], 16), int(colour[5:7], 16)


def _box_distance(x: float, y: float, x0: float, y0: float, x1: float, y1: float, r: float) -> float:
    """Signed distance to a rectangle with rounded corners of radius ``r`` (negative inside)."""
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    hx, hy = (x1 - x0) / 2 - r, (y1 - y0) / 2 - r
    qx, qy = abs(x - cx) - hx, abs(y - cy) - hy
    outside = math.hypot(max(qx, 0.0), max(qy, 0.0))
    return outside + min(max(qx, qy), 0.0) - r


def _capsule_distance(x: float, y: float, x0: float, y0: float, x1: float, y1: float, r: float) -> float:
    dx, dy = x1 - x0, y1 - y0
    t = max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / (dx * dx + dy * dy)))
    return math.hypot(x - x0 - t * dx, y - y0 - t * dy) - r


def _distance(kind: str, g: tuple, x: float, y: float) -> float:
    if kind == "circle":
        return math.hypot(x - g[0], y - g[1]) - g[2]
    if kind == "capsule":
        return _capsule_distance(x, y, *g)
    return _box_distance(x, y, *g)


def _bounds(kind: str, g: tuple) -> tuple[float, float, float, float]:
    if kind == "circle":
        return g[0] - g[2], g[1] - g[2], g[0] + g[2], g[1] + g[2]
    if kind == "capsule":
        return min(g[0], g[2]) - g[4], min(g[1], g[3]) - g[4], max(g[0], g[2]) + g[4], max(g[1], g[3]) + g[4]
    return g[0], g[1], g[2], g[3]


def _shapes(maskable: bool) -> list[tuple[str, str, tuple]]:
    """The drawing in icon units: on a full square (maskable, scaled into the safe zone) or a rounded one."""
    if not maskable:
        return [("box", BACKGROUND, (0, 0, UNITS, UNITS, RADIUS)), *SHAPES]
    k, c = MASKABLE_SCALE, UNITS / 2

    def scaled(kind: str, g: tuple) -> tuple:
        if kind == "circle":
            return (c + k * (g[0] - c), c + k * (g[1] - c), k * g[2])
        return (c + k * (g[0] - c), c + k * (g[1] - c), c + k * (g[2] - c), c + k * (g[3] - c), k * g[4])

    return [("square", BACKGROUND, ()), *((kind, colour, scaled(kind, g)) for kind, colour, g in SHAPES)]


def icon_svg(maskable: bool = False) -> str:
    """The icon as SVG (the same drawing)."""
    parts = []
    for kind, colour, g in _shapes(maskable):
        if kind == "square":
            parts.append(f'<rect width="{UNITS}" height="{UNITS}" fill="{colour}"/>')
        elif kind == "box":
            x0, y0, x1, y1, r = g
            parts.append(f'<rect x="{x0:g}" y="{y0:g}" width="{x1 - x0:g}" height="{y1 - y0:g}" rx="{r:g}" '
                         f'fill="{colour}"/>')
        elif kind == "capsule":
            x0, y0, x1, y1, r = g
            parts.append(f'<line x1="{x0:g}" y1="{y0:g}" x2="{x1:g}" y2="{y1:g}" stroke="{colour}" '
                         f'stroke-width="{2 * r:g}" stroke-linecap="round"/>')
        else:
            parts.append(f'<circle cx="{g[0]:g}" cy="{g[1]:g}" r="{g[2]:g}" fill="{colour}"/>')
    return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {UNITS} {UNITS}">'
            f'<title>Robotics Math Workbook</title>{"".join(parts)}</svg>\n')


def icon_png(size: int, maskable: bool = False) -> bytes:
    """The icon as an RGBA PNG of ``size`` x ``size`` pixels."""
    scale = UNITS / size
    rgba = [[0.0, 0.0, 0.0, 0.0] for _ in range(size * size)]
    for kind, colour, g in _shapes(maskable):
        r, gr, b = (v / 255 for v in _rgb(colour))
        if kind == "square":
            for px in rgba:
                px[:] = [r, gr, b, 1.0]
            continue
        x0, y0, x1, y1 = (v / scale for v in _bounds(kind, g))
        for j in range(max(0, int(y0) - 1), min(size, int(y1) + 2)):
            for i in range(max(0, int(x0) - 1), min(size, int(x1) + 2)):
                # coverage of the pixel from the distance of its centre, in pixels
                d = _distance(kind, g, (i + 0.5) * scale, (j + 0.5) * scale) / scale
                a = 0.5 - d
                if a <= 0:
                    continue
                a = min(a, 1.0)
                px = rgba[j * size + i]
                out = a + px[3] * (1 - a)  # "over": the shape on what is drawn
                for c, v in enumerate((r, gr, b)):
                    px[c] = (v * a + px[c] * px[3] * (1 - a)) / out
                px[3] = out
    rows = bytearray()
    for j in range(size):
        rows.append(0)  # filter: none
        for px in rgba[j * size:(j + 1) * size]:
            rows.extend(round(v * 255) for v in px)
    return _png(size, size, bytes(rows))


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def _png(width: int, height: int, rows: bytes) -> bytes:
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8-bit RGBA
    return PNG_SIGNATURE + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(rows, 9)) + _chunk(b"IEND", b"")
