"""The energy guard's push-out allowance: push-out may add only the energy of separating the
overlap it found (physics/step/energy_sums.push_sum).

Per overlapping manifold k (depth d_k > 0) between bodies a and b the allowance is
m_k ((P_k v_p)^2 / 2 + |g| d_k), m_k = 1 / (1/m_a + 1/m_b) (at least the contact's effective mass
along its normal), v_p the mode's push-out speed cap (SolverMode.push_speed) and P_k the contacts a
push can travel through in k's cluster of overlapping bodies (1 for a lone pair).  The rule before it,
1/2 sum_i m_i (c_i 10 m/s)^2 over the bodies with c_i manifolds, gave two 10 g discs overlapping
beside a 1 t block the block's 1/2 1000 (10)^2 = 50 kJ, enough to hide any gain of the world.
"""
import math

import numpy as np
import pytest

import physics
from physics.step.energy_guard import push_allowance
from physics.step.energy_sums import PUSH

MODES = physics.solvers_available()
LIGHT = 0.01  # kg
HEAVY = 1000.0  # kg


def light_pair_beside_heavy(mode):
    """No gravity: two 10 g discs created overlapping each other, the right one also 2 cm into a
    free-floating 1 t block."""
    w = physics.World(solver=mode, gravity=(0.0, 0.0))
    w.add_body(physics.Polygon.box(1.0, 1.0), position=(0.68, 0.0), density=HEAVY)
    for x in (0.0, 0.1):
        w.add_body(physics.Circle(0.1), position=(x, 0.0), density=LIGHT / (math.pi * 0.01))
    return w


def by_hand(w) -> float:
    """sum_k m_k ((P_k v_p)^2 / 2 + |g| d_k) over the current table's overlapping manifolds, from
    the bodies' masses (not the engine's inverse masses), the clusters found by a search."""
    store = w._store
    C, nc = store.contacts.cur, store.contacts.n
    masses = {b._s: b.mass if b.kind == "dynamic" else math.inf for b in w.bodies}
    rows = [(int(C.a[k]), int(C.b[k]), max(C.depth[k, p] for p in range(C.count[k]))) for k in range(nc)]
    rows = [(a, b, d) for a, b, d in rows if d > 0.0 and min(masses[a], masses[b]) < math.inf]
    links = {}
    for a, b, _ in rows:
        if max(masses[a], masses[b]) < math.inf:
            links.setdefault(a, set()).add(b)
            links.setdefault(b, set()).add(a)

    def cluster(i):
        seen, todo = {i}, [i]
        while todo:
            for j in links.get(todo.pop(), ()):
                if j not in seen:
                    seen.add(j)
                    todo.append(j)
        return seen
    v = w._mode.push_speed(w._settings_store(w.solver).values)
    g = math.hypot(*w.gravity)
    total = 0.0
    for a, b, d in rows:
        group = cluster(a if masses[a] < math.inf else b)
        fixed = any(masses[x] == math.inf or masses[y] == math.inf for x, y, _ in rows if x in group or y in group)
        p = len(group) - 1 + fixed
        m = 1.0 / (1.0 / masses[a] + 1.0 / masses[b])
        total += m * (0.5 * (p * v) ** 2 + g * d)
    return total


@pytest.mark.parametrize("mode", MODES)
def test_light_bodies_beside_a_heavy_one_get_their_own_allowance(mode):
    """Both manifolds overlap and a push may travel through both (P = 2), so the allowance is that
    of the two light pairs: at most 2 x 10 g x (2 v_p)^2 / 2 with v_p <= 10 m/s, 4 J, not the
    block's 50 kJ; the step's kernel (guard.end) and the numpy reference give the same figure."""
    w = light_pair_beside_heavy(mode)
    w.step()
    C = w._store.contacts.cur
    assert int((C.depth[:w._store.contacts.n].max(1) > 0.0).sum()) == 2  # (a 1-point row's second depth is 0)
    push = float(w._pipeline._guard.end[PUSH])
    assert push == pytest.approx(by_hand(w), rel=1e-12)
    assert push == pytest.approx(push_allowance(w), rel=1e-12)
    assert push <= 2 * LIGHT * 0.5 * (2 * 10.0) ** 2


@pytest.mark.parametrize("relax", [True, False])
def test_the_allowance_uses_the_modes_push_out_speed(relax):
    """soft_step at push_out_speed 3 and 0.5 m/s, a 10 g disc created 2 cm into a 1 t block: the
    kinetic part of the allowance scales with the speed's square, and the push stays inside it."""
    first = {}
    for speed in (3.0, 0.5):
        w = physics.World(gravity=(0.0, 0.0))
        w.add_body(physics.Polygon.box(1.0, 1.0), position=(0.68, 0.0), density=HEAVY)
        w.add_body(physics.Circle(0.1), position=(0.1, 0.0), density=LIGHT / (math.pi * 0.01))
        w.settings["push_out_speed"] = speed
        w.settings["relax"] = relax
        for _ in range(30):
            w.step()
            push = push_allowance(w)
            assert float(w._pipeline._guard.end[PUSH]) == pytest.approx(push, rel=1e-12)
            first.setdefault(speed, push)
    assert first[0.5] == pytest.approx(first[3.0] * (0.5 / 3.0) ** 2, rel=1e-9)


@pytest.mark.parametrize("mode", MODES)
def test_the_kernel_and_the_numpy_reference_agree_under_gravity(mode):
    """A pile of three boxes created overlapping on static ground (depth and gravity terms),
    ten steps through whichever path the mode takes (soft_step: the one-call driver)."""
    w = physics.World(solver=mode)
    w.add_body(physics.Polygon.box(10.0, 1.0), kind="static", position=(0.0, -0.5))
    for i in range(3):
        w.add_body(physics.Polygon.box(1.0, 1.0), position=(0.1 * i, 0.4 + 0.8 * i), density=1.0 + i)
    for _ in range(10):
        w.step()
        kernel = float(w._pipeline._guard.end[PUSH])
        assert kernel == pytest.approx(push_allowance(w), rel=1e-9, abs=1e-12)
        assert kernel == pytest.approx(by_hand(w), rel=1e-9, abs=1e-12)
    assert np.isfinite(kernel)
