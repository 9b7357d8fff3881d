"""Moving bodies by a row's impulse at the position level (non-linear Gauss-Seidel).

A position impulse lam along a row moves a by (m_a^-1 lam n, I_a^-1 lam ka) and
b the opposite way (Catto's NGS, Box2D 2.x SolvePositionConstraints).  The body
rows' displacement since the step began follows, so the next row sees where
the bodies are now; ``X0``/``Q0`` are the positions at the step start.
"""
from __future__ import annotations

import math

from .jit import row_inline
from ..body_rows import DCOS, DPX, DPY, DSIN, II, IM
from .layout import KA, KB, NX, NY

MAX_LINEAR = 0.2   # m per correction (Box2D 2.x's b2_maxLinearCorrection)
MAX_ANGULAR = 8.0 * math.pi / 180.0  # rad per correction (b2_maxAngularCorrection)


@row_inline
def move(B, JW, i, dx, dy, dq):
    SB = JW.SB
    B.x[i, 0] += dx
    B.x[i, 1] += dy
    B.q[i] += dq
    SB[i, DPX] += dx
    SB[i, DPY] += dy
    t = B.q[i] - JW.Q0[i]
    SB[i, DCOS] = math.cos(t)
    SB[i, DSIN] = math.sin(t)


@row_inline
def shift_row(B, JW, a, b, j, r, lam):
    """Position impulse lam along row r of joint j (bodies that cannot move stay)."""
    nx = JW.G[j, r, NX]
    ny = JW.G[j, r, NY]
    ima = JW.SB[a, IM]
    iia = JW.SB[a, II]
    imb = JW.SB[b, IM]
    iib = JW.SB[b, II]
    if ima > 0.0 or iia > 0.0:
        move(B, JW, a, ima * lam * nx, ima * lam * ny, iia * lam * JW.G[j, r, KA])
    if imb > 0.0 or iib > 0.0:
        move(B, JW, b, -imb * lam * nx, -imb * lam * ny, -iib * lam * JW.G[j, r, KB])


@row_inline
def capped_error(JW, j, r, c):
    """The position error a correction may remove at once (linear or angular cap)."""
    top = MAX_ANGULAR if JW.G[j, r, NX] == 0.0 and JW.G[j, r, NY] == 0.0 else MAX_LINEAR
    return min(max(c, -top), top)
