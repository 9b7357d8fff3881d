"""Issue 20's loader and shape-constructor defects, each from its minimal repro: hostile input gives
one SceneError (or ValueError from a constructor) naming the field, never another exception."""
import json
import math

import pytest

import physics
from physics import Circle, Polygon
from physics.scene import load_scene, scene_from_dict
from physics.scene import schema as fmt

BIG = "1" * 400  # a 400-digit integer: valid JSON, beyond the largest float (1.8e308)


def good():
    return {"format": "stelkropp.scene", "version": 1,
            "world": {"gravity": [0, -10], "settings": {"substeps": 4}},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [20, 1]}, "position": [0, -0.5]},
                       {"name": "a", "shape": {"box": [1, 1]}, "position": [0, 0.5], "density": 1},
                       {"name": "b", "shape": {"circle": 0.5}, "position": [2, 0.5]}],
            "springs": [{"name": "s", "a": "a", "b": "b", "stiffness": 10}]}


def load_text(tmp_path, text):
    p = tmp_path / "hostile.json"
    p.write_text(text, encoding="utf-8", errors="surrogatepass")
    with pytest.raises(physics.SceneError) as info:
        load_scene(p)
    assert info.value.path == str(p) and str(p) in str(info.value).splitlines()[0]
    return dict(info.value.problems), str(info.value)


# -- item 3: integers beyond float range, in any numeric field ---------------------------------
# (field's JSON path, the good() text it replaces, its replacement)
NUMERIC_FIELDS = [
    ("bodies[1].position[0]", '"position": [0, 0.5], "density"', f'"position": [{BIG}, 0.5], "density"'),
    ("bodies[1].density", '"density": 1', f'"density": {BIG}'),
    ("bodies[1].density", '"density": 1', f'"density": -{BIG}'),
    ("bodies[2].shape.circle", '"circle": 0.5', f'"circle": {BIG}'),
    ("bodies[0].shape.box[0]", '"box": [20, 1]', f'"box": [{BIG}, 1]'),
    ("springs[0].stiffness", '"stiffness": 10', f'"stiffness": {BIG}'),
    ("world.gravity[1]", '"gravity": [0, -10]', f'"gravity": [0, -{BIG}]'),
    ("world.settings.substeps", '"substeps": 4', f'"substeps": {BIG}'),
    ("version", '"version": 1', f'"version": {BIG}'),
    ("bodies[1].position[0]", '"position": [0, 0.5], "density"', f'"position": [{"9" * 5000}, 0.5], "density"'),
]


@pytest.mark.parametrize("path,old,new", NUMERIC_FIELDS)
def test_integer_beyond_float_range_names_its_field(tmp_path, path, old, new):
    text = json.dumps(good())
    assert old in text
    problems, _ = load_text(tmp_path, text.replace(old, new, 1))
    assert path in problems, problems
    assert "beyond the range of a float" in problems[path] or "unsupported version" in problems[path]


def test_integer_beyond_float_range_in_scene_data():
    d = good()
    d["bodies"][1]["angle"] = 10 ** 400
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert "beyond the range of a float" in dict(info.value.problems)["bodies[1].angle"]


def test_largest_float_sized_integer_still_loads():
    d = good()
    d["bodies"][1]["velocity"] = [int(1e300), 0]  # huge, but a float holds it
    assert scene_from_dict(d).bodies[1].velocity == (1e300, 0.0)


@pytest.mark.parametrize("depth", [40, 500, 5000, 200_000])
def test_deep_nesting_is_a_scene_error_not_recursion(tmp_path, depth):
    text = json.dumps(good()).replace('"settings": {"substeps": 4}', '"settings": ' + "[" * depth + "]" * depth)
    problems, _ = load_text(tmp_path, text)
    (path, reason), = problems.items()
    assert "nested" in reason and (path.startswith("world.settings") or path == "$")


def test_deep_nesting_in_scene_data():
    deep = []
    for _ in range(3000):
        deep = [deep]
    with pytest.raises(physics.SceneError, match="levels deep"):
        scene_from_dict({**good(), "camera": {"center": deep}})


@pytest.mark.parametrize("make, words", [
    (lambda: Circle(1e200), "too large"),
    (lambda: Circle(10 ** 400), "beyond the range of a float"),
    (lambda: Circle(1e-200), "too small"),
    (lambda: Polygon.regular(math.inf, 1), "integer 3..64 sides"),
    (lambda: Polygon.regular(math.nan, 1), "integer 3..64 sides"),
    (lambda: Polygon.regular(10 ** 5000, 1), "integer 3..64 sides"),
    (lambda: Polygon.regular(6, 1e200), "too large"),
    (lambda: Polygon.box(1e200, 1), "too large"),
    (lambda: Polygon.box(1e100, 1), "too thin"),
    (lambda: Polygon.box(1e80, 1e80), "too large"),
    (lambda: Polygon.box("2", 1), "must be a number"),
    (lambda: Polygon([(0, 0), (1e300, 0), (0, 1e300)]), "too large"),
    (lambda: Polygon([("0", "0"), ("1", "0"), ("0", "1")]), "not text"),
    (lambda: Polygon([(10 ** 400, 0), (1, 0), (0, 1)]), "(x, y) pairs"),
])
def test_shape_constructors_give_a_clear_value_error(make, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)").replace(".", r"\.")) as info:
        make()
    assert type(info.value) is ValueError
    assert "zero area" not in str(info.value)


def test_shapes_just_inside_the_limits_still_build():
    assert Polygon.box(1e76, 1e76).area == pytest.approx(1e152)
    assert Polygon.box(1e11, 0.1).area == pytest.approx(1e10)  # area 4e-12 of its extent squared
    assert Circle(1e-50).radius == 1e-50 and Polygon.regular(64.0, 2).vertices.shape == (64, 2)


@pytest.mark.parametrize("shape, path, words", [
    ({"circle": 1e200}, "bodies[2].shape.circle", "too large"),
    ({"regular": {"sides": 6, "radius": 1e200}}, "bodies[2].shape.regular", "too large"),
    ({"box": [1e200, 1]}, "bodies[2].shape.box", "too large"),
])
def test_huge_shapes_in_a_scene_name_the_shape(shape, path, words):
    d = good()
    d["bodies"][2]["shape"] = shape
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert words in dict(info.value.problems)[path]


def test_density_that_overflows_the_mass_names_density():
    d = good()
    d["bodies"][1].update(shape={"box": [1e76, 1e76]}, density=1e9)
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert "cannot represent" in dict(info.value.problems)["bodies[1].density"]


def test_body_at_the_edge_of_float_range_loads_finite():
    """Shape coordinates are capped at shapes.MAX_COORDINATE (1e150), far below half an ulp of the
    largest float, so position + the centroid cannot overflow."""
    d = good()
    d["bodies"][2].update(shape={"circle": {"radius": 1, "offset": [1e150, -1e150]}},
                          position=[1.7976931348623157e308, -1.7976931348623157e308])
    d["springs"] = []
    assert all(math.isfinite(x) for x in scene_from_dict(d).bodies[2].center_of_mass)


def test_spring_whose_default_rest_length_overflows_names_rest_length():
    d = good()  # spring s joins a (near the origin) and b, moved to the far end of float range
    d["bodies"][2]["position"] = [1.7976931348623157e308, -1.7976931348623157e308]
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert "give rest_length" in dict(info.value.problems)["springs[0].rest_length"]
    d["springs"][0]["rest_length"] = 1.0
    assert scene_from_dict(d).springs[0].rest_length == 1.0


@pytest.mark.parametrize("where", ["name", "description", "body name", "key"])
def test_lone_surrogate_is_refused_with_its_path(tmp_path, where):
    text = json.dumps(good())
    text = {"name": text.replace('"version": 1', '"version": 1, "name": "bad\\ud800name"'),
            "description": text.replace('"version": 1', '"version": 1, "description": "\\udfff"'),
            "body name": text.replace('"name": "a"', '"name": "a\\ud83d"'),
            "key": text.replace('"density": 1', '"\\ud800": 1')}[where]
    problems, message = load_text(tmp_path, text)
    assert any("lone surrogate" in r for r in problems.values()), problems
    message.encode("utf-8")  # the message itself is printable


# -- item 6: duplicate keys --------------------------------------------------------------------
def test_duplicate_key_hiding_a_negative_density_does_not_load(tmp_path):
    text = json.dumps(good()).replace('"density": 1', '"density": -5, "density": 1')
    problems, _ = load_text(tmp_path, text)
    assert "duplicate key" in problems["bodies[1].density"]


@pytest.mark.parametrize("old,new,path", [
    ('"format": "stelkropp.scene"', '"format": "stelkropp.scene", "format": "stelkropp.scene"', "format"),
    ('"substeps": 4', '"substeps": 4, "substeps": 4', "world.settings.substeps"),
    ('"box": [1, 1]', '"box": [1, 1], "box": [2, 2]', "bodies[1].shape.box"),
    ('"a": "a"', '"a": "b", "a": "a"', "springs[0].a"),
])
def test_every_duplicate_key_is_an_error_with_its_path(tmp_path, old, new, path):
    text = json.dumps(good())
    assert old in text
    problems, _ = load_text(tmp_path, text.replace(old, new, 1))
    assert "duplicate key" in problems[path], problems


# -- item 8: error messages have a size limit ---------------------------------------------------
def test_two_million_bad_elements_give_a_short_message(tmp_path):
    d = good()
    d["bodies"][1]["shape"] = {"polygon": [[0, 0], [1, 0], [0, 1]]}
    text = json.dumps(d).replace("[[0, 0], [1, 0], [0, 1]]", "[" + ",".join(["true"] * 2_000_000) + "]")
    problems, message = load_text(tmp_path, text)
    assert len(message) < 50_000, len(message)
    assert len(problems) <= fmt.MAX_PROBLEMS and "bodies[1].shape.polygon" in problems


def test_many_problems_are_capped_and_said_to_be_more():
    d = good()
    d["bodies"] = [{"shape": {"box": [1, -1]}, "position": [0, i]} for i in range(1000)]
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d, source="many.json")
    assert len(info.value.problems) == fmt.MAX_PROBLEMS
    first = str(info.value).splitlines()[0]
    assert first == f"many.json: more than {fmt.MAX_PROBLEMS} problems in scene; the first {fmt.MAX_PROBLEMS} found:"
    assert info.value.problems[0][0] == "bodies[0].shape.box[1]"


@pytest.mark.parametrize("edit", [
    lambda d: d["bodies"][1].update(name="x" * 10_000_000),                  # a huge string in a reason
    lambda d: d["bodies"][1].update({"k" * 1_000_000: 1}),                   # a huge unknown key
    lambda d: d["world"].update(solver="s" * 1_000_000),                     # a huge unknown solver
    lambda d: d["world"]["settings"].update(substeps="four" * 1_000_000),   # a huge bad setting
    lambda d: d["bodies"][1].update(shape={"box": [[0] * 1_000_000, 1]}),   # a huge wrong-type value
    lambda d: d.update(format="f" * 1_000_000),
])
def test_each_reason_and_path_is_clipped(edit):
    d = good()
    d["bodies"].append({"name": "x" * 10_000_000, "shape": {"box": [1, 1]}, "position": [5, 5]})
    edit(d)
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert len(str(info.value)) < 5_000, str(info.value)[:300]


@pytest.mark.parametrize("key", [3, (1, 2), None, 2.5])
def test_non_string_keys_in_scene_data_are_named(key):
    d = good()
    d["bodies"][1][key] = 1
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(d)
    assert any("keys must be strings" in r for _, r in info.value.problems), info.value.problems
