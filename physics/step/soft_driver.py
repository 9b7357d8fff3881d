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
from ..collision.broadphase.order import sort_pairs as sort_slot_pairs
from ..collision.broadphase.sweep import sweep_emit
from ..collision.broadphase.fixture_filter import filter_reachable
from ..collision.broadphase.resting_index import build_index, few_awake_of, indexed_pairs
from ..collision.narrowphase.collide import collide_with
from ..collision.narrowphase.kernel import sort_pairs
from ..constraints.joints.kinds import kinds_changed_in
from ..constraints.colouring import COLOURS, LANES
from ..solvers.soft_step.coloured import colour_blocks, soft_step_wide
from ..store.optional import optional_joints, optional_springs
from ..store.table_type import make_table
from ..threads import threads_of
from .clock import cycles
from .energy_bound import ACTIVE, guard_begin, guard_excess
from .energy_sums import motor_power_of
from .frame import begin_step, end_step
from .active import REST_SLOTS, link_islands, partition, step_rows
from .checkpoint import save_state
from .islands import WOKEN, joint_links, update_islands
from .pack import call_with_fields

#: P.S slots: counts (bodies, fixtures, springs, joints), the step number, contact rows, which
#: contact table and which touching set is current, the last touching count, the broad phase's
#: pairs and their limit, sleeping on, awake bodies, joints broken, the size a grow code asks
#: for, the touching merge's counts, the non-finite count, the sweep's choice, whether the
#: next step computes every fixture's geometry (set by Python after an edit or a settings change),
#: the lengths of the step's lists (active.py: moving bodies, fixtures, rows) and its stamp, how
#: many times the lists were made, the count the resting boxes' index was built at and its length
(S_N, S_NF, S_NS, S_NJ, S_STEP, S_NC, S_CPAR, S_EPAR, S_NTOUCH, S_NPAIRS, S_LIMIT, S_SLEEP, S_NAWAKE,
 S_BROKEN, S_NEED, S_NT, S_NB, S_NA, S_KBAD, S_SWEEP, S_GEOM, S_NACT, S_NACTF, S_NROWS, S_STAMP, S_PARTS, S_INDEXED,
 S_NREST) = range(28)
S_SLOTS = 28
#: P.D slots: the guard's growth r, |g|, the contact and joint impulses' adopt factors, the widest
#: resting box (the index's), then the sleeping bodies' guard sums (active.py: REST_SLOTS of them)
D_GROWTH, D_GMAG, D_CADOPT, D_JADOPT, D_WIDE, D_REST = range(6)
D_SLOTS = D_REST + REST_SLOTS
#: return codes
OK, GROW_PAIRS, TOO_MANY_PAIRS, GROW_ROWS, NEED_FULL, JOINT_KINDS, GROW_BLOCKS, NONFINITE, GAINED = range(9)
#: P.T: cycle stamps at the start and after each of the profile's six stages
T_SLOTS = 7


@kernel
def _motors(J, B, nj):
    """(power bound, dragged) of the joints' motors (energy_sums.motor_power_of); none without."""
    if J is None:
        return 0.0, np.bool_(False)  # a literal False would compile guard_begin twice
    return motor_power_of(J, B, nj)


@kernel
def _broad_phase(F, nf, pairs, swept, sweep, nthr, actf, index, S, D):
    """The count of the fixtures' overlapping pairs: brute force, sorted into ``pairs``, or
    (``swept``) the sweep with the world's scratch, unsorted into its ``tmp``, which is as long
    as ``pairs``, so a count that fits one fits both; with few boxes awake, their queries of
    the resting boxes' index instead (resting_index.py: the same pairs), the index rebuilt when
    the lists changed since.  A runtime choice, not an optional argument: both worlds then step
    with one compiled driver."""
    if not swept:
        return brute_pairs(F, nf, pairs)
    state, order, key, b0, b1, bstart, ent, tmp, head = sweep
    skey, iorder, itmp, rkey, rslot = index
    if few_awake_of(F, actf, S[S_NACTF]):
        if S[S_INDEXED] != S[S_PARTS]:
            S[S_NREST], D[D_WIDE] = build_index(F, nf, skey, iorder, itmp, rkey, rslot)
            S[S_INDEXED] = S[S_PARTS]
        return indexed_pairs(F, actf, S[S_NACTF], rkey, rslot, S[S_NREST], D[D_WIDE], tmp)
    return sweep_emit(F, nf, state, order, key, b0, b1, bstart, ent, tmp, nthr)


@kernel
def _kept_pairs(B, F, nf, pairs, npairs, exclude, swept, sweep, dt, spec):
    """The pairs the filters and the bodies' reach keep (fixture_filter.filter_reachable), sorted
    into ``pairs``: the sweep's are filtered before its sort, so dropped pairs cost no sorting."""
    if not swept:
        return filter_reachable(B, F, pairs, npairs, exclude, dt, spec)
    _, _, _, _, _, _, _, tmp, head = sweep
    k = filter_reachable(B, F, tmp, npairs, exclude, dt, spec)
    sort_slot_pairs(tmp, k, nf, head, pairs)
    return k


@kernel
def _joints_ready(J, B, nj, kinds):
    """False when a joined body changed kind (Python rebuilds the joint system)."""
    if J is None:
        return True
    return not kinds_changed_in(J, B, nj, kinds)


@kernel
def _scale_joint_impulses(J, nj, r):
    """JointTable.adopt: the joints' impulses times ``r``."""
    if J is None or r == 1.0:
        return
    for j in range(nj):
        for k in range(J.impulse.shape[1]):
            J.impulse[j, k] *= r


@kernel
def _links(J, nj, out):
    """The number of the joints' island links (islands.joint_links) in ``out``; none without."""
    if J is None:
        return 0
    return joint_links(J, nj, out)


@kernel
def _colour(B, C, n, nc, wide):
    """coloured.colour_blocks into ``wide``'s scratch: the slots the blocks need this step, minus
    that when they are shorter."""
    used, order, bstart, force, _, _, GA, _ = wide
    return colour_blocks(B, C, n, nc, used, order, bstart, force[0], GA)


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
    """One step of the world in ``P`` (see the module doc); returns a code.  The pack lends
    its arrays to ``_drive`` (pack.call_with_fields), which builds the tables over them without
    numba's runtime: no reference is counted while stepping."""
    return call_with_fields(_drive, P)


@kernel
def _drive(ctx, par, S, D, T, G, BF, BI, FF, FI, ghost, wghost, VF, VI, SF, SI, CAF, CAI, CApt, CBF, CBI, CBpt,
           pairs, exclude, pkeys, porder, mscratch, X, Q, V, W, bad, why, cluster, start, end, EK0, EK1, EB0, EB1,
           EA0, EA1, parent, min_t, label, links, R, SB, V0, JF, JI, JW, JS, kinds, SS, full, sweep, wide, split,
           active):
    """The step over the pack's arrays (pack.FIELDS, in order): the stages of the module doc."""
    T[0] = cycles()
    c = ctx[0]
    nthr = threads_of(split, c)  # None: the serial build (physics/threads.py)
    c.step = S[S_STEP]
    c.n = S[S_N]
    c.ns = S[S_NS]
    nj = c.nj = S[S_NJ]
    nf = S[S_NF]
    B = make_table("bodies", (BF, BI))
    F = make_table("fixtures", (FF, FI, ghost, wghost))
    Vt = make_table("verts", (VF,))
    Sp = make_table("springs", (SF, SI))
    J = optional_joints(JF, JI)
    act, actf, sleepers, rows, mark, index, ring, skey, sorder, stmp = active
    rest = D[D_REST:D_REST + REST_SLOTS]
    if S[S_GEOM] != 0:  # an edit: the moving bodies listed anew, the islands linked anew
        S[S_NACT], S[S_NACTF], nsleep = partition(B, F, c.n, nf, c.gx, c.gy, act, actf, sleepers, rest)
        link_islands(B, sleepers, nsleep, ring, skey, sorder, stmp)
        S[S_PARTS] += 1
    nact = S[S_NACT]
    begin_step(ctx, B, F, Vt, nf, X, Q, V, W, Sp, start, S[S_GEOM] != 0, nthr, act, nact, actf, S[S_NACTF], rest)
    S[S_GEOM] = 0  # static and sleeping bodies keep their geometry until Python says otherwise
    p_start, dragged = _motors(J, B, nj)
    guard_begin(G, start, D[D_GROWTH], p_start, dragged)
    if not _joints_ready(J, B, nj, kinds):
        return JOINT_KINDS
    T[1] = cycles()
    npairs = _broad_phase(F, nf, pairs, S[S_SWEEP] != 0, sweep, nthr, actf, index, S, D)
    S[S_NEED] = npairs
    if npairs > S[S_LIMIT]:
        return TOO_MANY_PAIRS
    if npairs > pairs.shape[0]:
        return GROW_PAIRS
    npairs = _kept_pairs(B, F, nf, pairs, npairs, exclude, S[S_SWEEP] != 0, sweep, c.dt, c.spec)
    S[S_NPAIRS] = npairs
    S[S_NEED] = npairs
    if S[S_CPAR] == 0:  # this step writes table B, reading last step's rows from A
        C, Cp = make_table("contacts", (CBF, CBI, CBpt)), make_table("contacts", (CAF, CAI, CApt))
    else:
        C, Cp = make_table("contacts", (CAF, CAI, CApt)), make_table("contacts", (CBF, CBI, CBpt))
    spare_keys = EK1 if S[S_EPAR] == 0 else EK0
    if npairs > min(C.a.shape[0], R.shape[0], spare_keys.shape[0]) or \
            S[S_NTOUCH] > (EA1 if S[S_EPAR] == 0 else EA0).shape[0]:
        return GROW_ROWS
    T[2] = cycles()
    nc = 0  # no pairs, no rows: a lone body or a scattered world skips the narrow phase's call
    if npairs:
        sort_pairs(F.id, pairs, npairs, pkeys, porder)
        nc = collide_with(ctx, B, F, Vt, pairs, npairs, C, Cp, S[S_NC], full, pkeys, porder, mscratch, nthr)
        if nc < 0:
            return NEED_FULL
    short = _colour(B, C, c.n, nc, wide)  # before the swap: a grow of the blocks calls again
    if short < 0:
        S[S_NEED] = -short
        return GROW_BLOCKS
    # the rows are final: the tables' roles swap (Python mirrors it: ContactBuffer.swap)
    S[S_CPAR] = 1 - S[S_CPAR]
    S[S_NC] = nc
    c.nc = nc
    S[S_STAMP] += 1
    nrows = S[S_NROWS] = step_rows(C.a, C.b, nc, J, nj, Sp, c.ns, act, nact, rows, mark, S[S_STAMP], skey, sorder,
                                   stmp)
    save_state(B, rows[nact:], nrows - nact, X, Q, V, W)  # the rows beyond act (begin_step saved those)
    T[3] = cycles()
    _scale_impulses(C, nc, D[D_CADOPT])
    _scale_joint_impulses(J, nj, D[D_JADOPT])
    # the soft step over the colouring _colour left in ``wide``: its blocks end at bstart[COLOURS]
    _, order, bstart, _, W, WV, GA, GB = wide
    S[S_BROKEN] = soft_step_wide(ctx, par, B, C, optional_springs(SS, SI), R, SB, J, JW, JS, V0, order, bstart,
                                 bstart[COLOURS] * LANES, W, WV, GA, GB, nthr, act, nact, rows, nrows)
    T[4] = cycles()
    if S[S_SLEEP]:
        changes = label[WOKEN]
        S[S_NAWAKE] = update_islands(ctx, B, C, Sp, links[:_links(J, nj, links)], parent, min_t, label, ring, act,
                                     nact, rows, nrows)
        if label[WOKEN] != changes:  # islands woke or fell asleep: the lists anew
            S[S_NACT], S[S_NACTF], _ = partition(B, F, c.n, nf, c.gx, c.gy, act, actf, sleepers, rest)
            S[S_PARTS] += 1
    T[5] = cycles()
    if S[S_EPAR] == 0:
        keys, out, begin, absent = EK0, EK1, EB1, EA1
    else:
        keys, out, begin, absent = EK1, EK0, EB0, EA0
    k, nt, nb, na = end_step(ctx, B, Sp, bad, why, C.a, C.b, nc, cluster, end, C.key, C.count, C.depth, C.jn,
                             keys, S[S_NTOUCH], out, begin, absent, act, S[S_NACT], rows, nrows, rest)
    return _finish(S, T, D, G, c, J, B, nj, end, k, nt, nb, na)


@kernel
def _finish(S, T, D, G, c, J, B, nj, end, k, nt, nb, na):
    """After end_step: the non-finite count ``k``, the energy guard, then the touching merge's
    counts (``nt``, ``nb``, ``na``) kept for Python."""
    S[S_KBAD] = k
    if k:
        return NONFINITE
    if G[ACTIVE] != 0.0:
        p_end = _motors(J, B, nj)[0]
        if guard_excess(G, end, D[D_GROWTH], c.dt, D[D_GMAG], c.slop, p_end):
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
