"""Bad scene input: one exception type (SceneError) naming the file, each JSON path and reason,
and listing every problem, not just the first."""
import copy
import json

import pytest

import physics
from physics.scene import schema as scene_schema
from physics.scene import load_scene, scene_from_dict

BOX = {"box": [1, 1]}


def good():
    return {
        "format": "stelkropp.scene", "version": 1, "name": "ok",
        "world": {"gravity": [0, -10], "solver": "soft_step", "settings": {"substeps": 4}},
        "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [20, 1]}, "position": [0, -0.5]},
                   {"name": "a", "shape": BOX, "position": [0, 0.5]},
                   {"name": "b", "shape": {"circle": 0.5}, "position": [2, 0.5]}],
        "springs": [{"name": "s", "a": "a", "b": "b", "stiffness": 10}],
    }


def problems_of(data):
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(data, source="test.json")
    exc = info.value
    assert isinstance(exc, ValueError)  # SceneError is a ValueError: callers may catch either
    assert str(exc).startswith("test.json: ")
    for path, reason in exc.problems:  # every problem is in the message, with its path
        assert f"{path}: {reason}" in str(exc)
    return dict(exc.problems), str(exc)


def edit(fn):
    d = good()
    fn(d)
    return d


def test_good_scene_loads():
    assert len(scene_from_dict(good()).bodies) == 3


# (case, edit, JSON path, words expected in the reason)
CASES = [
    ("unknown format", lambda d: d.update(format="box2d.scene"), "format", "not a Stelkropp scene"),
    ("missing format", lambda d: d.pop("format"), "format", "missing"),
    ("unknown version", lambda d: d.update(version=3), "version", "unsupported version"),
    ("version as string", lambda d: d.update(version="1"), "version", "unsupported version"),
    ("position wrong type", lambda d: d["bodies"][1].update(position="0,0"), "bodies[1].position",
     "expected an array"),
    ("position too short", lambda d: d["bodies"][1].update(position=[0]), "bodies[1].position", "at least 2"),
    ("position too long", lambda d: d["bodies"][1].update(position=[0, 1, 2]), "bodies[1].position", "expected 2"),
    ("coordinate wrong type", lambda d: d["bodies"][1].update(position=[0, "1"]), "bodies[1].position[1]",
     "expected a number"),
    ("boolean is not a number", lambda d: d["bodies"][1].update(angle=True), "bodies[1].angle", "expected a number"),
    ("density wrong type", lambda d: d["bodies"][1].update(density="heavy"), "bodies[1].density",
     "expected a number"),
    ("sleeping wrong type", lambda d: d["world"].update(sleeping="yes"), "world.sleeping", "expected a boolean"),
    ("bodies not a list", lambda d: d.update(bodies={}), "bodies", "expected an array"),
    ("name wrong type", lambda d: d["bodies"][1].update(name=3), "bodies[1].name", "expected a string"),
    ("missing shape", lambda d: d["bodies"][1].pop("shape"), "bodies[1].shape", "required"),
    ("missing position", lambda d: d["bodies"][1].pop("position"), "bodies[1].position", "required"),
    ("missing bodies", lambda d: d.pop("bodies"), "bodies", "required"),
    ("missing stiffness", lambda d: d["springs"][0].pop("stiffness"), "springs[0].stiffness", "required"),
    ("missing spring b", lambda d: d["springs"][0].pop("b"), "springs[0].b", "required"),
    ("unknown body key", lambda d: d["bodies"][1].update(colour="red"), "bodies[1].colour", "unknown key"),
    ("unknown world key", lambda d: d["world"].update(gravty=[0, 1]), "world.gravty", "unknown key"),
    ("unknown top-level key", lambda d: d.update(bodys=[]), "bodys", "unknown key"),
    ("unknown shape", lambda d: d["bodies"][1].update(shape={"triangle": 1}), "bodies[1].shape.triangle",
     "unknown key"),
    ("two shapes", lambda d: d["bodies"][1].update(shape={"box": [1, 1], "circle": 1}), "bodies[1].shape",
     "exactly one"),
    ("empty shape", lambda d: d["bodies"][1].update(shape={}), "bodies[1].shape", "exactly one"),
    ("unknown kind", lambda d: d["bodies"][1].update(kind="solid"), "bodies[1].kind", "must be one of"),
    ("unknown integrator", lambda d: d["world"].update(integrator="verlet"), "world.integrator", "must be one of"),
    ("duplicate body name", lambda d: d["bodies"][2].update(name="a"), "bodies[2].name", "duplicate body name"),
    ("duplicate spring name", lambda d: d["springs"].append(dict(d["springs"][0])), "springs[1].name",
     "duplicate spring name"),
    ("dangling spring a", lambda d: d["springs"][0].update(a="nobody"), "springs[0].a", "no body named 'nobody'"),
    ("dangling spring b", lambda d: d["springs"][0].update(b="nobody"), "springs[0].b", "no body named 'nobody'"),
    ("spring to itself", lambda d: d["springs"][0].update(b="a"), "springs[0].b", "two different bodies"),
    ("negative density", lambda d: d["bodies"][1].update(density=-1), "bodies[1].density", "must be > 0"),
    ("zero density", lambda d: d["bodies"][1].update(density=0), "bodies[1].density", "must be > 0"),
    ("negative friction", lambda d: d["bodies"][1].update(friction=-0.1), "bodies[1].friction", "must be >= 0"),
    ("negative static friction", lambda d: d["bodies"][1].update(friction={"static": -1, "dynamic": 0.5}),
     "bodies[1].friction.static", "must be >= 0"),
    ("half a friction pair", lambda d: d["bodies"][1].update(friction={"static": 0.5}),
     "bodies[1].friction.dynamic", "required"),
    ("restitution below 0", lambda d: d["bodies"][1].update(restitution=-0.1), "bodies[1].restitution",
     "must be >= 0"),
    ("restitution above 1", lambda d: d["bodies"][1].update(restitution=1.5), "bodies[1].restitution",
     "must be <= 1"),
    ("negative stiffness", lambda d: d["springs"][0].update(stiffness=-5), "springs[0].stiffness", "must be >= 0"),
    ("negative box", lambda d: d["bodies"][1].update(shape={"box": [1, -1]}), "bodies[1].shape.box[1]",
     "must be > 0"),
    ("zero radius", lambda d: d["bodies"][2].update(shape={"circle": 0}), "bodies[2].shape.circle", "must be > 0"),
    ("too few sides", lambda d: d["bodies"][1].update(shape={"regular": {"sides": 2, "radius": 1}}),
     "bodies[1].shape.regular.sides", "must be >= 3"),
    ("fractional sides", lambda d: d["bodies"][1].update(shape={"regular": {"sides": 4.5, "radius": 1}}),
     "bodies[1].shape.regular.sides", "expected an integer"),
    ("non-convex polygon", lambda d: d["bodies"][1].update(shape={"polygon": [[0, 0], [2, 0], [1, 0.3], [1, 2]]}),
     "bodies[1].shape.polygon", "not convex"),
    ("self-intersecting polygon",
     lambda d: d["bodies"][1].update(shape={"polygon": [[0, 0], [1, 1], [1, 0], [0, 1]]}),
     "bodies[1].shape.polygon", "polygon"),
    ("collinear polygon", lambda d: d["bodies"][1].update(shape={"polygon": [[0, 0], [1, 0], [2, 0]]}),
     "bodies[1].shape.polygon", "zero area"),
    ("repeated vertex", lambda d: d["bodies"][1].update(shape={"polygon": [[0, 0], [1, 0], [1, 0], [0, 1]]}),
     "bodies[1].shape.polygon", "repeated"),
    ("too few vertices", lambda d: d["bodies"][1].update(shape={"polygon": [[0, 0], [1, 0]]}),
     "bodies[1].shape.polygon", "at least 3"),
    ("unknown solver", lambda d: d["world"].update(solver="magic"), "world.solver", "unknown solver 'magic'"),
    ("unknown setting", lambda d: d["world"]["settings"].update(warp=9), "world.settings.warp",
     "has no setting 'warp'"),
    ("setting out of range", lambda d: d["world"]["settings"].update(substeps=0), "world.settings.substeps",
     ">= 1"),
    ("setting wrong type", lambda d: d["world"]["settings"].update(substeps="four"), "world.settings.substeps",
     "must be a number"),
    ("fractional integer setting", lambda d: d["world"]["settings"].update(substeps=2.5),
     "world.settings.substeps", "integer"),
    ("top level not an object", lambda d: d.clear() or d.update(x=1), "format", "not a Stelkropp scene"),
]


@pytest.mark.parametrize("edit_fn,path,words", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_each_kind_of_bad_input(edit_fn, path, words):
    problems, message = problems_of(edit(edit_fn))
    assert path in problems, f"{path} not in {problems}"
    assert words in problems[path], problems[path]
    assert path in message


def test_top_level_array_is_refused():
    problems, _ = problems_of([1, 2])
    assert "a JSON object" in problems["$"]


def test_every_problem_is_listed_not_just_the_first():
    d = good()
    d["world"]["settings"]["warp"] = 1
    d["world"]["integrator"] = "verlet"
    d["bodies"][1].update(density=-1, colour="red", restitution=3)
    d["bodies"][2]["shape"] = {"polygon": [[0, 0], [2, 0], [1, 0.3], [1, 2]]}
    d["bodies"].append({"name": "a", "shape": BOX})  # duplicate and missing position
    d["springs"][0].update(a="ghost", stiffness=-1)
    problems, message = problems_of(d)
    expected = {"world.settings.warp", "world.integrator", "bodies[1].density", "bodies[1].colour",
                "bodies[1].restitution", "bodies[2].shape.polygon", "bodies[3].name", "bodies[3].position",
                "springs[0].a", "springs[0].stiffness"}
    assert set(problems) == expected
    assert message.splitlines()[0] == f"test.json: {len(expected)} problems in scene"


def test_one_mistake_is_reported_once():
    problems, _ = problems_of(edit(lambda d: d["bodies"][1].update(shape={"box": [1, -1]})))
    assert list(problems) == ["bodies[1].shape.box[1]"]  # not also by the shape builder


# -- files ----------------------------------------------------------------------
def write(tmp_path, text, name="scene.json"):
    p = tmp_path / name
    p.write_bytes(text.encode() if isinstance(text, str) else text)
    return p


def load_problems(path):
    with pytest.raises(physics.SceneError) as info:
        load_scene(path)
    assert str(path) in str(info.value).splitlines()[0]  # the message names the file
    assert info.value.path == str(path)
    return dict(info.value.problems), str(info.value)


@pytest.mark.parametrize("literal", ["NaN", "Infinity", "-Infinity", "1e999", "-1e400"])
def test_non_finite_numbers_are_refused(tmp_path, literal):
    text = json.dumps(good()).replace('"position": [0, 0.5]', f'"position": [0, {literal}]')
    problems, _ = load_problems(write(tmp_path, text))
    assert problems == {"bodies[1].position[1]": f"{literal} is not allowed: numbers must be finite"}


def test_every_non_finite_number_is_listed(tmp_path):
    text = json.dumps(good()).replace('"position": [0, 0.5]', '"position": [NaN, Infinity]')
    text = text.replace('"stiffness": 10', '"stiffness": -Infinity').replace('"circle": 0.5', '"circle": NaN')
    problems, _ = load_problems(write(tmp_path, text))
    assert set(problems) == {"bodies[1].position[0]", "bodies[1].position[1]", "springs[0].stiffness",
                             "bodies[2].shape.circle"}


def test_not_json(tmp_path):
    problems, _ = load_problems(write(tmp_path, '{"format": "stelkropp.scene",, }'))
    assert "not valid JSON (line 1 column" in problems["$"]


def test_not_utf8(tmp_path):
    problems, _ = load_problems(write(tmp_path, b'{"name": "\xff\xfe"}'))
    assert "not UTF-8" in problems["$"]


def test_missing_file(tmp_path):
    problems, _ = load_problems(tmp_path / "nope.json")
    assert "cannot read the file" in problems["$"]


def test_file_over_the_size_limit_is_refused_before_reading(tmp_path, monkeypatch):
    p = write(tmp_path, json.dumps(good()))
    monkeypatch.setattr(scene_schema, "MAX_FILE_BYTES", 100)
    monkeypatch.setattr("physics.scene.load.parse", lambda text: pytest.fail("parsed an oversized file"))
    problems, message = load_problems(p)
    assert "limited to" in problems["$"] and "MB" in problems["$"]


def test_real_size_limit_is_50_mb_and_1e6_bodies():
    assert scene_schema.MAX_FILE_BYTES == 50 * 1024 * 1024
    assert scene_schema.MAX_BODIES == 1_000_000


def test_too_many_bodies_is_refused_before_validating(tmp_path, monkeypatch):
    d = good()
    d["bodies"].append({"shape": "not even valid", "position": 0})
    monkeypatch.setattr(scene_schema, "MAX_BODIES", 3)
    problems, _ = load_problems(write(tmp_path, json.dumps(d)))
    assert problems == {"bodies": "4 bodies; scenes are limited to 3 bodies"}


def test_scene_error_is_exported_and_carries_problems():
    assert physics.SceneError is physics.errors.SceneError
    d = copy.deepcopy(good())
    d["version"] = 9
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert info.value.problems == [("version", "unsupported version (got 9); this build reads versions 1, 2")]
    assert info.value.path == "<dict>"


def test_no_eval_or_pickle_in_the_scene_modules():
    import inspect
    import pkgutil
    import importlib
    import physics.scene
    from physics import cli
    mods = [importlib.import_module(f"physics.scene.{m.name}") for m in pkgutil.iter_modules(physics.scene.__path__)]
    assert len(mods) >= 6, mods
    for mod in (physics.scene, *mods, cli):
        src = inspect.getsource(mod)
        for banned in ("eval(", "exec(", "import pickle", "pickle.load", "yaml.load", "marshal"):
            assert banned not in src, f"{banned} in {mod.__name__}"


@pytest.mark.parametrize("key", ["positio\n", "x y", "a.b", "1st", "name\r", "\n"])
def test_a_key_that_is_not_a_plain_name_is_quoted_in_the_path(key):
    """A problem's path writes a key that is not a plain identifier as ["..."] (JSON-escaped), so
    the path names exactly the key in the file: an unknown key "positio" + newline was written
    bodies[1].positio<newline> (a regex's "$" matches before a final newline), a path nothing in
    the document answers to (the scene fuzzer, seed 1, case 18763)."""
    d = good()
    d["bodies"][1][key] = [0, 0]
    problems, _ = problems_of(d)
    want = f'bodies[1][{json.dumps(key)}]'
    assert want in problems and "unknown key" in problems[want], problems
