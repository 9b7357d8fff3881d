"""Whatever the public API accepts saves and loads again as the same world (a property test over
random worlds), and what a scene file could not hold is refused when it is set, naming the field.

The worlds are built only through the API: bodies of every shape kind with extra fixtures of
their own material, filter, name and sensor flag; springs; joints of every kind with random
parameters (welds that break); names and metadata drawn from all of Unicode, lone surrogates
included; then stepped, so the state a running world changes is in the file too: positions and
velocities, broken joints, sleeping islands and sleep timers, the time and the step count.
"""
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import physics
from physics import joint_params as jp

ANY_TEXT = st.text(st.characters(codec=None, exclude_categories=()), min_size=0, max_size=6)
NUM = st.floats(-5, 5, allow_nan=False).map(lambda x: round(x, 3))


def _lone_surrogate(s) -> bool:
    return isinstance(s, str) and any(0xD800 <= ord(c) <= 0xDFFF for c in s)


def _try(fn, value):
    """Set a name-like value; a lone surrogate (or an empty name) must be refused with ValueError."""
    try:
        fn(value)
    except ValueError as exc:
        assert _lone_surrogate(value) or value == "" or "already exists" in str(exc), (value, exc)
        return False
    assert not _lone_surrogate(value), f"accepted {value!r}"
    return True


SHAPES = {
    "box": lambda d: physics.Polygon.box(d(st.floats(0.2, 2)), d(st.floats(0.2, 2)), radius=d(st.sampled_from([0, 0.05]))),
    "regular": lambda d: physics.Polygon.regular(d(st.integers(3, 9)), d(st.floats(0.2, 1.5))),
    "circle": lambda d: physics.Circle(d(st.floats(0.1, 1)), (d(NUM) / 5, d(NUM) / 5)),
    "capsule": lambda d: physics.Capsule((-0.5, 0), (0.5, d(NUM) / 10), d(st.floats(0.1, 0.5))),
    "concave": lambda d: physics.decompose([(0, 0), (2, 0), (2, 0.5), (0.5, 0.5), (0.5, 2), (0, 2)]),
    "segment": lambda d: physics.Segment((-1, 0), (1, d(NUM) / 5)),
    "chain": lambda d: physics.Chain([(3, 0), (1, d(NUM) / 10), (-1, 0), (-3, 0.5)], loop=d(st.booleans())),
}


def _body(draw, w, i):
    kind = draw(st.sampled_from(list(SHAPES)))
    shape = SHAPES[kind](draw)
    static_only = kind in ("segment", "chain")
    body_kind = "static" if static_only or draw(st.integers(0, 5)) == 0 else draw(st.sampled_from(["dynamic", "kinematic"]))
    body = w.add_body(shape, kind=body_kind, position=(4.0 * i, draw(st.floats(0, 4))), angle=draw(NUM) / 3,
                      velocity=(draw(NUM), draw(NUM)), angular_velocity=draw(NUM), density=draw(st.floats(0.1, 5)),
                      restitution=draw(st.floats(0, 1)), friction=(draw(st.floats(0, 1)), draw(st.floats(0, 1))))
    _try(lambda v: setattr(body, "name", v), draw(ANY_TEXT))
    for _ in range(draw(st.integers(0, 2))):
        fx = body.add_fixture(physics.Circle(0.2, (draw(NUM) / 5, draw(NUM) / 5)), density=draw(st.floats(0.1, 5)),
                              category=draw(st.integers(0, 2 ** 64 - 1)), group=draw(st.integers(-3, 3)),
                              sensor=draw(st.booleans()) and body_kind != "dynamic")
        _try(lambda v: setattr(fx, "name", v), draw(ANY_TEXT))
    return body


def _joint(draw, w, a, b):
    kind = draw(st.sampled_from(["revolute", "prismatic", "weld", "distance", "wheel", "motor", "rotary"]))
    kw = {}
    if "anchor" in jp.GEOMETRY[kind]:
        kw["anchor"] = a.position
    if "axis" in jp.GEOMETRY[kind]:
        kw["axis"] = (0.0, 1.0)
    if kind == "weld" and draw(st.booleans()):
        kw["break_force"] = draw(st.sampled_from([1e-3, 1.0, 1e6]))
    if kind in ("revolute", "rotary"):
        kw.update(motor_speed=draw(NUM), max_motor_torque=draw(st.floats(0, 5)))
    j = w.add_joint(kind, a, b, collide_connected=draw(st.booleans()), **kw)
    _try(lambda v: setattr(j, "name", v), draw(ANY_TEXT))


@st.composite
def worlds(draw):
    w = physics.World(gravity=(0, draw(st.sampled_from([-9.81, 0.0]))), dt=draw(st.sampled_from([1 / 60, 1 / 120])),
                      solver=draw(st.sampled_from(["soft_step", "sequential_impulse"])))
    w.add_body(physics.Polygon.box(60, 1), kind="static", position=(10, -0.5))
    bodies = [_body(draw, w, i) for i in range(draw(st.integers(1, 5)))]
    movers = [b for b in bodies if b.kind == "dynamic"]
    for _ in range(draw(st.integers(0, 2))):
        if movers:
            sp = w.add_spring(draw(st.sampled_from(movers)), None, anchor_b=(draw(NUM), 5.0),
                              stiffness=draw(st.floats(0, 50)), damping=draw(st.floats(0, 2)))
            _try(lambda v: setattr(sp, "name", v), draw(ANY_TEXT))
    for _ in range(draw(st.integers(0, 2))):
        if len(movers) >= 2:
            a, b = draw(st.permutations(movers))[:2]
            _joint(draw, w, a, b)
    for key in ("name", "description"):
        _try(lambda v: w.metadata.__setitem__(key, v), draw(ANY_TEXT))
    if draw(st.booleans()):
        w.metadata["camera"] = {"center": [draw(NUM), draw(NUM)], "zoom": draw(st.floats(1, 100))}
    return w, draw(st.sampled_from([0, 1, 20, 200]))


def _fixture(f):
    s = f.shape
    geometry = (s.offset.tolist(),) if isinstance(s, physics.Circle) else (s.vertices.tolist(),)
    return (type(s).__name__, s.radius, geometry, f.density, f.friction, f.restitution, f.category, f.mask,
            f.group, f.name, f.sensor)


def signature(w):
    """Everything a world's public API shows, by position in its lists (auto-named bodies aside)."""
    index = {b.id: i for i, b in enumerate(w.bodies)}
    settings_ = dict(w.settings.items())
    world = (tuple(w.gravity), w.dt, w.solver, settings_, w.integrator, w.sleeping, w.time, w.steps)
    bodies = [(b.kind, b.position, b.angle, b.velocity, b.angular_velocity, b.awake, b.mass, b.inertia,
               b.center_of_mass, [_fixture(f) for f in b.fixtures]) for b in w.bodies]
    springs = [(s.name, index[s.body_a.id], None if s.body_b is None else index[s.body_b.id], s.anchor_a,
                s.anchor_b, s.stiffness, s.damping, s.rest_length) for s in w.springs]
    joints = [(j.kind, j.name, index[j.body_a.id], None if j.body_b is None else index[j.body_b.id], j.broken,
               j.break_force, j.break_torque, j.collide_connected, j.local_anchor_a,
               [getattr(j, p) for p in jp.PARAMS[j.kind] if p != "target"]) for j in w.joints]
    meta = {k: w.metadata.get(k) for k in ("name", "description", "camera")}
    return world, bodies, springs, joints, meta


def first_difference(x, y, path="world"):
    """The path of the first place two signatures differ (None if equal): a readable failure."""
    if isinstance(x, (list, tuple)) and isinstance(y, (list, tuple)) and len(x) == len(y):
        for k, (p, q) in enumerate(zip(x, y)):
            found = first_difference(p, q, f"{path}[{k}]")
            if found:
                return found
        return None
    if isinstance(x, dict) and isinstance(y, dict) and x.keys() == y.keys():
        return next((d for k in x if (d := first_difference(x[k], y[k], f"{path}[{k!r}]"))), None)
    return None if x == y else f"{path}: {x!r} != {y!r}"


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(worlds())
def test_save_then_load_gives_the_same_world(tmp_path_factory, built):
    w, steps = built
    try:
        for _ in range(steps):
            w.step()
    except physics.SimulationError:
        assume(False)  # a refused step is the energy guard's business, not the file's
    path = tmp_path_factory.mktemp("rt") / "world.json"
    w.save_scene(path)
    again = physics.load_scene(path)
    assert first_difference(signature(w), signature(again)) is None
    for b, c in zip(w.bodies, again.bodies):
        assert c.name == b.name or b.name is None
    path2 = path.with_name("again.json")
    again.save_scene(path2)
    assert path2.read_text() == path.read_text()  # a fixed point: nothing drifts on a second trip


def _weld_pair():
    w = physics.World()
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    a = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5), name="a")
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 1.5), name="b")
    j = w.add_joint("weld", a, b, anchor=(0, 1), break_force=1e-3)
    b.velocity = (2.0, 0.0)  # pull it apart: the weld breaks at once
    return w, a, b, j


def test_a_broken_weld_loads_broken_and_does_not_yank_its_bodies(tmp_path):
    w, a, b, j = _weld_pair()
    for _ in range(30):
        w.step()
    assert j.broken
    w.save_scene(tmp_path / "broken.json")
    again = physics.load_scene(tmp_path / "broken.json")
    assert again.joints[0].broken and again.broken_joints == []
    for _ in range(5):
        w.step()
        again.step()
    # the same motion (contact warm starts are not in a scene file, so not to the bit; an unbroken
    # weld pulled b back by 1 m in these 5 steps)
    assert again.body("b").position == pytest.approx(b.position, abs=5e-3)
    assert again.body("a").position == pytest.approx(a.position, abs=5e-3)


def test_sleeping_islands_load_asleep_and_wake_together(tmp_path):
    w = physics.World()
    w.add_body(physics.Polygon.box(20, 1), kind="static", position=(0, -0.5))
    stack = [w.add_body(physics.Polygon.box(1, 1), position=(0, 0.5 + k), name=f"s{k}") for k in range(3)]
    lone = w.add_body(physics.Circle(0.5), position=(5, 0.5), name="lone")
    for _ in range(400):
        w.step()
    assert not any(b.awake for b in stack + [lone])
    w.save_scene(tmp_path / "asleep.json")
    again = physics.load_scene(tmp_path / "asleep.json")
    assert [again.body(f"s{k}").awake for k in range(3)] == [False] * 3 and not again.body("lone").awake
    again.body("s0").wake()
    assert all(again.body(f"s{k}").awake for k in range(3)) and not again.body("lone").awake


@pytest.mark.parametrize("setter", [
    lambda w, b: setattr(b, "name", "a\ud800b"),
    lambda w, b: w.add_body(physics.Circle(1), name="\udfff"),
    lambda w, b: w.add_spring(b, None, name="s\ud800"),
    lambda w, b: w.add_joint("revolute", b, None, anchor=(0, 0), name="j\udc00"),
    lambda w, b: setattr(b.fixtures[0], "name", "f\ud800"),
    lambda w, b: b.add_fixture(physics.Circle(0.1), name="\ud800"),
    lambda w, b: w.metadata.__setitem__("description", "d\ud800"),
    lambda w, b: w.metadata.__setitem__("camera", {"center": "x"}),
    lambda w, b: w.metadata.__setitem__("camera", {"zoom": -1}),
    lambda w, b: w.metadata.update(name="\ud800"),
    lambda w, b: setattr(w, "metadata", {"camera": {"centre": [0, 0]}}),
])
def test_what_a_file_cannot_hold_is_refused_when_set(setter):
    w = physics.World()
    b = w.add_body(physics.Circle(1), name="ball")
    before = (len(w.bodies), len(w.springs), len(w.joints), len(b.fixtures), dict(w.metadata))
    with pytest.raises(ValueError, match=r"name|description|camera|centre|zoom"):
        setter(w, b)
    assert (len(w.bodies), len(w.springs), len(w.joints), len(b.fixtures), dict(w.metadata)) == before


def test_save_refuses_before_writing_what_was_edited_in_place(tmp_path):
    w = physics.World()
    w.add_body(physics.Circle(1))
    w.metadata["camera"] = {"center": [0, 0]}
    w.metadata["camera"]["center"] = "x"  # past the setter: caught when saving, nothing written
    with pytest.raises(ValueError, match=r"camera.*center"):
        w.save_scene(tmp_path / "x.json")
    with pytest.raises(ValueError, match="name"):
        physics.World().save_scene(tmp_path / "y.json", name="a\ud800")
    with pytest.raises(ValueError, match="description"):
        physics.World().save_scene(tmp_path / "y.json", description="\udfff")
    assert list(tmp_path.iterdir()) == []


def test_old_files_without_the_new_fields_load_as_before():
    data = {"format": "stelkropp.scene", "version": 2, "bodies": [
        {"name": "a", "shape": {"circle": 1}, "position": [0, 1]},
        {"name": "b", "shape": {"circle": 1}, "position": [3, 1]}],
        "joints": [{"kind": "weld", "a": "a", "b": "b", "anchor": [1.5, 1]}]}
    w = physics.scene.scene_from_dict(data)
    assert w.time == 0.0 and w.steps == 0 and all(b.awake for b in w.bodies) and not w.joints[0].broken
    assert math.isclose(w.body("b").position[0], 3.0)
    assert np.isfinite(w.body("a").mass)
