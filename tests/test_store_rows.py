"""The stores' row operations: a new row is all zeros, a removal moves the last row whole, and a
polygon added alone gets the vertices and edge normals of the batch path, to the bit."""
import numpy as np

from physics.store import BODY_FIELDS, Bodies, Table, VertexPool


def _rows(t):
    return {k: np.array(v[:t.n]) for k, v in t.arrays.items()}


def test_new_rows_are_zero_and_removal_moves_every_field():
    t = Table(BODY_FIELDS, Bodies, cap=2)  # small: the adds below grow it
    ids = [t.add()[0] for _ in range(5)]
    rng = np.random.default_rng(3)
    for name, a in t.arrays.items():
        if name != "id":
            a[:t.n] = rng.integers(1, 100, size=a[:t.n].shape).astype(a.dtype)
    before = _rows(t)
    removed, last = t.remove(ids[1])
    after = _rows(t)
    for name in before:  # the last row, every field, now in the removed one's slot
        assert np.array_equal(after[name][removed], before[name][last]), name
    oid, s = t.add()
    for name, a in t.arrays.items():
        assert name == "id" or not np.any(a[s]), f"{name} not zeroed in a reused slot"
    new_ids, slots = t.add_many(3)
    for name, a in t.arrays.items():
        assert name == "id" or not np.any(a[slots.start:slots.stop]), name
    assert [int(t.arrays["id"][k]) for k in slots] == new_ids


def test_one_polygon_matches_the_batch_path():
    pool = VertexPool()
    rng = np.random.default_rng(5)
    for k in (2, 3, 4, 5, 8):
        for _ in range(50):
            p = rng.standard_normal((k, 2)) * 10.0 ** rng.uniform(-3, 3)
            a = int(pool.add_many([p, p])[0])   # two polygons: the batch path
            b = int(pool.add_many([p])[0])      # one: its own path
            for field in ("local", "normal"):
                x = pool.arrays[field][a:a + k]
                y = pool.arrays[field][b:b + k]
                assert np.array_equal(x.view(np.uint64), y.view(np.uint64)), (k, field)


def test_set_gives_the_batch_paths_normals():
    """``set`` (a body's centre of mass moved) rewrites vertices and normals as ``add_many`` makes them."""
    pool = VertexPool()
    rng = np.random.default_rng(9)
    for k in (2, 3, 4, 7):
        p = rng.standard_normal((k, 2))
        a = int(pool.add_many([p, p])[0])
        b = int(pool.add_many([rng.standard_normal((k, 2)), p])[0])
        pool.set(b, p)
        for field in ("local", "normal"):
            assert np.array_equal(pool.arrays[field][a:a + k].view(np.uint64),
                                  pool.arrays[field][b:b + k].view(np.uint64)), (k, field)
