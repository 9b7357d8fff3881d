"""soft_step's whole step as one compiled call over a step pack (physics/step/pack.py).

The stages are the pipeline's (physics/step/pipeline.py), in Box2D v3's order of
``b2World_Step``: begin (checkpoint, geometry, the guard's opening sums), broad phase and pair
filter, narrow phase, the soft step (solver.c's stages), islands and sleep, the finite check,
the energy guard and the touching merge.  Each is the same kernel the pipeline calls, so both
paths give the same numbers.  Python calls ``soft_world_step(P)`` once per step and reads the
result from ``P.S`` (the S_* slots); what only Python can do (grow an array, raise, call the
user back) it does on the code returned.

A return before the narrow phase's rows are final leaves nothing changed that a second call
would not redo: Python grows what was short and calls again.
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel
from ..collision.broadphase.brute import brute_pairs
from ..collision.broadphase.sweep import sweep_pairs
from ..collision.broadphase.fixture_filter import filter_pairs
from ..collision.narrowphase.kernel import collide_with, sort_pairs
from ..constraints.joints.kinds import kinds_changed
from ..solvers.soft_step.kernel import soft_step
from ..store.flat import bodies_view, contacts_view, fixtures_view, springs_view, verts_view
from ..store.optional import optional_joints, optional_springs
from .clock import cycles
from .energy_bound import ACTIVE, guard_begin, guard_excess
from .energy_sums import motor_power
from .frame import begin_step, end_step
from .islands import joint_links_flat, update_islands

#: P.S slots: counts (bodies, fixtures, springs, joints), the step number, contact rows, which
#: contact table and which touching set is current, the last touching count, the broad phase's
#: pairs and their limit, sleeping on, awake bodies, joints broken, the size a grow code asks
#: for, the touching merge's counts, the non-finite count
(S_N, S_NF, S_NS, S_NJ, S_STEP, S_NC, S_CPAR, S_EPAR, S_NTOUCH, S_NPAIRS, S_LIMIT, S_SLEEP, S_NAWAKE,
 S_BROKEN, S_NEED, S_NT, S_NB, S_NA, S_KBAD, S_SWEEP) = range(20)
S_SLOTS = 20
#: P.D slots: the guard's growth r, |g|, the contact and joint impulses' adopt factors
D_GROWTH, D_GMAG, D_CADOPT, D_JADOPT = range(4)
D_SLOTS = 4
#: return codes
OK, GROW_PAIRS, TOO_MANY_PAIRS, GROW_ROWS, NEED_FULL, JOINT_KINDS, NONFINITE, GAINED = range(8)
#: P.T: cycle stamps at the start and after each of the profile's six stages
T_SLOTS = 7


@kernel
def _motors(JF, JI, BF, BI, nj):
    """(power bound, dragged) of the joints' motors (energy_sums.motor_power); none without."""
    if JF is None:
        return 0.0, np.bool_(False)  # a literal False would compile guard_begin twice
    return motor_power(JF, JI, BF, BI, nj)


@kernel
def _broad_phase(F, nf, pairs, swept, sweep):
    """The fixtures' overlapping pairs: brute force, or (``swept``) the sweep with the world's
    scratch, whose ``tmp`` is as long as ``pairs``, so a count that fits one fits both.  A runtime
    choice, not an optional argument: both worlds then step with one compiled driver."""
    if not swept:
        return brute_pairs(F, nf, pairs)
    state, order, key, b0, b1, bstart, ent, tmp, head = sweep
    return sweep_pairs(F, nf, state, order, key, b0, b1, bstart, ent, tmp, head, pairs)


@kernel
def _joints_ready(JF, JI, BF, BI, nj, kinds):
    """False when a joined body changed kind (Python rebuilds the joint system)."""
    if JF is None:
        return True
    return not kinds_changed(JF, JI, BF, BI, nj, kinds)


@kernel(runtime=True)
def _scale_joint_impulses(JF, JI, nj, r):
    """JointTable.adopt: the joints' impulses times ``r``."""
    if JF is None or r == 1.0:
        return
    J = optional_joints(JF, JI)
    for j in range(nj):
        for k in range(J.impulse.shape[1]):
            J.impulse[j, k] *= r


@kernel(runtime=True)
def _links(JF, JI, nj, out):
    """The joints' island links (islands.joint_links_flat); no rows without joints."""
    if JF is None:
        return out[:0]
    return out[:joint_links_flat(JF, JI, nj, out)]


@kernel
def _scale_impulses(C, nc, r):
    """ContactBuffer.adopt: the carried impulses times ``r``."""
    if r != 1.0:
        for k in range(nc):
            for p in range(C.jn.shape[1]):
                C.jn[k, p] *= r
                C.jt[k, p] *= r


@kernel(entry=True, runtime=True)
def soft_world_step(P):
    """One step of the world in ``P`` (see the module doc); returns a code."""
    S, T, D, G = P.S, P.T, P.D, P.G
    T[0] = cycles()
    c = P.ctx[0]
    c.step = S[S_STEP]
    c.n = S[S_N]
    c.ns = S[S_NS]
    c.nj = S[S_NJ]
    nf = S[S_NF]
    B = bodies_view(P.BF, P.BI)
    F = fixtures_view(P.FF, P.FI, P.ghost, P.wghost)
    Sp = springs_view(P.SF, P.SI)
    begin_step(P.ctx, B, F, verts_view(P.VF, P.VI), nf, P.X, P.Q, P.V, P.W, Sp, P.start)
    p_start, dragged = _motors(P.JF, P.JI, P.BF, P.BI, S[S_NJ])
    guard_begin(G, P.start, D[D_GROWTH], p_start, dragged)
    if not _joints_ready(P.JF, P.JI, P.BF, P.BI, S[S_NJ], P.kinds):
        return JOINT_KINDS
    T[1] = cycles()
    npairs = _broad_phase(F, nf, P.pairs, S[S_SWEEP] != 0, P.sweep)
    S[S_NEED] = npairs
    if npairs > S[S_LIMIT]:
        return TOO_MANY_PAIRS
    if npairs > P.pairs.shape[0]:
        return GROW_PAIRS
    npairs = filter_pairs(F, P.pairs, npairs, P.exclude)
    S[S_NPAIRS] = npairs
    S[S_NEED] = npairs
    if S[S_CPAR] == 0:  # this step writes table B, reading last step's rows from A
        C, Cp = contacts_view(P.CBF, P.CBI, P.CBpt), contacts_view(P.CAF, P.CAI, P.CApt)
    else:
        C, Cp = contacts_view(P.CAF, P.CAI, P.CApt), contacts_view(P.CBF, P.CBI, P.CBpt)
    spare_keys = P.EK1 if S[S_EPAR] == 0 else P.EK0
    if npairs > min(C.a.shape[0], P.R.shape[0], spare_keys.shape[0]) or \
            S[S_NTOUCH] > (P.EA1 if S[S_EPAR] == 0 else P.EA0).shape[0]:
        return GROW_ROWS
    T[2] = cycles()
    nc = 0  # no pairs, no rows: a lone body or a scattered world skips the narrow phase's call
    if npairs:
        sort_pairs(F.id, P.pairs, npairs, P.pkeys, P.porder)
        nc = collide_with(P.ctx, B, F, verts_view(P.VF, P.VI), P.pairs, npairs, C, Cp, S[S_NC], P.full,
                          P.pkeys, P.porder, P.mscratch)
        if nc < 0:
            return NEED_FULL
    # the rows are final: the tables' roles swap (Python mirrors it: ContactBuffer.swap)
    S[S_CPAR] = 1 - S[S_CPAR]
    S[S_NC] = nc
    c.nc = nc
    T[3] = cycles()
    _scale_impulses(C, nc, D[D_CADOPT])
    _scale_joint_impulses(P.JF, P.JI, S[S_NJ], D[D_JADOPT])
    S[S_BROKEN] = soft_step(P.ctx, P.par, B, C, optional_springs(P.SS, P.SI), P.R, P.SB,
                            optional_joints(P.JF, P.JI), P.JW, P.JS, P.V0)
    T[4] = cycles()
    if S[S_SLEEP]:
        links = _links(P.JF, P.JI, S[S_NJ], P.links)
        S[S_NAWAKE] = update_islands(P.ctx, B, C, Sp, links, P.parent, P.min_t, P.label)
    T[5] = cycles()
    return _finish(P, B, Sp, C, nc)


@kernel(runtime=True)
def _finish(P, B, Sp, C, nc):
    """The finite check, the energy guard and the touching merge (frame.end_step)."""
    S, T, D, G = P.S, P.T, P.D, P.G
    c = P.ctx[0]
    if S[S_EPAR] == 0:
        keys, out, begin, absent = P.EK0, P.EK1, P.EB1, P.EA1
    else:
        keys, out, begin, absent = P.EK1, P.EK0, P.EB0, P.EA0
    k, nt, nb, na = end_step(P.ctx, B, Sp, P.bad, P.why, C.a, C.b, nc, P.cluster, P.end, C.key, C.count, C.depth,
                             C.jn, keys, S[S_NTOUCH], out, begin, absent)
    S[S_KBAD] = k
    if k:
        return NONFINITE
    if G[ACTIVE] != 0.0:
        p_end = _motors(P.JF, P.JI, P.BF, P.BI, S[S_NJ])[0]
        if guard_excess(G, P.end, D[D_GROWTH], c.dt, D[D_GMAG], c.slop, p_end):
            return GAINED
    S[S_NT] = nt
    S[S_NB] = nb
    S[S_NA] = na
    S[S_NTOUCH] = nt
    S[S_EPAR] = 1 - S[S_EPAR]
    S[S_STEP] += 1  # the accepted step's number: the next step's, unless Python writes another
    T[6] = cycles()
    return OK


def empty_state():
    """Fresh S, D and T arrays for a pack."""
    return np.zeros(S_SLOTS, np.int64), np.zeros(D_SLOTS), np.zeros(T_SLOTS, np.int64)
