"""Mutations of scene data and scene files for the fuzzer (tests/fuzz/scene_fuzz.py).

Structural mutations edit the parsed data; text mutations edit the serialised bytes.  Deep
values, duplicate keys and bare literals (NaN, 400-digit integers) go in as placeholders that are
expanded in the text, so the fuzzer itself never recurses deeply or needs a JSON writer of its own.
Every mutation takes a ``random.Random`` (or hypothesis' stand-in), so a case is its seed.
"""
from __future__ import annotations

import copy
import json
import math
import re

EXTREME_NUMBERS = ["0", "-0.0", "1e308", "-1.7976931348623157e308", "5e-324", "1e-320", "2.2250738585072014e-308",
                   "1e400", "-1e999", "NaN", "Infinity", "-Infinity", "9" * 400, "-" + "1" * 5000, str(2 ** 63),
                   str(-2 ** 63 - 1), "1e200", "1e-200", "0.1", "1e16", "123456789012345678901234567890"]
WEIRD_VALUES = [None, True, False, "", "x", "1.5", [], {}, [1], [1, 2, 3], {"a": 1}, -1, 0, 3.5, [[0, 0]],
                {"radius": -1}, "\u0000", "\ufeff", "é", "\U0001f600"]
DEGENERATE_POLYGONS = [
    [[0, 0], [1, 0], [2, 0]], [[0, 0], [1, 0], [1, 0], [0, 1]], [[0, 0], [1, 0]], [[0, 0], [2, 0], [1, 0.3], [1, 2]],
    [[0, 0], [1, 1], [1, 0], [0, 1]], [[0, 0], [1, 1e-14], [2, 0]], [[0, 0], [1e-200, 0], [0, 1e-200]],
    [[0, 0], [1e200, 0], [0, 1e200]], [[1e300, 1e300], [1e300, -1e300], [-1e300, 0]],
    [[math.cos(2 * math.pi * k / 65), math.sin(2 * math.pi * k / 65)] for k in range(65)], [[5, 5]] * 3,
    [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], [[0, 0], [1e100, 0], [1e100, 1], [0, 1]],
]
SHAPES = [{"box": [1e200, 1]}, {"box": [1e-200, 1e-200]}, {"box": [1e100, 1]}, {"circle": 1e200},
          {"circle": 1e-200}, {"circle": {"radius": 1, "offset": [1e308, 0]}}, {"regular": {"sides": 64, "radius": 1e77}},
          {"regular": {"sides": 3, "radius": 5e-324}}, {"box": [1, 1], "circle": 1}, {}, {"triangle": [1, 2]}]


class Placeholders:
    """Values spliced into the serialised text: '"@@k@@"' becomes the k-th raw JSON fragment."""

    def __init__(self):
        self.raw = []

    def put(self, fragment: str) -> str:
        self.raw.append(fragment)
        return f"@@{len(self.raw) - 1}@@"

    def expand(self, text: str) -> str:
        return re.sub(r'"@@(\d+)@@"', lambda m: self.raw[int(m.group(1))], text)


def nodes(data):
    """Every (container, key) slot in the data, without recursion."""
    out, stack = [], [data]
    while stack:
        v = stack.pop()
        items = v.items() if isinstance(v, dict) else enumerate(v) if isinstance(v, list) else ()
        for k, item in items:
            out.append((v, k))
            stack.append(item)
    return out


def _slot(rnd, data, want=None):
    slots = [(c, k) for c, k in nodes(data) if want is None or want(c[k])]
    return rnd.choice(slots) if slots else None


def m_wrong_type(rnd, data, ph):
    s = _slot(rnd, data)
    if s:
        s[0][s[1]] = copy.deepcopy(rnd.choice(WEIRD_VALUES))


def m_extreme_number(rnd, data, ph):
    s = _slot(rnd, data, lambda v: isinstance(v, (int, float)) and not isinstance(v, bool))
    if s:
        s[0][s[1]] = ph.put(rnd.choice(EXTREME_NUMBERS))


def m_deep(rnd, data, ph):
    s = _slot(rnd, data)
    if s:
        depth = rnd.choice([7, 31, 33, 200, 500, 5000, 100_000])
        s[0][s[1]] = ph.put(("[" * depth + "]" * depth) if rnd.random() < 0.5 else ('{"a":' * depth + "1" + "}" * depth))


def m_huge_string(rnd, data, ph):
    n = rnd.choice([10_000, 1_000_000, 5_000_000])
    s = _slot(rnd, data, lambda v: isinstance(v, str)) if rnd.random() < 0.5 else _slot(rnd, data)
    if s and rnd.random() < 0.7:
        s[0][s[1]] = rnd.choice("ab\u00e9\U0001f600") * n
    elif isinstance(data, dict):
        target = _slot(rnd, data, lambda v: isinstance(v, dict))
        (target[0][target[1]] if target else data)["k" * n] = 1


def m_duplicate_key(rnd, data, ph):
    s = _slot(rnd, data, lambda v: isinstance(v, dict) and v)
    obj = s[0][s[1]] if s else data if isinstance(data, dict) else None
    if obj:
        key = rnd.choice(list(obj))
        other = copy.deepcopy(rnd.choice([obj[key], -5, None, "x", [1e9]]))
        dup = ph.put(json.dumps(key))  # the key itself, spliced in where the placeholder key was
        items = list(obj.items())
        obj.clear()
        for k, v in items[: rnd.randrange(len(items) + 1)] + [(dup, other)] + items[rnd.randrange(len(items) + 1):]:
            obj[k] = v


def m_remove(rnd, data, ph):
    s = _slot(rnd, data, lambda v: True)
    if s and isinstance(s[0], dict):
        del s[0][s[1]]
    elif s:
        s[0].pop(s[1])


def m_unknown_key(rnd, data, ph):
    s = _slot(rnd, data, lambda v: isinstance(v, dict))
    obj = s[0][s[1]] if s else data if isinstance(data, dict) else None
    if obj is not None:
        key = rnd.choice(["colour", "", " ", "\u0000", "shape ", "Density", "$ref"])
        obj[key] = copy.deepcopy(rnd.choice(WEIRD_VALUES))  # a copy: later mutations edit it in place


def m_reference(rnd, data, ph):
    springs = data.get("springs") if isinstance(data, dict) else None
    bodies = data.get("bodies") if isinstance(data, dict) else None
    if springs and isinstance(springs, list) and isinstance(springs[0], dict):
        sp = rnd.choice(springs)
        if isinstance(sp, dict):
            sp[rnd.choice("ab")] = rnd.choice(["ghost", "", None, sp.get("a"), 7])
    elif bodies and isinstance(bodies, list):
        b = rnd.choice(bodies)
        if isinstance(b, dict):
            b["name"] = rnd.choice([x.get("name") for x in bodies if isinstance(x, dict)] + ["dup"])
        if isinstance(data.setdefault("springs", []), list):
            data["springs"].append({"a": "nobody", "b": None, "stiffness": 1})


def m_degenerate_shape(rnd, data, ph):
    bodies = data.get("bodies") if isinstance(data, dict) else None
    if isinstance(bodies, list) and bodies and isinstance(b := rnd.choice(bodies), dict):
        b["shape"] = copy.deepcopy({"polygon": rnd.choice(DEGENERATE_POLYGONS)} if rnd.random() < 0.6
                                   else rnd.choice(SHAPES))


def m_header(rnd, data, ph):
    if isinstance(data, dict):
        data[rnd.choice(["format", "version"])] = rnd.choice(["stelkropp.scene", "box2d", 1, 2, "1", 1.0, True, None])


def _log_uniform(rnd, lo, hi):
    return math.exp(rnd.uniform(math.log(lo), math.log(hi)))


def m_valid_tweak(rnd, data, ph):
    """A change inside the documented ranges (the file should still load, and round-trip)."""
    bodies = data.get("bodies") if isinstance(data, dict) else None
    if isinstance(bodies, list) and bodies and isinstance(b := rnd.choice(bodies), dict):
        key = rnd.choice(["density", "velocity", "position", "angle", "angular_velocity", "friction",
                          "restitution", "kind", "shape"])
        b[key] = {"density": lambda: _log_uniform(rnd, 1e-6, 1e9),
                  "velocity": lambda: [rnd.uniform(-1e5, 1e5), rnd.uniform(-1e5, 1e5)],
                  "position": lambda: [rnd.uniform(-1e6, 1e6), rnd.uniform(-1e6, 1e6)],
                  "angle": lambda: rnd.uniform(-1e3, 1e3), "angular_velocity": lambda: rnd.uniform(-1e4, 1e4),
                  "friction": lambda: {"static": rnd.uniform(0, 10), "dynamic": rnd.uniform(0, 10)},
                  "restitution": lambda: rnd.random(), "kind": lambda: rnd.choice(["dynamic", "static", "kinematic"]),
                  "shape": lambda: rnd.choice([{"box": [_log_uniform(rnd, 1e-3, 1e3), _log_uniform(rnd, 1e-3, 1e3)]},
                                               {"circle": _log_uniform(rnd, 1e-3, 1e3)},
                                               {"regular": {"sides": rnd.randint(3, 64), "radius": rnd.uniform(0.01, 9)}}]),
                  }[key]()
    world = data.get("world") if isinstance(data, dict) else None
    if isinstance(world, dict) and rnd.random() < 0.3:
        world.update(rnd.choice([{"dt": _log_uniform(rnd, 1e-5, 1)}, {"gravity": [0, rnd.uniform(-1e3, 1e3)]},
                                 {"solver": rnd.choice(["soft_step", "sequential_impulse", "impulse", "penalty",
                                                        "hybrid"]), "settings": {}},
                                 {"integrator": rnd.choice(["euler", "symplectic_euler", "rk4"])},
                                 {"sleeping": rnd.random() < 0.5}]))


STRUCTURAL = [m_wrong_type, m_extreme_number, m_deep, m_huge_string, m_duplicate_key, m_remove, m_unknown_key,
              m_reference, m_degenerate_shape, m_header]


def t_truncate(rnd, raw: bytes) -> bytes:
    return raw[: rnd.randrange(len(raw) + 1)]


def t_garbage(rnd, raw: bytes) -> bytes:
    i = rnd.randrange(len(raw) + 1)
    junk = bytes(rnd.randrange(256) for _ in range(rnd.choice([1, 4, 64])))
    return raw[:i] + junk + raw[i + rnd.choice([0, len(junk)]):]


def t_bytes(rnd, raw: bytes) -> bytes:
    pick = rnd.choice([b"\xff\xfe", b"\xef\xbb\xbf", b"\x00", b"\xed\xa0\x80", b'"\\ud800"', b"\\", b"\x1b[2J"])
    i = rnd.randrange(len(raw) + 1)
    return raw[:i] + pick + raw[i:]


TEXTUAL = [t_truncate, t_garbage, t_bytes]


def make_case(rnd, base) -> tuple:
    """(name, file bytes, the mutations' names) for one case drawn with ``rnd``."""
    name, data = rnd.choice(base)
    data = copy.deepcopy(data)
    ph = Placeholders()
    done = []
    valid_only = rnd.random() < 0.25  # a quarter of the cases stay in range: they load and round-trip
    for _ in range(rnd.choice([1, 1, 2, 3, 4])):
        m = m_valid_tweak if valid_only else rnd.choice(STRUCTURAL)
        m(rnd, data, ph)
        done.append(m.__name__)
    raw = ph.expand(json.dumps(data, ensure_ascii=rnd.random() < 0.5)).encode("utf-8", "surrogatepass")
    if not valid_only and rnd.random() < 0.15:
        t = rnd.choice(TEXTUAL)
        raw = t(rnd, raw)
        done.append(t.__name__)
    return name, raw, done
