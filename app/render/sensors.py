"""Sensor fixtures' colours: translucent, lit while something is inside (``Decor.sensors``, from
``app.sensors``).  Every other part keeps its body's colours."""
from __future__ import annotations

import numpy as np

F32 = np.float32
SENSOR_FILL = np.array((0.35, 0.85, 0.55, 0.16), F32)       # see-through: what is inside shows
SENSOR_LINE = np.array((0.35, 0.85, 0.55, 0.65), F32)
LIT_FILL = np.array((0.55, 1.0, 0.45, 0.42), F32)           # a visitor inside
LIT_LINE = np.array((0.75, 1.0, 0.55, 1.0), F32)


def _paint(ids, body_rows, fill, line, sensors):
    f, ln = fill[body_rows].copy(), line[body_rows].copy()
    if len(ids):
        keys = np.fromiter(sensors, np.int64)
        lit_keys = np.fromiter((k for k, v in sensors.items() if v), np.int64)
        s = np.isin(ids, keys)
        lit = np.isin(ids, lit_keys)
        f[s & ~lit], ln[s & ~lit] = SENSOR_FILL, SENSOR_LINE
        f[lit], ln[lit] = LIT_FILL, LIT_LINE
    return f, ln


def sensor_colors(parts, fill, line, sensors):
    """((fill, line) per polygon part, (fill, line) per circle part) of ``parts``
    (app.render.parts.Parts) with the sensors in ``sensors`` ({fixture id: lit}) recoloured."""
    return (_paint(parts.fixture, parts.body, fill, line, sensors),
            _paint(parts.circle_fixture, parts.circle_body, fill, line, sensors))
