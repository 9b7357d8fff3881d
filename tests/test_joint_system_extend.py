"""Joints added while a world runs grow the global joint system in place (system/extend.py):
the grown system must be, array for array, the one a full build makes, the world must step the
same bits as with the full build, and an added joint that touches a body of an older joint (or
any other edit) must still take the full build."""
import numpy as np
import pytest

from bench.suite.common import body, box, circle, scene, strip_box2d
from bench.suite.ragdoll import human
from bench.suite.scripts import _checked
from physics.constraints.joints import work as joint_work_module
from physics.constraints.joints.system import extend as extend_module
from physics.constraints.joints.system import topology as T
from physics.scene import scene_from_dict
from physics.scene.joints import add_joints
from physics.scene.load import _add_body
from physics.scene.problems import scene_error


def _world():
    bodies, joints = [body(box(40.0, 0.5), 0.0, -0.5, kind="static", name="ground")], []
    b, j = human("h0_", 0.0, 1.0, group=1)
    bodies += b
    joints += j
    bodies.append(body(circle(0.2), 10.0, 5.0, name="c0"))
    joints.append({"kind": "revolute", "a": "c0", "b": None, "anchor": [9.5, 5.0]})  # a lone joint
    return scene_from_dict(strip_box2d(scene("grow", "a ragdoll and a lone joint", bodies, joints)))


def _add(world, bodies, joints):
    """Bodies and joints through the scene loader's calls, as bench.suite's events add them (their
    joints may also name bodies already in the world)."""
    bodies, shapes, joints = _checked({"bodies": bodies, "joints": joints}, 0)
    for i, (b, s) in enumerate(zip(bodies, shapes)):
        _add_body(world, b, s, f"bodies[{i}]", "test")
    add_joints(world, joints, {b.name: b for b in world.bodies}, scene_error, "test")


def _ragdoll(i):
    return human(f"n{i}_", 3.0 * i + 3.0, 1.0, group=i + 2)


def _chain():
    """A chain of three discs from the world: new bodies, a new structure."""
    bodies = [body(circle(0.2), 20.0 + k, 5.0, name=f"k{k}") for k in range(3)]
    joints = [{"kind": "revolute", "a": f"k{k}", "b": f"k{k - 1}" if k else None, "anchor": [19.5 + k, 5.0]}
              for k in range(3)]
    return bodies, joints


def _same_as_full_build(world):
    s = world._store
    jw = s.joint_work
    nj = s.joints.n
    full, seq = T.build(s.joints.view, nj, s.bodies.view.kind[: s.bodies.n], len(jw.W.on))
    for name in T.STRUCTURE:
        assert np.array_equal(getattr(jw.S, name), getattr(full, name)), name
    assert np.array_equal(jw.S.dims[:4], full.dims[:4])  # the last: the factors' state in the step
    assert np.array_equal(jw.W.seq[:nj], seq[:nj])


@pytest.fixture
def calls(monkeypatch):
    """How many times the step grew the system in place."""
    seen = []
    real = joint_work_module.extend

    def spy(*a, **k):
        seen.append(a[3] - a[2])
        return real(*a, **k)

    monkeypatch.setattr(joint_work_module, "extend", spy)
    return seen


def test_added_structures_grow_the_system_as_a_full_build_would(calls):
    w = _world()
    w.step()
    for i in range(3):
        _add(w, *_ragdoll(i))
        w.step()
        _same_as_full_build(w)
    _add(w, *_chain())
    w.step()
    _same_as_full_build(w)
    assert calls == [10, 10, 10, 3], calls


def test_a_joint_on_an_older_body_takes_the_full_build(calls):
    w = _world()
    w.step()
    _add(w, [], [{"kind": "weld", "a": "h0_head", "b": "c0", "anchor": [5.0, 3.0]}])
    w.step()
    _same_as_full_build(w)
    assert calls == []
    w.remove(w.body("h0_torso"))  # a removal: the rows before are not as they were
    _add(w, *_ragdoll(0))
    w.step()
    _same_as_full_build(w)
    assert calls == []


def _run(grow: bool, monkeypatch):
    if not grow:
        monkeypatch.setattr(joint_work_module, "new_structures_only", lambda *a: False)
    w = _world()
    for k in range(40):
        if k % 8 == 0:
            _add(w, *_ragdoll(k // 8))
        w.step()
    monkeypatch.undo()
    return np.array([b.position + (b.angle,) for b in w.bodies])


def test_the_world_steps_the_same_bits_either_way(monkeypatch):
    assert np.array_equal(_run(True, monkeypatch), _run(False, monkeypatch))


def test_new_structures_only_reads_dynamic_bodies():
    w = _world()
    w.step()
    s = w._store
    J, kinds = s.joints.view, s.bodies.view.kind[: s.bodies.n]
    nj = s.joints.n
    # every joint after the first shares a body with an earlier one; the lone joint is last
    assert not extend_module.new_structures_only(J, 1, nj, kinds)
    assert extend_module.new_structures_only(J, nj - 1, nj, kinds)  # the disc joined to the world
