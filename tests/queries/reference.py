"""Brute-force references for the spatial queries: every fixture, plain Python, other formulas.

The engine's kernels clip rays against edges and compare vertex-to-edge distances over a tree;
these references loop over every fixture handle, place its shape from ``body.position`` and
``body.angle`` (not the store), and use

- separation: the largest gap along candidate axes (edge normals and vertex-to-vertex
  directions of both cores, which contain the closest-point direction of two convex polygons;
  separating axis theorem), floored at 0;
- rays: the first root of h(t) = dist(p + t d, core) - r, which is convex in t (a distance to
  a convex set along a line), found by golden-section minimisation then bisection;
- zero-radius segments: the 2x2 linear solve of the two lines.
"""
from __future__ import annotations

import math

import numpy as np

import physics


def world_core(fx):
    """(core points (k, 2) in world coordinates, radius) of fixture ``fx`` from its handles."""
    b = fx.body
    c, s = math.cos(b.angle), math.sin(b.angle)
    rot = np.array([[c, -s], [s, c]])
    shape = fx.shape
    local = np.array(shape.offset, float).reshape(1, 2) if isinstance(shape, physics.Circle) else np.array(shape.vertices, float)
    return local @ rot.T + np.array(b.position), float(shape.radius)


def _axes(P):
    """Unit edge normals of core P, both ways (a 2-point core has one edge, a point none)."""
    k = len(P)
    if k < 2:
        return np.zeros((0, 2))
    E = (np.roll(P, -1, axis=0) - P)[:k if k > 2 else 1]
    N = np.stack([E[:, 1], -E[:, 0]], axis=1)
    L = np.hypot(N[:, 0], N[:, 1])
    N = N[L > 0] / L[L > 0, None]
    return np.concatenate([N, -N])


def separation(P, Q):
    """Distance between convex cores P and Q (0 when they meet) by the largest axis gap."""
    D = (Q[None, :, :] - P[:, None, :]).reshape(-1, 2)   # every vertex-to-vertex direction
    L = np.hypot(D[:, 0], D[:, 1])
    U = np.concatenate([_axes(P), _axes(Q), D[L > 0] / L[L > 0, None]])
    if not len(U):
        return 0.0
    pu, qu = P @ U.T, Q @ U.T                             # projections, one column per axis
    gaps = np.maximum(qu.min(0) - pu.max(0), pu.min(0) - qu.max(0))
    return max(0.0, float(gaps.max()))


def point_distance(p, P):
    return separation(np.asarray(p, float).reshape(1, 2), P)


def _first_root(h, lo=0.0, hi=1.0):
    """First t in [lo, hi] with h(t) <= 0 for convex h, or None; also the minimum found."""
    if h(lo) <= 0:
        return lo, h(lo)
    g = (math.sqrt(5) - 1) / 2
    a, b = lo, hi
    for _ in range(200):
        c, d = b - g * (b - a), a + g * (b - a)
        if h(c) < h(d):
            if b == d:
                break           # the bracket stopped shrinking: its fixed point in floats
            b = d
        else:
            if a == c:
                break
            a = c
    tm = 0.5 * (a + b)
    hm = min(h(tm), h(hi))
    if h(hi) < h(tm):
        tm = hi
    if hm > 0:
        return None, hm
    a, b = lo, tm
    for _ in range(200):
        m = 0.5 * (a + b)
        if m == a or m == b:
            break               # adjacent floats: nothing left to halve
        if h(m) <= 0:
            b = m
        else:
            a = m
    return b, hm


def ray_fraction(fx, p, e):
    """(fraction or None, ambiguity): the reference hit of segment p -> e on fixture ``fx``;
    ambiguity is |min h| (a grazing ray has ~0 and is not compared)."""
    P, r = world_core(fx)
    p, e = np.asarray(p, float), np.asarray(e, float)
    d = e - p
    if r == 0.0 and len(P) == 2:
        a, b = P
        M = np.array([d, a - b]).T
        if abs(np.linalg.det(M)) < 1e-12:
            return None, 0.0
        t, u = np.linalg.solve(M, a - p)
        n = np.array([(b - a)[1], -(b - a)[0]])
        if isinstance(fx.shape, physics.ChainSegment) and n @ d >= 0:
            return None, 1.0
        amb = min(abs(t), abs(1 - t), abs(u), abs(1 - u))
        return (float(t) if 0 <= t <= 1 and 0 <= u <= 1 else None), amb
    t, hm = _first_root(lambda t: point_distance(p + t * d, P) - r)
    return t, abs(hm)


def cast_fraction(P, rp, T, fx):
    """Reference first fraction in [0, 1] at which core P (radius rp) moved by T meets ``fx``."""
    Q, rq = world_core(fx)
    t, hm = _first_root(lambda t: separation(P + t * np.asarray(T), Q) - rp - rq)
    return t, abs(hm)
