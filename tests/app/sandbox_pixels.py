"""Pixel checks for sandbox screenshots (colours from app/render/colors.py)."""
from functools import lru_cache
from pathlib import Path

import numpy as np

from app.body_colors import hex_to_rgb
from app.render import colors

ROOT = Path(__file__).resolve().parents[2]


def _known_fills(static=True) -> np.ndarray:
    """(K, 3) 0-255 fills a body can be drawn in (app/render/colors.py): the default palette and
    the inspector's, each awake, hovered and asleep, and (``static``) the static grey."""
    rgb = np.array([hex_to_rgb(h) for h in (*colors.DEFAULT_PALETTE, *colors.PALETTE)])
    fills = [rgb, rgb + (1.0 - rgb) * colors.HOVER_TINT, colors.asleep(rgb)] + ([colors.STATIC_FILL[None, :3]] if static else [])
    return np.round(np.concatenate(fills) * 255)


@lru_cache(maxsize=None)
def _near_fill_table(static: bool, tol: int) -> np.ndarray:
    """(256, 256, 256) bool: True for every 0-255 colour within ``tol`` (every channel: |d| < tol)
    of a body fill, so a screenshot is classified by one lookup per pixel."""
    table = np.zeros((256, 256, 256), bool)
    for r, g, b in _known_fills(static).astype(int):
        table[max(0, r - tol + 1):r + tol, max(0, g - tol + 1):g + tol, max(0, b - tol + 1):b + tol] = True
    return table


def body_mask(img: np.ndarray, x0, x1, y0, y1, static=True, tol=24) -> np.ndarray:
    """Which pixels of ``img[y0:y1, x0:x1]`` are within ``tol`` (every channel) of a body fill."""
    area = img[max(0, y0):y1, max(0, x0):x1, :3].astype(np.intp)
    return _near_fill_table(bool(static), int(tol))[area[..., 0], area[..., 1], area[..., 2]]


def body_pixels(img: np.ndarray, x0=360, x1=1272, y0=0, y1=490, static=True) -> int:
    """How many pixels in the scene area (default: the free area at 1280x800, right of the side
    panel and above the stats strip) look like a drawn body's fill (any palette colour, awake or
    asleep; static grey unless ``static`` is False)."""
    return int(np.count_nonzero(body_mask(img, x0, x1, y0, y1, static)))


def orange_pixels(img, x0, y0, x1, y1) -> int:
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 170) & (g > 90) & (g < 200) & (b < 140)))


def red_text_pixels(img, x0, y0, x1, y1) -> int:
    a = img[y0:y1, x0:x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 200) & (g < 150) & (b < 150)))


def yellow_pixels(img, x0, y0, x1, y1) -> int:
    """Spring coils (#e8c45a)."""
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 180) & (g > 140) & (b < 130) & (r - b > 90)))


def purple_pixels(img, x0, y0, x1, y1) -> int:
    """Quadtree overlay outlines (#c890ff at alpha 0.45 over the background)."""
    a = img[max(0, y0):y1, max(0, x0):x1]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((b - g > 35) & (r - g > 12) & (b > 100)))


def pink_pixels(img, x0, y0, x1, y1) -> int:
    """Joints (#ff6ec7, app/render/colors.py JOINT_COLOR): red and blue high, green low."""
    a = img[max(0, int(y0)):int(y1), max(0, int(x0)):int(x1)]
    r, g, b = a[..., 0], a[..., 1], a[..., 2]
    return int(np.count_nonzero((r > 200) & (b > 140) & (r - g > 90) & (b - g > 50)))
