"""Drawing a comparison: the rivals as ghost outlines over the scene, or split view (the free area
in equal columns, the main world in the left one and each rival in one of its own, the same
region of the world in every column, the camera shared so tools and panning work in the left
pane as usual)."""
from __future__ import annotations

import numpy as np
from imgui_bundle import imgui

from . import framing
from .camera import Camera
from .compare import LANE_COLORS
from .render.ghost import LaneLayers

DIVIDER = (0.85, 0.88, 0.95, 0.9)


class CompareView:
    """Per-lane vertex layers of ``app.compare`` and the panes of split view."""

    def __init__(self, app):
        self.app = app
        self.layers: list[LaneLayers] = []

    def set_view(self, view):
        """"ghost" or "split" (ValueError otherwise); split view frames the scene in the left pane."""
        cmp = self.app.compare
        if view not in cmp.VIEWS:
            raise ValueError(f"view: choose one of {list(cmp.VIEWS)}, got {view!r}")
        cmp.view = view
        if view == "split":
            app = self.app
            framing.fit(app.camera, app.bound.content(app.world.render_data()), [self.panes()[0]])

    def split(self) -> bool:
        cmp = self.app.compare
        return cmp.active and cmp.view == "split" and bool(cmp.lanes)

    def panes(self):
        """Window rectangles (y down) of split view, left to right: the main world's and one per
        rival, the free area in equal columns."""
        x0, y0, x1, y1 = self.app.free_rect()
        n = 1 + max(1, len(self.app.compare.lanes))
        w = (x1 - x0) / n
        return [(x0 + k * w, y0, x0 + (k + 1) * w, y1) for k in range(n)]

    def build(self):
        """Upload every rival's bodies (ghost outlines, or solid in split view's right pane)."""
        cmp = self.app.compare
        lanes = cmp.lanes if cmp.active else []
        while len(self.layers) < len(lanes):
            self.layers.append(LaneLayers(self.app.renderer))
        split = self.split()
        for k, layer in enumerate(self.layers):
            if k < len(lanes):
                layer.build(lanes[k].world.render_data(), lanes[k].color, solid=split, scale=self.app.camera.scale)
            else:
                layer.clear()

    def draw(self, fw, fh):
        """Draw the scene and the comparison into the framebuffer (fw x fh pixels)."""
        app, r = self.app, self.app.renderer
        if not self.split():
            extra = [lay for layer in self.layers for lay in layer.layers]
            r.draw(app.camera, fw, fh, extra=extra)
            return
        panes = self.panes()
        left = panes[0]
        sx = fw / max(1, app.width)
        # the main world left of the first divider (under the side panel too), each rival in its column
        r.draw(app.camera, fw, fh, scissor=(0, 0, panes[1][0] * sx, fh))
        for k, pane in enumerate(panes[1:]):
            cam = Camera(app.camera.width, app.camera.height, app.camera.center, app.camera.scale)
            cam.center = app.camera.center - np.array([(pane[0] - left[0]) / cam.scale, 0.0])
            x0, x1 = pane[0] * sx, (fw if k == len(panes) - 2 else pane[2] * sx)
            r.draw(cam, fw, fh, extra=self.layers[k].layers, scissor=(x0, 0, x1 - x0, fh), scene=False)

    def labels(self):
        """The panes' names and the divider (imgui's background list: the panels stay above)."""
        if not self.split():
            return
        app = self.app
        panes = self.panes()
        dl = imgui.get_background_draw_list()
        for x0, y0, _, y1 in panes[1:]:
            dl.add_line(imgui.ImVec2(x0, y0), imgui.ImVec2(x0, y1), imgui.get_color_u32(imgui.ImVec4(*DIVIDER)), 2.0)
        names = [(f"main: {app.world.solver}", LANE_COLORS[0])] + [(ln.label, ln.color) for ln in app.compare.lanes]
        for (x0, y0, _, _), (text, col) in zip(panes, names):
            dl.add_text(imgui.ImVec2(x0 + 10, y0 + 8), imgui.get_color_u32(imgui.ImVec4(*col)), text)
