"""Pins of the extreme scenarios (bench/scenarios/extremes): a digest of every scenario's initial
world and run lengths, so that editing a scenario -- which changes what both the reliability
table and tests/extremes measure -- fails tests/extremes/test_pinned_scenarios.py until the pin
is updated on purpose:

    .venv/bin/python -m tests.extreme_pins          # rewrites tests/data/extreme_scenarios.json

The digest is SHA-256 over a canonical JSON description read through the public API (every
body's name, kind, shape, pose, velocity, mass, inertia, material; every spring; the world's
gravity, dt, solver, integrator, phases, sleeping and settings), built in soft_step.
"""
from __future__ import annotations

import hashlib
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RECORD = ROOT / "tests" / "data" / "extreme_scenarios.json"
SOLVER = "soft_step"


def _plain(v):
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if hasattr(v, "tolist"):
        return _plain(v.tolist())
    if isinstance(v, float) or type(v).__name__.startswith("float"):
        return repr(float(v))  # exact: repr round-trips every double
    return v


def describe(world) -> dict:
    """The world as plain data, from public accessors only."""
    index = {id(b): i for i, b in enumerate(world.bodies)}
    bodies = [dict(name=b.name, kind=b.kind, shape=b.shape.spec, position=b.position, angle=b.angle,
                   velocity=b.velocity, angular_velocity=b.angular_velocity, mass=b.mass, inertia=b.inertia,
                   friction=b.friction, restitution=b.restitution) for b in world.bodies]
    springs = [dict(name=s.name, a=index[id(s.body_a)], b=None if s.body_b is None else index[id(s.body_b)],
                    anchor_a=s.anchor_a, anchor_b=s.anchor_b, stiffness=s.stiffness, damping=s.damping,
                    rest_length=s.rest_length) for s in world.springs]
    info = world.info()
    head = dict(gravity=world.gravity, dt=world.dt, solver=world.solver, integrator=world.integrator,
                broadphase=world.broadphase, narrowphase=world.narrowphase, sleeping=world.sleeping,
                settings=info["settings"])
    return _plain(dict(world=head, bodies=bodies, springs=springs))


def digest(name) -> str:
    """SHA-256 of scenario ``name`` of PINNED: its initial world and its measure's defaults."""
    from bench.scenarios.extremes import PINNED, defaults
    build, kwargs, measure = PINNED[name]
    w, _ = build(SOLVER, **kwargs)
    data = dict(world=describe(w), build=_plain(kwargs), measure=measure.__name__,
                defaults=_plain(defaults(measure)))
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()


def load_record() -> dict:
    """The pinned digests, {scenario name: hex digest}."""
    return json.loads(RECORD.read_text())


def main() -> int:
    """Re-pin every scenario (after a deliberate change; say why in the commit)."""
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    from bench.scenarios.extremes import PINNED
    out = {}
    for name in PINNED:
        out[name] = digest(name)
        print(f"{name:22s} {out[name][:16]}", flush=True)
    RECORD.parent.mkdir(parents=True, exist_ok=True)
    RECORD.write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
