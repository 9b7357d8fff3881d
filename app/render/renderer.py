"""Batched OpenGL 3.3 core renderer.

Every layer is one vertex buffer rebuilt with numpy each frame from
``world.render_data()`` and drawn with one call: no per-body Python loop.
Shaders live in ``shaders/`` at the project root (``shaders/poly.vert`` ...),
loaded and compiled at start.
"""
from __future__ import annotations

import time

import numpy as np
from OpenGL import GL

from .colors import (AABB_COLOR, COM_COLOR, COM_EDGE, CONTACT_COLOR, DYNAMIC_LINE, HOVER_TINT, KINEMATIC_FILL,
                     KINEMATIC_LINE, NORMAL_COLOR, QUADTREE_COLOR, SELECT_FILL, SELECT_LINE, SLEEP_LINE, SPRING_COLOR, SPRING_SELECTED, STATIC_FILL, STATIC_LINE,
                     VEL_COLOR, asleep, default_fills)
from .decor import Decor, Overlays
from .fans import Fans
from .geometry import arrows, coils, discs, grid_lines, rects, thick_segments
from .gl import Layer, load_program
from .joints import joint_lines, joint_markers
from .parts import Parts
from .sensors import sensor_colors

F32 = np.float32


class Renderer:
    def __init__(self):
        self.prog_poly = load_program("poly")
        self.prog_circle = load_program("circle")
        self.prog_line = load_program("line")
        self.prog_flat = load_program("flat")
        self.grid = Layer(self.prog_flat, [2, 4], GL.GL_LINES)
        self.polys = Layer(self.prog_poly, [2, 1, 4, 4])
        self.circles = Layer(self.prog_circle, [2, 2, 1, 1, 4, 4])
        self.lines = Layer(self.prog_line, [2, 1, 4])
        self.markers = Layer(self.prog_circle, [2, 2, 1, 1, 4, 4])
        self.fans = Fans()
        self.outline_px = 1.6
        self.uniforms = {}
        self.last_upload_ms = 0.0
        self.last_draw_ms = 0.0

    def _loc(self, prog, name):
        key = (prog, name)
        if key not in self.uniforms:
            self.uniforms[key] = GL.glGetUniformLocation(prog, name)
        return self.uniforms[key]

    # -- geometry ------------------------------------------------------------
    @staticmethod
    def body_colors(rd, decor: Decor):
        n = len(rd.kind)
        kind = rd.kind
        fill = default_fills(rd.ids)
        line = np.broadcast_to(DYNAMIC_LINE, (n, 4)).copy()
        if decor.colors:
            own = np.isin(rd.ids, np.fromiter(decor.colors, np.int64))
            idx = np.nonzero(own)[0]
            fill[idx, :3] = np.array([decor.colors[int(i)] for i in rd.ids[idx]], F32)
        sleeping = (rd.awake == 0) & (kind == 0)
        fill[sleeping, :3] = asleep(fill[sleeping, :3])
        line[sleeping] = SLEEP_LINE
        st = kind == 1
        fill[st], line[st] = STATIC_FILL, STATIC_LINE
        kin = kind == 2
        fill[kin], line[kin] = KINEMATIC_FILL, KINEMATIC_LINE
        if decor.hovered_body is not None:
            h = rd.ids == decor.hovered_body
            fill[h, :3] = fill[h, :3] + (1.0 - fill[h, :3]) * HOVER_TINT
            line[h] = SELECT_LINE
        if decor.selected_bodies:
            sel = np.isin(rd.ids, np.fromiter(decor.selected_bodies, np.int64))
            fill[sel, :3] = 0.45 * fill[sel, :3] + 0.55 * SELECT_FILL[:3]
            line[sel] = SELECT_LINE
        return fill, line

    def build(self, rd, camera, overlays: Overlays, decor: Decor, spring_ids=None, quadtree=None,
              velocities=None):
        """numpy: render data -> vertex arrays for every layer, then upload them.

        ``quadtree``: (K, 4) cell rectangles (``world.quadtree_cells()``) when that overlay is on;
        ``velocities``: (N, 2) body velocities in render-data order when the arrows are on."""
        t0 = time.perf_counter()
        fill, line = self.body_colors(rd, decor)
        parts = Parts(rd) if getattr(rd, "fixtures", None) is not None else None
        sc = sensor_colors(parts, fill, line, decor.sensors) if parts is not None and decor.sensors else None
        self.polys.upload(self.fans.build(rd, fill, line, parts, sc and sc[0]))
        self.circles.upload(self.circle_layer(rd, parts, fill, line, sc and sc[1]))
        shape_lines = self.shape_lines(parts, line, camera.scale)
        self.lines.upload(np.concatenate([shape_lines, self.line_layer(rd, camera.scale, overlays, decor, spring_ids,
                                                                       quadtree, velocities)]))
        self.markers.upload(self.marker_layer(rd, camera.scale, overlays, decor))
        self.last_upload_ms = (time.perf_counter() - t0) * 1e3

    def polygon_fans(self, rd, fill, line):
        """The polygon fixtures' fans (see :class:`app.render.fans.Fans`)."""
        parts = Parts(rd) if getattr(rd, "fixtures", None) is not None else None
        return self.fans.build(rd, fill, line, parts)

    @staticmethod
    def circle_layer(rd, parts, fill, line, part_colors=None):
        """Circle fixtures as discs at their own centres, turning with their body (the spoke);
        ``part_colors``: (fill, line) per circle fixture instead of per body (sensors)."""
        if parts is None:
            ci = np.nonzero(rd.vcount == 0)[0]
            return discs(rd.center[ci], rd.radius[ci], rd.angle[ci], 1.0, fill[ci], line[ci])
        b = parts.circle_body
        f, ln = part_colors if part_colors is not None else (fill[b], line[b])
        return discs(parts.circle_centre, parts.circle_radius, rd.angle[b], 1.0, f, ln)

    @staticmethod
    def shape_lines(parts, line, scale):
        """Segments and chain segments (no area): lines in their body's outline colour."""
        if parts is None or not len(parts.line_body):
            return np.zeros((0, 7), F32)
        return thick_segments(parts.line_p0, parts.line_p1, 2.5, line[parts.line_body], scale)

    @staticmethod
    def line_layer(rd, scale, overlays, decor, spring_ids, quadtree, velocities):
        """Springs, joints, the line overlays (quadtree, AABBs, velocities, normals) and tool previews."""
        segs = []
        ends = rd.spring_ends
        if overlays.springs and len(ends):
            mask = np.ones(len(ends), bool)
            sel = np.zeros(len(ends), bool)
            if spring_ids is not None and (decor.hidden_springs or decor.selected_springs):
                mask = ~np.isin(spring_ids, list(decor.hidden_springs) or [-1])
                sel = np.isin(spring_ids, list(decor.selected_springs) or [-1])
            segs += coils(ends[mask & ~sel], scale, SPRING_COLOR)
            segs += coils(ends[mask & sel], scale, SPRING_SELECTED, 3.0)
        if overlays.joints and rd.joints is not None and len(rd.joints):
            segs.append(joint_lines(rd.joints, scale, decor.selected_joints, decor.hidden_joints))
        if overlays.quadtree and quadtree is not None and len(quadtree):
            segs.append(rects(quadtree, 1.0, QUADTREE_COLOR, scale))
        if overlays.aabbs and len(rd.aabb):
            segs.append(rects(rd.aabb, 1.0, AABB_COLOR, scale))
        if overlays.velocities and len(rd.kind):
            dyn = np.nonzero(rd.kind == 0)[0]
            from_ = rd.center[dyn]
            v = velocities[dyn] if velocities is not None and len(velocities) == len(rd.kind) \
                else np.zeros_like(from_)
            segs.append(arrows(from_, v, scale, VEL_COLOR))
        if overlays.contacts and len(rd.contact_points):
            p = rd.contact_points
            segs.append(thick_segments(p, p + rd.contact_normals * (22.0 / scale), 1.5, NORMAL_COLOR, scale))
        if decor.trails is not None:
            p0, p1, col = decor.trails
            segs.append(thick_segments(p0, p1, 2.0, col.astype(F32), scale))
        if decor.segments:
            p0 = np.array([s[0] for s in decor.segments], dtype=np.float64)
            p1 = np.array([s[1] for s in decor.segments], dtype=np.float64)
            w = np.array([s[2] for s in decor.segments])
            col = np.array([s[3] for s in decor.segments], F32)
            segs.append(thick_segments(p0, p1, w, col, scale))
        return np.concatenate(segs) if segs else np.zeros((0, 7), F32)

    @staticmethod
    def marker_layer(rd, scale, overlays, decor):
        """Joint pins and hubs, contact points, centres of mass and tool points as small discs."""
        mk = []
        if overlays.joints and rd.joints is not None and len(rd.joints):
            mk.append(joint_markers(rd.joints, scale, decor.selected_joints, decor.hidden_joints, decor.motor_pins))
        if overlays.contacts and len(rd.contact_points):
            p = rd.contact_points
            mk.append(discs(p, np.full(len(p), 3.5 / scale), np.zeros(len(p)), 0.0, CONTACT_COLOR, CONTACT_COLOR))
        if overlays.com and len(rd.kind):
            p = rd.center
            mk.append(discs(p, np.full(len(p), 3.0 / scale), np.zeros(len(p)), 0.0, COM_COLOR, COM_EDGE))
        if decor.points:
            p = np.array([q[0] for q in decor.points], dtype=np.float64)
            r = np.array([q[1] for q in decor.points]) / scale
            col = np.array([q[2] for q in decor.points], F32)
            mk.append(discs(p, r, np.zeros(len(p)), 0.0, col, col))
        return np.concatenate(mk) if mk else np.zeros((0, 14), F32)

    # -- drawing -------------------------------------------------------------
    def draw(self, camera, width_px: int, height_px: int, clear=True, extra=(), scissor=None, scene=True):
        """Draw the grid, the scene's layers (unless ``scene`` is False) with ``camera``, then
        ``extra`` layers (comparison lanes).  ``scissor``: (x, y, w, h) framebuffer pixels (y up)
        to draw into, or None (all)."""
        t0 = time.perf_counter()
        GL.glViewport(0, 0, width_px, height_px)
        GL.glDisable(GL.GL_DEPTH_TEST)
        GL.glDisable(GL.GL_CULL_FACE)
        GL.glEnable(GL.GL_BLEND)
        GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)
        if scissor is not None:
            GL.glEnable(GL.GL_SCISSOR_TEST)
            GL.glScissor(*(int(v) for v in scissor))
        if clear:
            # background: a clear and grid lines (a full-screen shader costs ~35 ms on llvmpipe)
            GL.glClearColor(0.062, 0.072, 0.098, 1.0)
            GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        self.grid.upload(grid_lines(camera))
        own = (self.polys, self.circles, self.lines, self.markers) if scene else ()
        self.draw_layers(camera, (self.grid, *own, *extra))
        if scissor is not None:
            GL.glDisable(GL.GL_SCISSOR_TEST)
        self.last_draw_ms = (time.perf_counter() - t0) * 1e3

    def draw_layers(self, camera, layers):
        """Draw ``layers`` (app.render.gl.Layer) with ``camera``'s view."""
        view = camera.matrix()
        for layer in layers:
            if not layer.count:
                continue
            GL.glUseProgram(layer.program)
            GL.glUniformMatrix3fv(self._loc(layer.program, "u_view"), 1, GL.GL_TRUE, view)
            if layer.program not in (self.prog_line, self.prog_flat):
                GL.glUniform1f(self._loc(layer.program, "u_scale"), camera.scale)
                GL.glUniform1f(self._loc(layer.program, "u_outline"), self.outline_px)
            layer.draw()
        GL.glBindVertexArray(0)
        GL.glUseProgram(0)
