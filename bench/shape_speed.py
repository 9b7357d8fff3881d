"""The shipped many-shape scenes' speed in soft_step beside pymunk, in one interleaved run (issue 13).

    python -m bench.shape_speed                          # compounds, tumbler, cup, capsules, terrain
    python -m bench.shape_speed --scenes compounds --steps 120 --out /tmp/ss

Each scene of ``bench.scenes.SHAPE_BENCH`` (its shipped file; sleeping off) runs in Stelkropp's
soft_step defaults and in pymunk (every fixture as its Chipmunk shape: rounded polygons, offset
circles, capsules as radius segments, chains as segments with neighbours;
bench/engines/pymunk_shapes.py), chunk by chunk in turn, timed as ``bench.joint_speed`` times the
joint scenes.  Writes ``shape_speed.json`` and ``shape_speed.md`` into ``--out`` (default
bench/results/).
"""
from __future__ import annotations

from .joint_speed import cli
from .scenes import SHAPE_BENCH


def main(argv=None) -> int:
    """``python -m bench.shape_speed``: measure, write the JSON and the table, print it."""
    return cli(argv, "python -m bench.shape_speed", __doc__, SHAPE_BENCH, "shapes", "fixtures")


if __name__ == "__main__":
    raise SystemExit(main())
