"""Slider tool: drag out an axis from a point over one or two bodies: a prismatic joint there,
the topmost body sliding along the drag's direction relative to the next one (or the
background).  With "slider limits" on, the travel is the dragged segment: from the start
(translation 0) to the release point."""
from __future__ import annotations

import numpy as np

from .base import PREVIEW
from .joining import DragJointTool, add_joint


class SliderTool(DragJointTool):
    name = "slider"
    verb = "make a slider"
    help = "drag from a body along the axis it should slide on (over two bodies: the top one slides " \
           "on the other)"

    def finish(self, a, b, p0, p1):
        d = p1 - p0
        length = float(np.hypot(*d))
        fields = {"anchor": tuple(map(float, p0)), "axis": (float(d[0] / length), float(d[1] / length))}
        if self.editor.tool_options.slider_limits:
            fields.update(lower=0.0, upper=length)
        add_joint(self.editor, "prismatic", a, b, **fields)

    def decorate(self, decor, cursor):
        if self.start is not None:
            p0 = self.start[2]
            decor.segments.append((p0, cursor, 2.0, PREVIEW))
            decor.points.append((p0, 4.0, PREVIEW))

