"""Property-based scene files (issue 9): hypothesis writes random scene dicts, valid and broken.

Broken ones raise only physics.SceneError, with a message that names a JSON path; valid ones run
200 steps finite, conserve linear momentum in zero gravity without static bodies (1e-9 relative)
and never gain kinetic energy with e <= 1 and no springs or external forces (tolerance below).
"""
import copy
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import physics
from physics.scene import scene_from_dict

HEADER = {"format": "stelkropp.scene", "version": 1}
# kinetic energy may rise by at most this fraction of its largest value so far plus 1 mJ: the
# soft contacts' push-out (capped at push_out_speed) can turn overlap into a little motion
KE_RISE = 0.02
KE_ABS = 1e-3

coord = st.floats(-6.0, 6.0, allow_nan=False)
size = st.floats(0.2, 1.5, allow_nan=False)
shape = st.one_of(
    st.tuples(size, size).map(lambda wh: {"box": [wh[0], wh[1]]}),
    st.floats(0.1, 0.8).map(lambda r: {"circle": r}),
    st.tuples(st.integers(3, 8), st.floats(0.15, 0.8)).map(lambda t: {"regular": {"sides": t[0], "radius": t[1]}}),
)


@st.composite
def bodies(draw, n_min=1, n_max=8, restitution=st.floats(0.0, 1.0)):
    n = draw(st.integers(n_min, n_max))
    out = []
    for i in range(n):
        out.append({
            "name": f"b{i}", "shape": draw(shape),
            "position": [draw(coord) + 3.0 * i, draw(coord)],
            "angle": draw(st.floats(-3.2, 3.2)),
            "velocity": [draw(st.floats(-8, 8)), draw(st.floats(-8, 8))],
            "angular_velocity": draw(st.floats(-4, 4)),
            "density": draw(st.floats(0.2, 5.0)),
            "restitution": draw(restitution),
            "friction": draw(st.floats(0.0, 1.0)),
        })
    return out


def zero_g_scene(bs, solver="soft_step"):
    return {**HEADER, "world": {"gravity": [0.0, 0.0], "solver": solver, "sleeping": False}, "bodies": bs}


def run(world, steps, each=None):
    for k in range(steps):
        world.step()
        if each:
            each(k)


def finite(world):
    n = world._bodies.n
    B = world._bodies.view
    return bool(np.all(np.isfinite(B.x[:n])) and np.all(np.isfinite(B.v[:n]))
                and np.all(np.isfinite(B.q[:n])) and np.all(np.isfinite(B.w[:n])))


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(bodies())
def test_valid_zero_gravity_scene_is_finite_and_conserves_momentum(bs):
    """Regime: 1-8 random dynamic bodies (boxes, discs, regular polygons), zero gravity, no static
    bodies, no springs, e in [0, 1], 200 steps of soft_step.

    Outcome: finite; linear momentum equal to its start within 1e-9 of the largest of |p0|,
    sum m|v0| (the scale of the momenta exchanged); kinetic energy never above the largest value so
    far by more than 2% + 1 mJ."""
    w = scene_from_dict(zero_g_scene(bs))
    p0 = np.array(w.linear_momentum())
    scale = max(float(np.hypot(*p0)), sum(b.mass * math.hypot(*b.velocity) for b in w.bodies), 1e-12)
    peak = [w.kinetic_energy()]

    def each(k):
        ke = w.kinetic_energy()
        assert ke <= peak[0] * (1 + KE_RISE) + KE_ABS, (k, ke, peak[0])
        peak[0] = max(peak[0], ke)

    run(w, 200, each)
    assert finite(w)
    assert np.hypot(*(np.array(w.linear_momentum()) - p0)) <= 1e-9 * scale


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(bodies(n_max=6), st.sampled_from(["soft_step", "sequential_impulse"]))
def test_valid_scene_with_ground_runs_200_steps_finite(bs, solver):
    """Regime: random bodies above a static ground in gravity, springs between neighbours, in
    soft_step or sequential_impulse.  Outcome: 200 steps finite, no SimulationError, nothing
    falls more than 1 m through the ground."""
    for b in bs:
        b["position"][1] = abs(b["position"][1]) + 2.0
    data = {**HEADER, "world": {"solver": solver},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [80.0, 1.0]}, "position": [0, -0.5]}] + bs,
            "springs": [{"a": bs[i]["name"], "b": bs[i + 1]["name"], "stiffness": 50.0, "damping": 1.0}
                        for i in range(len(bs) - 1)]}
    w = scene_from_dict(data)
    run(w, 200)
    assert finite(w)
    assert all(b.center_of_mass[1] > -1.0 for b in w.bodies)


# -- broken scenes ----------------------------------------------------------------------------
BREAKS = [
    ("$", lambda d: d.pop("format")),
    ("version", lambda d: d.__setitem__("version", 99)),
    ("bodies", lambda d: d.__setitem__("bodies", "many")),
    ("bodies[0]", lambda d: d["bodies"][0].pop("shape")),
    ("bodies[0]", lambda d: d["bodies"][0].pop("position")),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("position", [float("nan"), 0])),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("position", [1e400, 0])),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("density", -1)),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("density", 0)),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("density", 1e300)),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("restitution", 2.0)),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("friction", -0.5)),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("kind", "ghost")),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("shape", {"box": [1, -1]})),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("shape", {"polygon": [[0, 0], [1, 0], [2, 0]]})),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("shape", {"polygon": [[0, 0], [2, 0], [1, 0.2], [1, 2]]})),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("shape", {"circle": 0})),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("shape", {"box": [1, 1], "circle": 1})),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("velocity", "fast")),
    ("bodies[0]", lambda d: d["bodies"][0].__setitem__("unknown_field", 1)),
    ("bodies", lambda d: d["bodies"].append(copy.deepcopy(d["bodies"][0]))),  # duplicate name
    ("springs[0]", lambda d: d.__setitem__("springs", [{"a": "b0", "b": "nobody"}])),
    ("springs[0]", lambda d: d.__setitem__("springs", [{"a": "b0", "b": None, "stiffness": -5}])),
    ("springs[0]", lambda d: d.__setitem__("springs", [{"a": "b0", "b": "b0"}])),
    ("world", lambda d: d.__setitem__("world", {"solver": "magic"})),
    ("world", lambda d: d.__setitem__("world", {"dt": 0})),
    ("world", lambda d: d.__setitem__("world", {"gravity": [0, "down"]})),
    ("world", lambda d: d.__setitem__("world", {"settings": {"substeps": -3}})),
    ("world", lambda d: d.__setitem__("world", {"integrator": "leapfrog"})),
]


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(bodies(n_max=3), st.lists(st.sampled_from(range(len(BREAKS))), min_size=1, max_size=3, unique=True))
def test_broken_scene_raises_scene_error_naming_a_path(bs, which):
    """Regime: a valid random scene with 1-3 of 29 kinds of damage (missing/extra fields, NaN,
    overflowing numbers, negative or extreme density, bad shapes, dangling or self springs,
    unknown solver, bad settings).

    Outcome: scene_from_dict raises physics.SceneError and nothing else; its message names the
    source and every problem carries a JSON path and a non-empty reason; no problem is put at the
    root ("$": only for data that is not an object); a damage still in the data is named by a
    problem at (or under) the damaged part's path -- a bad header (not a scene, another version)
    is reported alone: then exactly the header's fields."""
    data = zero_g_scene(bs)
    applied = []
    for i in which:
        try:
            BREAKS[i][1](data)
        except (KeyError, TypeError, AttributeError, IndexError):
            continue  # an earlier break removed what this one edits
        applied.append(BREAKS[i][0])
    try:
        scene_from_dict(data, source="prop.json")
    except physics.SceneError as err:
        assert "prop.json" in str(err)
        assert err.problems, str(err)
        for path, reason in err.problems:
            assert isinstance(path, str) and path and isinstance(reason, str) and reason.strip()
        paths = [p for p, _ in err.problems]
        assert "$" not in paths, paths
        header = {"$": "format", "version": "version"}
        if any(r in header for r in applied):
            assert sorted(paths) == sorted({header[r] for r in applied if r in header}), (applied, paths)
        else:
            # a later break that replaced the whole body list took the earlier bodies[0] damage with it
            live = [r for r in applied if isinstance(data.get("bodies"), list) or not r.startswith("bodies[")]
            named = [r for r in live if any(p == r or p.startswith((r + ".", r + "[")) for p in paths)]
            assert named, (applied, paths)
    except Exception as exc:  # noqa: BLE001 -- the property: nothing but SceneError escapes
        pytest.fail(f"{type(exc).__name__} escaped scene_from_dict: {exc}")
    else:
        pytest.fail(f"broken scene {[BREAKS[i][0] for i in which]} was accepted")


@settings(max_examples=60, deadline=None)
@given(st.recursive(st.none() | st.booleans() | st.floats() | st.integers() | st.text(max_size=8),
                    lambda c: st.lists(c, max_size=4) | st.dictionaries(st.text(max_size=8), c, max_size=4),
                    max_leaves=20))
def test_arbitrary_json_raises_only_scene_error(data):
    """Regime: arbitrary JSON-like values (not scenes at all).  Outcome: SceneError, nothing else."""
    with pytest.raises(physics.SceneError):
        scene_from_dict(data)
