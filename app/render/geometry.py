"""numpy builders of vertex arrays: thick segments, discs, rectangle outlines, spring coils and
the metre grid.  Every function handles all items of a layer in one call (no per-body loop)."""
from __future__ import annotations

import numpy as np

F32 = np.float32


def thick_segments(p0: np.ndarray, p1: np.ndarray, width_px, color, scale: float) -> np.ndarray:
    """Quads (6 vertices each) for segments p0->p1: columns x, y, side, r, g, b, a."""
    n = len(p0)
    if n == 0:
        return np.zeros((0, 7), F32)
    d = p1 - p0
    ln = np.hypot(d[:, 0], d[:, 1])
    ln[ln == 0] = 1.0
    nrm = np.stack([-d[:, 1], d[:, 0]], 1) / ln[:, None]
    hw = (0.5 * np.broadcast_to(np.asarray(width_px, dtype=np.float64), (n,)) + 1.0) / scale
    off = nrm * hw[:, None]
    # extend each segment a little along its direction so joins close
    ext = d / ln[:, None] * (0.5 * hw[:, None])
    a0, a1 = p0 - ext - off, p0 - ext + off
    b0, b1 = p1 + ext - off, p1 + ext + off
    out = np.empty((n, 6, 7), F32)
    out[:, :, 0:2] = np.stack([a0, b0, b1, a0, b1, a1], 1)
    out[:, :, 2] = np.array([-1, -1, 1, -1, 1, 1], F32)
    out[:, :, 3:7] = np.broadcast_to(np.asarray(color, F32).reshape(-1, 1, 4), (n, 6, 4))
    return out.reshape(-1, 7)


def discs(centers: np.ndarray, radius: np.ndarray, angle: np.ndarray, spoke, fill, line) -> np.ndarray:
    """Quads for discs: columns x, y, lx, ly, radius, spoke, fill(4), line(4)."""
    n = len(centers)
    if n == 0:
        return np.zeros((0, 14), F32)
    k = 1.08
    corners = np.array([[-k, -k], [k, -k], [k, k], [-k, -k], [k, k], [-k, k]])
    c, s = np.cos(angle), np.sin(angle)
    # world = center + radius * R(angle) @ corner
    wx = c[:, None] * corners[None, :, 0] - s[:, None] * corners[None, :, 1]
    wy = s[:, None] * corners[None, :, 0] + c[:, None] * corners[None, :, 1]
    out = np.empty((n, 6, 14), F32)
    out[:, :, 0] = centers[:, None, 0] + radius[:, None] * wx
    out[:, :, 1] = centers[:, None, 1] + radius[:, None] * wy
    out[:, :, 2:4] = corners[None]
    out[:, :, 4] = radius[:, None]
    out[:, :, 5] = np.broadcast_to(np.asarray(spoke, F32).reshape(-1, 1), (n, 6))
    out[:, :, 6:10] = np.broadcast_to(np.asarray(fill, F32).reshape(-1, 1, 4), (n, 6, 4))
    out[:, :, 10:14] = np.broadcast_to(np.asarray(line, F32).reshape(-1, 1, 4), (n, 6, 4))
    return out.reshape(-1, 14)


def rects(bx, width, color, scale):
    """Outlines of axis-aligned rectangles (K, 4: min x, min y, max x, max y): 4 quads each."""
    bx = np.asarray(bx, dtype=np.float64)
    c00, c10 = bx[:, [0, 1]], bx[:, [2, 1]]
    c11, c01 = bx[:, [2, 3]], bx[:, [0, 3]]
    p0 = np.concatenate([c00, c10, c11, c01])
    p1 = np.concatenate([c10, c11, c01, c00])
    return thick_segments(p0, p1, width, color, scale)


def coils(ends, scale, color, width=2.0):
    """Zig-zag spring coils between ends (K, 2, 2); a list of segment arrays (empty if K = 0)."""
    if not len(ends):
        return []
    a, b = ends[:, 0], ends[:, 1]
    turns = 9
    t = np.concatenate([[0.0, 0.12], np.linspace(0.12, 0.88, 2 * turns + 1)[1:-1], [0.88, 1.0]])
    off = np.zeros_like(t)
    off[2:-2] = np.where(np.arange(len(t) - 4) % 2 == 0, 1.0, -1.0)
    d = b - a
    ln = np.hypot(d[:, 0], d[:, 1])
    ln1 = np.where(ln == 0, 1.0, ln)
    nrm = np.stack([-d[:, 1], d[:, 0]], 1) / ln1[:, None]
    amp = np.clip(0.08 * np.maximum(ln, 0.5), 4.0 / scale, 0.25)  # world metres
    amp = np.where(ln * scale < 50.0, 0.0, amp)   # short on screen: a plain line reads better
    pts = a[:, None, :] + t[None, :, None] * d[:, None, :] + \
        (off[None, :, None] * amp[:, None, None]) * nrm[:, None, :]
    p0 = pts[:, :-1].reshape(-1, 2)
    p1 = pts[:, 1:].reshape(-1, 2)
    return [thick_segments(p0, p1, width, color, scale)]


def arrows(from_, v, scale, color):
    """Velocity arrows: a shaft 0.2 s of travel long and a two-stroke head, for speeds > 1 mm/s."""
    sp = np.hypot(v[:, 0], v[:, 1])
    keep = sp > 1e-3
    from_, v, sp = from_[keep], v[keep], sp[keep]
    to = from_ + v * 0.2
    d = v / sp[:, None]
    hl = np.minimum(10.0 / scale, 0.4 * sp * 0.2)[:, None]
    nrm = np.stack([-d[:, 1], d[:, 0]], 1)
    h1 = to - d * hl + nrm * hl * 0.5
    h2 = to - d * hl - nrm * hl * 0.5
    return thick_segments(np.concatenate([from_, to, to]), np.concatenate([to, h1, h2]), 1.5, color, scale)


def grid_lines(camera):
    """Minor/major metre grid and the axes as thin lines (a few hundred vertices)."""
    lo, hi = camera.visible_box()
    step = 10.0 ** np.ceil(np.log10(max(1e-6, 24.0 / camera.scale)))
    segs = []
    for axis in (0, 1):
        other = 1 - axis
        k0, k1 = int(np.floor(lo[axis] / step)), int(np.ceil(hi[axis] / step))
        if k1 - k0 > 400:
            continue
        ks = np.arange(k0, k1 + 1)
        pos = ks * step
        major = ks % 5 == 0
        p0 = np.zeros((len(ks), 2))
        p1 = np.zeros((len(ks), 2))
        p0[:, axis] = p1[:, axis] = pos
        p0[:, other], p1[:, other] = lo[other], hi[other]
        col = np.where(major[:, None], np.array([[1, 1, 1, 0.075]]), np.array([[1, 1, 1, 0.035]]))
        col[ks == 0] = (0.55, 0.62, 0.78, 0.35)
        v = np.empty((len(ks), 2, 6), F32)
        v[:, 0, :2], v[:, 1, :2] = p0, p1
        v[:, :, 2:] = col[:, None, :]
        segs.append(v.reshape(-1, 6))
    return np.concatenate(segs) if segs else np.zeros((0, 6), F32)
