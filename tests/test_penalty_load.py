"""Penalty contacts stay stable when several points load one body (physics/solvers/classic/penalty_load.py).

The defect: Box2D's compounds scene (bodies of two overlapping triangles) gained 4.5e6 J in one
step in ``penalty`` and 3.5e8 J in ``hybrid`` (tests/test_shipped_scenes.py, slow tier): the
overlapping fixtures give coincident contact points whose springs add up beyond what the sub-step
count integrates.  The measure is the largest eigenvalue lambda of the points' Gram matrix
G_ij = sqrt(m_i m_j) J_i M^-1 J_j^T; its analytic values below come from the rows J = (n, r x n).
"""
import gc

import numpy as np
import pytest

import physics
from physics.solvers.classic.penalty_load import ITERATIONS, gram_lambda, stable_load


def penalty_mode():
    return next(o for o in gc.get_objects() if type(o).__name__ == "PenaltyMode")


def lam(w):
    st = w._store
    return gram_lambda(st.bodies.view, st.contacts.cur, st.contacts.n, penalty_mode().P, ITERATIONS)


def box_on_ground(copies=1):
    w = physics.World(solver="penalty")
    w.add_body(physics.Polygon.box(10.0, 1.0), kind="static", position=(0.0, -0.5))
    w.add_body([physics.Polygon.box(1.0, 1.0)] * copies, position=(0.0, 0.4995))
    return w


def test_a_box_on_the_ground_has_lambda_six_fifths():
    """Two corner rows of a unit square on static ground: J_1 M^-1 J_2^T = 1/m - a^2/I and
    J_i M^-1 J_i^T = 1/m + a^2/I with I = 2/3 m a^2 (a = 1/2), so cos = -1/5 and lambda = 1 + 1/5."""
    w = box_on_ground()
    w.step()
    assert lam(w) == pytest.approx(1.2, rel=1e-9)
    assert penalty_mode().P.scale[0, :2].tolist() == [1.0, 1.0]  # within the limit: untouched


def test_coincident_fixtures_multiply_lambda():
    """Four copies of the box's shape (one body, four coincident fixtures) repeat each row four
    times: G is the 2x2 block above in every 4x4 tile, lambda = 4 x 1.2."""
    w = box_on_ground(copies=4)
    w.step()
    assert w._store.contacts.n == 4
    assert lam(w) == pytest.approx(4.8, rel=1e-9)


def test_stable_load_is_twice_the_linear_bound():
    """u = omega h = 2 pi 25 / 480 at the defaults (8 sub-steps at 60 Hz, zeta 1):
    0.9 * 2 * 4 / (u^2 + 4 u)."""
    u = 2.0 * np.pi * 25.0 / 480.0
    assert stable_load(2.0 * np.pi * 25.0, 1.0, 1.0 / 480.0) == pytest.approx(7.2 / (u * u + 4.0 * u))


def stacked_compounds(solver, copies):
    """Two bodies of ``copies`` coincident boxes each, stacked on the ground, dropped 2 cm."""
    w = physics.World(solver=solver)
    w.add_body(physics.Polygon.box(10.0, 1.0), kind="static", position=(0.0, -0.5))
    for k in range(2):
        w.add_body([physics.Polygon.box(1.0, 1.0)] * copies, position=(0.03 * k, 0.52 + 1.02 * k))
    return w


@pytest.mark.parametrize("solver", ["penalty", "hybrid"])
def test_stacked_compounds_settle_without_gaining_energy(solver):
    """With 6 coincident fixtures per body there are 42 manifolds (6 under the lower body, 36
    between the two) and lambda = 46 (measured), far past the limit (5.08 at the defaults); without
    the scaling the energy guard refuses step 5 (4.65e6 J).  Scaled: 300 steps, the guard (which
    refuses a step gaining energy without input) never fires and the top box rests on the lower."""
    w = stacked_compounds(solver, copies=6)
    for _ in range(300):
        w.step()  # SimulationError if a step gains energy (physics/step/energy_guard.py)
    top = w.bodies[2]
    assert abs(top.velocity[1]) < 1e-2 and abs(top.angular_velocity) < 1e-2
    assert 1.4 < top.position[1] < 1.5  # rests on the lower box: 1.5 minus a penalty sink
