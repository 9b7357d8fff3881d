"""soft_step's contact solve (issue 17): graph-coloured contact manifolds solved eight side by
side (physics/constraints/colouring.py, contact_wide.py, contact_coloured.py), Box2D v3's
constraint graph and wide solver.

The wide solve is checked against scalar code exactly, through colouring.py's test flags: every
colour's lanes solved one after another (scalar code that reads each lane's result before the
next) must give the side-by-side vector solve's numbers bit for bit, since no two lanes of a
colour share a moving body; the manifolds prepared through the rows and packed (the path of a
bouncy step) must give the blocks prepare_wide writes.  Both on a stack and on bouncing boxes
(the restitution hand-over).  The colouring itself is checked as a property on random contact
graphs; the physics on the pyramid with the bound of tests/test_stacking.py, also with every
manifold in the overflow colour (Box2D v3's B2_FORCE_OVERFLOW); the vector code by grepping the
machine code.
"""
import re

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import physics
from builders import DT, finite, ground, pyramid_world, state_array, state_digest, world
from physics.constraints.colouring import (BSTART, COLOURS, COUNT, FORCE_OVERFLOW, IN_TURN, LANES, OVERFLOW,
                                          RUNS, VIA_ROWS, colour_contacts)

PROPERTY = settings(derandomize=True, database=None, deadline=None, max_examples=200)


def coloured(w, force=0):
    """``w`` with colouring.py's test flags ``force`` (the mode's scratch is the process's: every
    test sets them)."""
    w._mode.coloured.force[0] = force
    return w


def test_coloured_is_the_one_layout_and_rows_reads_as_it():
    w = physics.World()
    assert w.settings["solver_layout"] == "coloured"
    with pytest.warns(DeprecationWarning, match="'rows' was removed"):
        w.settings["solver_layout"] = "rows"
    assert w.settings["solver_layout"] == "coloured"
    with pytest.raises(ValueError, match="solver_layout"):
        w.settings["solver_layout"] = "columns"


def test_contacts_with_a_fixed_body_take_the_highest_free_colour():
    """Box2D v3's order (constraint_graph.c): a contact with a fixed body is solved after the
    moving pairs, in the highest free colour below the overflow; moving pairs from colour 0 up."""
    # bodies 0, 1 move; 2 is fixed: 0 on 1, both on the ground, and 0 twice more on the ground
    fixed = [False, False, True]
    pairs = [(0, 2), (0, 1), (1, 2), (2, 0), (0, 2)]
    _, _, _, col = colour(3, fixed, pairs)
    assert col.tolist() == [OVERFLOW - 1, 0, OVERFLOW - 1, OVERFLOW - 2, OVERFLOW - 3]


@st.composite
def contact_graphs(draw):
    n = draw(st.integers(1, 40))
    fixed = draw(st.lists(st.booleans(), min_size=n, max_size=n))
    pairs = draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)), max_size=300))
    # a body never touches itself (fixtures of one body do not collide: collision/narrowphase)
    return n, fixed, [p for p in pairs if p[0] != p[1]]


def colour(n, fixed, pairs, force=False, carried=None):
    inv_m = np.array([0.0 if f else 1.0 for f in fixed])
    inv_i = inv_m * 2.0
    ca = np.array([p[0] for p in pairs], np.int32)
    cb = np.array([p[1] for p in pairs], np.int32)
    nc = len(pairs)
    order = np.full(nc * LANES + COLOURS * LANES, -9, np.int32)
    col = np.full(max(nc, 1), -1, np.int8)  # the contact table's column: -1 for a new pair
    if carried is not None:
        col[:nc] = carried
    bstart = np.full(BSTART, -9, np.int64)
    slots = colour_contacts(ca, cb, nc, inv_m, inv_i, n, np.zeros(n, np.uint64), col, order, bstart,
                            np.int64(FORCE_OVERFLOW if force else 0))
    return slots, order[:slots], bstart, col[:nc]


@PROPERTY
@given(contact_graphs())
def test_colouring_is_valid(graph):
    n, fixed, pairs = graph
    slots, order, bstart, col = colour(n, fixed, pairs)
    assert slots % LANES == 0 and bstart[0] == 0 and bstart[COLOURS] * LANES == slots
    assert np.all(np.diff(bstart[:COLOURS + 1]) >= 0)
    # every manifold exactly once, the rest padding
    real = order[order >= 0]
    assert sorted(real.tolist()) == list(range(len(pairs)))
    assert np.all((order >= 0) | (order == -1))
    # the passes visit the colours in use (RUNS) and the real lanes of each one's last block (COUNT)
    in_use = [r for r in range(COLOURS) if bstart[r + 1] > bstart[r]]
    assert bstart[RUNS + 1:RUNS + 1 + bstart[RUNS]].tolist() == in_use
    for r in range(COLOURS):
        members = order[bstart[r] * LANES:bstart[r + 1] * LANES]
        members = members[members >= 0]
        assert bstart[COUNT + (OVERFLOW if r == 0 else r - 1)] == len(members)
        assert np.all(order[bstart[r] * LANES:bstart[r] * LANES + len(members)] >= 0)  # padding last
        if r == 0:  # the overflow colour, solved first, lane after lane: packed, in the table's order
            assert np.all(col[members] == OVERFLOW)
            assert np.all(np.diff(members) > 0)
            assert (bstart[1] - bstart[0]) * LANES - len(members) < LANES
            continue
        assert np.all(col[members] == r - 1)
        moving = [b for k in members for b in pairs[k] if not fixed[b]]
        # no moving body twice in one colour
        assert len(moving) == len(set(moving))


def check_valid(n, fixed, pairs, slots, order, bstart, col):
    assert slots % LANES == 0 and bstart[0] == 0 and bstart[COLOURS] * LANES == slots
    assert sorted(order[order >= 0].tolist()) == list(range(len(pairs)))
    for r in range(1, COLOURS):
        members = order[bstart[r] * LANES:bstart[r + 1] * LANES]
        members = members[members >= 0]
        assert np.all(col[members] == r - 1)
        moving = [b for k in members for b in pairs[k] if not fixed[b]]
        assert len(moving) == len(set(moving))


@PROPERTY
@given(contact_graphs(), st.data())
def test_colours_persist_while_contacts_touch(graph, data):
    """A step later some pairs are gone and some new: every surviving pair keeps its colour
    (Box2D v3's constraint graph; a recolouring from scratch would shift the ones after a
    change), and the colouring stays valid, also from arbitrary (stale, invalid) carried colours."""
    n, fixed, pairs = graph
    _, _, _, col = colour(n, fixed, pairs)
    keep = data.draw(st.lists(st.booleans(), min_size=len(pairs), max_size=len(pairs)))
    extra = data.draw(st.lists(st.tuples(st.integers(0, n - 1), st.integers(0, n - 1)), max_size=30))
    extra = [p for p in extra if p[0] != p[1]]
    survivors = [k for k in range(len(pairs)) if keep[k]]
    pairs2 = [pairs[k] for k in survivors] + extra
    carried = np.array([col[k] for k in survivors] + [-1] * len(extra), np.int8)
    slots, order, bstart, col2 = colour(n, fixed, pairs2, carried=carried)
    check_valid(n, fixed, pairs2, slots, order, bstart, col2)
    for j in range(len(survivors)):
        if carried[j] != OVERFLOW:
            assert col2[j] == carried[j]
    junk = np.array(data.draw(st.lists(st.integers(-1, COLOURS - 1), min_size=len(pairs), max_size=len(pairs))),
                    np.int8)
    check_valid(n, fixed, pairs, *colour(n, fixed, pairs, carried=junk))


def test_overflow_when_colours_run_out():
    # one moving body touching 30 others: it has DYNAMIC_COLOURS colours for them, the rest overflow
    pairs = [(0, i) for i in range(1, 31)]
    slots, order, bstart, col = colour(31, [False] * 31, pairs)
    assert np.sum(col == OVERFLOW) == 30 - 20
    assert sorted(order[order >= 0].tolist()) == list(range(30))


def run_pair(build, steps, force, **settings_):
    """(default state, state with the test flags ``force``) after ``steps`` steps of ``build()``."""
    out = []
    for f in (0, force):
        w = coloured(build(), f)
        w.settings.update(settings_)
        for _ in range(steps):
            w.step()
        out.append(state_array(w))
    coloured(w, 0)
    return out


@pytest.mark.parametrize("force", [IN_TURN, VIA_ROWS], ids=["lanes_in_turn", "via_rows"])
def test_the_wide_solve_equals_scalar_code_bit_for_bit(force):
    side, turn = run_pair(lambda: pyramid_world(10)[0], 120, force)
    assert np.array_equal(side, turn)
    side, turn = run_pair(lambda: pyramid_world(10)[0], 30, force, block_solver=False, relax=False, substeps=2)
    assert np.array_equal(side, turn)
    for fp in ("both", "relax"):
        side, turn = run_pair(lambda: pyramid_world(6)[0], 60, force, friction_pass=fp)
        assert np.array_equal(side, turn)


def bouncing():
    w = world()
    ground(w, width=30.0)
    for i in range(8):
        w.add_body(physics.Polygon.box(1.0, 1.0), position=(2.0 * i - 7.0, 1.0 + 0.7 * i), restitution=0.6,
                   angle=0.1 * i)
    w.add_body(physics.Polygon.box(1.0, 1.0), position=(0.3, 9.0), restitution=0.0)
    return w


def test_lanes_in_turn_reproduce_restitution_bit_for_bit():
    side, turn = run_pair(bouncing, 150, IN_TURN)
    assert np.array_equal(side, turn)
    assert np.ptp(side[:, 1]) > 0.0


def test_every_manifold_in_the_overflow_colour_still_holds_a_pyramid():
    """Box2D v3's B2_FORCE_OVERFLOW: the table's order, one manifold at a time; another
    Gauss-Seidel order, so other numbers, but the same model: pyramid 10's top box moves less
    than test_stacking.py's bound for soft_step (0.05 m in 10 s) in 5 s."""
    w, top = pyramid_world(10)
    coloured(w, FORCE_OVERFLOW)
    p0 = np.array(top.position)
    try:
        for _ in range(int(round(5.0 / DT))):
            w.step()
        assert finite(w) and w._store.contacts.n > 0
        assert np.all(w._store.contacts.cur.colour[:w._store.contacts.n] == OVERFLOW)
    finally:
        coloured(w, 0)
    d = float(np.hypot(*(np.array(top.position) - p0)))
    print(f"pyramid 10, every manifold in the overflow colour: top box moved {d:.4f} m")
    assert d < 0.05


def top_drift_coloured(base, steps):
    w, top = pyramid_world(base)
    coloured(w)
    p0 = np.array(top.position)
    for _ in range(steps):
        w.step()
    assert finite(w)
    return w, float(np.hypot(*(np.array(top.position) - p0)))


def test_pyramid_20_coloured_holds():
    # the bound of tests/test_stacking.py::test_pyramid_20 for soft_step (10 s); measured 0.025 m
    # (0.076 m with friction_pass "both"; Box2D v3.2: 0.030 m)
    _, d = top_drift_coloured(20, int(round(10.0 / DT)))
    print(f"pyramid 20 coloured: top box moved {d:.4f} m")
    assert d < 0.05


def test_coloured_is_deterministic():
    a, _ = top_drift_coloured(12, 90)
    b, _ = top_drift_coloured(12, 90)
    assert state_digest(a) == state_digest(b)


def _host_has(feature):
    import llvmlite.binding as llvm
    return llvm.get_host_cpu_features().get(feature, False)


@pytest.mark.skipif(not _host_has("avx2"), reason="the vector code is AVX2/AVX-512; this CPU has neither")
def test_coloured_kernels_vectorise():
    """The lane loops compile to vector code: packed double arithmetic on ymm/zmm registers.
    Compiled afresh (cached code cannot be inspected); this fails if a numba upgrade drops the
    noalias flag (physics/_jit.py) or a change puts a branch or call in the loop.  The same
    kernel compiled without the flag is the contrast (measured: solve_colour 192 packed ops with
    it, 0 without).  Gathers of the bodies' state are the CPU's cost model's choice, not counted:
    LLVM emits them for Intel's AVX2/AVX-512 cores, and scalar loads and inserts for AMD Zen 2
    (znver2: 0 gathers, 1130 vector operands), where gathers are slow.  Packed arithmetic is counted
    in doubles (4 per ymm op, 8 per zmm op): an AVX-512 core does the same work in half the ops
    (measured, warm_colour: 60 ymm ops on znver2, 30 zmm ops on znver4, 240 doubles on both)."""
    from numba import njit

    from physics._jit import kernel_noalias
    from physics.constraints import contact_coloured as cc
    W = np.zeros(cc.BLOCK_SIZE)
    WV = np.zeros(cc.V_SIZE)
    G = np.zeros(LANES, np.uint64)
    S = np.zeros(4 * 9)
    packed_op = r"\bv(?:fn?m(?:add|sub)\d+|mul|add|sub|div|max|min)pd\s+%([yz])mm"
    # the least packed doubles each must show: solve_colour 776 here; warm_colour 128 since it reads
    # the inverse masses from the float64 body rows (240 when they were block fields)
    least = {"solve_colour": 160, "warm_colour": 96}
    for k, args in ((cc.solve_colour, (1.0, 1.0, True, np.int64(2), None)), (cc.warm_colour, (None,))):
        counts = []
        for jit in (kernel_noalias(cache=False), njit(cache=False)):
            f = jit(k.py_func)
            f(0, LANES, W, WV, G, G, S, *args)
            asm = next(iter(f.inspect_asm().values()))
            doubles = sum(4 if r == "y" else 8 for r in re.findall(packed_op, asm))
            counts.append((doubles, len(re.findall(r"%[yz]mm\d+", asm)),
                           len(re.findall(r"\bvgather\w+", asm))))
        print(k.__name__, "(packed doubles, ymm/zmm operands, gathers): noalias", counts[0], "plain", counts[1])
        (packed, wide, _), (plain_packed, _, _) = counts
        assert packed >= least[k.__name__] and wide > 100, k.__name__
        assert plain_packed < packed // 4, f"{k.__name__}: vector code without noalias too: the contrast is gone"


@pytest.mark.skipif(not _host_has("avx2"), reason="the vector code is AVX2/AVX-512; this CPU has neither")
def test_wide_preparation_vectorises():
    """contact_prepare._lanes (the blocks' terms from the staged inputs) compiles to vector code,
    divisions and square root included: packed double arithmetic, as the passes', and the same
    kernel without the noalias flag as the contrast.  Fails if a helper it inlines takes a branch
    on the data or divides with Python's error model (an exception branch) again."""
    from numba import njit

    from physics._jit import kernel_noalias
    from physics.constraints import contact_prepare as cp
    W = np.zeros(cp.BLOCK_SIZE, np.float32)
    T = np.zeros(cp.T_SIZE)
    packed_op = r"\bv(?:fn?m(?:add|sub)\d+|mul|add|sub|div|max|min|sqrt)pd\s+%([yz])mm"
    counts = []
    for jit in (kernel_noalias(cache=False, error_model="numpy"), njit(cache=False, error_model="numpy")):
        f = jit(cp._lanes.py_func)
        f(np.int64(1), W, T, 0.01, True, 120.0, 60.0, 10.0, 1.0 / 240.0, 9.8)
        asm = next(iter(f.inspect_asm().values()))
        counts.append((sum(4 if r == "y" else 8 for r in re.findall(packed_op, asm)),
                       len(re.findall(r"\bvdivpd", asm)) + len(re.findall(r"\bvdivsd", asm))))
    print("_lanes (packed doubles, divisions): noalias", counts[0], "plain", counts[1])
    (packed, _), (plain_packed, _) = counts
    assert packed >= 300, "the preparation's lane loop is not vector code"  # measured: 388 (znver, ymm)
    assert plain_packed < packed // 4, "vector code without noalias too: the contrast is gone"
