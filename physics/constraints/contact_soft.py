"""Soft contact rows (Box2D v3 style): the model, and the prepared rows restitution works on.

The verbs every constraint kind speaks, for contacts: prepare (once per step), warm start,
solve (with bias; without bias it is the relax pass), restitution
(constraints/contact_restitution.py) and store.  The passes run colour by colour over the wide
blocks (constraints/contact_coloured.py, contact_wide.py); this module holds what they share:
the prepared terms of a point and a manifold (``prepared_point``/``point_terms``,
``prepared_softness``, ``prepared_block``), the deep-overlap bias, the friction pass rule, and
the scratch rows ``R`` (``prepare_contacts``, ``store_impulses``) that restitution reads and
writes.  The model: soft
normal rows with bias (constraints/softness.py), relax, Coulomb friction, the 2x2 block solver
of constraints/block.py, restitution.

Everything that is fixed for the step is computed once: for each point the anchor projections
r x n and r . n of both bodies (the tangent is t = (-n_y, n_x), so r x t = r . n), the effective
masses, the separation at the start of the step, the friction coefficient in force, and for
two-point manifolds the block solver's K matrix and whether it is well conditioned.  The
largest normal impulse of each point (restitution needs to know whether a point pushed this
step) is tracked inside the passes, not by an extra loop.

With these projections the relative normal speed is
  v_n = (v_b - v_a) . n + w_b (r_b x n) - w_a (r_a x n),
an impulse j along n changes w_a by -I_a^-1 j (r_a x n), and the separation
after the bodies moved by (dp, R(dq)) since the step began is
  s = s0 + (dp_b - dp_a) . n + (c_b - 1)(r_b . n) + s_b (r_b x n) - (same for a).
A point still apart (s > 0) is a speculative row: the bodies may close the gap and no further.
A biased pass records, for each point that has not pushed yet this step, its normal speed
before the impulse (``VN0``): once it pushes, that is the speed at first touch (after this
sub-step's gravity), which restitution reflects.

Arguments: ``c`` the step context record (physics/step/context.py: ``nc``),
``p`` the mode's parameter record, which must have ``stick_speed``, ``h``, ``inv_h``,
``hertz_dyn``, ``hertz_static`` (contact frequencies, raised per contact by
constraints/contact_stiffness.py) and ``damping_ratio``, ``push_out_speed``,
``block_solver``, ``friction_pass`` and ``restitution_threshold``; ``B`` the body table,
``C`` the contact table, ``R`` the rows' scratch.
"""
from __future__ import annotations

import math

from .._jit import kernel
from .block import block_mass
from .contact_stiffness import contact_hertz, moving_size
from .softness import softness

# per point p the fields start at p * PT
# VN0: the normal speed just before the point first pushed this step (the speed at first touch:
# restitution's reference), MAXJ its largest normal impulse, BOUNCED 1.0 once restitution acted
RNA, RNB, RTA, RTB, MASS_N, MASS_T, SEP0, MU, VN0, MAXJ, JN, JT, BOUNCED = range(13)
PT = 13
# Deep overlap (bodies created or dragged into each other) is pushed out softer than shallow
# overlap: beyond DEEP of the smaller moving body's bounding radius the bias grows at
# DEEP_SOFTEN of the rate.  At one rate for every depth, a pyramid created 25 % overlapping
# (Box2D's OverlapRecovery) saturated push_out_speed at every contact, the layers' speeds added
# up (4.1 m/s) and it burst (top box 17 cm low); with this, 3.2 m/s and 0.7 mm (Box2D v3:
# 3.4 m/s, 2.2 mm).  Resting and impact depths stay far below DEEP (1 m boxes: 10 cm), so their
# stiffness is the mode's (constraints/contact_stiffness.py).
DEEP = 0.14
DEEP_SOFTEN = 0.25
# Where the friction rows are solved (soft_step's ``friction_pass``).  Box2D v3 solves friction in
# the relax pass only (contact_solver.c: b2SolveContactTwoPointsTask, ``useBias == false``): in
# the biased pass the normal impulses carry push-out, and friction fighting the sideways part of
# that push lets a pile creep.  Measured over Box2D v3's samples (docs/reliability.md), that order
# for every contact lets confined discs jitter 100x Box2D's speed and overlap recovery push
# harder, while in both passes a pyramid's face contacts creep (pyramid 20's top 0.076 m in 10 s
# with the ground contacts solved last).  "faces_in_relax", the default, takes Box2D's order
# where it helps: a face contact (two points) between two moving bodies, the contacts of a pile.
FRICTION_PASSES = ("both", "relax", "faces_in_relax")
FRICTION_BOTH, FRICTION_RELAX, FRICTION_FACES = range(3)
K11 = 2 * PT      # block solver: K = [[k11, k12], [k12, k22]] and 1 / det K
K22 = K11 + 1
K12 = K11 + 2
INV_DET = K11 + 3
BLOCK = K11 + 4   # 1.0 when K is well conditioned (the block solver may run)
RIGID = K11 + 5   # 1.0 when one of the bodies does not move (static/kinematic): stiffer rows
NX = K11 + 6      # the normal
NY = K11 + 7
KE0 = K11 + 8     # kinetic energy of the pair when the manifold first pushed this step (restitution's cap)
SOFT = K11 + 9    # this manifold's (bias rate, mass scale, impulse scale): constraints/contact_stiffness.py
DEEPD = K11 + 12  # this manifold's deep-overlap depth (m): DEEP x the smaller moving body's radius
NF = K11 + 13


@kernel(forceinline=True)
def manifold_state(B, C, k):
    """(a, b, n_x, n_y, 1/m_a, 1/m_b, 1/I_a, 1/I_b, w_a, w_b, (v_b - v_a) . n, (v_b - v_a) . t) of
    manifold k at the start of the step."""
    a = C.a[k]
    b = C.b[k]
    nx = C.normal[k, 0]
    ny = C.normal[k, 1]
    dvx = B.v[b, 0] - B.v[a, 0]
    dvy = B.v[b, 1] - B.v[a, 1]
    return (a, b, nx, ny, B.inv_m[a], B.inv_m[b], B.inv_i[a], B.inv_i[b], B.w[a], B.w[b], dvx * nx + dvy * ny,
            -dvx * ny + dvy * nx)


@kernel(forceinline=True)
def prepared_point(C, k, q, xax, xay, xbx, xby, nx, ny, ima, imb, iia, iib, dvnx, dvtx, wa, wb, stick_speed):
    """Point q of manifold k at the start of the step: ``point_terms`` of its point and depth."""
    return point_terms(C.point[k, q, 0], C.point[k, q, 1], C.depth[k, q], C.mu_s[k], C.mu_d[k], xax, xay, xbx, xby,
                       nx, ny, ima, imb, iia, iib, dvnx, dvtx, wa, wb, stick_speed)


@kernel(forceinline=True, error_model="numpy")
def point_terms(px, py, depth, mu_s, mu_d, xax, xay, xbx, xby, nx, ny, ima, imb, iia, iib, dvnx, dvtx, wa, wb,
                stick_speed):
    """A contact point at (px, py), ``depth`` deep, at the start of the step: (r_a x n, r_b x n,
    r_a . n, r_b . n, normal mass, tangent mass, separation, normal speed, friction coefficient);
    the module doc's terms.  Plain numbers in and out and numpy's division (no exception branch)
    keep the wide preparation's lane loop vector code (contact_prepare.py)."""
    rax = px - xax
    ray = py - xay
    rbx = px - xbx
    rby = py - xby
    rna = rax * ny - ray * nx
    rnb = rbx * ny - rby * nx
    rta = rax * nx + ray * ny
    rtb = rbx * nx + rby * ny
    kn = ima + imb + iia * rna * rna + iib * rnb * rnb
    kt = ima + imb + iia * rta * rta + iib * rtb * rtb
    vt = dvtx + wb * rtb - wa * rta
    # Coulomb (seed eq. 23): static coefficient while sticking, dynamic once sliding
    mu = mu_s if abs(vt) <= stick_speed else mu_d
    return (rna, rnb, rta, rtb, 1.0 / kn if kn > 0.0 else 0.0, 1.0 / kt if kt > 0.0 else 0.0, -depth,
            dvnx + wb * rnb - wa * rna, mu)


@kernel(forceinline=True)
def prepared_softness(p, B, C, k, a, b, ima, imb, g):
    """(rigid, bias rate, mass scale, impulse scale, deep-overlap depth) of manifold k
    (constraints/contact_stiffness.py, softness.py)."""
    rigid = ima == 0.0 or imb == 0.0
    load = 0.0
    for q in range(C.count[k]):
        load += C.jn[k, q]
    hz = contact_hertz(p.hertz_static if rigid else p.hertz_dyn, load, ima, imb, B.bound_r[a], B.bound_r[b], p.h, g)
    rate, mscale, iscale = softness(hz, p.damping_ratio, p.h)
    return rigid, rate, mscale, iscale, DEEP * moving_size(ima, imb, B.bound_r[a], B.bound_r[b])


@kernel(forceinline=True, error_model="numpy")
def prepared_block(ima, imb, iia, iib, ra0, rb0, ra1, rb1):
    """(k11, k22, k12, well conditioned, 1 / det K) of a two-point manifold (constraints/block.py)."""
    im = ima + imb
    k11 = im + iia * ra0 * ra0 + iib * rb0 * rb0
    k22 = im + iia * ra1 * ra1 + iib * rb1 * rb1
    k12 = im + iia * ra0 * ra1 + iib * rb0 * rb1
    ok, inv_det = block_mass(k11, k12, k22)
    return k11, k22, k12, ok, inv_det


@kernel
def prepare_contacts(c, p, B, C, R):
    """Fill R[:nc] from the manifolds and the bodies' state at the start of the step."""
    stick_speed = p.stick_speed
    g = math.hypot(c.gx, c.gy)
    for k in range(c.nc):
        a, b, nx, ny, ima, imb, iia, iib, wa, wb, dvnx, dvtx = manifold_state(B, C, k)
        cnt = C.count[k]
        for q in range(cnt):
            o = q * PT
            (R[k, o + RNA], R[k, o + RNB], R[k, o + RTA], R[k, o + RTB], R[k, o + MASS_N], R[k, o + MASS_T],
             R[k, o + SEP0], R[k, o + VN0], R[k, o + MU]) = prepared_point(
                C, k, q, B.x[a, 0], B.x[a, 1], B.x[b, 0], B.x[b, 1], nx, ny, ima, imb, iia, iib, dvnx, dvtx, wa, wb,
                stick_speed)
            R[k, o + MAXJ] = 0.0
            R[k, o + BOUNCED] = 0.0
            R[k, o + JN] = C.jn[k, q]
            R[k, o + JT] = C.jt[k, q]
        if cnt < 2:  # the restitution checks read the second point's flags
            R[k, PT + MAXJ] = 0.0
            R[k, PT + BOUNCED] = 0.0
        R[k, NX] = nx
        R[k, NY] = ny
        rigid, R[k, SOFT], R[k, SOFT + 1], R[k, SOFT + 2], R[k, DEEPD] = prepared_softness(p, B, C, k, a, b, ima,
                                                                                        imb, g)
        R[k, RIGID] = 1.0 if rigid else 0.0
        R[k, BLOCK] = 0.0
        if cnt == 2:
            k11, k22, k12, ok, inv_det = prepared_block(ima, imb, iia, iib, R[k, RNA], R[k, RNB], R[k, PT + RNA],
                                                        R[k, PT + RNB])
            R[k, K11] = k11
            R[k, K22] = k22
            R[k, K12] = k12
            if ok:
                R[k, BLOCK] = 1.0
                R[k, INV_DET] = inv_det


@kernel(forceinline=True)
def deep_bias(rate, sep, deep):
    """The soft row's velocity bias at separation ``sep`` < 0: the bias ``rate`` up to ``deep``
    of overlap, DEEP_SOFTEN of it beyond (continuous; written as a max so that the coloured
    solve's lanes stay branch-free)."""
    return rate * max(sep, DEEP_SOFTEN * sep - (1.0 - DEEP_SOFTEN) * deep)


@kernel(forceinline=True)
def friction_late(fp, use_bias, two, ima, iia, imb, iib):
    """Does a manifold leave its friction rows to the relax pass (``fp`` the friction_pass)?  In
    the biased pass (``use_bias``) with "relax", or with "faces_in_relax" for a two-point
    manifold (``two``) between two moving bodies (inverse masses and inertias).  Written
    with & and |, not branches, so that the wide solve's lane loop stays vector code."""
    moving = ((ima > 0.0) | (iia > 0.0)) & ((imb > 0.0) | (iib > 0.0))
    return use_bias & ((fp == FRICTION_RELAX) | ((fp == FRICTION_FACES) & two & moving))


@kernel
def store_impulses(c, C, R):
    """The accumulated impulses back into the contact table (next step's warm start)."""
    for k in range(c.nc):
        for q in range(C.count[k]):
            C.jn[k, q] = R[k, q * PT + JN]
            C.jt[k, q] = R[k, q * PT + JT]
