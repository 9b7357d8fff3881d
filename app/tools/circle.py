"""Circle tool: drag from the centre to the rim."""
from __future__ import annotations

import physics

from .radial import RadialTool


class CircleTool(RadialTool):
    name = "circle"
    help = "drag from the centre: draw a circle (click: a default circle)"

    def shape(self, r):
        return physics.Circle(r)
