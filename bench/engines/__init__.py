"""The engines the benchmark runs, one module each, all behind ``Sim`` (bench/engines/base.py).

    from bench.engines import build
    sim = build("pymunk", desc)      # desc: a scene description (bench/desc.py)
    sim.step(); com, angle, v, w = sim.state()

``ENGINES`` maps an engine name to "module:class"; the module is imported on first use, so an
engine whose library is missing fails only when it is asked for.  A new engine is one module
with a ``Sim`` subclass and one line here.
"""
from __future__ import annotations

import importlib

from .base import Sim

ENGINES = {
    "stelkropp": "bench.engines.ours:OursSim",
    "pymunk": "bench.engines.pymunk_sim:PymunkSim",
    "pybox2d": "bench.engines.pybox2d_sim:Box2DSim",
    # Box2D v3 itself, built from its C sources with cmake and driven through our shim (bench/box2d/)
    "box2d_v3": "bench.box2d.engine:Box2DV3Sim",
}
# the engines every Stelkropp configuration is timed against, interleaved chunk by chunk
REF_ENGINES = ("pymunk", "pybox2d", "box2d_v3")


def why_unusable(engine) -> str | None:
    """Why ``engine`` cannot run here (its library missing, Box2D v3 not buildable), or None.
    Building Box2D v3 the first time happens here (cmake + ninja into the cache, ~2 min)."""
    if engine == "box2d_v3":
        from bench.box2d import why_unavailable
        return why_unavailable()
    try:
        engine_class(engine)
    except ImportError as exc:
        return f"{engine}: {exc}"
    return None


def usable(engines) -> tuple[tuple, dict]:
    """(the engines of ``engines`` that can run here, {engine: why not} for the others)."""
    why = {e: why_unusable(e) for e in engines}
    return tuple(e for e in engines if why[e] is None), {e: r for e, r in why.items() if r}


def engine_class(engine) -> type[Sim]:
    """The ``Sim`` class of ``engine``; ValueError for a name not in ENGINES."""
    try:
        target = ENGINES[engine]
    except KeyError:
        raise ValueError(f"unknown engine {engine!r} (known: {', '.join(ENGINES)})") from None
    mod, _, cls = target.partition(":")
    return getattr(importlib.import_module(mod), cls)


def build(engine, desc, **kw) -> Sim:
    """A ``Sim`` of description ``desc`` in ``engine``; keyword arguments go to its constructor."""
    return engine_class(engine)(desc, **kw)


__all__ = ["ENGINES", "REF_ENGINES", "Sim", "build", "engine_class", "usable", "why_unusable"]
