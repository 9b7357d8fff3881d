"""The scene's ``sandbox`` section (lasers and tracers, app data like a body's colour): schema,
the check that names refer to bodies, the round trip through world.metadata, and files without
it loading as before."""
from __future__ import annotations

import json

import pytest

import physics
from physics.scene import scene_from_dict, scene_metadata, scene_to_dict

BODIES = [{"name": "g", "kind": "static", "shape": {"box": [4, 1]}, "position": [0, 0]},
          {"shape": {"circle": 0.5}, "position": [0, 3]}]


def scene(sandbox=None):
    data = {"format": "stelkropp.scene", "version": 2, "bodies": json.loads(json.dumps(BODIES))}
    if sandbox is not None:
        data["sandbox"] = sandbox
    return data


def test_round_trip_through_metadata():
    w = scene_from_dict(scene({"lasers": [{"body": "g", "point": [0.5, 0], "angle": 1.0},
                                          {"body": None, "point": [3, 3]}],
                               "tracers": [{"body": "g", "point": [0, 0]}]}))
    g, ball = w.bodies
    assert w.metadata["lasers"] == [{"body": g.id, "point": (0.5, 0), "angle": 1.0},
                                    {"body": None, "point": (3, 3), "angle": 0.0}]
    w.metadata["tracers"].append({"body": ball.id, "point": (0.1, 0.2)})   # an unnamed body: named on save
    out = scene_to_dict(w, scene_metadata(w))
    name = out["bodies"][1]["name"]
    assert name and out["sandbox"]["tracers"][1] == {"body": name, "point": [0.1, 0.2]}
    again = scene_to_dict(scene_from_dict(out), None)
    assert again["sandbox"] == out["sandbox"]


def test_names_must_be_bodies_and_fields_are_checked():
    with pytest.raises(physics.SceneError) as e:
        scene_from_dict(scene({"lasers": [{"body": "nope", "point": [0, 0]}], "tracers": [{"point": [1, 2]}],
                               "extra": 1}))
    msg = str(e.value)
    assert "sandbox.lasers[0].body: no body named 'nope'" in msg
    assert "sandbox.tracers[0].body: required field is missing" in msg and "extra" in msg


def test_scenes_without_the_section_load_and_save_without_it():
    w = scene_from_dict(scene())
    assert "lasers" not in w.metadata and "sandbox" not in scene_to_dict(w, None)
    w.remove(w.bodies[0])
    w.metadata["lasers"] = [{"body": 1, "point": (0, 0), "angle": 0.0}]      # its body is gone
    assert "sandbox" not in scene_to_dict(w, None)
