"""Where the scene is shown: the free area beside the panels, fitting the scene into it, and the
scene file's own camera block.  Rectangles are window pixels (x0, y0, x1, y1) with y down, as
imgui reports them."""
from __future__ import annotations

import itertools
import math

import numpy as np

GAP = 8.0         # pixels kept clear around a panel
MIN_SIDE = 200.0  # a free area narrower or lower than this is not worth framing into


def free_regions(panels, width, height):
    """Axis-aligned rectangles of the window that no panel covers, bounded by panel edges
    (a few candidates: there are at most a handful of panels)."""
    xs0 = {0.0} | {r[2] + GAP for r in panels}
    xs1 = {float(width)} | {r[0] - GAP for r in panels}
    ys0 = {0.0} | {r[3] + GAP for r in panels}
    ys1 = {float(height)} | {r[1] - GAP for r in panels}
    out = []
    for x0, x1, y0, y1 in itertools.product(xs0, xs1, ys0, ys1):
        if x1 - x0 < MIN_SIDE or y1 - y0 < MIN_SIDE or x0 < 0 or y0 < 0 or x1 > width or y1 > height:
            continue
        if any(x0 < r[2] + GAP and r[0] - GAP < x1 and y0 < r[3] + GAP and r[1] - GAP < y1 for r in panels):
            continue
        out.append((x0, y0, x1, y1))
    return out or [(0.0, 0.0, float(width), float(height))]


def best_region(regions, size=None):
    """The region showing a box of ``size`` (w, h metres) largest, or the largest region."""
    def score(r):
        w, h = r[2] - r[0], r[3] - r[1]
        return min(w / size[0], h / size[1]) if size is not None else w * h
    return max(regions, key=score)


def panel_rects(ui_rects: dict, keys=("main_window", "stats_window")):
    """The rectangles of the panels that take room from the scene (collapsed ones do not)."""
    rects = [ui_rects.get(k) for k in keys]
    return [r for r in rects if r is not None and r[3] - r[1] >= 60]


def content_box(world):
    """(lo, hi) corners of every body's bounding box (m), or None for an empty world."""
    rd = world.render_data()
    if not len(rd.aabb):
        return None
    box = rd.aabb[np.all(np.isfinite(rd.aabb), axis=1)]
    if not len(box):
        return None
    return box[:, :2].min(0), box[:, 2:].max(0)


def focus_box(world):
    """What a scene is about: its moving bodies' extent grown by a tenth of its size (at least 1.5 m) on
    every side, down to the ground they will land on, kept within the whole scene; the whole scene
    when nothing moves.  A long static ground or terrain should not shrink a card house to a few
    pixels, and bodies dropped from high up should not fall out of the view they opened in."""
    rd = world.render_data()
    whole = content_box(world)
    if whole is None:
        return None
    moving = rd.kind != 1
    box = rd.aabb[moving]
    box = box[np.all(np.isfinite(box), axis=1)]
    if not len(box):
        return whole
    lo, hi = box[:, :2].min(0), box[:, 2:].max(0)
    lo[1] = min(lo[1], ground_below(rd.aabb[~moving], lo, hi))
    grow = np.maximum(0.1 * (hi - lo), 1.5)
    return np.maximum(lo - grow, whole[0]), np.minimum(hi + grow, whole[1])


def ground_below(static_boxes, lo, hi) -> float:
    """The lowest top of the static bodies under the box [lo, hi] (overlapping it in x, their top
    below its bottom): where what falls from the box comes to rest; ``lo[1]`` when there is none."""
    b = static_boxes[np.all(np.isfinite(static_boxes), axis=1)]
    under = (b[:, 0] <= hi[0]) & (b[:, 2] >= lo[0]) & (b[:, 3] <= lo[1])
    return float(b[under, 3].min()) if np.any(under) else float(lo[1])


def fit(camera, box, regions) -> None:
    """Frame ``box`` = (lo, hi) in the region of ``regions`` where it shows largest."""
    if box is None:
        return
    lo, hi = box
    size = np.maximum(np.asarray(hi) - np.asarray(lo), 1.0)
    camera.fit(lo, hi, rect=best_region(regions, size))


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


def view_box(center, zoom, rect):
    """The world box (lo, hi) that ``rect`` (pixels) shows around ``center`` at ``zoom`` px/m."""
    half = 0.5 * np.array([rect[2] - rect[0], rect[3] - rect[1]]) / zoom
    c = np.asarray(center, dtype=np.float64)
    return c - half, c + half


def frame_scene(camera, world, regions) -> None:
    """On opening a scene: its own camera block if the file has one and it shows what the scene
    is about (``focus_box``) in the largest free region; a block made for another layout that
    would hide it gives way to fitting that box.  A scene without a block is fitted whole.  So
    nothing a scene is about opens hidden under the panels."""
    cam = scene_camera(world)
    if cam is None:
        fit(camera, content_box(world), regions)
        return
    box = focus_box(world)
    rect = best_region(regions)
    if box is not None:
        lo, hi = view_box(cam[0], cam[1], rect)
        slack = 0.02 * (hi - lo)
        if not (np.all(box[0] >= lo - slack) and np.all(box[1] <= hi + slack)):
            fit(camera, box, regions)
            return
    camera.look_at(cam[0], cam[1], rect=rect)
