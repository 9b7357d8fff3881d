"""The global joint system's numbering (constraints/joints/system/topology.py) is numpy over the
arrays since issue 17 (rain's 10,000 ragdoll joints cost 0.3-0.5 s per rebuild in the loop that
listed every contribution); it must give exactly the arrays of that loop, kept here as the
reference, on ragdolls (trees), chains, a closed loop and a world anchor.  And removing a body
removes its joints in creation order (the table's order after the swap-removes), as the scan over
every joint handle did."""
import numpy as np
import pytest

from bench.suite.ragdoll import human
from physics.constraints.joints.prepare import equality_counts
from physics.constraints.joints.system import topology as T
from physics.scene import scene_from_dict
from bench.suite.common import body, box, circle, scene, strip_box2d


def _reference_numbering(J, order, m, moving, jcap):
    """The loop of topology._numbering before issue 17 (commit f04d69b), verbatim in effect."""
    jrow = np.full(jcap, -1, np.int64)
    row_j, row_r = [], []
    for j in order:
        jrow[j] = len(row_j)
        for r in range(int(m[j])):
            row_j.append(j)
            row_r.append(r)
    nrows = len(row_j)
    if nrows == 0:
        return T.empty_system(jcap)
    entries, contrib, by_body = {}, [], {}
    for j in order:
        for c, side in moving[j]:
            by_body.setdefault(c, []).append((j, side))
    for c, inc in by_body.items():
        for j, sj in inc:
            for k, sk in inc:
                if jrow[j] > jrow[k]:
                    continue
                for r in range(int(m[j])):
                    for s in range(int(m[k])):
                        i, col = jrow[j] + r, jrow[k] + s
                        if i <= col:
                            contrib.append((entries.setdefault((col, i), len(entries)), c, j, r, sj, k, s, sk))
    keys = sorted(entries)
    index = np.zeros(len(keys), np.int64)
    for new, key in enumerate(keys):
        index[entries[key]] = new
    q = np.array(contrib, np.int64)
    q[:, 0] = index[q[:, 0]]
    cols = np.array([k[0] for k in keys], np.int64)
    Ap = np.zeros(nrows + 1, np.int64)
    Ap[1:] = np.cumsum(np.bincount(cols, minlength=nrows))
    return dict(jrow=jrow, row_j=np.array(row_j), row_r=np.array(row_r), Ai=np.array([k[1] for k in keys]),
                Ap=Ap, contrib=q)


def _order(J, nj, kinds, m):
    moving = T._moving_bodies(J, nj, kinds, m)
    order = []
    for comp in T._components(moving):
        e = T.minimum_degree(comp, T._adjacency(comp, moving), T.FILL_BUDGET * len(comp) + T.FILL_SLACK) \
            if len(comp) > 1 else comp
        order += e or []
    return order, moving


def _world():
    bodies, joints = [body(box(20.0, 0.5), 0.0, -0.5, kind="static", name="ground")], []
    for i in range(3):
        b, j = human(f"h{i}_", 2.0 * i, 1.0, group=i + 1)
        bodies += b
        joints += j
    for i in range(6):  # a chain hung from the world, closed into a loop by a weld
        bodies.append(body(circle(0.2), 10.0 + i, 5.0, name=f"c{i}"))
        joints.append({"kind": "revolute", "a": f"c{i}", "b": f"c{i - 1}" if i else None, "anchor": [9.5 + i, 5.0]})
    joints.append({"kind": "weld", "a": "c5", "b": "c2", "anchor": [13.0, 5.0]})
    return scene_from_dict(strip_box2d(scene("topology", "ragdolls and a closed chain", bodies, joints)))


@pytest.mark.parametrize("drop", [(), ("h1_hip", "c3")])
def test_numbering_matches_the_loop(drop):
    w = _world()
    for name in drop:  # removals renumber body and joint slots
        w.remove(w.body(name))
    s = w._store
    J, nj = s.joints.view, s.joints.n
    m = np.zeros(max(nj, 1), np.int64)
    equality_counts(J, nj, m)
    order, moving = _order(J, nj, s.bodies.view.kind[: s.bodies.n], m)
    assert len(order) > 20
    got = T._numbering(J, order, m, moving, len(J.a))
    want = _reference_numbering(J, order, m, moving, len(J.a))
    for field, arr in want.items():
        g = getattr(got, field)
        assert g.dtype == np.int64 and np.array_equal(g, arr), field
    assert int(got.dims[1]) == len(want["contrib"]) and int(got.dims[2]) == len(want["Ai"])


def test_removing_a_body_removes_its_joints_in_creation_order():
    w = _world()
    body = w.body("h1_torso")  # four joints: to the hip, the head and both upper arms
    expect = [j.id for j in w._joint_handles.values() if j.body_a is body or j.body_b is body]
    assert len(expect) == 4 and w._joint_ids_on(body._s) == expect
    before = {j.id for j in w.joints}
    w.remove(body)
    assert before - {j.id for j in w.joints} == set(expect)
    assert all(j.body_a is not body and j.body_b is not body for j in w.joints)


@pytest.mark.parametrize("seed", range(6))
def test_remembered_elimination_orders_equal_minimum_degree(seed):
    """An order remembered from one copy of a rig serves a copy with other joint and body
    numbers exactly as minimum degree on that copy would: random joint graphs (trees, loops and
    grids of shared bodies), each met twice, numbered apart."""
    rng = np.random.default_rng(seed)
    T._ORDERS.clear()
    nb = int(rng.integers(3, 30))
    edges = [tuple(int(x) for x in rng.choice(nb, 2, replace=False)) for _ in range(int(rng.integers(2, 3 * nb)))]
    sizes = []
    for copy in range(2):
        # copy 1: joints offset and interleaved with others' numbers, bodies renumbered upwards
        js = [7 * copy + 3 * k for k in range(len(edges))]
        moving = {j: [(100 * copy + 2 * a, 1), (100 * copy + 2 * b, -1)] for j, (a, b) in zip(js, edges)}
        for comp in T._components(moving):
            if len(comp) < 2:
                continue
            want = T.minimum_degree(comp, T._adjacency(comp, moving), T.FILL_BUDGET * len(comp) + T.FILL_SLACK)
            assert T._elimination(comp, moving) == want
        sizes.append(len(T._ORDERS))
    assert sizes[0] > 0 and sizes[1] == sizes[0]  # the second copy was served from what the first left
