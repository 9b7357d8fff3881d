"""The layout's promises (docs/internals.md): layers import downward only, names come from
physics/options.py, settings reach the kernels through the step's records, handles cannot be
desynchronised from the arrays, and the step profiles itself."""
import ast
from pathlib import Path

import numpy as np
import pytest

import physics
from physics import options
from physics.collision import broadphase
from physics.collision.narrowphase import METHODS as NARROW_METHODS
from physics.solvers.classic.integrators import METHODS as INTEGRATOR_METHODS

PHYSICS = Path(physics.__file__).resolve().parent

# a package may import only packages of the same or a lower layer (index)
LAYERS = [
    {"_jit", "threads", "options", "errors", "validate", "settings", "joint_params"},
    {"store", "geometry"},
    {"collision"},
    {"constraints"},
    {"solvers"},
    {"step"},
]


def layer_of(module: str):
    top = module.split(".")[1] if module.startswith("physics.") else None
    for i, names in enumerate(LAYERS):
        if top in names:
            return i
    return None  # the public face (world, body, ...), scene and cli: above every layer


def imports_of(path: Path):
    """Modules a file imports (``from .. import x`` counts as importing ``physics.x``)."""
    parts = list(path.relative_to(PHYSICS.parent).with_suffix("").parts)
    pkg = parts[:-1]  # the package the file is in (for __init__.py: that package itself)
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            base = pkg[: len(pkg) - node.level + 1] if node.level else []
            mod = ".".join(base + ([node.module] if node.module else []))
            if node.module:
                yield mod
            else:
                for a in node.names:
                    yield f"{mod}.{a.name}"
        elif isinstance(node, ast.Import):
            for a in node.names:
                yield a.name


def test_layers_import_downward_only():
    wrong = []
    for path in PHYSICS.rglob("*.py"):
        mod = ".".join(path.relative_to(PHYSICS.parent).with_suffix("").parts)
        mine = layer_of(mod)
        if mine is None:
            continue
        for target in imports_of(path):
            if not target.startswith("physics"):
                continue
            theirs = layer_of(target)
            if theirs is None or theirs > mine:
                wrong.append(f"{mod} imports {target}")
    assert wrong == []


def test_names_come_from_options():
    assert tuple(physics.solvers_available()) == options.SOLVERS
    assert broadphase.METHODS == options.BROADPHASES
    assert tuple(NARROW_METHODS) == options.NARROWPHASES
    assert tuple(INTEGRATOR_METHODS) == options.INTEGRATORS
    assert set(options.SOLVER_SUMMARIES) == set(options.SOLVERS)
    w = physics.World()
    for attr, names in (("solver", options.SOLVERS), ("integrator", options.INTEGRATORS),
                        ("broadphase", options.BROADPHASES), ("narrowphase", options.NARROWPHASES)):
        for name in names:
            setattr(w, attr, name)
        with pytest.raises(ValueError, match=attr.replace("phase", " phase").split()[0]):
            setattr(w, attr, "no-such-" + attr)


def falling_box(**world):
    w = physics.World(**world)
    w.add_body(physics.Polygon.box(10, 1), kind="static", position=(0, -0.5))
    b = w.add_body(physics.Polygon.box(1, 1), position=(0, 0.6), angle=0.3)
    return w, b


def run(w, steps=60):
    for _ in range(steps):
        w.step()
    return w.state()


def test_a_setting_assigned_mid_run_reaches_the_kernel():
    # the parameter record is reloaded when a value changes: assigning substeps after 10 steps
    # must give the run of a world created with it from the start of step 11
    a, _ = falling_box()
    b, _ = falling_box()
    run(a, 10)
    run(b, 10)
    a.settings["substeps"] = 8
    b2, _ = falling_box(settings={"substeps": 8})
    ref, _ = falling_box()
    assert not np.array_equal(run(a, 50)["position"], run(b, 50)["position"])
    # and switching back restores the default's behaviour exactly
    c, _ = falling_box()
    run(c, 10)
    c.settings["substeps"] = 8
    c.settings["substeps"] = 4
    assert np.array_equal(run(c, 50)["position"], run(ref, 60)["position"])


def test_world_tolerances_are_validated_and_reach_the_step():
    w, box = falling_box()
    for field in ("linear_slop", "speculative_distance", "sleep_linear", "sleep_angular", "time_to_sleep"):
        for bad in (float("nan"), -1.0, None):
            with pytest.raises(ValueError, match=field):
                setattr(w, field, bad)
    # a larger speculative distance changes the contacts the narrow phase keeps
    w.speculative_distance = 0.5
    w.step()
    assert w._pipeline.ctx.get("spec") == 0.5


def test_body_shape_and_spring_bodies_are_read_only():
    w, box = falling_box()
    other = w.add_body(physics.Circle(0.5), position=(3, 3))
    sp = w.add_spring(box, other, stiffness=10)
    with pytest.raises(AttributeError):
        box.shape = physics.Circle(1.0)
    with pytest.raises(AttributeError):
        sp.body_a = other
    with pytest.raises(AttributeError):
        sp.body_b = box


def test_set_shape_updates_mass_and_geometry_about_the_same_origin():
    w, box = falling_box()
    origin, m1 = box.position, box.mass
    box.set_shape(physics.Polygon([(0, 0), (2, 0), (2, 1), (0, 1)]))  # origin at a corner now
    assert box.position == pytest.approx(origin)
    assert box.mass == pytest.approx(2 * m1)
    assert box.center_of_mass == pytest.approx(box.local_to_world((1.0, 0.5)))
    assert box.inertia == pytest.approx(2.0 * (4 + 1) / 12)
    assert w.query_point(box.local_to_world((1.9, 0.9))) is box
    with pytest.raises(ValueError, match="shape"):
        box.set_shape("a box")
    assert box.mass == pytest.approx(2 * m1)


def test_profile_covers_every_stage_of_the_last_step():
    w, _ = falling_box(sleeping=False)
    run(w, 5)
    p = w.profile
    stages = ("begin", "broadphase", "narrowphase", "solve", "islands", "finish")
    assert set(stages) | {"step"} == set(p)
    assert all(p[s] > 0 for s in stages)
    assert p["step"] == pytest.approx(sum(p[s] for s in stages))


def test_state_matches_the_handles():
    w, _ = falling_box()
    w.add_body(physics.Circle(0.3, offset=(0.2, 0.1)), position=(2, 2), angle=0.7)
    run(w, 30)
    S = w.state()
    assert not S.flags.writeable
    for row, b in zip(S, w.bodies):
        assert row["id"] == b.id
        assert tuple(row["position"]) == pytest.approx(b.position, abs=1e-12)
        assert row["angle"] == b.angle and tuple(row["velocity"]) == b.velocity
        assert row["angular_velocity"] == b.angular_velocity and bool(row["awake"]) == b.awake
