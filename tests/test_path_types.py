"""Scene paths may be str, bytes or os.PathLike (save_scene with a bytes path raised an internal
TypeError); anything else is refused with a TypeError that says what a path must be."""
import os

import pytest

import physics


def _world():
    w = physics.World()
    w.add_body(physics.Circle(0.5), position=(1, 2), name="ball")
    return w


def test_bytes_paths_save_and_load(tmp_path):
    p = bytes(tmp_path / "bytes.json")
    _world().save_scene(p)
    assert physics.load_scene(p).body("ball").position == (1.0, 2.0)
    odd = os.fsencode(tmp_path) + b"/caf\xe9.json"  # not UTF-8: decoded with surrogateescape and back
    physics.save_scene(_world(), odd)
    assert os.path.exists(odd) and physics.load_scene(odd).body("ball").position == (1.0, 2.0)


@pytest.mark.parametrize("path", [3, 3.5, None, ["a.json"]])
def test_other_types_are_refused_clearly(path):
    with pytest.raises(TypeError, match="path: expected a str, bytes or os.PathLike"):
        _world().save_scene(path)
    with pytest.raises(TypeError, match="path: expected a str, bytes or os.PathLike"):
        physics.load_scene(path)
