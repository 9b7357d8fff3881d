"""Mouse tools: select/drag (soft mouse joint), create box / polygon / n-gon / circle / spring."""
from __future__ import annotations

import math

import numpy as np

import physics

from .commands import AddBody, AddSpring, SetProperty

PREVIEW = (1.0, 1.0, 1.0, 0.85)
PREVIEW_DIM = (1.0, 1.0, 1.0, 0.35)
JOINT = (1.0, 0.85, 0.35, 0.95)


class ToolOptions:
    """Palette parameters shared by the creation tools."""

    def __init__(self):
        self.kind = "dynamic"
        self.sides = 6
        self.default_size = 1.0
        self.density = 1.0
        self.friction = 0.6
        self.restitution = 0.1
        self.spring_stiffness = 60.0
        self.spring_damping = 1.0
        self.joint_hertz = 4.0
        self.joint_damping_ratio = 0.7


def body_args(opts: ToolOptions, position, angle=0.0) -> dict:
    return {"kind": opts.kind, "position": tuple(map(float, position)), "angle": angle,
            "velocity": (0.0, 0.0), "angular_velocity": 0.0, "density": opts.density,
            "restitution": opts.restitution, "friction": (opts.friction, opts.friction), "name": None}


class Tool:
    name = ""
    help = ""

    def __init__(self, app):
        self.app = app

    def press(self, p, button, mods):
        pass

    def drag(self, p):
        pass

    def release(self, p):
        pass

    def key(self, symbol) -> bool:
        return False

    def cancel(self):
        pass

    def decorate(self, decor, cursor):
        pass

    def update(self, cursor):
        """Called every frame before stepping (the mouse joint follows the cursor here)."""


class SelectTool(Tool):
    name = "select"
    help = "click: select (shift: add), drag a dynamic body: pull it on a soft spring, release to throw; " \
           "drag a static body: move it"

    def __init__(self, app):
        super().__init__(app)
        self.joint = None          # the temporary world spring of the mouse joint
        self.body = None
        self.moving = None         # (body, grab offset, start position) for static/kinematic moves
        self.cursor = None

    def press(self, p, button, mods):
        from pyglet.window import key as K
        app = self.app
        b = app.world.query_point(p)
        spring = None if b is not None else app.spring_near(p)
        if spring is not None:
            app.select(spring, add=bool(mods & K.MOD_SHIFT))
            return
        if b is None:
            if not mods & K.MOD_SHIFT:
                app.select(None)
            return
        app.select(b, add=bool(mods & K.MOD_SHIFT))
        self.cursor = np.array(p, dtype=float)
        if b.kind == "dynamic":
            self.start_joint(b, p)
        else:
            self.moving = (b, np.array(b.position) - np.array(p), b.position)

    def start_joint(self, b, p):
        opts = self.app.tool_options
        w = 2 * math.pi * opts.joint_hertz
        m = max(b.mass, 1e-6)
        self.body = b
        self.joint = self.app.world.add_spring(b, None, anchor_a=b.world_to_local(p), anchor_b=tuple(p),
                                               stiffness=m * w * w, damping=2 * m * opts.joint_damping_ratio * w,
                                               rest_length=0.0)
        self.app.tool_springs.add(self.joint.id)

    def drag(self, p):
        self.cursor = np.array(p, dtype=float)
        if self.moving is not None:
            b, off, _ = self.moving
            if b.alive:
                b.position = tuple(self.cursor + off)

    def update(self, cursor):
        if self.joint is not None:
            if not (self.joint.alive and self.body.alive):
                self.end_joint()
            elif self.cursor is not None:
                self.joint.anchor_b = tuple(self.cursor)

    def release(self, p):
        self.end_joint()
        if self.moving is not None:
            b, off, start = self.moving
            self.moving = None
            if b.alive and tuple(b.position) != tuple(start):
                new = b.position
                self.app.execute(SetProperty(self.app, b, "position", new, old=start))

    def end_joint(self):
        if self.joint is not None:
            if self.joint.alive:
                self.app.tool_springs.discard(self.joint.id)
                self.app.world.remove(self.joint)
            self.joint = None
            self.body = None

    def cancel(self):
        self.end_joint()
        self.moving = None

    def decorate(self, decor, cursor):
        if self.joint is not None and self.joint.alive:
            pa, pb = self.joint.endpoints()
            decor.hidden_springs.add(self.joint.id)
            decor.segments.append((pa, pb, 1.5, JOINT))
            decor.points.append((pa, 4.0, JOINT))
            decor.points.append((pb, 3.0, (1, 1, 1, 0.9)))


class BoxTool(Tool):
    name = "box"
    help = "drag: draw a box (click: a default box)"

    def __init__(self, app):
        super().__init__(app)
        self.start = None
        self.end = None

    def press(self, p, button, mods):
        self.start = self.end = np.array(p, dtype=float)

    def drag(self, p):
        if self.start is not None:
            self.end = np.array(p, dtype=float)

    def release(self, p):
        if self.start is None:
            return
        a, b = self.start, np.array(p, dtype=float)
        self.start = self.end = None
        size = np.abs(b - a)
        opts = self.app.tool_options
        if np.max(size) * self.app.camera.scale < 6:   # a click: default size
            size = np.array([opts.default_size, opts.default_size])
            centre = a
        else:
            size = np.maximum(size, 0.05)
            centre = 0.5 * (a + b)
        self.app.create(AddBody({"shape": physics.Polygon.box(*size), **body_args(opts, centre)}, "create box"))

    def cancel(self):
        self.start = self.end = None

    def decorate(self, decor, cursor):
        if self.start is not None:
            a, b = self.start, self.end
            c = [a, (b[0], a[1]), b, (a[0], b[1])]
            for i in range(4):
                decor.segments.append((c[i], c[(i + 1) % 4], 1.5, PREVIEW))


class RadialTool(Tool):
    """Press at the centre, drag out the radius (click: default size)."""

    def __init__(self, app):
        super().__init__(app)
        self.centre = None
        self.radius = 0.0

    def press(self, p, button, mods):
        self.centre = np.array(p, dtype=float)
        self.radius = 0.0

    def drag(self, p):
        if self.centre is not None:
            self.radius = float(np.hypot(*(np.array(p) - self.centre)))

    def release(self, p):
        if self.centre is None:
            return
        c, r = self.centre, self.radius
        self.centre = None
        if r * self.app.camera.scale < 6:
            r = 0.5 * self.app.tool_options.default_size
        r = max(r, 0.03)
        self.app.create(AddBody({"shape": self.shape(r), **body_args(self.app.tool_options, c)},
                                f"create {self.name}"))

    def cancel(self):
        self.centre = None

    def outline(self, r):
        k = 48
        t = np.linspace(0, 2 * np.pi, k, endpoint=False)
        return np.stack([np.cos(t), np.sin(t)], 1) * r

    def decorate(self, decor, cursor):
        if self.centre is not None and self.radius > 0:
            pts = self.outline(self.radius) + self.centre
            for i in range(len(pts)):
                decor.segments.append((pts[i], pts[(i + 1) % len(pts)], 1.5, PREVIEW))
            decor.segments.append((self.centre, cursor, 1.0, PREVIEW_DIM))


class CircleTool(RadialTool):
    name = "circle"
    help = "drag from the centre: draw a circle (click: a default circle)"

    def shape(self, r):
        return physics.Circle(r)


class NgonTool(RadialTool):
    name = "n-gon"
    help = "drag from the centre: a regular polygon (sides in the palette)"

    def shape(self, r):
        return physics.Polygon.regular(self.app.tool_options.sides, r)

    def outline(self, r):
        return self.shape(r).vertices


class PolygonTool(Tool):
    name = "polygon"
    help = "click points; Enter (or click the first point) makes their convex hull; Esc cancels"

    def __init__(self, app):
        super().__init__(app)
        self.points: list[np.ndarray] = []

    def press(self, p, button, mods):
        p = np.array(p, dtype=float)
        if len(self.points) >= 3 and np.hypot(*(p - self.points[0])) * self.app.camera.scale < 10:
            self.finish()
            return
        self.points.append(p)

    def finish(self):
        pts = np.array(self.points)
        self.points = []
        if len(pts) < 3:
            return
        try:
            shape = physics.Polygon.hull(pts)
        except ValueError as exc:
            self.app.notify(f"polygon refused: {exc}", error=True)
            return
        # vertices about the centroid, body placed at the centroid
        c = shape.centroid
        shape = physics.Polygon(shape.vertices - c)
        self.app.create(AddBody({"shape": shape, **body_args(self.app.tool_options, c)}, "create polygon"))

    def key(self, symbol) -> bool:
        from pyglet.window import key as K
        if symbol in (K.ENTER, K.RETURN):
            self.finish()
            return True
        if symbol == K.ESCAPE and self.points:
            self.points = []
            return True
        if symbol == K.BACKSPACE and self.points:
            self.points.pop()
            return True
        return False

    def cancel(self):
        self.points = []

    def decorate(self, decor, cursor):
        if not self.points:
            return
        pts = self.points + [np.array(cursor)]
        if len(pts) >= 3:
            try:
                h = physics.Polygon.hull(np.array(pts)).vertices
                for i in range(len(h)):
                    decor.segments.append((h[i], h[(i + 1) % len(h)], 1.0, PREVIEW_DIM))
            except ValueError:
                pass
        for i in range(len(self.points) - 1):
            decor.segments.append((self.points[i], self.points[i + 1], 1.5, PREVIEW))
        decor.segments.append((self.points[-1], cursor, 1.0, PREVIEW_DIM))
        for q in self.points:
            decor.points.append((q, 4.0, PREVIEW))


class SpringTool(Tool):
    name = "spring"
    help = "drag from a body to another body (or to empty space: a world anchor)"

    def __init__(self, app):
        super().__init__(app)
        self.a = None
        self.pa = None
        self.local_a = None

    def press(self, p, button, mods):
        b = self.app.world.query_point(p)
        if b is None:
            self.app.notify("start a spring on a body")
            return
        self.a, self.pa, self.local_a = b, np.array(p, dtype=float), b.world_to_local(p)

    def release(self, p):
        if self.a is None:
            return
        a, local_a = self.a, self.local_a
        self.a = None
        if not a.alive:
            return
        b = self.app.world.query_point(p)
        if b is a:
            b = None if np.hypot(*(np.array(p) - self.pa)) * self.app.camera.scale > 10 else a
            if b is a:
                return  # a click on one body: nothing
        opts = self.app.tool_options
        spec = {"a": self.app.refs.of(a), "b": None if b is None else self.app.refs.of(b),
                "anchor_a": local_a, "anchor_b": tuple(map(float, p)) if b is None else b.world_to_local(p),
                "stiffness": opts.spring_stiffness, "damping": opts.spring_damping, "rest_length": None,
                "name": None}
        self.app.create(AddSpring(spec))

    def cancel(self):
        self.a = None

    def decorate(self, decor, cursor):
        if self.a is not None and self.a.alive:
            pa = self.a.local_to_world(self.local_a)
            decor.segments.append((pa, cursor, 2.0, PREVIEW))
            decor.points.append((pa, 4.0, PREVIEW))


TOOLS = (SelectTool, BoxTool, PolygonTool, NgonTool, CircleTool, SpringTool)
