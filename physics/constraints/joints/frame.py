"""The joint's frame now: arms and anchor separation from the step-start frame.

Box2D v3 (joint.c, b2PrepareJointsTask and the solvers' use of deltaPosition /
deltaRotation) keeps each joint's arms as rotated at the step start and moves
them by each body's rotation since then, so the separation of the anchors is
    d = (x_a0 - x_b0) + (dp_a - dp_b) + R(dq_a) r_a0 - R(dq_b) r_b0
without adding large world coordinates again every pass.  The body rows hold dp
and (cos, sin) of dq (constraints/body_rows.py); the world is a row that never
moves.
"""
from __future__ import annotations

from .jit import row_inline
from ..body_rows import DCOS, DPX, DPY, DSIN
from .layout import D0, RA0, RB0, U0


@row_inline
def arms(JW, j, a, b):
    """(r_a, r_b, d = p_a - p_b) of joint j now, as six floats."""
    ca = JW.SB[a, DCOS]
    sa = JW.SB[a, DSIN]
    cb = JW.SB[b, DCOS]
    sb = JW.SB[b, DSIN]
    rax = ca * JW.F[j, RA0] - sa * JW.F[j, RA0 + 1]
    ray = sa * JW.F[j, RA0] + ca * JW.F[j, RA0 + 1]
    rbx = cb * JW.F[j, RB0] - sb * JW.F[j, RB0 + 1]
    rby = sb * JW.F[j, RB0] + cb * JW.F[j, RB0 + 1]
    dx = JW.F[j, D0] + (JW.SB[a, DPX] - JW.SB[b, DPX]) + (rax - rbx)
    dy = JW.F[j, D0 + 1] + (JW.SB[a, DPY] - JW.SB[b, DPY]) + (ray - rby)
    return rax, ray, rbx, rby, dx, dy


@row_inline
def axis(JW, j, a):
    """The joint axis now (fixed in a's frame)."""
    ca = JW.SB[a, DCOS]
    sa = JW.SB[a, DSIN]
    return ca * JW.F[j, U0] - sa * JW.F[j, U0 + 1], sa * JW.F[j, U0] + ca * JW.F[j, U0 + 1]


@row_inline
def relative_angle(B, J, j):
    """q_a - q_b - ref: a's angle relative to b (or the world) from the reference."""
    b = J.b[j]
    qb = B.q[b] if b >= 0 else 0.0
    return B.q[J.a[j]] - qb - J.ref[j]


@row_inline
def cross(ax, ay, bx, by):
    return ax * by - ay * bx
