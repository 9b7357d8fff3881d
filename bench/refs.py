"""The names of the former bench/refs.py, kept for code written against it (bench/box2d/ and
bench/suite/ were started on it).  New code imports where each concept now lives:
scene descriptions bench/desc.py, generated scenes bench/scenes.py, engines bench/engines/
(one module each behind ``Sim``), engine-independent measures bench/metrics.py."""
from __future__ import annotations

from .desc import body_records as _bodies, box, load_desc, make_desc as _desc, shape_of, spring_ends as _spring_ends
from .desc import with_world
from .engines import ENGINES, Sim, build
from .engines.ours import OursSim, build_ours_world
from .engines.pybox2d_sim import BOX2D_POSITION_ITERATIONS, BOX2D_VELOCITY_ITERATIONS, Box2DSim
from .engines.pymunk_sim import PYMUNK_ITERATIONS, PymunkSim
from .metrics import penetration, world_shapes
from .paths import ROOT, SCENES
from .scenes import columns, pyramid, rain

__all__ = ["BOX2D_POSITION_ITERATIONS", "BOX2D_VELOCITY_ITERATIONS", "Box2DSim", "ENGINES", "OursSim",
           "PYMUNK_ITERATIONS", "PymunkSim", "ROOT", "SCENES", "Sim", "box", "build", "build_ours_world", "columns",
           "load_desc", "penetration", "pyramid", "rain", "shape_of", "with_world", "world_shapes", "_bodies", "_desc",
           "_spring_ends"]
