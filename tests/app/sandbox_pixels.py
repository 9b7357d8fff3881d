"""Pixel checks for sandbox screenshots (colours from app/render/colors.py)."""
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


# colours (see app/render/colors.py): dynamic fills are blue, static grey-blue, selection orange
def body_pixels(img: np.ndarray, x0=360, x1=1272, y0=0, y1=490) -> int:
    """How many pixels in the scene area (default: the free area at 1280x800, right of the side
    panel and above the stats strip) look like a drawn body."""
    area = img[y0:y1, x0:x1]
    r, g, b = area[..., 0], area[..., 1], area[..., 2]
    blue = (b > 150) & (b > r + 40) & (g > 90)           # dynamic fill / outline
    grey = (abs(r - 74) < 14) & (abs(g - 83) < 14) & (abs(b - 97) < 14)   # static fill
    return int(np.count_nonzero(blue | grey))


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
