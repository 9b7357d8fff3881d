"""The joint verbs for all joints at once: a solver mode calls one function per verb.  The
branches on a joint's kind are all here (``joint_prepare``, ``joint_rows``); a kind's own work is
in its module (``prepare_<kind>``, ``rows_<kind>``).

- ``warm_start_joints``: every row's accumulated impulse applied again;
- ``solve_joints(use_bias)``: the spring, motor and limit rows (and the motor and
  mouse joints) in sequence, then the equality rows: each joint's block in
  sequence (Box2D v3) or, with ``eq_global``, all of them together
  (system/solve.py) except those of structures the system left sequential, and
  a structure of one joint as its own block (system/block.py, the system's numbers);
  without bias it is the relax pass;
- ``store_joints``: reaction force and torque of the last pass into the table,
  and breaking (returns how many joints broke).
Rows are written by the kind's ``rows_*`` at the bodies' current positions, by ``refresh_rows``
(and ``warm_start_joints``, which calls it): once after each move, for every pass until the next.
"""
from __future__ import annotations

import math

from .jit import row_inline, row_kernel
from ...store.joints import BROKEN, DISTANCE, MOTOR, MOUSE, PRISMATIC, REVOLUTE, ROWS, WELD, WHEEL
from .distance import prepare_distance, rows_distance
from .frame import arms, cross
from .layout import KA, NX, NY
from .motor import prepare_motor, rows_motor, solve_motor_joint
from .mouse import prepare_mouse, rows_mouse, solve_mouse
from .prismatic import prepare_prismatic, rows_prismatic
from .revolute import prepare_revolute, rows_revolute
from .rotary import ROTARY, prepare_rotary, rows_rotary
from .rows import block_factors, solve_equality, solve_free_rows, warm_start_rows
from .system.block import BLOCK, SEQUENTIAL, correct_block, solve_block
from .system.solve import FACTORED, STALE, correct_system, solve_system
from .weld import prepare_weld, rows_weld
from .wheel import prepare_wheel, rows_wheel


@row_inline
def joint_prepare(J, JW, j, h):
    """Softness and clamps of joint j for a step of passes of span h (its kind's ``prepare_*``);
    returns its row mask (which of its rows take part)."""
    k = J.kind[j]
    if k == REVOLUTE:
        return prepare_revolute(J, JW, j, h)
    if k == PRISMATIC:
        return prepare_prismatic(J, JW, j, h)
    if k == WELD:
        return prepare_weld(J, JW, j, h)
    if k == DISTANCE:
        return prepare_distance(J, JW, j, h)
    if k == WHEEL:
        return prepare_wheel(J, JW, j, h)
    if k == MOTOR:
        return prepare_motor(J, JW, j, h)
    if k == MOUSE:
        return prepare_mouse(J, JW, j, h)
    if k == ROTARY:
        return prepare_rotary(J, JW, j, h)
    return 0


@row_inline
def joint_rows(B, J, JW, j, a, b):
    """Row geometry of joint j now (its kind's ``rows_*``)."""
    k = J.kind[j]
    if k == REVOLUTE:
        rows_revolute(B, J, JW, j, a, b)
    elif k == PRISMATIC:
        rows_prismatic(B, J, JW, j, a, b)
    elif k == WELD:
        rows_weld(B, J, JW, j, a, b)
    elif k == DISTANCE:
        rows_distance(B, J, JW, j, a, b)
    elif k == WHEEL:
        rows_wheel(B, J, JW, j, a, b)
    elif k == MOTOR:
        rows_motor(B, J, JW, j, a, b)
    elif k == MOUSE:
        rows_mouse(B, J, JW, j, a, b)
    elif k == ROTARY:
        rows_rotary(B, J, JW, j, a, b)


@row_inline
def equality_rows_of(mask):
    return (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1)


@row_kernel
def refresh_rows(c, B, J, JW, JS):
    """Every joint's rows at the bodies' current positions.  A row's geometry depends on the
    positions only (the arms, the separation, the angle, the effective mass), so the rows built
    here serve every velocity pass until the bodies move again: this is the one place the kinds'
    row builders are compiled into, and each is run once per move, not once per pass.  The global
    system's factors are of the old rows: stale (system/solve.py); each joint's own equality block
    is factored here (rows.block_factors)."""
    JS.dims[FACTORED] = STALE
    for j in range(c.nj):
        if JW.on[j]:
            a = JW.ab[j, 0]
            b = JW.ab[j, 1]
            joint_rows(B, J, JW, j, a, b)
            m = equality_rows_of(JW.mask[j])
            if m > 0:
                block_factors(JW, j, a, b, m)


@row_kernel
def warm_start_joints(c, B, J, JW, JS, refresh):
    """The rows at the current positions (unless ``refresh`` is False: the caller's last
    ``refresh_rows`` came after the last move), then every row's accumulated impulse applied
    again."""
    if refresh:
        refresh_rows(c, B, J, JW, JS)
    for j in range(c.nj):
        if JW.on[j]:
            warm_start_rows(J, JW, j, JW.ab[j, 0], JW.ab[j, 1])


@row_kernel
def solve_joints(c, B, J, JW, JS, use_bias, inv_h, eq_global):
    """One pass over every joint (see the module doc) on the rows of the last ``refresh_rows``
    or ``warm_start_joints``: the caller refreshes them after the bodies moved."""
    for j in range(c.nj):
        if not JW.on[j]:
            continue
        a = JW.ab[j, 0]
        b = JW.ab[j, 1]
        kind = J.kind[j]
        if kind == MOTOR:
            solve_motor_joint(J, JW, j, a, b, inv_h)
            continue
        if kind == MOUSE:
            solve_mouse(J, JW, j, a, b)
            continue
        mask = JW.mask[j]
        solve_free_rows(J, JW, j, a, b, mask, use_bias, inv_h)
        m = equality_rows_of(mask)
        if m > 0 and (not eq_global or JW.seq[j] == SEQUENTIAL):
            solve_equality(J, JW, j, a, b, m, use_bias)
    if eq_global:
        for j in range(c.nj):  # the structures of one joint, where the system is solved
            if JW.on[j] and JW.seq[j] == BLOCK:
                solve_block(J, JW, j, JW.ab[j, 0], JW.ab[j, 1], equality_rows_of(JW.mask[j]), use_bias)
        if JS.dims[0] > 0:
            solve_system(J, JW, JS, use_bias)


@row_kernel
def correct_structures(c, B, JW, JS):
    """One Newton step on the positions of the globally solved structures, at the rows as they
    are: each lone joint's block, then the system (the position passes of every mode)."""
    for j in range(c.nj):
        if JW.on[j] and JW.seq[j] == BLOCK:
            correct_block(B, JW, j, JW.ab[j, 0], JW.ab[j, 1], equality_rows_of(JW.mask[j]))
    if JS.dims[0] > 0:
        correct_system(B, JW, JS, 1.0)


@row_kernel
def project_joints(c, B, J, JW, JS):
    """``correct_structures`` at the rows where the bodies are now; nothing without such
    structures."""
    blocks = False
    for j in range(c.nj):
        blocks |= JW.seq[j] == BLOCK
    if not blocks and JS.dims[0] == 0:
        return
    refresh_rows(c, B, J, JW, JS)
    correct_structures(c, B, JW, JS)


@row_kernel
def store_joints(c, J, JW, inv_span):
    """Reaction force on a and torque about a's anchor (from every row's impulse) per second of
    the last pass, and breaking; returns the number of joints that broke in this step."""
    broken = 0
    G = JW.G
    for j in range(c.nj):
        if not JW.on[j]:
            continue
        a = JW.ab[j, 0]
        b = JW.ab[j, 1]
        rax, ray, _, _, _, _ = arms(JW, j, a, b)
        fx = 0.0
        fy = 0.0
        tq = 0.0
        for r in range(ROWS):
            lam = J.impulse[j, r]
            if lam != 0.0:
                nx = G[j, r, NX]
                ny = G[j, r, NY]
                fx += lam * nx
                fy += lam * ny
                tq += lam * (G[j, r, KA] - cross(rax, ray, nx, ny))
        fx *= inv_span
        fy *= inv_span
        tq *= inv_span
        J.force[j, 0] = fx
        J.force[j, 1] = fy
        J.torque[j] = tq
        bf = J.break_force[j]
        bt = J.break_torque[j]
        if (not math.isnan(bf) and math.hypot(fx, fy) >= bf) or (not math.isnan(bt) and abs(tq) >= bt):
            J.flags[j] |= BROKEN
            JW.on[j] = 0
            for r in range(ROWS):
                J.impulse[j, r] = 0.0
            broken += 1
    return broken
