"""Scene descriptions: plain dicts in the scene-file format, readable by every engine.

A description is a dict in the scene-file format (``scenes/*.json``, ``"format":
"stelkropp.scene"``): JSON data only, never live objects, so a benchmark case can carry it
to any process or machine.  This module writes descriptions (``make_desc``, ``box``), reads
and overrides them (``load_desc``, ``with_world``) and normalises their bodies and springs
into records every engine adapter builds from (``shape_of``, ``body_records``,
``spring_ends``).
"""
from __future__ import annotations

import copy
import json


def make_desc(name, description, bodies, springs=(), gravity=(0.0, -10.0), dt=1 / 60) -> dict:
    """A description with sleeping off; ``gravity`` in m/s^2, ``dt`` in s."""
    return {"format": "stelkropp.scene", "version": 1, "name": name, "description": description,
            "world": {"gravity": list(gravity), "dt": dt, "sleeping": False},
            "bodies": list(bodies), "springs": list(springs)}


def box(w, h, x, y, kind="dynamic", angle=0.0, friction=0.6, restitution=0.0, density=1.0, name=None,
        velocity=(0.0, 0.0)) -> dict:
    """A body record for a ``w`` x ``h`` m box centred at (``x``, ``y``) m."""
    b = {"shape": {"box": [w, h]}, "position": [x, y], "friction": friction, "kind": kind,
         "restitution": restitution, "density": density}
    if angle:
        b["angle"] = angle
    if velocity != (0.0, 0.0):
        b["velocity"] = list(velocity)
    if name:
        b["name"] = name
    return b


def load_desc(path) -> dict:
    """The description in a scene file (plain JSON, not checked: the engines check what they use)."""
    with open(path) as f:
        return json.load(f)


def with_world(desc, **world) -> dict:
    """A copy of ``desc`` with world fields overridden (gravity, dt, sleeping)."""
    d = copy.deepcopy(desc)
    d.setdefault("world", {}).update(world)
    return d


def shape_of(spec):
    """The ``physics`` shape for a scene-file shape spec; ValueError for an unknown spec."""
    import physics
    if "box" in spec:
        w, h = spec["box"]
        return physics.Polygon.box(float(w), float(h))
    if "polygon" in spec:
        return physics.Polygon(spec["polygon"])
    if "regular" in spec:
        r = spec["regular"]
        return physics.Polygon.regular(int(r["sides"]), float(r["radius"]))
    if "circle" in spec:
        c = spec["circle"]
        if isinstance(c, dict):
            return physics.Circle(float(c["radius"]), tuple(c.get("offset", (0.0, 0.0))))
        return physics.Circle(float(c))
    raise ValueError(f"unsupported shape spec {spec!r}")


class Compound:
    """The shapes of a body with several fixtures, for the adapters' mass bookkeeping: the same
    ``mass_properties`` / ``centroid`` interface as one shape (physics/geometry/mass.py sums the
    parts with the parallel-axis theorem), each part with its own density."""

    def __init__(self, parts):
        self.parts = parts  # [(shape, fixture record)]

    def mass_properties(self, density=None):
        """(mass, centre of mass, inertia about it) of the parts at their fixtures' densities."""
        from physics.geometry.mass import compound_mass
        return compound_mass([s.mass_properties(f["density"]) for s, f in self.parts])

    @property
    def centroid(self):
        """The centre of mass in body coordinates (m)."""
        return self.mass_properties()[1]


def fixture_records(b) -> list:
    """[(shape, {density, mu_s, mu_d, restitution})] for every fixture of body ``b``: its
    ``"shapes"`` list (scene format version 2; a concave outline decomposed, a chain split into
    its segments) or its one ``"shape"``; a shape object's own material overrides the body's."""
    from physics.scene.shapes import make_shapes
    specs = b["shapes"] if "shapes" in b else [b["shape"]]
    out = []
    for spec in specs:
        mu_s, mu_d = _friction({**b, **({"friction": spec["friction"]} if "friction" in spec else {})})
        rec = dict(density=float(spec.get("density", b.get("density", 1.0))), mu_s=mu_s, mu_d=mu_d,
                   restitution=float(spec.get("restitution", b.get("restitution", 0.0))))
        out.extend((shape, rec) for shape in make_shapes(spec))
    return out


def _one_v1_shape(b) -> bool:
    """True for a body of one version-1 shape with no fixture fields (``shape_of`` builds it)."""
    return "shape" in b and len(b["shape"]) == 1 and next(iter(b["shape"])) in ("box", "polygon", "regular", "circle")


def _friction(b):
    f = b.get("friction", 0.6)
    if isinstance(f, dict):
        return float(f.get("static", 0.6)), float(f.get("dynamic", f.get("static", 0.6)))
    if isinstance(f, (list, tuple)):
        return float(f[0]), float(f[1])
    return float(f), float(f)


def body_records(desc) -> list[dict]:
    """Normalised body records: shape object, kind, pose, velocity, material (in description order)."""
    out = []
    for b in desc["bodies"]:
        mu_s, mu_d = _friction(b)
        parts = None if _one_v1_shape(b) else fixture_records(b)
        shape = Compound(parts) if parts else shape_of(b["shape"])
        out.append(dict(name=b.get("name"), shape=shape, parts=parts, kind=b.get("kind", "dynamic"),
                        position=tuple(map(float, b.get("position", (0.0, 0.0)))),
                        angle=float(b.get("angle", 0.0)),
                        velocity=tuple(map(float, b.get("velocity", (0.0, 0.0)))),
                        angular_velocity=float(b.get("angular_velocity", 0.0)),
                        density=float(b.get("density", 1.0)), restitution=float(b.get("restitution", 0.0)),
                        mu_s=mu_s, mu_d=mu_d))
    return out


def spring_ends(desc):
    """Per spring: (body index a, body index b or None for a world anchor, anchor_a, anchor_b,
    stiffness N/m, damping N s/m, rest length m or None for the initial distance)."""
    names = {b.get("name", i): i for i, b in enumerate(desc["bodies"])}
    for s in desc.get("springs", []):
        yield (names[s["a"]], None if s.get("b") is None else names[s["b"]], tuple(s.get("anchor_a", (0, 0))),
               tuple(s.get("anchor_b", (0, 0))), float(s.get("stiffness", 100.0)), float(s.get("damping", 0.0)),
               s.get("rest_length"))
