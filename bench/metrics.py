"""Engine-independent measures of a running ``Sim``: penetration by exact geometry, and the
per-scene figures the speed tables report (top-box drift, penetration, escaped bodies)."""
from __future__ import annotations

import math

import numpy as np


def world_shapes(sim):
    """Per body: ('poly', world vertices) or ('circle', centre, radius) at the current pose."""
    org = sim.origins()
    _, ang, _, _ = sim.state()
    out = []
    for i, r in enumerate(sim.recs):
        c, s = math.cos(ang[i]), math.sin(ang[i])
        R = np.array([[c, -s], [s, c]])
        shp = r["shape"]
        if hasattr(shp, "vertices"):
            out.append(("poly", np.asarray(shp.vertices) @ R.T + org[i]))
        else:
            out.append(("circle", R @ np.asarray(shp.offset, float) + org[i], float(shp.radius)))
    return out


def _poly_depth(A, B):
    """Penetration depth of two convex CCW polygons by SAT (<= 0 when apart)."""
    best = np.inf
    for P, Q in ((A, B), (B, A)):
        e = np.roll(P, -1, 0) - P
        nrm = np.stack([e[:, 1], -e[:, 0]], 1)
        nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
        # overlap along each of P's face normals: face offset minus deepest point of Q
        face = np.einsum("ij,ij->i", nrm, P)
        deepest = (Q @ nrm.T).min(0)
        best = min(best, float((face - deepest).min()))
    return best


def _circle_poly_depth(c, r, P):
    e = np.roll(P, -1, 0) - P
    nrm = np.stack([e[:, 1], -e[:, 0]], 1)
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    sep = (c - P) @ nrm.T
    sep = np.einsum("ij,ij->i", c[None, :] - P, nrm)
    k = int(np.argmax(sep))
    if sep[k] > 0:
        # outside: distance to the closest point of the polygon's boundary
        t = np.clip(np.einsum("ij,ij->i", c - P, e) / np.einsum("ij,ij->i", e, e), 0, 1)
        d = np.linalg.norm(P + t[:, None] * e - c, axis=1).min()
        return r - d
    return r - sep[k]


def penetration(sim, include_static=True):
    """(max, mean over touching pairs) penetration depth of the current poses, measured by
    exact geometry the same way for every engine (ideal: zero).  NaN for a scene with bodies
    of several or rounded shapes: this measure knows convex polygons and circles only."""
    if any(r.get("parts") for r in sim.recs):
        return float("nan"), float("nan")
    shapes = world_shapes(sim)
    n = len(shapes)
    ctr = np.empty((n, 2))
    rad = np.empty(n)
    for i, s in enumerate(shapes):
        if s[0] == "poly":
            ctr[i] = s[1].mean(0)
            rad[i] = np.linalg.norm(s[1] - ctr[i], axis=1).max()
        else:
            ctr[i], rad[i] = s[1], s[2]
    dyn = sim.dynamic
    order = np.argsort(ctr[:, 0])
    depths = []
    xs = ctr[order, 0]
    rmax = rad.max() if n else 0.0
    for a_i, a in enumerate(order):
        hi = np.searchsorted(xs, xs[a_i] + rad[a] + rmax, side="right")
        for b in order[a_i + 1:hi]:
            if not (dyn[a] or dyn[b]):
                continue
            if not include_static and not (dyn[a] and dyn[b]):
                continue
            if np.hypot(*(ctr[a] - ctr[b])) > rad[a] + rad[b]:
                continue
            sa, sb = shapes[a], shapes[b]
            if sa[0] == "poly" and sb[0] == "poly":
                d = _poly_depth(sa[1], sb[1])
            elif sa[0] == "circle" and sb[0] == "circle":
                d = sa[2] + sb[2] - float(np.hypot(*(sa[1] - sb[1])))
            elif sa[0] == "circle":
                d = _circle_poly_depth(sa[1], sa[2], sb[1])
            else:
                d = _circle_poly_depth(sb[1], sb[2], sa[1])
            if d > 0:
                depths.append(d)
    if not depths:
        return 0.0, 0.0
    return float(max(depths)), float(np.mean(depths))


def scene_metrics(sim, top, p0, width=None) -> dict:
    """Figures of ``sim`` now: ``top_drift`` (m the body ``top`` moved from ``p0``), max and mean
    penetration (m), bodies ``escaped`` (below -2 m, or beyond a container ``width`` m wide),
    ``finite``."""
    com = sim.state()[0]
    m = {"top_drift": float(np.hypot(*(com[top] - p0[top]))) if top is not None else None}
    mx, mean = penetration(sim)
    m["max_penetration"], m["mean_penetration"] = mx, mean
    d = sim.dynamic
    m["escaped"] = int(np.sum(com[d, 1] < -2.0)) if width is None else \
        int(np.sum((com[d, 1] < -2.0) | (np.abs(com[d, 0]) > 0.5 * width + 2.0)))
    m["finite"] = bool(np.all(np.isfinite(com)))
    return m


def top_index(sim) -> int | None:
    """Index of the highest dynamic body (None without one)."""
    com = sim.state()[0]
    dyn = np.nonzero(sim.dynamic)[0]
    return int(dyn[np.argmax(com[dyn, 1])]) if len(dyn) else None
