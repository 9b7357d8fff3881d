"""A comparison lane's bodies: drawn over the scene as tinted outlines (ghost view) or as tinted
bodies in a pane of their own (split view), in the lane's colour; a compound body's every
fixture drawn (circles at their own centres, rounded parts, segments and chains as lines)."""
from __future__ import annotations

import numpy as np

from .fans import Fans
from .gl import Layer
from .parts import Parts
from .renderer import Renderer

F32 = np.float32
GHOST_FILL_ALPHA = 0.10     # ghost view: the scene shows through the rival's bodies
SOLID_FILL = 0.55           # split view: the lane colour's share of the fill (the rest is dark)
STATIC_SHADE = (0.29, 0.33, 0.38, 1.0)


def lane_arrays(rd, color, solid=False, scale=1.0, fans=None):
    """(polygon fans, discs, lines) vertex arrays of ``rd``'s bodies in ``color`` (RGBA), every
    fixture drawn by itself as the scene's renderer draws it (app.render.parts): outlines with a
    faint fill, or (``solid``) filled bodies; static bodies grey either way (in ghost view they
    are left out: the main scene draws the same walls).  ``scale``: pixels per metre (the lines'
    width is in pixels); ``fans``: the lane's Fans (its fan topology kept between frames)."""
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
    parts = Parts(rd) if getattr(rd, "fixtures", None) is not None else None
    polys = (fans or Fans()).build(rd, fill, line, parts)
    return polys, Renderer.circle_layer(rd, parts, fill, line), Renderer.shape_lines(parts, line, scale)


class LaneLayers:
    """Vertex layers for one lane, built from its world's render data every frame."""

    def __init__(self, renderer):
        self.polys = Layer(renderer.prog_poly, [2, 1, 4, 4])
        self.circles = Layer(renderer.prog_circle, [2, 2, 1, 1, 4, 4])
        self.lines = Layer(renderer.prog_line, [2, 1, 4])
        self.fans = Fans()

    @property
    def layers(self):
        return (self.polys, self.circles, self.lines)

    def build(self, rd, color, solid=False, scale=1.0):
        """Upload ``rd``'s bodies (see :func:`lane_arrays`)."""
        polys, circles, lines = lane_arrays(rd, color, solid, scale, self.fans)
        self.polys.upload(polys)
        self.circles.upload(circles)
        self.lines.upload(lines)

    def clear(self):
        self.polys.count = self.circles.count = self.lines.count = 0
