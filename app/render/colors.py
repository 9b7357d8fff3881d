"""Colours of the scene by body state, overlays and previews (RGBA float32)."""
from __future__ import annotations

import numpy as np

F32 = np.float32


def _rgba(hexstr: str, a: float = 1.0) -> np.ndarray:
    h = hexstr.lstrip("#")
    return np.array([int(h[i:i + 2], 16) / 255.0 for i in (0, 2, 4)] + [a], dtype=F32)


# colours by state (fill, outline)
DYNAMIC_FILLS = np.stack([_rgba(c) for c in ("#4f8fd6", "#5aa2e0", "#4a7fc9", "#62a8d8", "#5891e3", "#4c9ac8")])
STATIC_FILL, STATIC_LINE = _rgba("#4a5361"), _rgba("#8a97a8")
KINEMATIC_FILL, KINEMATIC_LINE = _rgba("#8f6bd1"), _rgba("#d4c2f5")
SLEEP_FILL = _rgba("#44617f")
DYNAMIC_LINE = _rgba("#d8ecff")
SLEEP_LINE = _rgba("#8ea4bb")
SELECT_FILL, SELECT_LINE = _rgba("#f0a040"), _rgba("#fff2c0")
HOVER_TINT = 0.22
#: the inspector's colour swatches: a soft palette that reads on the dark background
PALETTE = ("#4f8fd6", "#e07a5f", "#f2cc8f", "#81b29a", "#9d8df1", "#f28cb1", "#5ec8d8", "#c9d36a")
SLEEP_DIM = 0.62          # a sleeping body's own colour is dimmed and greyed by this much
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
