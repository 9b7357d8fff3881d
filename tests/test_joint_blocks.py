"""A structure of one joint is solved as its own block (constraints/joints/system/block.py), not
through the global system's sparse LDL^T: the numbers must be the system's, bit for bit, in
every mode, for every kind with equality rows (1 to 3 rows, rigid and soft, with limits and a
motor beside them), with the positions projected, and with a joint between two moving bodies.
The reference is the same world with lone joints put into the system (topology.LONE_AS_BLOCK)."""
import numpy as np
import pytest

import physics
from physics.constraints.joints.system import topology
from physics.constraints.joints.system.block import BLOCK
from physics.constraints.joints.work import joint_work

MODES = ["soft_step", "sequential_impulse", "impulse", "penalty", "hybrid"]


def _lone_joints():
    """One world of lone joints, each a structure of its own: to the world, to a static body and
    between two moving bodies; rigid, soft (spring rows inside the block), limited, motorised."""
    w = physics.World(gravity=(0, -10), sleeping=False)
    ground = w.add_body(physics.Polygon.box(30, 0.5), position=(0, -6), kind="static")
    box = lambda x, y: w.add_body(physics.Polygon.box(0.6, 0.3), position=(x, y), angle=0.3, angular_velocity=2.0)
    w.add_joint("revolute", box(-9, 1), None, anchor=(-9.5, 1.0), lower_angle=-0.4, upper_angle=0.5,
                max_motor_torque=3.0, motor_speed=1.0)
    w.add_joint("prismatic", box(-6, 1), ground, anchor=(-6, 1), axis=(0.6, 0.8), lower=-0.5, upper=0.3)
    w.add_joint("weld", box(-3, 1), None, anchor=(-3.4, 1.0))
    w.add_joint("weld", box(0, 1), ground, anchor=(-0.4, 1.0), linear_hertz=3.0, angular_hertz=2.0,
                damping_ratio=0.4)
    w.add_joint("distance", box(3, 1), None, anchor_a=(3, 1), anchor_b=(3.5, 3))
    w.add_joint("wheel", box(6, 1), ground, anchor=(6, 1), axis=(0, 1))
    w.add_joint("revolute", box(8, 1), box(9, 1.2), anchor=(8.5, 1.1))  # two moving bodies
    return w


def _run(make, mode, lone_as_block, steps=90, **settings):
    topology.LONE_AS_BLOCK[0] = lone_as_block
    try:
        w = make()
        w.solver = mode
        for k, v in settings.items():
            w.settings[k] = v
        for _ in range(steps):
            w.step()
        work = joint_work(w._store)
        blocks = int((work.W.seq[:w._store.joints.n] == BLOCK).sum())
        st = w.state()
        return np.concatenate([st["position"].ravel(), st["angle"], st["velocity"].ravel(),
                               st["angular_velocity"]]), blocks, work.global_rows
    finally:
        topology.LONE_AS_BLOCK[0] = True


@pytest.mark.parametrize("mode", MODES)
def test_lone_joints_as_blocks_give_the_systems_numbers(mode):
    blocks, nb, rows = _run(_lone_joints, mode, True)
    system, nb0, rows0 = _run(_lone_joints, mode, False)
    assert nb == 7 and rows == 0, "every joint here is a structure of its own"
    assert nb0 == 0 and rows0 == 2 + 2 + 3 + 3 + 1 + 1 + 2
    assert np.array_equal(blocks, system)
    assert np.isfinite(blocks).all() and np.abs(blocks).max() < 1e3  # a world that ran, not a blow-up


def test_projected_positions_match_too():
    """soft_step's joint_projection corrects the lone joints' blocks as the system corrects itself."""
    a = _run(_lone_joints, "soft_step", True, joint_projection=True)[0]
    b = _run(_lone_joints, "soft_step", False, joint_projection=True)[0]
    assert np.array_equal(a, b)
