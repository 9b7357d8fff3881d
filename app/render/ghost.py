"""A comparison lane's bodies: drawn over the scene as tinted outlines (ghost view) or as tinted
bodies in a pane of their own (split view), in the lane's colour."""
from __future__ import annotations

import numpy as np

from .fans import Fans
from .geometry import discs
from .gl import Layer

F32 = np.float32
GHOST_FILL_ALPHA = 0.10     # ghost view: the scene shows through the rival's bodies
SOLID_FILL = 0.55           # split view: the lane colour's share of the fill (the rest is dark)
STATIC_SHADE = (0.29, 0.33, 0.38, 1.0)


class LaneLayers:
    """Vertex layers for one lane, built from its world's render data every frame."""

    def __init__(self, renderer):
        self.polys = Layer(renderer.prog_poly, [2, 1, 4, 4])
        self.circles = Layer(renderer.prog_circle, [2, 2, 1, 1, 4, 4])
        self.fans = Fans()

    @property
    def layers(self):
        return (self.polys, self.circles)

    def build(self, rd, color, solid=False):
        """Upload ``rd``'s bodies in ``color`` (RGBA): outlines with a faint fill, or (``solid``)
        filled bodies; static bodies grey either way (in ghost view they are left out: the main
        scene draws the same walls)."""
        n = len(rd.kind)
        col = np.asarray(color, F32)
        static = rd.kind != 0
        line = np.broadcast_to(col, (n, 4)).copy()
        if solid:
            fill = np.empty((n, 4), F32)
            fill[:, :3] = col[:3] * SOLID_FILL + 0.08 * (1 - SOLID_FILL)
            fill[:, 3] = 1.0
            fill[static] = STATIC_SHADE
            line[static] = (0.55, 0.6, 0.68, 1.0)
            keep = np.ones(n, bool)
        else:
            fill = np.broadcast_to(np.array([*col[:3], GHOST_FILL_ALPHA], F32), (n, 4)).copy()
            keep = ~static
        fill[~keep, 3] = 0.0
        line[~keep, 3] = 0.0
        self.polys.upload(self.fans.build(rd, fill, line))
        ci = np.nonzero((rd.vcount == 0) & keep)[0]
        self.circles.upload(discs(rd.center[ci], rd.radius[ci], rd.angle[ci], 1.0, fill[ci], line[ci]))

    def clear(self):
        self.polys.count = self.circles.count = 0

