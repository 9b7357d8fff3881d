"""Regular polygon tool: drag from the centre; the number of sides comes from the palette."""
from __future__ import annotations

import physics

from .radial import RadialTool


class NgonTool(RadialTool):
    name = "n-gon"
    help = "drag from the centre: a regular polygon (sides in the palette)"

    def shape(self, r):
        return physics.Polygon.regular(self.editor.tool_options.sides, r)

    def outline(self, r):
        return self.shape(r).vertices
