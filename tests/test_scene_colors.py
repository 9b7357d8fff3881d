"""A body's optional sandbox colour in the scene format (issue 16, "per-body colours"): "#rrggbb",
kept beside the world (world.metadata["colors"], by body id) and never in the physics core;
saved and loaded back exactly; a bad value is refused naming its field."""
from __future__ import annotations

import json

import pytest

import physics
from physics.scene import load_scene, save_scene, scene_from_dict, scene_to_dict
from physics.scene import schema as scene_schema


def scene(**colors):
    """Ground and two boxes; ``colors``: body name -> its "color" value."""
    bodies = [{"name": "ground", "kind": "static", "shape": {"box": [20, 1]}, "position": [0, -0.5]},
              {"name": "a", "shape": {"box": [1, 1]}, "position": [0, 0.5]},
              {"name": "b", "shape": {"circle": 0.5}, "position": [2, 0.5]}]
    for b in bodies:
        if b["name"] in colors:
            b["color"] = colors[b["name"]]
    return {"format": "stelkropp.scene", "version": 2, "bodies": bodies}


def test_round_trip_with_colours(tmp_path):
    w = scene_from_dict(scene(a="#e07a5f", ground="#4A5361"))
    ground, a, b = w.bodies
    assert w.metadata["colors"] == {ground.id: "#4a5361", a.id: "#e07a5f"}   # stored lower case
    d = scene_to_dict(w)
    assert [x.get("color") for x in d["bodies"]] == ["#4a5361", "#e07a5f", None]
    path = tmp_path / "c.json"
    save_scene(w, path)
    again = load_scene(path)
    assert scene_to_dict(again) == d
    assert json.loads(path.read_text())["bodies"][1]["color"] == "#e07a5f"
    assert not hasattr(a, "color")          # the core's body knows nothing of colours


def test_round_trip_without_colours(tmp_path):
    w = scene_from_dict(scene())
    assert "colors" not in w.metadata
    d = scene_to_dict(w)
    assert all("color" not in x for x in d["bodies"])
    save_scene(w, tmp_path / "n.json")
    assert scene_to_dict(load_scene(tmp_path / "n.json")) == d


def test_colour_does_not_change_the_physics():
    plain, coloured = scene_from_dict(scene()), scene_from_dict(scene(a="#81b29a", b="#f2cc8f"))
    for w in (plain, coloured):
        for _ in range(30):
            w.step()
    assert [tuple(x.position) for x in plain.bodies] == [tuple(x.position) for x in coloured.bodies]


@pytest.mark.parametrize("bad,reason", [
    ("red", 'must look like "#e07a5f" (pattern ^#[0-9a-fA-F]{6}$); got "red"'),
    ("#e07a5", 'must look like "#e07a5f"'),
    ("#e07a5fff", 'must look like "#e07a5f"'),
    ("#gg7a5f", 'must look like "#e07a5f"'),
    ([1, 0, 0], "expected a string, got an array"),
])
def test_bad_colour_names_the_field(bad, reason):
    data = scene(b=bad)
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(data, source="bad.json")
    msg = str(info.value)
    assert "bodies[2].color: " in msg and reason in msg, msg
    assert len(info.value.problems) == 1, info.value.problems


def test_schema_documents_the_colour():
    prop = scene_schema.SCHEMA["$defs"]["body"]["properties"]["color"]
    assert prop["type"] == "string" and prop["pattern"] == scene_schema.COLOR_PATTERN
    from jsonschema import Draft202012Validator
    v = Draft202012Validator(scene_schema.SCHEMA)
    assert v.is_valid(scene(a="#0aF09b")) and not v.is_valid(scene(a="0af09b"))
