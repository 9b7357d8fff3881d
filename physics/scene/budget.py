"""The work a scene may ask for: counted from the lengths of its lists, before anything is checked.

Checking and building cost time per body, per shape, per chain point and per outline vertex
(a concave outline is decomposed: earcut, a Shamos-Hoey sweep and Hertel-Mehlhorn, then up
to one convex fixture per two vertices).  A file under the size limit can still list millions
of them, so the cost is counted first, in units of about one fixture row, and a scene that
asks for more than ``WORK_LIMIT`` is refused at the field where the count ran over — before
its values are walked, validated or decomposed.  The weights are the measured costs
relative to a chain point (``python -m physics validate`` on a scene of 20,000 of each kind
alone, 2-core machine under load: a chain point 26 us, a circle body 145 us, a box in a
body of many 300 us, a 64-gon 700 us, an outline vertex 150 us, a spring 90 us).
"""
from __future__ import annotations

#: units a scene may ask for in all: a validate of the largest scene takes a few seconds
WORK_LIMIT = 250_000
WEIGHTS = {
    "body": 2,            # schema, hand checks, a body row and its handle
    "shape": 4,           # a shape object of its own: built, weighed, a fixture row
    "polygon": 8,         # a box, polygon or regular polygon: validated, plus a unit per 4 vertices
    "chain point": 1,     # a chain segment: a fixture row and its ghosts
    "concave vertex": 6,  # decomposition plus about half a convex fixture
    "spring": 4,
    "joint": 4,
}
_CORNERS = {"box": lambda v: 4, "polygon": lambda v: len(v) if isinstance(v, list) else 0,
            "regular": lambda v: v.get("sides", 0) if isinstance(v, dict) and type(v.get("sides")) is int else 0}


def _shape_cost(spec) -> tuple[int, str]:
    """(units, what) for one shape object (anything else costs a shape: the schema refuses it)."""
    if isinstance(spec, dict):
        chain = spec.get("chain")
        if isinstance(chain, dict) and isinstance(chain.get("points"), list):
            return len(chain["points"]) * WEIGHTS["chain point"], "chain"
        if isinstance(spec.get("concave"), list):
            return len(spec["concave"]) * WEIGHTS["concave vertex"], "concave"
        for key, corners in _CORNERS.items():
            if key in spec:  # a huge "sides" is refused by the schema; count at most 64
                return WEIGHTS["polygon"] + min(corners(spec[key]), 64) // 4, ""
    return WEIGHTS["shape"], ""


def _items(data):
    """(path, units) for each body, shape, spring and joint, in document order."""
    bodies = data.get("bodies")
    for i, b in enumerate(bodies if isinstance(bodies, list) else []):
        yield ("bodies", i), WEIGHTS["body"]
        if not isinstance(b, dict):
            continue
        if "shape" in b:
            units, key = _shape_cost(b["shape"])
            yield ("bodies", i, "shape", key) if key else ("bodies", i, "shape"), units
        shapes = b.get("shapes")
        for k, spec in enumerate(shapes if isinstance(shapes, list) else []):
            units, key = _shape_cost(spec)
            yield ("bodies", i, "shapes", k, key) if key else ("bodies", i, "shapes", k), units
    for section, weight in (("springs", WEIGHTS["spring"]), ("joints", WEIGHTS["joint"])):
        items = data.get(section)
        for i in range(len(items) if isinstance(items, list) else 0):
            yield (section, i), weight


def work_problem(data):
    """(path, reason) at the field where the scene's work runs over WORK_LIMIT, or None."""
    total = 0
    for path, units in _items(data):
        total += units
        if total > WORK_LIMIT:
            return path, (f"the scene asks for more work than a scene may: over {WORK_LIMIT:,} units by here "
                          f"(a body {WEIGHTS['body']}, a circle, capsule or segment {WEIGHTS['shape']}, a "
                          f"polygon {WEIGHTS['polygon']} plus 1 per 4 vertices, a chain point "
                          f"{WEIGHTS['chain point']}, a concave outline vertex {WEIGHTS['concave vertex']}, a "
                          f"spring or joint {WEIGHTS['spring']}); split it into several scenes")
    return None
