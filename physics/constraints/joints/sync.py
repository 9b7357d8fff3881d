"""Body rows and the body table in step, for modes whose contacts work on the table.

sequential_impulse and the classic modes move the body table; their joint
passes work on body rows (constraints/body_rows.py) like soft_step's, so the
velocities are copied in and out around each joint pass, and the displacement
since the step began is taken from the step-start positions ``X0``/``Q0``.
Only worlds with joints pay for it.
"""
from __future__ import annotations

import math

from .jit import row_kernel
from ..body_rows import DCOS, DPX, DPY, DSIN, VX, VY, W


@row_kernel
def save_start(B, n, X0, Q0):
    for i in range(n):
        X0[i, 0] = B.x[i, 0]
        X0[i, 1] = B.x[i, 1]
        Q0[i] = B.q[i]


@row_kernel
def rows_from_table(B, n, SB):
    for i in range(n):
        SB[i, VX] = B.v[i, 0]
        SB[i, VY] = B.v[i, 1]
        SB[i, W] = B.w[i]


@row_kernel
def table_from_rows(B, n, SB):
    for i in range(n):
        B.v[i, 0] = SB[i, VX]
        B.v[i, 1] = SB[i, VY]
        B.w[i] = SB[i, W]


@row_kernel
def displacement_from_table(B, n, JW):
    """dp = x - x0 and (cos, sin) of q - q0 for every body row (x0, q0: JW.X0, JW.Q0)."""
    SB = JW.SB
    X0 = JW.X0
    Q0 = JW.Q0
    for i in range(n):
        SB[i, DPX] = B.x[i, 0] - X0[i, 0]
        SB[i, DPY] = B.x[i, 1] - X0[i, 1]
        t = B.q[i] - Q0[i]
        if t == 0.0:
            SB[i, DCOS] = 1.0
            SB[i, DSIN] = 0.0
        else:
            SB[i, DCOS] = math.cos(t)
            SB[i, DSIN] = math.sin(t)
