"""The batch API equals the per-body API to the bit, refuses bad rows without writing, and
explode pushes bodies radially with the linear falloff it documents."""
from __future__ import annotations

import numpy as np
import pytest

import physics


def _pair(n=6, seed=3):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(2):
        w = physics.World(gravity=(0, -9.81))
        w.add_body(physics.Polygon.box(40, 1), kind="static", position=(0, -0.5))
        for i in range(n):
            w.add_body(physics.Polygon.box(0.5 + 0.1 * i, 0.4), position=(2.0 * i, 1.0 + i), angle=0.1 * i)
        out.append(w)
    ids = np.array([b.id for b in out[0].bodies[1:]])
    return out, ids, rng


def _same(a, b):
    for x, y in zip(a.bodies, b.bodies):
        assert (x.position, x.angle, x.velocity, x.angular_velocity) == (y.position, y.angle, y.velocity, y.angular_velocity)


def test_batch_equals_per_body_api_over_steps():
    (wa, wb), ids, rng = _pair()
    k = len(ids)
    for step in range(30):
        v, w = rng.normal(size=(k, 2)), rng.normal(size=k)
        f, pts, tq = rng.normal(size=(k, 2)) * 20, rng.normal(size=(k, 2)) * 3, rng.normal(size=k)
        j, jp, ja = rng.normal(size=(k, 2)), rng.normal(size=(k, 2)), rng.normal(size=k) * 0.1
        if step % 10 == 0:
            wa.set_velocities(ids, v, w)
            for b, vi, wi in zip(wb.bodies[1:], v, w):
                b.velocity, b.angular_velocity = vi, wi
        wa.apply_forces(ids, f, points=pts, torques=tq)
        wa.apply_impulses(ids, j * 0.01, points=jp, angular=ja)
        for b, fi, pi, ti, ji, jpi, jai in zip(wb.bodies[1:], f, pts, tq, j * 0.01, jp, ja):
            b.apply_force(fi, pi)
            b.apply_torque(ti)
            b.apply_impulse(ji, jpi)
            b.apply_angular_impulse(jai)
        _same(wa, wb)
        wa.step()
        wb.step()
        _same(wa, wb)
    assert wa.bodies[1].position != (0.0, 1.0)  # they moved: the comparison was not of still worlds


def test_refused_rows_change_nothing():
    (wa, _), ids, _ = _pair()
    before = wa.state().copy()
    f = np.ones((len(ids), 2))
    f[3, 1] = np.nan
    with pytest.raises(ValueError, match=r"f\[3\]"):
        wa.apply_forces(ids, f)
    with pytest.raises(ValueError, match=r"ids\[1\]"):
        wa.apply_impulses([ids[0], 9999], np.ones((2, 2)))
    with pytest.raises(ValueError, match=r"w\[2\]"):
        wa.set_velocities(ids, np.zeros((len(ids), 2)), w=[0, 0, np.inf, 0, 0, 0])
    with pytest.raises(ValueError, match=r"j\[0\]"):
        wa.apply_impulses(ids[:1], [[1e308 * 10, 0]])
    with pytest.raises(ValueError, match="torques"):
        wa.apply_forces(ids[:1], [[1e308, 0]], torques=[np.nan])
    assert np.array_equal(wa.state(), before)
    B = wa._bodies.view
    assert not B.f[: wa._bodies.n].any() and not B.tau[: wa._bodies.n].any()


def test_batch_wakes_sleeping_bodies():
    (wa, _), ids, _ = _pair()
    for _ in range(400):
        wa.step()
    assert not wa.state()["awake"][1:].any()  # all asleep on the ground
    wa.apply_impulses(ids[:1], [[0, 1]])
    assert wa.state()["awake"][1]


def test_explode_pushes_radially_with_linear_falloff():
    w = physics.World(gravity=(0, 0))
    c = np.array([1.0, 2.0])
    bodies = [w.add_body(physics.Circle(0.2), position=tuple(c + r * np.array([np.cos(a), np.sin(a)])))
              for r, a in [(1, 0.3), (2, 2.0), (3, 4.0), (5, 1.0)]]
    static = w.add_body(physics.Circle(0.2), kind="static", position=(1.5, 2.0))
    w.explode(c, radius=4.0, impulse=8.0)
    for b, r in zip(bodies, [1, 2, 3, 5]):
        v = np.array(b.velocity)
        d = np.array(b.position) - c
        expect = max(0.0, 8.0 * (1 - r / 4.0)) / b.mass
        assert np.hypot(*v) == pytest.approx(expect, rel=1e-12)
        if expect:
            assert abs(v[0] * d[1] - v[1] * d[0]) < 1e-12 and v @ d > 0  # radial, outward
        assert b.angular_velocity == 0.0  # applied at the centre of mass: no spin
    assert static.velocity == (0.0, 0.0)
