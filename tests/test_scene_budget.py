"""The work a scene may ask for is bounded and counted first (physics/scene/budget.py), and the
cheap checks run before the expensive ones: a body that is refused anyway is never decomposed,
and huge files are refused by their counts before any value is walked.  How long validation takes
at the limits is measured by ``python -m bench.scene_limits`` (a benchmark, not a timed test)."""
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import physics
from physics.scene import scene_from_dict

ROOT = Path(__file__).resolve().parent.parent


def star(n):
    a = np.linspace(0, 2 * math.pi, n, endpoint=False)
    r = np.where(np.arange(n) % 2 == 0, 1.0, 0.6)
    return np.c_[r * np.cos(a), r * np.sin(a)].tolist()


def scene(bodies, springs=()):
    return {"format": "stelkropp.scene", "version": 2, "bodies": bodies, "springs": list(springs)}


def refused(data):
    with pytest.raises(physics.SceneError) as info:
        scene_from_dict(data)
    return dict(info.value.problems)


@pytest.fixture
def no_decompose(monkeypatch):
    def fail(outline):
        raise AssertionError("decomposed an outline of a scene that is refused anyway")
    monkeypatch.setattr("physics.scene.shapes.decompose", fail)


@pytest.mark.parametrize("field, value, words", [
    ("density", -1, "must be > 0"),
    ("kind", "floating", "must be one of"),
    ("velocity", [0, "fast"], "expected a number"),
])
def test_a_body_with_a_bad_field_is_refused_before_it_is_decomposed(no_decompose, field, value, words):
    body = {"shape": {"concave": star(10_000)}, "position": [0, 0], field: value}
    problems = refused(scene([body]))
    assert any(p.startswith(f"bodies[0].{field}") and words in r for p, r in problems.items()), problems


def test_a_body_with_a_duplicate_name_is_not_decomposed(no_decompose):
    bodies = [{"name": "a", "shape": {"circle": 1}, "position": [0, 0]},
              {"name": "a", "shape": {"concave": star(10_000)}, "position": [5, 0]}]
    assert "duplicate body name" in refused(scene(bodies))["bodies[1].name"]


def test_too_much_work_is_refused_at_its_field_before_anything_is_built(no_decompose):
    bodies = [{"shape": {"concave": star(10_000)}, "position": [3.0 * i, 0]} for i in range(6)]
    problems = refused(scene(bodies))
    (path, reason), = problems.items()
    assert path == "bodies[4].shape.concave"   # 4 x 60,000 units fit in 250,000, the fifth does not
    assert "more work than a scene may" in reason and "250,000" in reason


@pytest.mark.parametrize("make, path", [
    (lambda: scene([{"shape": {"circle": 1}, "position": [i, 0]} for i in range(50_000)]), "bodies[41666].shape"),
    (lambda: scene([{"shapes": [{"box": [1, 1]}] * 30_000, "position": [0, 0]}]), "bodies[0].shapes[27777]"),
    (lambda: scene([{"name": "a", "shape": {"circle": 1}, "position": [0, 0]}],
                   [{"a": "a", "b": None, "stiffness": 1}] * 70_000), "springs[62498]"),
])
def test_counts_of_cheap_things_are_bounded_too(make, path):
    problems = refused(make())
    assert list(problems) == [path]


def test_the_largest_allowed_chain_and_outline_load():
    w = scene_from_dict(scene([
        {"kind": "static", "shape": {"chain": {"points": [[float(-i), 0.0] for i in range(100_000)]}}, "position": [0, 0]},
        {"shape": {"concave": star(10_000)}, "position": [0, 5]}]))
    assert len(w.bodies[0].fixtures) == 99_999 and len(w.bodies[1].fixtures) > 1000


def _validate(path):
    return subprocess.run([sys.executable, "-m", "physics", "validate", str(path)], cwd=ROOT,
                          capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize("kind", ["outlines", "circles", "chain"])
def test_a_big_file_validates(tmp_path, kind):
    """Files near the limit of what a scene may ask for (or beyond it): validate answers, with the
    refusal where the work runs over (bench.scene_limits times it: the 10,000-vertex outline alone
    took four minutes)."""
    if kind == "outlines":
        data = scene([{"shape": {"concave": star(10_000)}, "position": [3.0 * i, 0]} for i in range(4)])
    elif kind == "circles":
        data = scene([{"shape": {"circle": 0.5}, "position": [i % 1000, i // 1000]} for i in range(200_000)])
    else:
        data = scene([{"kind": "static", "position": [0, 0],
                       "shape": {"chain": {"points": [[float(-i), math.sin(i)] for i in range(100_000)]}}}])
    p = tmp_path / "big.json"
    p.write_text(json.dumps(data))
    run = _validate(p)
    assert (run.returncode == 0) == (kind != "circles"), run.stdout[-500:]


@pytest.mark.parametrize("extra, path, words", [
    ({"junk": [[0, 1]] * 2_000_000}, "junk", "no list or object in a scene may have more than 1,000,000"),
    ({"junk": [[[0]] * 100] * 20_000}, "junk", "more than 1,500,000 values"),
    ({"junk": {f"k{i}": 0 for i in range(1_100_000)}}, "junk", "1,100,000 keys"),
])
def test_huge_values_outside_the_counted_lists_are_refused_without_walking_them(extra, path, words):
    data = {**scene([{"shape": {"circle": 1}, "position": [0, 0]}]), **extra}
    problems = refused(data)
    assert any(p.startswith(path) and words in r for p, r in problems.items()), problems


def test_a_world_too_big_for_a_scene_file_is_refused_when_saved(tmp_path):
    w = physics.World()
    w.add_body(physics.Chain([(float(-i), 0.0) for i in range(100_000)]), kind="static")
    w.add_body(physics.Chain([(float(-i), 5.0) for i in range(100_000)]), kind="static")
    w.add_body(physics.Chain([(float(-i), 9.0) for i in range(100_000)]), kind="static")
    with pytest.raises(ValueError, match=r"bodies\[2\].shape.chain: the scene asks for more work"):
        w.save_scene(tmp_path / "big.json")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
@pytest.mark.parametrize("kind", ["one long chain", "a million bodies", "one huge unknown list"])
def test_a_file_at_the_size_limit_is_refused_by_its_counts(tmp_path, kind):
    """Just under 50 MB of the densest JSON: parsed (json's C number parsing unless a literal
    could overflow), then refused by the counts before any value is walked."""
    head = '{"format": "stelkropp.scene", "version": 2, '
    if kind == "one long chain":
        body = '{"kind": "static", "position": [0, 0], "shape": {"chain": {"points": [' + \
               ",".join(["[0.25,1.5]"] * 4_600_000) + "]}}}"
        text = head + '"bodies": [' + body + "]}"
    elif kind == "a million bodies":
        text = head + '"bodies": [' + ",".join(['{"shape":{"circle":1},"position":[0,0]}'] * 1_000_000) + "]}"
    else:
        text = head + '"bodies": [], "junk": [' + ",".join(["0"] * 20_000_000) + "]}"
    assert len(text) < 50 * 2 ** 20
    p = tmp_path / "limit.json"
    p.write_text(text)
    run = _validate(p)
    assert run.returncode == 1, run.stdout[-300:]
    assert "more than" in run.stdout or "more work" in run.stdout, run.stdout[-300:]
