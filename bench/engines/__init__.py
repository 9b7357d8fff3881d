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
    # Box2D v3 (issue 17) is being written in bench/box2d/ with the same Sim interface; it joins
    # the comparison with one line here, e.g. "box2d_v3": "bench.box2d:<its Sim class>", and a
    # name in REF_ENGINES.
}
# the engines every Stelkropp configuration is timed against, interleaved chunk by chunk
REF_ENGINES = ("pymunk", "pybox2d")


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


__all__ = ["ENGINES", "REF_ENGINES", "Sim", "build", "engine_class"]
