"""Scene files: building worlds from data, exact round-trips, atomic saving, the published schema."""
import json
import math
import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

import physics
from physics.scene import schema as scene_schema
from physics.scene import load_scene, save_scene, scene_from_dict, scene_metadata, scene_to_dict
from physics.store import BODY_FIELDS, SPRING_FIELDS

ROOT = Path(__file__).resolve().parent.parent
# per-step scratch state: not part of what a scene describes
TRANSIENT = {"awake", "sleep_t", "island", "aabb", "f", "tau"}
WORLD_ATTRS = ("gravity", "dt", "solver", "integrator", "sleeping", "broadphase", "narrowphase")


def assert_same_world(w1, w2, skip=()):
    """Every body field, vertex, spring field, name and world setting equal, bit for bit."""
    for attr in WORLD_ATTRS:
        assert getattr(w1, attr) == getattr(w2, attr), attr
    assert w1.settings.to_dict() == w2.settings.to_dict()
    n = w1._bodies.n
    assert w2._bodies.n == n
    for f in BODY_FIELDS:
        if f not in skip:
            a, b = getattr(w1._bodies.view, f)[:n], getattr(w2._bodies.view, f)[:n]
            assert np.array_equal(a, b), f"body field {f}: first difference at slot {np.argwhere(a != b)[0]}"
    top = w1._verts.top
    assert w2._verts.top == top
    assert np.array_equal(w1._verts.view.local[:top], w2._verts.view.local[:top])
    assert [b.name for b in w1.bodies] == [b.name for b in w2.bodies]
    assert [b.shape.spec for b in w1.bodies] == [b.shape.spec for b in w2.bodies]
    ns = w1._springs.n
    assert w2._springs.n == ns
    for f in SPRING_FIELDS:
        assert np.array_equal(getattr(w1._springs.view, f)[:ns], getattr(w2._springs.view, f)[:ns]), f
    assert [s.name for s in w1.springs] == [s.name for s in w2.springs]


def minimal(**extra):
    return {"format": "stelkropp.scene", "version": 1, "bodies": [], **extra}


EXAMPLE = {  # the issue's example, verbatim
    "format": "stelkropp.scene", "version": 1,
    "name": "Pyramid 20", "description": "210 boxes on static ground",
    "world": {"gravity": [0, -10], "dt": 0.016666666666666666, "solver": "soft_step",
              "settings": {"substeps": 4}, "integrator": "symplectic_euler", "sleeping": True},
    "bodies": [
        {"name": "ground", "kind": "static", "shape": {"box": [40, 1]}, "position": [0, -0.5]},
        {"name": "b0", "shape": {"polygon": [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]},
         "position": [0, 0.5], "angle": 0, "velocity": [0, 0], "angular_velocity": 0,
         "density": 1, "restitution": 0, "friction": {"static": 0.6, "dynamic": 0.6}},
        {"name": "hex", "shape": {"regular": {"sides": 6, "radius": 0.5}}, "position": [3, 2]},
    ],
    "springs": [
        {"name": "s0", "a": "b0", "b": None, "anchor_a": [0, 0.5], "anchor_b": [0, 5],
         "stiffness": 50, "damping": 1, "rest_length": 2},
    ],
}


# -- building ---------------------------------------------------------------
def test_issue_example_builds():
    w = scene_from_dict(EXAMPLE)
    assert w.gravity == (0.0, -10.0) and w.dt == 1 / 60 and w.solver == "soft_step"
    assert w.settings["substeps"] == 4 and w.integrator == "symplectic_euler" and w.sleeping
    ground, b0, hexa = w.bodies
    assert ground.kind == "static" and ground.position == (0.0, -0.5)
    assert b0.friction == (0.6, 0.6) and b0.position == (0.0, 0.5)
    assert hexa.shape.spec == {"regular": {"sides": 6, "radius": 0.5}}
    s = w.spring("s0")
    assert s.body_a is b0 and s.body_b is None
    assert (s.anchor_a, s.anchor_b, s.stiffness, s.damping, s.rest_length) == ((0, 0.5), (0, 5), 50, 1, 2)
    assert scene_metadata(w)["name"] == "Pyramid 20"


def test_defaults_are_the_documented_ones():
    w = scene_from_dict(minimal(bodies=[{"shape": {"circle": 0.5}, "position": [1, 2]},
                                        {"name": "x", "shape": {"box": [1, 1]}, "position": [0, 5]}],
                                springs=[{"a": "x", "b": None, "anchor_b": [0, 7], "stiffness": 10}]))
    d = scene_schema.WORLD_DEFAULTS
    assert w.gravity == tuple(d["gravity"]) and w.dt == d["dt"] and w.solver == d["solver"]
    assert w.integrator == d["integrator"] and w.sleeping is d["sleeping"]
    assert w.broadphase == d["broadphase"] and w.narrowphase == d["narrowphase"]
    declared = physics.solvers.get(w.solver).settings
    assert w.settings.to_dict() == {k: s.default for k, s in declared.items()}
    b = w.bodies[0]
    bd = scene_schema.BODY_DEFAULTS
    assert (b.kind, b.angle, b.velocity, b.angular_velocity) == (bd["kind"], 0.0, (0.0, 0.0), 0.0)
    assert (b.density, b.restitution, b.friction) == (bd["density"], bd["restitution"], (0.6, 0.6))
    assert b.name is None
    sp = w.springs[0]
    assert sp.anchor_a == (0.0, 0.0) and sp.damping == 0.0
    assert sp.rest_length == pytest.approx(2.0)  # distance at creation: body origin (0, 5) to (0, 7)


def test_every_shape_form_keeps_its_spec():
    shapes = [{"box": [2.0, 1.0]}, {"regular": {"sides": 5, "radius": 0.7}}, {"circle": 0.4},
              {"circle": {"radius": 0.3, "offset": [0.1, -0.2]}},
              {"polygon": [[0.0, 0.0], [1.0, 0.1], [0.3, 0.9]]}]
    data = minimal(bodies=[{"shape": s, "position": [3.0 * i, 0.0]} for i, s in enumerate(shapes)])
    w = scene_from_dict(data)
    assert [b.shape.spec for b in w.bodies] == shapes
    assert isinstance(w.bodies[2].shape, physics.Circle)
    assert scene_to_dict(w)["bodies"] == data["bodies"]


def test_clockwise_polygon_is_accepted_and_saved_counter_clockwise():
    cw = [[-0.5, 0.5], [0.5, 0.5], [0.5, -0.5], [-0.5, -0.5]]
    w = scene_from_dict(minimal(bodies=[{"shape": {"polygon": cw}, "position": [0, 0]}]))
    saved = scene_to_dict(w)["bodies"][0]["shape"]["polygon"]
    assert saved == cw[::-1]


# -- round trips ----------------------------------------------------------------
def test_round_trip_of_the_example(tmp_path):
    w1 = scene_from_dict(EXAMPLE)
    p = tmp_path / "x.json"
    w1.save_scene(p)
    w2 = load_scene(p)
    assert_same_world(w1, w2)
    assert scene_metadata(w2) == {"name": "Pyramid 20", "description": "210 boxes on static ground"}
    # saving the reloaded world writes the same bytes
    p2 = tmp_path / "y.json"
    w2.save_scene(p2)
    assert p.read_text() == p2.read_text()


def test_round_trip_of_a_built_world_with_unnamed_spring_bodies(tmp_path):
    w = physics.World(gravity=(0.3, -7.1), dt=0.01, integrator="rk4", sleeping=False, broadphase="sweep",
                      narrowphase="gjk")
    w.settings["substeps"] = 7
    a = w.add_body(physics.Polygon([(0, 0), (1.3, 0.2), (0.7, 1.1)]), position=(0.1, 0.2), angle=0.7,
                   velocity=(1.0 / 3, -2.2), angular_velocity=0.123, density=2.5, restitution=0.3,
                   friction=(0.9, 0.4))
    b = w.add_body(physics.Circle(0.4, offset=(0.2, -0.1)), kind="kinematic", position=(3, 1),
                   velocity=(0.5, 0), angular_velocity=-1.0)
    c = w.add_body(physics.Polygon.regular(7, 0.5), position=(-2, 3), name="body1")  # blocks the auto-name
    w.add_spring(a, b, anchor_a=(0.3, 0.3), anchor_b=(0.1, 0.0), stiffness=33.0, damping=0.5)
    w.add_spring(c, None, anchor_a=(0.1, 0.2), anchor_b=(-2, 6), stiffness=12.0, name="hang")
    p = tmp_path / "built.json"
    w.save_scene(p, name="built", description="by hand")
    data = json.loads(p.read_text())
    names = [bd.get("name") for bd in data["bodies"]]
    # named by id (a's "body1" is taken by c: a suffix)
    assert names[0] == f"body{a.id}_1" and names[1] == f"body{b.id}" and names[2] == "body1", (a.id, names)
    w2 = load_scene(p)
    # the auto-names are the only difference: give the original the same ones, then compare all
    a.name, b.name = names[0], names[1]
    assert_same_world(w, w2)
    assert scene_metadata(w2) == {"name": "built", "description": "by hand"}


def test_round_trip_after_stepping_is_exact(tmp_path):
    """Mid-simulation state (arbitrary floats, rotated off-centre bodies) reloads bit for bit."""
    w = scene_from_dict(EXAMPLE)
    w.add_body(physics.Polygon([(0, 0), (2, 0.3), (0.4, 1.7)]), position=(-3, 4), angle=2.0)
    for _ in range(45):
        w.step()
    p = tmp_path / "stepped.json"
    save_scene(w, p)
    assert_same_world(w, load_scene(p), skip=TRANSIENT)


coord = st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(coord, coord, st.floats(-50, 50), st.floats(0.05, 20), st.integers(0, 2)),
                min_size=1, max_size=6),
       st.floats(-10, 10), st.floats(-10, 10))
def test_round_trip_property(bodies, ax, ay):
    """Any positions, angles and shapes (off-centre centroids included) survive save and load exactly."""
    w = physics.World()
    made = []
    for i, (x, y, ang, size, kind) in enumerate(bodies):
        shape = (physics.Polygon([(0, 0), (size, 0.1 * size), (0.3 * size, 0.9 * size)]) if kind == 0
                 else physics.Circle(size, offset=(0.3 * size, -0.1)) if kind == 1
                 else physics.Polygon.regular(3 + i, size))
        made.append(w.add_body(shape, position=(x, y), angle=ang, name=f"b{i}"))
    if len(made) > 1:
        w.add_spring(made[0], made[1], anchor_a=(ax, ay), anchor_b=(ay, ax), stiffness=1.0)
    w2 = scene_from_dict(json.loads(json.dumps(scene_to_dict(w))))
    assert_same_world(w, w2)


# -- atomic saving ------------------------------------------------------------
def test_save_is_atomic_and_leaves_no_temp_files(tmp_path, monkeypatch):
    w = scene_from_dict(EXAMPLE)
    p = tmp_path / "scene.json"
    w.save_scene(p)
    before = p.read_text()
    os.chmod(p, 0o640)

    def crash(*a, **k):
        raise OSError("disk full")

    # a failure while writing leaves the old file untouched and no temporary file behind
    monkeypatch.setattr(os, "fsync", crash)
    w.bodies[1].position = (5, 5)
    with pytest.raises(OSError):
        w.save_scene(p)
    assert p.read_text() == before
    assert [f.name for f in tmp_path.iterdir()] == ["scene.json"]
    monkeypatch.undo()
    w.save_scene(p)
    assert p.read_text() != before
    assert [f.name for f in tmp_path.iterdir()] == ["scene.json"]
    assert os.stat(p).st_mode & 0o777 == 0o640  # the old file's permissions are kept


def test_save_uses_os_replace(tmp_path, monkeypatch):
    calls = []
    real = os.replace
    monkeypatch.setattr(os, "replace", lambda a, b: (calls.append((a, b)), real(a, b)))
    scene_from_dict(EXAMPLE).save_scene(tmp_path / "s.json")
    (src, dst), = calls
    assert Path(src).parent == tmp_path and Path(dst) == tmp_path / "s.json"


def test_saved_file_is_strict_json_with_schema_reference(tmp_path):
    p = tmp_path / "s.json"
    scene_from_dict(EXAMPLE).save_scene(p, name="renamed", description="new words")
    data = json.loads(p.read_text(), parse_constant=lambda c: pytest.fail(f"non-strict JSON constant {c}"))
    assert data["$schema"] == "stelkropp.schema.json"
    assert (data["format"], data["version"], data["name"], data["description"]) == \
        ("stelkropp.scene", 2, "renamed", "new words")


def test_camera_is_kept():
    cam = {"center": [1.0, 2.0], "zoom": 33.0}
    w = scene_from_dict(dict(EXAMPLE, camera=cam))
    assert scene_metadata(w)["camera"] == cam
    assert scene_to_dict(w)["camera"] == cam


# -- the published schema -------------------------------------------------------
def test_published_schema_file_matches_the_module():
    published = json.loads((ROOT / "scenes" / "stelkropp.schema.json").read_text())
    assert published == json.loads(json.dumps(scene_schema.SCHEMA)), \
        "run: .venv/bin/python scenes/make_scenes.py --schema"
    assert (ROOT / "scenes" / "stelkropp.schema.json").read_text() == scene_schema.schema_text()


def test_schema_is_valid_draft_2020_12():
    from jsonschema import Draft202012Validator
    Draft202012Validator.check_schema(scene_schema.SCHEMA)
    assert scene_schema.SCHEMA["$schema"] == "https://json-schema.org/draft/2020-12/schema"


def test_schema_choices_match_the_world():
    """The schema's choices are the ones the world accepts (physics/options.py) and nothing else."""
    from physics import options
    from physics.store import KINDS
    assert scene_schema.SOLVERS == list(options.SOLVERS) == physics.solvers_available()
    assert scene_schema.INTEGRATORS == list(options.INTEGRATORS)
    assert scene_schema.BROADPHASES == list(options.BROADPHASES)
    assert scene_schema.NARROWPHASES == list(options.NARROWPHASES)
    assert scene_schema.KINDS == list(KINDS)
    w = physics.World()
    for attr, names in (("integrator", scene_schema.INTEGRATORS), ("broadphase", scene_schema.BROADPHASES),
                        ("narrowphase", scene_schema.NARROWPHASES), ("solver", scene_schema.SOLVERS)):
        for name in names:
            setattr(w, attr, name)
            assert getattr(w, attr) == name
        with pytest.raises(ValueError):
            setattr(w, attr, "no_such_" + attr)


def test_docs_list_exactly_the_solvers_this_build_has():
    """docs/scene-format.md's world.solver row names every mode and no other (it once listed xpbd)."""
    import re
    doc = (ROOT / "docs" / "scene-format.md").read_text()
    row = next(line for line in doc.splitlines() if line.startswith("| `solver` |"))
    listed = re.findall(r"`([a-z_]+)`", row.split("|")[3].split("—")[0])
    assert listed == physics.solvers_available(), row


def test_schema_defaults_match_the_api():
    import inspect
    sig = inspect.signature(physics.World.add_body).parameters
    for key in ("kind", "angle", "angular_velocity", "density", "restitution", "friction"):
        assert sig[key].default == scene_schema.BODY_DEFAULTS[key], key
    wsig = inspect.signature(physics.World.__init__).parameters
    for key in ("dt", "solver", "integrator", "sleeping", "broadphase", "narrowphase"):
        assert wsig[key].default == scene_schema.WORLD_DEFAULTS[key], key
    assert list(wsig["gravity"].default) == scene_schema.WORLD_DEFAULTS["gravity"]
    assert math.isclose(scene_schema.WORLD_DEFAULTS["dt"], 1 / 60)


# -- the package's public face and its import direction ---------------------------
def test_physics_save_scene_is_public_and_writes_what_world_save_scene_writes(tmp_path):
    assert "save_scene" in physics.__all__ and "load_scene" in physics.__all__
    w = scene_from_dict(EXAMPLE)
    physics.save_scene(w, tmp_path / "a.json", name="n", description="d")
    w.save_scene(tmp_path / "b.json", name="n", description="d")
    save_scene(w, tmp_path / "c.json", name="n", description="d")
    texts = {(tmp_path / f).read_text() for f in ("a.json", "b.json", "c.json")}
    assert len(texts) == 1
    assert json.loads(texts.pop())["name"] == "n"
    assert w.metadata["name"] == "Pyramid 20"  # overrides go to the file, not the world


def test_metadata_is_a_plain_attribute_of_the_world():
    w = physics.World()
    assert w.metadata == {} and scene_metadata(w) is w.metadata
    w.metadata["name"] = "renamed"
    assert scene_to_dict(w)["name"] == "renamed"
    loaded = scene_from_dict(dict(EXAMPLE, camera={"center": [0.0, 1.0], "zoom": 9.0}))
    assert loaded.metadata == {"name": "Pyramid 20", "description": "210 boxes on static ground",
                               "camera": {"center": [0.0, 1.0], "zoom": 9.0}}


def _project_imports(name: str) -> set:
    """Modules of physics/ that module ``name`` imports anywhere (lazy imports too), resolved the
    way ../shared/tools/arch_check.py does: each target to the longest name that is a module, and
    a package's __init__ importing its own submodules is not an edge."""
    import ast
    path = _module_file(name)
    is_pkg = path.name == "__init__.py"
    parts = name.split(".") if is_pkg else name.split(".")[:-1]
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        targets = []
        if isinstance(node, ast.ImportFrom):
            base = parts[: len(parts) - node.level + 1] if node.level else []
            mod = ".".join(base + ([node.module] if node.module else []))
            targets = [mod] + [f"{mod}.{a.name}" for a in node.names]
        elif isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        for t in targets:
            while t and _module_file(t) is None:
                t = t.rpartition(".")[0]
            if t.startswith("physics") and t != name and not (is_pkg and t.startswith(name + ".")):
                out.add(t)
    return out


def _module_file(name: str):
    p = ROOT.joinpath(*name.split("."))
    if (p / "__init__.py").exists():
        return p / "__init__.py"
    return p.with_suffix(".py") if p.with_suffix(".py").exists() else None


def test_imports_run_one_way_world_never_reaches_the_scene_loader():
    """world.py may import only physics.scene.save, and nothing save reaches imports physics.world."""
    from_world = {m for m in _project_imports("physics.world") if m.startswith("physics.scene")}
    assert from_world == {"physics.scene.save"}, from_world
    seen, todo = set(), ["physics.scene.save"]
    while todo:
        name = todo.pop()
        if name not in seen:
            seen.add(name)
            todo += list(_project_imports(name))
    assert "physics.world" not in seen and "physics.scene.load" not in seen, sorted(seen)
    assert "physics.scene.dump" in seen  # the walk did follow save's imports
