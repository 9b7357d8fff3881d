"""Scene format version 2 (issue 13): several shapes per body, new shape kinds, per-shape
fixture fields; version 1 files load exactly as before.

- tests/data/scenes_v1/ holds the shipped scenes as they were saved in version 1 (issue 14's
  joint scenes included); each loads
  to the same world (every body field bit for bit, vertices, shapes) as its version 2 file,
  whose 600-step end states tests/test_shipped_scenes.py compares with the record.  The
  tumbler is the exception: it was rebuilt as a real drum (issue 13), so only its version 1
  file's own world is checked.  soft_body's version 1 file holds the two walls its scene gained
  later (plain static boxes, which version 1 writes the same way); car's and walker's hold their
  later courses (one body, one shape each: version 1 writes them the same way).
- a world using every new feature saves, reloads and saves again to the same text and the
  same world bit for bit;
- every bad new field is refused with its JSON path.
"""
import json
from pathlib import Path

import numpy as np
import pytest

import physics
from physics.scene import scene_from_dict, scene_to_dict
from physics.store.fixtures import FIXTURE_FIELDS

from test_scene import assert_same_world

ROOT = Path(__file__).resolve().parent.parent
V1 = sorted((ROOT / "tests" / "data" / "scenes_v1").glob("*.json"))


@pytest.mark.parametrize("path", [p for p in V1 if p.stem != "tumbler"], ids=lambda p: p.stem)
def test_version_1_scenes_load_the_same_worlds(path):
    assert json.loads(path.read_text())["version"] == 1
    w1 = physics.load_scene(path)
    w2 = physics.load_scene(ROOT / "scenes" / path.name)
    assert_same_world(w1, w2)
    assert [(b.mass, b.inertia) for b in w1.bodies] == [(b.mass, b.inertia) for b in w2.bodies]


def test_version_1_tumbler_still_loads():
    w = physics.load_scene(ROOT / "tests" / "data" / "scenes_v1" / "tumbler.json")
    assert sum(b.kind == "dynamic" for b in w.bodies) == 500


def every_feature():
    w = physics.World(gravity=(0, -10))
    w.add_body(physics.Chain([(10, 0), (0, -1), (-10, 0)]), kind="static", name="valley", friction=0.3)
    w.add_body(physics.Chain([(-3, 5), (3, 5), (3, 6), (-3, 6)], loop=True), kind="static")
    w.add_body(physics.Segment((-10, 3), (-8, 2.5)), kind="kinematic", angular_velocity=0.1)
    w.add_body(physics.decompose([(0, 0), (3, 0), (3, 1), (1, 1), (1, 3), (0, 3)]), position=(0.3, 2.1),
               angle=0.7, density=2.5, name="ell")
    car = w.add_body([physics.Polygon.box(2, 0.5, radius=0.05), physics.Circle(0.3, offset=(0.8, -0.4))],
                     position=(3.1, 2.2), velocity=(1.5, 0), name="car")
    car.fixtures[1].density = 3.3
    car.fixtures[1].friction = (0.9, 0.7)
    car.fixtures[1].restitution = 0.4
    f = car.add_fixture(physics.Capsule((-1, 0.3), (0, 0.6), 0.1), category=0x4, mask=0x3, group=-2, name="arm")
    f.group = -2
    w.add_body(physics.Polygon.regular(5, 0.5, corner_radius=0.1), position=(-2, 4))
    w.add_body(physics.Capsule((0, 0), (1, 0.2), 0.25), position=(5, 3), angle=0.3)
    return w


def fixture_table(w):
    F = w._store.fixtures
    return {k: getattr(F.view, k)[: F.n].copy() for k in FIXTURE_FIELDS if k not in ("aabb", "wcenter", "wghost")}


def test_version_2_round_trip_is_bit_exact(tmp_path):
    w = every_feature()
    p = tmp_path / "all.json"
    w.save_scene(p)
    data = json.loads(p.read_text())
    assert data["version"] == 2
    kinds = {k for b in data["bodies"] for s in b.get("shapes", [b.get("shape")]) for k in s}
    assert {"chain", "segment", "concave", "capsule", "radius", "category", "mask", "group", "name",
            "density", "friction", "restitution"} <= kinds
    w2 = physics.load_scene(p)
    assert_same_world(w, w2, skip=("aabb",))
    t1, t2 = fixture_table(w), fixture_table(w2)
    for k in t1:
        assert np.array_equal(t1[k], t2[k]), k
    assert [[f.name for f in b.fixtures] for b in w.bodies] == [[f.name for f in b.fixtures] for b in w2.bodies]
    p2 = tmp_path / "again.json"
    w2.save_scene(p2)
    assert p2.read_text() == p.read_text()


def scene(*bodies, version=2):
    return {"format": "stelkropp.scene", "version": version, "bodies": list(bodies)}


OK = {"shape": {"box": [1, 1]}, "position": [0, 0]}
BAD = [  # (body, path, words)
    ({"shapes": [{"box": [1, 1]}, {"capsule": {"a": [0, 0], "b": [0, 0], "radius": 1}}], "position": [0, 0]},
     "bodies[0].shapes[1].capsule", "coincide"),
    ({"shapes": [{"box": [1, 1], "radius": -1}], "position": [0, 0]}, "bodies[0].shapes[0].radius", ">= 0"),
    ({"shape": {"circle": 1, "radius": 0.1}, "position": [0, 0]}, "bodies[0].shape.radius", "rounds"),
    ({"shape": {"concave": [[0, 0], [1, 1], [1, 0], [0, 1]]}, "position": [0, 0]}, "bodies[0].shape.concave",
     "self-intersecting"),
    ({"shape": {"box": [1, 1], "mask": -3}, "position": [0, 0]}, "bodies[0].shape.mask", ">= 0"),
    ({"shape": {"box": [1, 1], "group": 2 ** 40}, "position": [0, 0]}, "bodies[0].shape.group", "<="),
    ({"shape": {"box": [1, 1], "density": 0}, "position": [0, 0]}, "bodies[0].shape.density", "> 0"),
    ({"shape": {"box": [1, 1], "colour": 1}, "position": [0, 0]}, "bodies[0].shape.colour", "unknown key"),
    ({"shape": {"segment": [[0, 0], [1, 0]]}, "position": [0, 0]}, "bodies[0].shape", "dynamic body needs"),
    ({"shape": {"chain": {"points": [[0, 0]]}}, "position": [0, 0], "kind": "static"},
     "bodies[0].shape.chain.points", "needs at least 2"),
    ({"shape": {"chain": {"points": [[0, 0], [0, 0]]}}, "position": [0, 0], "kind": "static"},
     "bodies[0].shape.chain", "repeated"),
    ({"shape": {"box": [1, 1], "circle": 1}, "position": [0, 0]}, "bodies[0].shape", "exactly one"),
    ({"shape": {"box": [1, 1]}, "shapes": [{"box": [1, 1]}], "position": [0, 0]}, "bodies[0].shapes", "not both"),
    ({"shapes": [], "position": [0, 0]}, "bodies[0].shapes", "at least 1"),
    ({"shapes": [{"polygon": [[0, 0], [2, 0], [1, 0.2], [1, 2]]}], "position": [0, 0]},
     "bodies[0].shapes[0].polygon", "not convex"),
]


@pytest.mark.parametrize("body, path, words", BAD, ids=[b[1] + ":" + b[2] for b in BAD])
def test_bad_shape_specs_are_refused_with_their_paths(body, path, words):
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(scene(body))
    problems = dict(info.value.problems)
    assert path in problems, problems
    assert words in problems[path]


@pytest.mark.parametrize("body, path", [
    ({"shape": {"capsule": {"a": [0, 0], "b": [1, 0], "radius": 1}}, "position": [0, 0]}, "bodies[0].shape.capsule"),
    ({"shapes": [{"box": [1, 1]}], "position": [0, 0]}, "bodies[0].shapes"),
    ({"shape": {"box": [1, 1], "radius": 0.1}, "position": [0, 0]}, "bodies[0].shape.radius"),
])
def test_version_1_files_cannot_use_version_2_fields(body, path):
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(scene(body, version=1))
    assert "version 2" in dict(info.value.problems)[path]


def test_saving_writes_version_2_and_a_single_shape_stays_shape():
    w = scene_from_dict(scene(OK, version=1))
    d = scene_to_dict(w)
    assert d["version"] == 2 and d["bodies"][0]["shape"] == {"box": [1.0, 1.0]}
