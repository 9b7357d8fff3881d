"""Batched OpenGL 3.3 core renderer.

Every layer is one vertex buffer rebuilt with numpy each frame from
``world.render_data()`` and drawn with one call: no per-body Python loop.
Shaders live in ``shaders/*.glsl``-style files next to the package
(``shaders/poly.vert`` ...), loaded and compiled at start.
"""
from __future__ import annotations

import ctypes
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from OpenGL import GL

SHADER_DIR = Path(os.environ.get("STELKROPP_SHADERS", Path(__file__).resolve().parent.parent / "shaders"))

F32 = np.float32


def _rgba(hexstr: str, a: float = 1.0) -> np.ndarray:
    h = hexstr.lstrip("#")
    return np.array([int(h[i:i + 2], 16) / 255.0 for i in (0, 2, 4)] + [a], dtype=F32)


# colours by state (fill, outline)
DYNAMIC_FILLS = np.stack([_rgba(c) for c in ("#4f8fd6", "#5aa2e0", "#4a7fc9", "#62a8d8", "#5891e3", "#4c9ac8")])
STATIC_FILL, STATIC_LINE = _rgba("#4a5361"), _rgba("#8a97a8")
KINEMATIC_FILL, KINEMATIC_LINE = _rgba("#8f6bd1"), _rgba("#d4c2f5")
SLEEP_FILL = _rgba("#44617f")
DYNAMIC_LINE = _rgba("#d8ecff")
SLEEP_LINE = _rgba("#8ea4bb")
SELECT_FILL, SELECT_LINE = _rgba("#f0a040"), _rgba("#fff2c0")
HOVER_TINT = 0.22
SPRING_COLOR = _rgba("#e8c45a")
SPRING_SELECTED = _rgba("#fff2c0")
CONTACT_COLOR = _rgba("#ff5a5a")
NORMAL_COLOR = _rgba("#ffd05a")
AABB_COLOR = _rgba("#7fe0a0", 0.55)
QUADTREE_COLOR = _rgba("#c890ff", 0.45)
VEL_COLOR = _rgba("#6df0ff", 0.9)
COM_COLOR = _rgba("#ffffff")
PREVIEW_COLOR = _rgba("#ffffff", 0.85)


def load_program(name: str) -> int:
    """Compile and link shaders/<name>.vert + shaders/<name>.frag."""
    shaders = []
    for ext, kind in (("vert", GL.GL_VERTEX_SHADER), ("frag", GL.GL_FRAGMENT_SHADER)):
        path = SHADER_DIR / f"{name}.{ext}"
        src = path.read_text()
        sh = GL.glCreateShader(kind)
        GL.glShaderSource(sh, src)
        GL.glCompileShader(sh)
        if not GL.glGetShaderiv(sh, GL.GL_COMPILE_STATUS):
            log = GL.glGetShaderInfoLog(sh).decode(errors="replace")
            raise RuntimeError(f"shader {path} failed to compile:\n{log}")
        shaders.append(sh)
    prog = GL.glCreateProgram()
    for sh in shaders:
        GL.glAttachShader(prog, sh)
    GL.glLinkProgram(prog)
    if not GL.glGetProgramiv(prog, GL.GL_LINK_STATUS):
        log = GL.glGetProgramInfoLog(prog).decode(errors="replace")
        raise RuntimeError(f"shader program {name} failed to link:\n{log}")
    for sh in shaders:
        GL.glDeleteShader(sh)
    return prog


class Layer:
    """One VAO + one VBO with an interleaved float32 layout; rebuilt per frame."""

    def __init__(self, program: int, sizes: list[int], mode=GL.GL_TRIANGLES):
        self.program = program
        self.mode = mode
        self.sizes = sizes
        self.stride = sum(sizes)
        self.vao = GL.glGenVertexArrays(1)
        self.vbo = GL.glGenBuffers(1)
        self.count = 0
        self.capacity = 0
        GL.glBindVertexArray(self.vao)
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, self.vbo)
        off = 0
        for loc, size in enumerate(sizes):
            GL.glEnableVertexAttribArray(loc)
            GL.glVertexAttribPointer(loc, size, GL.GL_FLOAT, GL.GL_FALSE, self.stride * 4, ctypes.c_void_p(off * 4))
            off += size
        GL.glBindVertexArray(0)

    def upload(self, data: np.ndarray) -> None:
        data = np.ascontiguousarray(data, dtype=F32)
        assert data.ndim == 2 and data.shape[1] == self.stride, (data.shape, self.stride)
        self.count = len(data)
        GL.glBindBuffer(GL.GL_ARRAY_BUFFER, self.vbo)
        nbytes = data.nbytes
        if nbytes > self.capacity:
            self.capacity = max(nbytes, 2 * self.capacity, 4096)
            GL.glBufferData(GL.GL_ARRAY_BUFFER, self.capacity, None, GL.GL_STREAM_DRAW)
        else:
            GL.glBufferData(GL.GL_ARRAY_BUFFER, self.capacity, None, GL.GL_STREAM_DRAW)  # orphan
        if nbytes:
            GL.glBufferSubData(GL.GL_ARRAY_BUFFER, 0, nbytes, data)

    def draw(self) -> None:
        if self.count:
            GL.glBindVertexArray(self.vao)
            GL.glDrawArrays(self.mode, 0, self.count)


@dataclass
class Overlays:
    contacts: bool = False
    aabbs: bool = False
    quadtree: bool = False
    velocities: bool = False
    com: bool = False
    springs: bool = True


@dataclass
class Decor:
    """Extra things to draw this frame (tool previews, mouse joint, selection)."""
    selected_bodies: set = field(default_factory=set)   # body ids
    hovered_body: int | None = None
    selected_springs: set = field(default_factory=set)  # spring ids
    hidden_springs: set = field(default_factory=set)    # spring ids drawn as plain lines (mouse joint)
    segments: list = field(default_factory=list)        # (p0, p1, width_px, rgba)
    points: list = field(default_factory=list)          # (p, radius_px, rgba)


def thick_segments(p0: np.ndarray, p1: np.ndarray, width_px, color, scale: float) -> np.ndarray:
    """Quads (6 vertices each) for segments p0->p1: columns x, y, side, r, g, b, a."""
    n = len(p0)
    if n == 0:
        return np.zeros((0, 7), F32)
    d = p1 - p0
    ln = np.hypot(d[:, 0], d[:, 1])
    ln[ln == 0] = 1.0
    nrm = np.stack([-d[:, 1], d[:, 0]], 1) / ln[:, None]
    hw = (0.5 * np.broadcast_to(np.asarray(width_px, dtype=np.float64), (n,)) + 1.0) / scale
    off = nrm * hw[:, None]
    # extend each segment a little along its direction so joins close
    ext = d / ln[:, None] * (0.5 * hw[:, None])
    a0, a1 = p0 - ext - off, p0 - ext + off
    b0, b1 = p1 + ext - off, p1 + ext + off
    out = np.empty((n, 6, 7), F32)
    out[:, :, 0:2] = np.stack([a0, b0, b1, a0, b1, a1], 1)
    out[:, :, 2] = np.array([-1, -1, 1, -1, 1, 1], F32)
    out[:, :, 3:7] = np.broadcast_to(np.asarray(color, F32).reshape(-1, 1, 4), (n, 6, 4))
    return out.reshape(-1, 7)


def discs(centers: np.ndarray, radius: np.ndarray, angle: np.ndarray, spoke, fill, line) -> np.ndarray:
    """Quads for discs: columns x, y, lx, ly, radius, spoke, fill(4), line(4)."""
    n = len(centers)
    if n == 0:
        return np.zeros((0, 14), F32)
    k = 1.08
    corners = np.array([[-k, -k], [k, -k], [k, k], [-k, -k], [k, k], [-k, k]])
    c, s = np.cos(angle), np.sin(angle)
    # world = center + radius * R(angle) @ corner
    wx = c[:, None] * corners[None, :, 0] - s[:, None] * corners[None, :, 1]
    wy = s[:, None] * corners[None, :, 0] + c[:, None] * corners[None, :, 1]
    out = np.empty((n, 6, 14), F32)
    out[:, :, 0] = centers[:, None, 0] + radius[:, None] * wx
    out[:, :, 1] = centers[:, None, 1] + radius[:, None] * wy
    out[:, :, 2:4] = corners[None]
    out[:, :, 4] = radius[:, None]
    out[:, :, 5] = np.broadcast_to(np.asarray(spoke, F32).reshape(-1, 1), (n, 6))
    out[:, :, 6:10] = np.broadcast_to(np.asarray(fill, F32).reshape(-1, 1, 4), (n, 6, 4))
    out[:, :, 10:14] = np.broadcast_to(np.asarray(line, F32).reshape(-1, 1, 4), (n, 6, 4))
    return out.reshape(-1, 14)


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
        self._topo_key = None
        self._edge_body = self._ia = self._ib = None
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
    def _topology(self, vstart, vcount):
        poly = np.nonzero(vcount >= 3)[0]
        key = (len(vcount), poly.tobytes(), vstart[poly].tobytes(), vcount[poly].tobytes())
        if key != self._topo_key:
            counts = vcount[poly].astype(np.int64)
            edge_body = np.repeat(poly, counts)
            starts = np.repeat(np.cumsum(counts) - counts, counts)
            k = np.arange(counts.sum()) - starts
            cnt = np.repeat(counts, counts)
            base = np.repeat(vstart[poly].astype(np.int64), counts)
            self._edge_body, self._ia, self._ib = edge_body, base + k, base + (k + 1) % np.maximum(cnt, 1)
            self._topo_key = key
        return self._edge_body, self._ia, self._ib

    @staticmethod
    def body_colors(rd, decor: Decor):
        n = len(rd.kind)
        kind = rd.kind
        fill = DYNAMIC_FILLS[(rd.ids.astype(np.int64) * 7) % len(DYNAMIC_FILLS)].copy()
        line = np.broadcast_to(DYNAMIC_LINE, (n, 4)).copy()
        asleep = (rd.awake == 0) & (kind == 0)
        fill[asleep] = SLEEP_FILL
        line[asleep] = SLEEP_LINE
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
        scale = camera.scale
        fill, line = self.body_colors(rd, decor)
        # polygons: a fan of (centre, v_i, v_i+1) per edge
        eb, ia, ib = self._topology(rd.vstart, rd.vcount)
        V = rd.vertices
        if len(eb):
            c = rd.center[eb]
            a = V[ia]
            b = V[ib]
            e = b - a
            el = np.hypot(e[:, 0], e[:, 1])
            el[el == 0] = 1.0
            dist = np.abs(e[:, 0] * (c[:, 1] - a[:, 1]) - e[:, 1] * (c[:, 0] - a[:, 0])) / el
            m = len(eb)
            pv = np.empty((m, 3, 11), F32)
            pv[:, 0, 0:2] = c
            pv[:, 1, 0:2] = a
            pv[:, 2, 0:2] = b
            pv[:, 0, 2] = dist
            pv[:, 1:, 2] = 0.0
            pv[:, :, 3:7] = fill[eb][:, None, :]
            pv[:, :, 7:11] = line[eb][:, None, :]
            polys = pv.reshape(-1, 11)
        else:
            polys = np.zeros((0, 11), F32)
        # circle bodies
        ci = np.nonzero(rd.vcount == 0)[0]
        circles = discs(rd.center[ci], rd.radius[ci], rd.angle[ci], 1.0, fill[ci], line[ci])
        # lines: springs, overlays, decorations
        segs = []
        ends = rd.spring_ends
        if overlays.springs and len(ends):
            mask = np.ones(len(ends), bool)
            sel = np.zeros(len(ends), bool)
            if spring_ids is not None and (decor.hidden_springs or decor.selected_springs):
                mask = ~np.isin(spring_ids, list(decor.hidden_springs) or [-1])
                sel = np.isin(spring_ids, list(decor.selected_springs) or [-1])
            segs += self._coils(ends[mask & ~sel], scale, SPRING_COLOR)
            segs += self._coils(ends[mask & sel], scale, SPRING_SELECTED, 3.0)
        if overlays.quadtree and quadtree is not None and len(quadtree):
            segs.append(self._rects(quadtree, 1.0, QUADTREE_COLOR, scale))
        if overlays.aabbs and len(rd.aabb):
            segs.append(self._rects(rd.aabb, 1.0, AABB_COLOR, scale))
        if overlays.velocities and len(rd.kind):
            dyn = np.nonzero(rd.kind == 0)[0]
            from_ = rd.center[dyn]
            v = velocities[dyn] if velocities is not None and len(velocities) == len(rd.kind) \
                else np.zeros_like(from_)
            sp = np.hypot(v[:, 0], v[:, 1])
            keep = sp > 1e-3
            from_, v, sp = from_[keep], v[keep], sp[keep]
            to = from_ + v * 0.2
            d = v / sp[:, None]
            hl = np.minimum(10.0 / scale, 0.4 * sp * 0.2)[:, None]
            nrm = np.stack([-d[:, 1], d[:, 0]], 1)
            h1 = to - d * hl + nrm * hl * 0.5
            h2 = to - d * hl - nrm * hl * 0.5
            segs.append(thick_segments(np.concatenate([from_, to, to]), np.concatenate([to, h1, h2]),
                                       1.5, VEL_COLOR, scale))
        if overlays.contacts and len(rd.contact_points):
            p = rd.contact_points
            segs.append(thick_segments(p, p + rd.contact_normals * (22.0 / scale), 1.5, NORMAL_COLOR, scale))
        if decor.segments:
            p0 = np.array([s[0] for s in decor.segments], dtype=np.float64)
            p1 = np.array([s[1] for s in decor.segments], dtype=np.float64)
            w = np.array([s[2] for s in decor.segments])
            col = np.array([s[3] for s in decor.segments], F32)
            segs.append(thick_segments(p0, p1, w, col, scale))
        lines = np.concatenate(segs) if segs else np.zeros((0, 7), F32)
        # markers: contact points, centres of mass, decoration points
        mk = []
        if overlays.contacts and len(rd.contact_points):
            p = rd.contact_points
            mk.append(discs(p, np.full(len(p), 3.5 / scale), np.zeros(len(p)), 0.0, CONTACT_COLOR, CONTACT_COLOR))
        if overlays.com and len(rd.kind):
            p = rd.center
            mk.append(discs(p, np.full(len(p), 3.0 / scale), np.zeros(len(p)), 0.0, COM_COLOR, _rgba("#202020")))
        if decor.points:
            p = np.array([q[0] for q in decor.points], dtype=np.float64)
            r = np.array([q[1] for q in decor.points]) / scale
            col = np.array([q[2] for q in decor.points], F32)
            mk.append(discs(p, r, np.zeros(len(p)), 0.0, col, col))
        markers = np.concatenate(mk) if mk else np.zeros((0, 14), F32)
        self.polys.upload(polys)
        self.circles.upload(circles)
        self.lines.upload(lines)
        self.markers.upload(markers)
        self.last_upload_ms = (time.perf_counter() - t0) * 1e3

    @staticmethod
    def _rects(bx, width, color, scale):
        """Outlines of axis-aligned rectangles (K, 4: min x, min y, max x, max y): 4 quads each."""
        bx = np.asarray(bx, dtype=np.float64)
        c00, c10 = bx[:, [0, 1]], bx[:, [2, 1]]
        c11, c01 = bx[:, [2, 3]], bx[:, [0, 3]]
        p0 = np.concatenate([c00, c10, c11, c01])
        p1 = np.concatenate([c10, c11, c01, c00])
        return thick_segments(p0, p1, width, color, scale)

    @staticmethod
    def _coils(ends, scale, color, width=2.0):
        if not len(ends):
            return []
        a, b = ends[:, 0], ends[:, 1]
        coils = 9
        t = np.concatenate([[0.0, 0.12], np.linspace(0.12, 0.88, 2 * coils + 1)[1:-1], [0.88, 1.0]])
        off = np.zeros_like(t)
        off[2:-2] = np.where(np.arange(len(t) - 4) % 2 == 0, 1.0, -1.0)
        d = b - a
        ln = np.hypot(d[:, 0], d[:, 1])
        ln1 = np.where(ln == 0, 1.0, ln)
        nrm = np.stack([-d[:, 1], d[:, 0]], 1) / ln1[:, None]
        amp = np.clip(0.08 * np.maximum(ln, 0.5), 4.0 / scale, 0.25)  # world metres
        amp = np.where(ln * scale < 50.0, 0.0, amp)   # short on screen: a plain line reads better
        pts = a[:, None, :] + t[None, :, None] * d[:, None, :] + (off[None, :, None] * amp[:, None, None]) * nrm[:, None, :]
        p0 = pts[:, :-1].reshape(-1, 2)
        p1 = pts[:, 1:].reshape(-1, 2)
        out = [thick_segments(p0, p1, width, color, scale)]
        return out

    @staticmethod
    def grid_lines(camera):
        """Minor/major metre grid and the axes as thin quads (a few hundred vertices)."""
        lo, hi = camera.visible_box()
        step = 10.0 ** np.ceil(np.log10(max(1e-6, 24.0 / camera.scale)))
        segs = []
        for axis in (0, 1):
            other = 1 - axis
            k0, k1 = int(np.floor(lo[axis] / step)), int(np.ceil(hi[axis] / step))
            if k1 - k0 > 400:
                continue
            ks = np.arange(k0, k1 + 1)
            pos = ks * step
            major = ks % 5 == 0
            p0 = np.zeros((len(ks), 2))
            p1 = np.zeros((len(ks), 2))
            p0[:, axis] = p1[:, axis] = pos
            p0[:, other], p1[:, other] = lo[other], hi[other]
            col = np.where(major[:, None], np.array([[1, 1, 1, 0.075]]), np.array([[1, 1, 1, 0.035]]))
            col[ks == 0] = (0.55, 0.62, 0.78, 0.35)
            v = np.empty((len(ks), 2, 6), F32)
            v[:, 0, :2], v[:, 1, :2] = p0, p1
            v[:, :, 2:] = col[:, None, :]
            segs.append(v.reshape(-1, 6))
        return np.concatenate(segs) if segs else np.zeros((0, 6), F32)

    # -- drawing -------------------------------------------------------------
    def draw(self, camera, width_px: int, height_px: int, clear=True):
        t0 = time.perf_counter()
        GL.glViewport(0, 0, width_px, height_px)
        GL.glDisable(GL.GL_DEPTH_TEST)
        GL.glDisable(GL.GL_CULL_FACE)
        GL.glEnable(GL.GL_BLEND)
        GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)
        # background: a clear and grid lines (a full-screen shader costs ~35 ms on llvmpipe)
        GL.glClearColor(0.062, 0.072, 0.098, 1.0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        self.grid.upload(self.grid_lines(camera))
        view = camera.matrix()
        for layer in (self.grid, self.polys, self.circles, self.lines, self.markers):
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
        self.last_draw_ms = (time.perf_counter() - t0) * 1e3
