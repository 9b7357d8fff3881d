"""Newton's cradle in the default mode: an impact passes along a row of touching bodies pair by
pair (physics/constraints/restitution_chain.py).

The cradle is bench/cradle.py's (the accuracy issue's): five discs (r 0.25 m, e = 1, no
friction) touching in a row on 2 m distance joints, the first released from 60 degrees, dt
1/60, gravity -10.  Figures measured on this machine with ``python -m bench.cradle``
(docs/reliability.md):
- pymunk 7 (PinJoints, 10 iterations) keeps 0.953 of the swing energy at 2.5 s and 0.918 at
  10 s, and its middle discs wander up to 0.216 m from rest;
- soft_step before the impact pass kept 0.233 and 0.200 (one impact shared the swing over the
  whole row).
The bounds: at least 90 % kept after 10 s (the issue's target, under pymunk's 0.918), the middle
discs within 5 cm of rest (a quarter of pymunk's wander), never more than 1 % above the start
(the distance joints' soft stretch moves the energy by about 0.5 %), and the last test measures
pymunk again beside us.
"""
import pytest

import physics
from bench import cradle


def test_the_cradle_keeps_swinging_for_ten_seconds_with_the_middle_still():
    run = cradle.stelkropp()
    assert run.kept[600] >= 0.90, run
    assert run.peak <= 1.01, run
    assert run.wander < 0.05, run


def test_the_cradle_keeps_more_swing_than_pymunk_measured_beside_it():
    pytest.importorskip("pymunk")  # a bench extra: .ci/run installs it
    ours, theirs = cradle.stelkropp(), cradle.pymunk()
    assert ours.kept[600] >= theirs.kept[600], (ours, theirs)
    assert ours.wander <= theirs.wander, (ours, theirs)


@pytest.mark.parametrize("side", [-1, 1])
def test_a_free_row_passes_a_blow_from_either_end(side):
    """Five touching discs at rest in zero gravity, a sixth arriving at 3 m/s from the left or from
    the right (the contacts are visited in table order, so one side is the row's far end): the
    disc at the other end leaves at 3 m/s, every other disc is still, energy and momentum kept."""
    w = physics.World(gravity=(0.0, 0.0), sleeping=False)
    row = [w.add_body(physics.Circle(0.5), position=(1.0 * i, 0.0), restitution=1.0, friction=0.0) for i in range(5)]
    start = -1.5 if side < 0 else 5.5
    striker = w.add_body(physics.Circle(0.5), position=(start, 0.0), velocity=(-3.0 * side, 0.0),
                         restitution=1.0, friction=0.0)
    e0 = w.kinetic_energy()
    for _ in range(90):
        w.step()
    far = row[-1] if side < 0 else row[0]
    assert far.velocity[0] == pytest.approx(-3.0 * side, abs=1e-6)
    for b in [striker] + row:
        if b is not far:
            assert abs(b.velocity[0]) < 1e-6, (b.name, b.velocity)
    assert w.kinetic_energy() == pytest.approx(e0, rel=1e-6)


def test_a_half_bouncy_row_passes_less_and_never_gains():
    """e = 0.5 along the row: a pair impact keeps at most (1 + e^2) / 2 of its energy in the
    pair's frame, so the far disc leaves slower than the striker came and the energy only falls."""
    w = physics.World(gravity=(0.0, 0.0), sleeping=False)
    row = [w.add_body(physics.Circle(0.5), position=(1.0 * i, 0.0), restitution=0.5, friction=0.0) for i in range(4)]
    w.add_body(physics.Circle(0.5), position=(-1.5, 0.0), velocity=(3.0, 0.0), restitution=0.5, friction=0.0)
    e0 = w.kinetic_energy()
    p0 = w.linear_momentum()[0]
    for _ in range(90):
        w.step()
        assert w.kinetic_energy() <= e0 * (1 + 1e-9)
    assert w.linear_momentum()[0] == pytest.approx(p0, rel=1e-9)
    assert 0.0 < row[-1].velocity[0] < 3.0
