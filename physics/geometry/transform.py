"""World-space geometry for the collision stages: vertices, normals, AABBs."""
from __future__ import annotations

import math

from .._jit import kernel
from ..store import CIRCLE


@kernel
def update_geometry(B, V, n, dt, spec):
    """Transform every polygon to world space and refresh the AABBs.

    Each AABB is fattened by m_i = spec/2 + dt (|v_i| + |w_i| r_i): two boxes
    then overlap whenever the bodies can come within the pair's speculative
    margin during the step, so the narrow phase never misses a fast pair.
    """
    for i in range(n):
        c = math.cos(B.q[i])
        s = math.sin(B.q[i])
        px = B.x[i, 0]
        py = B.x[i, 1]
        margin = 0.5 * spec + dt * (math.hypot(B.v[i, 0], B.v[i, 1]) + abs(B.w[i]) * B.bound_r[i])
        if B.shape[i] == CIRCLE:
            r = B.radius[i]
            B.aabb[i, 0] = px - r - margin
            B.aabb[i, 1] = py - r - margin
            B.aabb[i, 2] = px + r + margin
            B.aabb[i, 3] = py + r + margin
            continue
        lo_x = math.inf
        lo_y = math.inf
        hi_x = -math.inf
        hi_y = -math.inf
        for k in range(B.vstart[i], B.vstart[i] + B.vcount[i]):
            lx = V.local[k, 0]
            ly = V.local[k, 1]
            wx = px + c * lx - s * ly
            wy = py + s * lx + c * ly
            V.world[k, 0] = wx
            V.world[k, 1] = wy
            nx = V.normal[k, 0]
            ny = V.normal[k, 1]
            V.wnormal[k, 0] = c * nx - s * ny
            V.wnormal[k, 1] = s * nx + c * ny
            lo_x = min(lo_x, wx)
            lo_y = min(lo_y, wy)
            hi_x = max(hi_x, wx)
            hi_y = max(hi_y, wy)
        B.aabb[i, 0] = lo_x - margin
        B.aabb[i, 1] = lo_y - margin
        B.aabb[i, 2] = hi_x + margin
        B.aabb[i, 3] = hi_y + margin
