"""Exact mass properties of a rounded convex polygon (a core swept by a disc of radius r).

The Minkowski sum of a convex core with a disc splits into pieces whose moments are closed
forms: the core itself, one rectangle of width r outside each edge, and one circular sector
of radius r at each vertex, spanning the turn between the normals of its two edges (the
sectors add up to one full disc).  Summing areas, first and second moments of the pieces
gives the exact area A_core + P r + pi r^2 and inertia, where Box2D v3's b2ComputePolygonMass
approximates the rounding by pushing the vertices out.  A two-vertex core is a capsule
(rectangle + two half discs); the sum covers it unchanged.

Moments are taken about the core's vertex mean to avoid cancellation far from the origin.
"""
from __future__ import annotations

import math

import numpy as np


def successors(p: np.ndarray) -> np.ndarray:
    """Each vertex's successor around the outline, ``np.roll(p, -1, axis=0)`` without its
    generic-axis overhead (a box's moments are taken thousands of times as a big scene loads)."""
    return np.concatenate((p[1:], p[:1]))


def _polygon_moments(p: np.ndarray) -> tuple[float, np.ndarray, float]:
    """(area, first moment (2,), polar second moment) of a CCW polygon about the origin.

    Sum over the triangles (0, p_i, p_i+1): A = 1/2 sum c_i, S = 1/6 sum c_i (p_i + p_i+1),
    J = 1/12 sum c_i (p_i.p_i + p_i.p_i+1 + p_i+1.p_i+1) with c_i = p_i x p_i+1.
    """
    q = successors(p)
    cr = p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]
    area = 0.5 * float(cr.sum())
    first = ((p + q) * cr[:, None]).sum(axis=0) / 6.0
    dots = (p * p).sum(1) + (p * q).sum(1) + (q * q).sum(1)
    return area, first, float((cr * dots).sum()) / 12.0


def _sector_moments(v: np.ndarray, r: float, a0: float, a1: float) -> tuple[float, np.ndarray, float]:
    """(area, first moment, polar second moment about the origin) of the sector at v, angles a0..a1.

    About the apex: A = r^2 t / 2, S = r^3/3 (sin a1 - sin a0, cos a0 - cos a1), J = r^4 t / 4
    (t = a1 - a0); moved to the origin: J_o = J + 2 v.S + |v|^2 A.
    """
    t = a1 - a0
    area = 0.5 * r * r * t
    s = (r ** 3 / 3.0) * np.array([math.sin(a1) - math.sin(a0), math.cos(a0) - math.cos(a1)])
    j = 0.25 * r ** 4 * t
    return area, s + v * area, j + 2.0 * float(v @ s) + float(v @ v) * area


# rounded_mass of the cores met lately, by their exact bytes: a world that adds the same shape
# many times (rain's ragdolls: 275 capsules per event, each mass computed twice, at 0.2 ms in
# numpy) reuses the numbers, which are the same function of the same inputs (bit-identical)
_MEMO: dict = {}
_MEMO_SIZE = 4096


def rounded_mass(core: np.ndarray, r: float) -> tuple[float, np.ndarray, float]:
    """(area m^2, centroid (2,), polar second moment about the centroid per unit density).

    ``core``: CCW convex vertices (n >= 2; n == 2 is a capsule's segment), ``r`` > 0.
    """
    core = np.asarray(core)
    key = (core.shape, core.dtype.str, core.tobytes(), type(r), float(r))  # a numpy r computes as numpy
    hit = _MEMO.get(key)
    if hit is None:
        if len(_MEMO) >= _MEMO_SIZE:
            _MEMO.clear()
        hit = _MEMO[key] = _rounded_mass(core, r)
    area, c, j = hit
    return area, c.copy(), j


def _rounded_mass(core: np.ndarray, r: float) -> tuple[float, np.ndarray, float]:
    """rounded_mass computed (the sum of the core, edge strips and corner sectors)."""
    o = core.mean(axis=0)
    p = core - o
    n = len(p)
    area, first, j = (0.0, np.zeros(2), 0.0) if n < 3 else _polygon_moments(p)
    normals = []
    for i in range(n):
        e = p[(i + 1) % n] - p[i]
        nrm = np.array([e[1], -e[0]]) / math.hypot(e[0], e[1])
        normals.append(nrm)
        rect = np.array([p[i], p[i] + r * nrm, p[(i + 1) % n] + r * nrm, p[(i + 1) % n]])  # CCW
        a_, s_, j_ = _polygon_moments(rect)
        area, first, j = area + a_, first + s_, j + j_
    for i in range(n):
        n0, n1 = normals[i - 1], normals[i]
        a0 = math.atan2(n0[1], n0[0])
        turn = math.atan2(n0[0] * n1[1] - n0[1] * n1[0], n0 @ n1)
        if n == 2:  # the two normals of a segment are opposite: each end is a half disc
            turn = math.pi
        a_, s_, j_ = _sector_moments(p[i], r, a0, a0 + turn)
        area, first, j = area + a_, first + s_, j + j_
    c = first / area
    return area, o + c, j - area * float(c @ c)
