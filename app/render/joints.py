"""Joints as lines and markers, from ``RenderData.joints`` (physics/views.py JOINT_DRAW_DTYPE).

What each kind looks like (sizes in screen pixels, so a joint reads at any zoom):
- revolute: a pin (a disc at the anchor), a line to body b's anchor when they drift apart;
- weld: an X mark over the anchor;
- prismatic: its axis through body b's anchor, ticks at the finite limits, a slider disc on a;
- distance: a rod (straight line) or, with a max_length, a rope that sags when slack;
- wheel: the suspension axis through the chassis anchor with limit ticks, a coil from the mount to
  the hub, and the hub disc;
- motor and mouse joints: a line between the two points;
- any other kind (declared in physics/joint_params.py, with no drawing of its own here): a line
  between its two anchors and a dot at each end.
``joint_segments`` gives the lines (the picking in app/picking.py uses the same ones).
"""
from __future__ import annotations

import numpy as np

from physics import joint_params

from .colors import JOINT_BROKEN, JOINT_COLOR, JOINT_HUB, JOINT_SELECTED
from .geometry import discs, thick_segments

F32 = np.float32
KIND = {name: k for k, name in enumerate(joint_params.KINDS)}   # RenderData.joints["kind"] codes
#: the kinds drawn their own way below; the rest are drawn as a plain link
DRAWN = [KIND[k] for k in ("revolute", "prismatic", "weld", "distance", "wheel", "motor", "mouse")]
TICK_PX = 7.0         # half length of a limit tick and of the weld mark's strokes
FREE_AXIS_PX = 45.0   # a free (unlimited) axis is drawn this far past the joint's travel
MOUNT_PX = 32.0       # a wheel's suspension coil starts this far up the axis from the hub's rest place
ROPE_SEGMENTS = 14


def _perp(u):
    return np.stack([-u[:, 1], u[:, 0]], 1)


def _unit(d):
    n = np.hypot(d[:, 0], d[:, 1])
    return d / np.where(n > 0, n, 1.0)[:, None], n


def _axis_span(base, u, t, lower, upper, scale):
    """The drawn axis: from base + lo u to base + hi u, where a finite limit ends it and a free side
    extends past the travel t; ticks (p0, p1, row) at the finite limits."""
    ext = FREE_AXIS_PX / scale
    lo = np.where(np.isfinite(lower), lower, np.minimum(t, 0.0) - ext)
    hi = np.where(np.isfinite(upper), upper, np.maximum(t, 0.0) + ext)
    segs = [(base + lo[:, None] * u, base + hi[:, None] * u, np.arange(len(u)))]
    n = _perp(u) * (TICK_PX / scale)
    for lim in (lower, upper):
        k = np.nonzero(np.isfinite(lim))[0]
        at = base[k] + lim[k, None] * u[k]
        segs.append((at - n[k], at + n[k], k))
    return segs


def _rope(a, b, max_len, scale):
    """A rope between a and b: straight when taut, a sagging parabola when slack.  The sag s of a
    parabola of chord c and arc length L follows from L ~ c + 8 s^2 / (3 c) (the shallow-arc length)."""
    d = b - a
    u, c = _unit(d)
    slack = np.where(np.isfinite(max_len), np.maximum(max_len - c, 0.0), 0.0)
    s = np.minimum(np.sqrt(3.0 * c * slack / 8.0), 0.5 * np.where(np.isfinite(max_len), max_len, 0.0))
    down = _perp(u)
    down = np.where(down[:, 1:2] > 0, -down, down)            # sag towards -y (gravity's side)
    t = np.linspace(0.0, 1.0, ROPE_SEGMENTS + 1)
    pts = a[:, None] + t[None, :, None] * d[:, None] + (4 * t * (1 - t))[None, :, None] * s[:, None, None] * down[:, None]
    return pts[:, :-1].reshape(-1, 2), pts[:, 1:].reshape(-1, 2), np.repeat(np.arange(len(a)), ROPE_SEGMENTS)


def _zigzag(a, b, scale, turns=5):
    """A spring coil from a to b (segments and their item index)."""
    d = b - a
    u, ln = _unit(d)
    t = np.concatenate([[0.0, 0.15], np.linspace(0.15, 0.85, 2 * turns + 1)[1:-1], [0.85, 1.0]])
    off = np.zeros_like(t)
    off[2:-2] = np.where(np.arange(len(t) - 4) % 2 == 0, 1.0, -1.0)
    amp = np.full(len(a), 5.0 / scale)
    pts = a[:, None] + t[None, :, None] * d[:, None] + (off[None, :, None] * amp[:, None, None]) * _perp(u)[:, None]
    m = len(t) - 1
    return pts[:, :-1].reshape(-1, 2), pts[:, 1:].reshape(-1, 2), np.repeat(np.arange(len(a)), m)


def joint_segments(rows, scale):
    """(row index, p0, p1) of every line drawn for the joint rows."""
    out = []

    def add(sel, p0, p1, k=None):
        idx = np.nonzero(sel)[0]
        out.append((idx if k is None else idx[k], p0, p1))

    kind, pa, pb = rows["kind"], rows["anchor_a"], rows["anchor_b"]
    for s in (kind == KIND["revolute"], kind == KIND["motor"], kind == KIND["mouse"], ~np.isin(kind, DRAWN)):
        add(s, pa[s], pb[s])
    s = kind == KIND["weld"]
    r = TICK_PX / scale
    for dx, dy in ((1, 1), (1, -1)):
        v = np.array([dx, dy]) * (r / np.sqrt(2))
        add(s, pa[s] - v, pa[s] + v)
    s = kind == KIND["distance"]
    rigid = s & ~np.isfinite(rows["upper"])
    add(rigid, pa[rigid], pb[rigid])
    rope = s & np.isfinite(rows["upper"])
    p0, p1, k = _rope(pa[rope], pb[rope], rows["upper"][rope], scale)
    add(rope, p0, p1, k)
    # t = (pa - pb) . u: a prismatic's a sits at pb + t u, a wheel's hub (b) at pa + t (-u)
    for code, base, sign in ((KIND["prismatic"], pb, 1.0), (KIND["wheel"], pa, -1.0)):
        s = kind == code
        t = np.einsum("ij,ij->i", pa[s] - pb[s], rows["axis"][s])
        for q0, q1, k in _axis_span(base[s], sign * rows["axis"][s], t, rows["lower"][s], rows["upper"][s], scale):
            add(s, q0, q1, k)
    s = kind == KIND["wheel"]
    mount = pa[s] + rows["axis"][s] * (MOUNT_PX / scale)
    p0, p1, k = _zigzag(mount, pb[s], scale)
    add(s, p0, p1, k)
    if not out:
        return np.zeros(0, np.int64), np.zeros((0, 2)), np.zeros((0, 2))
    return (np.concatenate([o[0] for o in out]).astype(np.int64), np.concatenate([o[1] for o in out]),
            np.concatenate([o[2] for o in out]))


def _colors(rows, selected):
    col = np.broadcast_to(JOINT_COLOR, (len(rows), 4)).copy()
    col[rows["broken"]] = JOINT_BROKEN
    if selected:
        col[np.isin(rows["id"], np.fromiter(selected, np.int64, len(selected)))] = JOINT_SELECTED
    return col


def _visible(rows, hidden):
    if hidden:
        rows = rows[~np.isin(rows["id"], np.fromiter(hidden, np.int64, len(hidden)))]
    return rows


def joint_lines(rows, scale, selected=(), hidden=()):
    """Thick-segment vertices for the joints' lines (selected ones wider, in the selection colour)."""
    rows = _visible(rows, hidden)
    row, p0, p1 = joint_segments(rows, scale)
    if not len(row):
        return np.zeros((0, 7), F32)
    col = _colors(rows, selected)[row]
    width = np.where(np.isin(rows["id"][row], np.fromiter(selected, np.int64, len(selected))), 3.0, 2.0)
    return thick_segments(p0, p1, width, col, scale)


def joint_markers(rows, scale, selected=(), hidden=(), motors=None):
    """Disc vertices: pins, slider blocks, rod ends, wheel hubs (the circle shader).  ``motors``:
    {joint id: angle} of the hinges and wheels with a motor on: their pin or hub is drawn larger
    with a spoke at that angle (the turning body's), so a motor reads as one and is seen turning."""
    rows = _visible(rows, hidden)
    if not len(rows):
        return np.zeros((0, 14), F32)
    kind, pa, pb = rows["kind"], rows["anchor_a"], rows["anchor_b"]
    col = _colors(rows, selected)
    dark = np.broadcast_to(JOINT_HUB, (len(rows), 4))
    motors = motors or {}
    motor = np.isin(rows["id"], np.fromiter(motors, np.int64, len(motors)))
    wheel = kind == KIND["wheel"]
    pin = np.isin(kind, [KIND["revolute"], KIND["prismatic"]]) & ~motor
    ends = np.isin(kind, [KIND["distance"], KIND["motor"], KIND["wheel"], KIND["weld"], KIND["mouse"]])
    ends |= ~np.isin(kind, DRAWN)
    # (selection, centres, radius px, fill, spoke): plain markers first, the motors' spoked ones last
    groups = [(pin, pa, 5.5, col), (ends, pa, 3.0, col), (ends & ~wheel, pb, 3.0, col),
              (wheel & ~motor, pb, 5.0, dark), (motor, np.where(wheel[:, None], pb, pa), 7.5, dark)]
    centers = np.concatenate([c[sel] for sel, c, _, _ in groups])
    radius = np.concatenate([np.full(sel.sum(), r) for sel, _, r, _ in groups]) / scale
    fill = np.concatenate([f[sel] for sel, _, _, f in groups])
    line = np.concatenate([col[sel] for sel, _, _, _ in groups])
    n_plain = len(centers) - int(motor.sum())
    spoke = np.concatenate([np.zeros(n_plain), np.ones(motor.sum())])
    angles = np.concatenate([np.zeros(n_plain), [motors[int(i)] for i in rows["id"][motor]]])
    return discs(centers, radius, angles, spoke, fill, line)
