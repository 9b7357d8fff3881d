"""Bounces never gain energy across bodies that meet together (constraints/restitution_cluster.py).

The case hypothesis found (tests/test_property_scenes.py, zero gravity, soft_step): a unit box at
rest, a disc (r 0.5) at -4 m/s and a unit box at -6 m/s in a line, e = 1 (the pair's restitution
is the larger of the two), frictionless: the disc reaches the box at rest in the same sub-step as
the fast box reaches the disc.  Each pair's bounce was capped by its own energy at first touch,
the disc's counted in both, and the three left with 31.54 J from 24.28 J.  An elastic impact of
bodies alone conserves kinetic energy at most (Stronge's energetic bound), so the bound here is
the initial energy, to rounding.
"""
import pytest

import physics


def squeeze():
    w = physics.World(gravity=(0.0, 0.0))
    w.sleeping = False
    w.add_body(physics.Polygon.box(1.0, 1.0), position=(0.0, 0.0), restitution=1.0, friction=0.0)
    w.add_body(physics.Circle(0.5), position=(3.0, 0.0), velocity=(-4.0, 0.0), restitution=0.0, friction=0.0)
    w.add_body(physics.Polygon.box(1.0, 1.0), position=(5.0, 0.0), velocity=(-6.0, 0.0), restitution=1.0,
               friction=0.0)
    return w


def cradle(n=5):
    """n touching discs (e = 1) in a row, one more arriving at 3 m/s."""
    w = physics.World(gravity=(0.0, 0.0))
    w.sleeping = False
    for i in range(n):
        w.add_body(physics.Circle(0.5), position=(1.0 * i, 0.0), restitution=1.0, friction=0.0)
    w.add_body(physics.Circle(0.5), position=(-1.5, 0.0), velocity=(3.0, 0.0), restitution=1.0, friction=0.0)
    return w


@pytest.mark.parametrize("make,kept", [(squeeze, 0.999), (cradle, 0.999)])
def test_bodies_meeting_together_never_leave_with_more_energy(make, kept):
    """Before the cluster cap: the squeeze 24.28 -> 31.54 J, the cradle 3.53 -> 4.20 J.  The
    squeeze keeps its energy (the cap scales its bounces to exactly the start); so does the
    cradle, whose impact passes along the row pair by pair (constraints/restitution_chain.py;
    before that pass it kept 1.63 J of 3.53)."""
    w = make()
    e0 = w.kinetic_energy()
    peak = e0
    for _ in range(90):
        w.step()
        peak = max(peak, w.kinetic_energy())
    assert peak <= e0 * (1.0 + 1e-9)
    assert w.kinetic_energy() >= kept * e0


def test_the_squeeze_keeps_momentum_and_separates():
    w = squeeze()
    p0 = w.linear_momentum()
    for _ in range(90):
        w.step()
    p = w.linear_momentum()
    assert p[0] == pytest.approx(p0[0], abs=1e-9) and p[1] == pytest.approx(p0[1], abs=1e-9)
    v = [b.velocity[0] for b in w.bodies]
    assert v[0] <= v[1] <= v[2]  # left to right, nobody passes through anybody
