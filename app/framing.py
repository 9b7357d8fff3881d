"""Where the scene is shown: the free area between the panels, fitting the bodies into it, and the
scene file's own camera block."""
from __future__ import annotations

import math

import numpy as np


def free_area(ui_rects: dict, width: float, show_ui: bool, default: tuple[float, float]) -> tuple[float, float]:
    """Pixels covered by panels at the left and right edges of the window: the scene is framed
    in the area between them.  Uses the panels' rectangles from the last frame (they can be
    moved), or ``default`` (their places before the first frame with panels)."""
    if not show_ui:
        return 0.0, 0.0
    rects = [ui_rects.get(k) for k in ("main_window", "stats_window")]
    if rects[0] is None:      # not drawn yet: the default layout
        return default
    W = float(width)
    left = right = 0.0
    for r in rects:
        if r is None or r[3] - r[1] < 60:      # absent, or collapsed to its title bar
            continue
        x0, _, x1, _ = r
        if 0.5 * (x0 + x1) < 0.5 * W:
            left = max(left, x1 + 8.0)
        else:
            right = max(right, W - x0 + 8.0)
    return left, right


def fit(camera, world, free) -> None:
    """Frame every body in the free area ``free`` = (left, right) pixels (F)."""
    rd = world.render_data()
    if not len(rd.aabb):
        return
    box = rd.aabb[np.all(np.isfinite(rd.aabb), axis=1)]
    if not len(box):
        return
    left, right = free
    camera.fit(box[:, :2].min(0), box[:, 2:].max(0), avoid_left=left, avoid_right=right)


def scene_camera(world):
    """The scene file's camera block ``{"center": [x, y], "zoom": px per m}`` as (centre, zoom),
    or None when it is absent or unusable."""
    cam = world.metadata.get("camera")
    try:
        center = np.asarray(cam["center"], dtype=np.float64).reshape(2)
        zoom = float(cam["zoom"])
    except (TypeError, KeyError, ValueError):
        return None
    if not (np.all(np.isfinite(center)) and math.isfinite(zoom) and zoom > 0):
        return None
    return center, zoom


def frame_scene(camera, world, free) -> None:
    """On opening a scene: its own camera if the file has one (centred in the free area),
    otherwise fit the scene into the free area."""
    cam = scene_camera(world)
    if cam is None:
        fit(camera, world, free)
    else:
        left, right = free
        camera.look_at(cam[0], cam[1], avoid_left=left, avoid_right=right)
