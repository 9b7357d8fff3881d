"""Push-out of the penetration left after the impulses (seed 3.2-3.3).

Acts on the points flagged IMPULSE; depths are measured at the current
state (solvers/classic/contact_geometry.py), down to ``allow`` metres.  Rows are
visited in order, ``iterations`` times, so a stack settles.

- Linear (3.2): body i moves along the penetration vector by the share
  (1/m_i) / (1/m_a + 1/m_b) (eq. 1 as printed, m1/(m1+m2), would move the heavy
  body more).  The eq. 2 energy correction lives in the impulse stage
  (impulses.activate_impulses), on the approach speed.
- Non-linear (3.3): the push-out of the deepest point is split into a linear
  and a rotational part per body, weighted by 1/m_i and (r_i x n)^2 / I_i (eqs.
  3-4; eq. 4 as printed repeats 1/m_i, and eq. 3's 1/I terms lack the arm).  The
  rotation is solved explicitly (eqs. 5-7): turn the arm r about the centre of
  mass until the point lies on the line it must reach (|r'| = |r|, n.r' = n.r + s),
  taking the smaller of the two solutions (eq. 7's arccos with the sign of r x r').
  If the line is out of reach the remainder is translated.  ``min_linear`` is the
  report's lower bound on the linear share (deep penetration, large inertia).
  A two-point (edge) contact first translates by the shallower depth, which
  rotation cannot remove, and rotates only for the difference.
"""
from __future__ import annotations

import math

from ..._jit import kernel
from ...store import DYNAMIC
from .contact_geometry import IMPULSE, depth_at

MAX_TURN = 0.25  # rad per push: the linearised depth is trusted no further


@kernel
def _inv(B, i):
    if B.kind[i] != DYNAMIC or B.awake[i] == 0:
        return 0.0, 0.0
    return B.inv_m[i], B.inv_i[i]


@kernel
def translate(B, a, b, d, nx, ny):
    """Linear push-out by d along n, shares by inverse mass (eq. 1 corrected)."""
    ima, _ = _inv(B, a)
    imb, _ = _inv(B, b)
    w = ima + imb
    if w <= 0.0 or d <= 0.0:
        return
    B.x[a, 0] -= d * ima / w * nx
    B.x[a, 1] -= d * ima / w * ny
    B.x[b, 0] += d * imb / w * nx
    B.x[b, 1] += d * imb / w * ny


@kernel
def turn_to_line(rx, ry, nx, ny, s):
    """Rotation taking arm r to r' with |r'| = |r| and n.r' = n.r + s (eqs. 5-7); nan if none."""
    rr = rx * rx + ry * ry
    h = nx * rx + ny * ry + s
    if h * h > rr:
        return math.nan
    tx, ty = -ny, nx
    st = math.sqrt(rr - h * h)
    if tx * rx + ty * ry < 0.0:  # keep the tangential side: the smaller rotation
        st = -st
    px = h * nx + st * tx
    py = h * ny + st * ty
    return math.atan2(rx * py - ry * px, rx * px + ry * py)


@kernel
def rotate_part(B, i, rx, ry, nx, ny, s):
    """Move body i's material point by s along n by rotation; returns what is left."""
    th = turn_to_line(rx, ry, nx, ny, s)
    if math.isnan(th):
        return s
    if abs(th) > MAX_TURN:
        frac = MAX_TURN / abs(th)
        B.q[i] += frac * th
        return s * (1.0 - frac)
    B.q[i] += th
    return 0.0


@kernel
def push_point(B, C, P, k, p, d, min_linear, R):
    """Non-linear push-out of depth d at point p (eqs. 3-7)."""
    a = C.a[k]
    b = C.b[k]
    nx = C.normal[k, 0]
    ny = C.normal[k, 1]
    _, rax, ray, rbx, rby = depth_at(C, P, k, p, B.x, B.q, R.X0, R.Q0)
    ima, iia = _inv(B, a)
    imb, iib = _inv(B, b)
    ca = rax * ny - ray * nx
    cb = rbx * ny - rby * nx
    wa_ang = ca * ca * iia
    wb_ang = cb * cb * iib
    tot = ima + imb + wa_ang + wb_ang
    if tot <= 0.0:
        return
    lin = (ima + imb) / tot
    ang_scale = 1.0
    if lin < min_linear:
        ang_scale = (1.0 - min_linear) / (1.0 - lin)
    # rotational parts first (they need the arms measured now), leftovers are translated
    left_a = rotate_part(B, a, rax, ray, -nx, -ny, d * wa_ang / tot * ang_scale) if wa_ang > 0.0 else 0.0
    left_b = rotate_part(B, b, rbx, rby, nx, ny, d * wb_ang / tot * ang_scale) if wb_ang > 0.0 else 0.0
    lin_d = d * (1.0 - (wa_ang + wb_ang) / tot * ang_scale) + left_a + left_b
    translate(B, a, b, lin_d, nx, ny)


@kernel
def project(B, C, nc, P, R, allow, nonlinear, min_linear, iterations):
    for _ in range(iterations):
        for k in range(nc):
            d0 = -1e300
            d1 = -1e300
            for p in range(C.count[k]):
                if P.role[k, p] != IMPULSE:
                    continue
                d = depth_at(C, P, k, p, B.x, B.q, R.X0, R.Q0)[0] - allow
                if p == 0:
                    d0 = d
                else:
                    d1 = d
            deep = max(d0, d1)
            if deep <= 0.0:
                continue
            nx = C.normal[k, 0]
            ny = C.normal[k, 1]
            if not nonlinear:
                translate(B, C.a[k], C.b[k], deep, nx, ny)
                continue
            common = min(d0, d1)
            if common > 0.0:  # an edge on an edge: the shared depth is a translation
                translate(B, C.a[k], C.b[k], common, nx, ny)
            else:
                common = 0.0
            push_point(B, C, P, k, 0 if d0 >= d1 else 1, deep - common, min_linear, R)
