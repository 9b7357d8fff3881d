"""Scene files and scene data to a new World.

Reading is strict and bounded (``json_io``); every problem is found before
anything is built (``checks``), so a bad file raises one SceneError listing
all of them and never half-builds a world.
"""
from __future__ import annotations

import math

import numpy as np

from . import schema as fmt
from .atomic import scene_path
from .checks import check
from .joints import add_joints
from .json_io import parse, read_text
from .problems import scene_error
from .sandbox import load_sandbox


def read_scene(path) -> dict:
    """Parse a scene file into plain data without checking it (SceneError for unreadable files)."""
    src = scene_path(path)
    try:
        text = read_text(src, fmt.MAX_FILE_BYTES)
    except OSError as exc:
        raise scene_error(src, [("$", f"cannot read the file: {exc.strerror or exc}")]) from None
    except UnicodeDecodeError as exc:
        raise scene_error(src, [("$", f"not UTF-8 text ({exc.reason} at byte {exc.start})")]) from None
    except ValueError as exc:
        raise scene_error(src, [("$", str(exc))]) from None
    try:
        return parse(text)
    except ValueError as exc:  # JSONDecodeError, and ints too long to convert
        where = f"line {exc.lineno} column {exc.colno}: {exc.msg}" if hasattr(exc, "lineno") else str(exc)
        raise scene_error(src, [("$", f"not valid JSON ({where})")]) from None


def load_scene(path):
    """Load a scene file into a new World; raises SceneError listing every problem."""
    src = scene_path(path)
    return scene_from_dict(read_scene(src), source=src)


def scene_from_dict(data, source: str = "<dict>"):
    """Build a World from scene data; raises SceneError (naming ``source``) listing every problem."""
    problems, shapes = check(data)
    if problems:
        raise scene_error(source, problems)
    return _build(data, shapes, source)


def _build(data, shapes, source):
    from ..world import World
    w = {**fmt.WORLD_DEFAULTS, **data.get("world", {})}
    try:
        world = World(gravity=w["gravity"], dt=w["dt"], solver=w["solver"], integrator=w["integrator"],
                      sleeping=w["sleeping"], broadphase=w["broadphase"], narrowphase=w["narrowphase"],
                      settings=w["settings"])
    except (ValueError, KeyError, ImportError) as exc:  # the checks should have caught it; say so anyway
        raise scene_error(source, [("world", str(exc))]) from None
    world.time = w.get("time", 0.0)
    world.steps = w.get("steps", 0)
    handles = {}
    for i, (b, shape) in enumerate(zip(data["bodies"], shapes)):
        handles[i] = _add_body(world, b, shape, f"bodies[{i}]", source)
    by_name = {b["name"]: handles[i] for i, b in enumerate(data["bodies"]) if "name" in b}
    for i, sp in enumerate(data.get("springs", [])):
        _add_spring(world, sp, by_name, f"springs[{i}]", source)
    add_joints(world, data.get("joints", []), by_name, scene_error, source)
    _sleep_state(world, data["bodies"], handles)
    world.metadata.update({k: data[k] for k in ("name", "description", "camera") if k in data})
    # the sandbox's body colours are app data: kept beside the world, by body id, never in the core
    colors = {handles[i].id: b["color"].lower() for i, b in enumerate(data["bodies"]) if "color" in b}
    if colors:
        world.metadata["colors"] = colors
    load_sandbox(data, by_name, world.metadata)      # the sandbox's lasers and tracers: app data too
    return world


# what a running world changed in a body, set once every body is built
_STATE = ("asleep", "awake", "sleep_time", "center_of_mass")


def _sleep_state(world, bodies, handles) -> None:
    """Each body's sleep timer, and the sleeping islands: one fresh island label per number the
    file gives (numbers are the file's, labels the world's), and one for each body marked
    ``awake: false`` without a number; all at rest."""
    islands = {}
    for i, b in enumerate(bodies):
        body = handles[i]
        if "sleep_time" in b:
            world._bodies.view.sleep_t[body._s] = b["sleep_time"]
        if "center_of_mass" in b:  # exact where no origin reaches it (dump.py)
            world._bodies.view.x[body._s] = b["center_of_mass"]
        if body.kind != "dynamic" or not world.sleeping:
            continue
        if "asleep" in b:
            islands.setdefault(b["asleep"], []).append(body)
        elif b.get("awake", True) is False:  # an island of its own, apart from every file number
            islands[("own", i)] = [body]
    for members in islands.values():
        world._put_to_sleep(members)


def _add_body(world, b, fixtures, path, source):
    """One body from its (shape, fixture fields) pairs: the body's material first, then each
    fixture's own fields (a fixture's density moves the centre of mass: set before stepping)."""
    kw = {**fmt.BODY_DEFAULTS, **{k: v for k, v in b.items() if k not in ("shape", "shapes", "color") + _STATE}}
    try:
        body = world.add_body([sh for sh, _ in fixtures], **kw)
        weighed = False
        with world._placing_once():
            for fx, (_, fields) in zip(body.fixtures, fixtures):
                for key, value in fields.items():
                    setattr(fx, key, value)
                    weighed |= key == "density"
        if weighed:  # place once more from the file's origin: x = origin + R com, as the saver assumes
            world._place_body(body, np.array(kw["position"], dtype=np.float64))
        return body
    except ValueError as exc:
        raise scene_error(source, [(path, str(exc))]) from None


def _add_spring(world, sp, by_name, path, source):
    kw = {**fmt.SPRING_DEFAULTS, **{k: v for k, v in sp.items() if k not in ("a", "b")}}
    b = None if sp["b"] is None else by_name[sp["b"]]
    try:
        spring = world.add_spring(by_name[sp["a"]], b, **kw)
    except ValueError as exc:
        raise scene_error(source, [(path, str(exc))]) from None
    if not math.isfinite(spring.rest_length):  # the default, the anchors' distance, can overflow
        raise scene_error(source, [(f"{path}.rest_length", "the anchors are too far apart for a float "
                                    "(the default rest length overflows); give rest_length")])
    return spring
