"""Colours of the scene by body state, overlays and previews (RGBA float32)."""
from __future__ import annotations

import numpy as np

F32 = np.float32


def _rgba(hexstr: str, a: float = 1.0) -> np.ndarray:
    h = hexstr.lstrip("#")
    return np.array([int(h[i:i + 2], 16) / 255.0 for i in (0, 2, 4)] + [a], dtype=F32)


#: bodies without a colour of their own, picked by body id: soft, mid-bright hues of different
#: families that read on the dark background and stay clear of the state and overlay colours
#: (no orange: the selection and the first compare rival; no saturated pink or yellow: joints
#: and springs; no purple: kinematic bodies; no grey: static ones)
DEFAULT_PALETTE = ("#4f8fd6", "#81b29a", "#c48aa5", "#4fb8c4", "#b8b070")
DEFAULT_FILLS = np.stack([_rgba(c) for c in DEFAULT_PALETTE])
# colours by state (fill, outline)
STATIC_FILL, STATIC_LINE = _rgba("#4a5361"), _rgba("#8a97a8")
KINEMATIC_FILL, KINEMATIC_LINE = _rgba("#8f6bd1"), _rgba("#d4c2f5")
DYNAMIC_LINE = _rgba("#d8ecff")
SLEEP_LINE = _rgba("#8ea4bb")
SELECT_FILL, SELECT_LINE = _rgba("#f0a040"), _rgba("#fff2c0")
HOVER_TINT = 0.22
#: the inspector's colour swatches: a soft palette that reads on the dark background
PALETTE = ("#4f8fd6", "#e07a5f", "#f2cc8f", "#81b29a", "#9d8df1", "#f28cb1", "#5ec8d8", "#c9d36a")
SLEEP_DIM, SLEEP_GREY = 0.7, 0.35   # a sleeping body's colour: this much of it greyed, the whole dimmed
SPRING_COLOR = _rgba("#e8c45a")
SPRING_SELECTED = _rgba("#fff2c0")
CONTACT_COLOR = _rgba("#ff5a5a")
NORMAL_COLOR = _rgba("#ffd05a")
AABB_COLOR = _rgba("#7fe0a0", 0.55)
QUADTREE_COLOR = _rgba("#c890ff", 0.45)
VEL_COLOR = _rgba("#6df0ff", 0.9)
COM_COLOR = _rgba("#ffffff")
COM_EDGE = _rgba("#202020")
PREVIEW_COLOR = _rgba("#ffffff", 0.85)
JOINT_COLOR = _rgba("#ff6ec7")       # joints: pink, apart from the springs' yellow and the selection's orange
JOINT_SELECTED = _rgba("#fff2c0")
JOINT_BROKEN = _rgba("#8a8a8a", 0.7)
JOINT_HUB = _rgba("#2a1f2e")         # a wheel joint's hub: dark inside the joint-coloured ring


def default_fills(ids) -> np.ndarray:
    """(N, 4) fills of bodies ``ids`` that have no colour of their own: the palette in turn, so
    bodies made one after another differ (and a body keeps its hue while the world lasts)."""
    return DEFAULT_FILLS[np.asarray(ids, np.int64) % len(DEFAULT_FILLS)].copy()


def asleep(rgb: np.ndarray) -> np.ndarray:
    """A sleeping body's fill (r, g, b rows): its colour half greyed and dimmed, so a sleeping
    pile reads as resting whatever its hues."""
    grey = rgb.mean(axis=-1, keepdims=True)
    return SLEEP_DIM * ((1.0 - SLEEP_GREY) * rgb + SLEEP_GREY * grey)
