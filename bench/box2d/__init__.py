"""Box2D v3 itself, from Python: build it (``build``), load the shim (``engine``), run scenes.

``available()`` / ``why_unavailable()`` say whether Box2D v3 can be used here (tools and
sources present, build succeeded); ``Box2DV3Sim`` runs a bench scene description in it.
"""

__all__ = ["BuildError", "available", "why_unavailable", "Box2DV3Sim"]


def __getattr__(name):
    # lazy, so that ``python -m bench.box2d.build`` does not import itself twice
    if name == "Box2DV3Sim":
        from .engine import Box2DV3Sim
        return Box2DV3Sim
    if name in ("BuildError", "available", "why_unavailable"):
        from . import build
        return getattr(build, name)
    raise AttributeError(name)
