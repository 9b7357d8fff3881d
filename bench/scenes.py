"""The benchmark's scenes: generators for the scenes no file ships, and the table of scenes.

Each scene is plain data (``BenchScene``): the shipped scene file or the generator (by name,
with its keyword arguments) that writes its description, the error metric it is judged by,
and the run plans (steps, chunk, warm-up) of the full and the quick run.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .desc import box, load_desc, make_desc, with_world
from .paths import ROOT, SCENES as SCENE_DIR

GENERATED = "generated (bench/scenes.py)"


# -- generators -------------------------------------------------------------------------------
def pyramid(base=20, friction=0.6) -> dict:
    """Boxes 1x1 in a pyramid of ``base`` (base*(base+1)/2 boxes) on a static ground."""
    bodies = [box(max(40.0, 2.0 * base + 20), 1.0, 0.0, -0.5, kind="static", friction=friction, name="ground")]
    for row in range(base):
        for k in range(base - row):
            x = -0.5 * base + 0.5 + 0.5 * row + k
            bodies.append(box(1.0, 1.0, x, 0.5 + row, friction=friction))
    n = len(bodies) - 1
    return make_desc(f"Pyramid {base}", f"{n} boxes (1x1) in a pyramid of base {base} on static ground", bodies)


def rain(n=1000, width=40.0, friction=0.6, seed=1) -> dict:
    """``n`` 1x1 boxes dropped from a grid of columns into an open container ``width`` metres wide."""
    rng = np.random.default_rng(seed)
    wall_h = 4.0 + 1.25 * n / width
    bodies = [box(width + 2.0, 1.0, 0.0, -0.5, kind="static", friction=friction, name="floor"),
              box(1.0, wall_h, -0.5 * width - 0.5, 0.5 * wall_h, kind="static", friction=friction, name="left"),
              box(1.0, wall_h, 0.5 * width + 0.5, 0.5 * wall_h, kind="static", friction=friction, name="right")]
    cols = int((width - 2.0) // 1.5)
    for i in range(n):
        c, r = i % cols, i // cols
        x = -0.5 * (cols - 1) * 1.5 + 1.5 * c + rng.uniform(-0.2, 0.2)
        y = 2.0 + 1.5 * r + rng.uniform(0.0, 0.3)
        bodies.append(box(1.0, 1.0, x, y, angle=float(rng.uniform(-0.3, 0.3)), friction=friction))
    return make_desc(f"Rain {n}", f"{n} boxes (1x1) rained into a {width:g} m open container", bodies)


def columns(n=1000, height=10, friction=0.6) -> dict:
    """``n`` 1x1 boxes in free-standing columns of ``height`` (1.5 m apart) on one static ground:
    contacts per body stay constant as n grows (the scaling scene)."""
    ncol = max(1, math.ceil(n / height))
    span = 1.5 * ncol
    bodies = [box(span + 4.0, 1.0, 0.5 * span, -0.5, kind="static", friction=friction, name="ground")]
    for i in range(n):
        c, r = i // height, i % height
        bodies.append(box(1.0, 1.0, 1.5 * c + 0.75, 0.5 + r, friction=friction))
    return make_desc(f"Columns {n}", f"{n} boxes in {ncol} columns of {height}", bodies)


from .small_descs import SMALL, small  # noqa: E402  (the small scenes' descriptions)

GENERATORS = {"pyramid": pyramid, "rain": rain, "columns": columns, "small": small}


# -- the table ----------------------------------------------------------------------------------
BENCH_WORLD = {"gravity": [0.0, -10.0], "dt": 1 / 60, "sleeping": False}


@dataclass(frozen=True)
class BenchScene:
    """One benchmark scene (plain data).  ``file``: a scene file in scenes/ (used when present);
    ``gen``: (generator name, kwargs) otherwise; ``error``: the metric the scene is judged by;
    ``full`` / ``quick``: run plans (steps, chunk, warm; ``quick`` None: not in the quick run);
    ``sweep``: every configuration (else defaults only); ``keep_world``: keep the file's gravity
    and dt (only sleeping is turned off); ``engines``: the only reference engines that model the
    scene (None: every one; the joint scenes run in pymunk alone, bench/engines/pymunk_joints.py)."""
    title: str
    error: str
    full: dict
    quick: dict | None
    sweep: bool
    file: str | None = None
    gen: tuple | None = None
    keep_world: bool = False
    engines: tuple | None = None


SCENES = {
    "pyramid20": BenchScene("Pyramid, base 20 (210 boxes)", "top_drift", dict(steps=600, chunk=30, warm=60),
                            dict(steps=180, chunk=20, warm=40), True, file="pyramid.json",
                            gen=("pyramid", {"base": 20})),
    "pyramid40": BenchScene("Pyramid, base 40 (820 boxes)", "top_drift", dict(steps=600, chunk=30, warm=60),
                            None, True, file="pyramid_large.json", gen=("pyramid", {"base": 40})),
    "rain1000": BenchScene("Rain: 1000 boxes (1x1) into a 40 m container", "max_penetration",
                           dict(steps=720, chunk=30, warm=120), dict(steps=140, chunk=20, warm=80), True,
                           gen=("rain", {"n": 1000})),
    "rain_mixed": BenchScene("scenes/rain.json: 1000 mixed convex shapes (defaults only)", "max_penetration",
                             dict(steps=480, chunk=30, warm=120), None, False, file="rain.json", keep_world=True),
}
# the shipped joint scenes (issue 14): defaults only, beside pymunk (the one reference with joints here)
JOINT_BENCH = ("pendulum", "double_pendulum", "newtons_cradle", "hinge_bridge", "wrecking_ball", "piston",
               "car", "ragdoll", "walker", "joint_grid")
for _name in JOINT_BENCH:
    SCENES[f"joints_{_name}"] = BenchScene(f"scenes/{_name}.json (joints)", "max_penetration",
                                           dict(steps=300, chunk=20, warm=40), None, False, file=f"{_name}.json",
                                           keep_world=True, engines=("pymunk",))
# the shipped scenes of bodies made of several shapes (issue 13): beside pymunk, which has compound
# bodies, rounded polygons, capsules (radius segments) and smooth segment chains
SHAPE_BENCH = ("compounds", "tumbler", "cup", "capsules", "terrain")
for _name in SHAPE_BENCH:
    SCENES[f"shapes_{_name}"] = BenchScene(f"scenes/{_name}.json (shapes)", "max_penetration",
                                           dict(steps=300, chunk=20, warm=40), None, False, file=f"{_name}.json",
                                           keep_world=True, engines=("pymunk",))
# the small scenes most people build (bench/small_descs.py): beside pymunk, many steps each
for _name in SMALL:
    SCENES[f"small_{_name}"] = BenchScene(f"{_name} (generated)", "max_penetration",
                                          dict(steps=3000, chunk=200, warm=200), None, False,
                                          gen=("small", {"which": _name}), keep_world=True, engines=("pymunk",))
ERROR_LABEL = {"top_drift": "top-box drift after the run (m)", "max_penetration": "max penetration at the end (m)"}


@dataclass(frozen=True)
class SceneData:
    """What a case needs to rebuild a scene anywhere: the raw description (``data``, as in the
    file), the world fields the benchmark overrides, where it came from (``source``, for the
    tables) and whether Stelkropp builds it with the scene loader (``from_file``)."""
    key: str
    data: dict
    world: dict
    source: str
    from_file: bool

    @property
    def desc(self) -> dict:
        """The description every engine runs: ``data`` with the world overrides applied."""
        return with_world(self.data, **self.world)


def scene_data(key) -> SceneData | None:
    """The scene ``key`` of SCENES: the shipped file when there is one, else generated; None when
    neither exists.  KeyError for an unknown key."""
    sc = SCENES[key]
    path = SCENE_DIR / sc.file if sc.file else None
    if path is not None and path.exists():
        data, src, from_file = load_desc(path), str(path.relative_to(ROOT)), True
    elif sc.gen is not None:
        name, kw = sc.gen
        data, src, from_file = GENERATORS[name](**kw), GENERATED, False
    else:
        return None
    world = {"sleeping": False} if sc.keep_world else dict(BENCH_WORLD)
    return SceneData(key, data, world, src, from_file)


def scene_desc(key):
    """(description with the benchmark's world fields, source) of scene ``key``; (None, None)
    when it has neither a file nor a generator."""
    sd = scene_data(key)
    return (None, None) if sd is None else (sd.desc, sd.source)


def container_width(desc) -> float | None:
    """Width (m) between the outermost static bodies of a rain scene (for the escaped count)."""
    xs = [b["position"][0] for b in desc["bodies"] if b.get("kind") == "static"]
    return max(xs) - min(xs) if xs else None
