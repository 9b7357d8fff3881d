"""The sandbox window: pyglet event loop, fixed-timestep physics, input, drawing, imgui."""
from __future__ import annotations

import json
import math
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pyglet
from imgui_bundle import imgui, implot
from imgui_bundle.python_backends.pyglet_backend import create_renderer
from OpenGL import GL
from pyglet.window import key as K
from pyglet.window import mouse

import physics
from physics.scene import scene_metadata

from .autosave import Autosaver
from .camera import Camera
from .commands import AddBody, Group, RemoveBodies, RemoveSpring, SetProperty, SetWorld, body_spec
from .document import Document, demo_world, format_scene_error, load_world, restore
from .panels import PANEL_W, STATS_W, Panels, apply_style
from .renderer import Decor, Overlays, Renderer
from .tools import TOOLS, ToolOptions, body_args
from .warmup import Warmup

MAX_STEPS_PER_FRAME = 4
PROFILE = bool(__import__("os").environ.get("STELKROPP_PROFILE"))


class Stats:
    """Ring buffers of per-frame samples for the plots (the last ``cap`` frames)."""

    KEYS = ("t", "step_ms", "ke", "pe", "p", "pen", "contacts")

    def __init__(self, cap: int = 600):
        self.cap = cap
        self.data = {k: np.zeros(cap) for k in self.KEYS}
        self.n = 0
        self.i = 0

    def add(self, **values):
        for k in self.KEYS:
            self.data[k][self.i] = values.get(k, 0.0)
        self.i = (self.i + 1) % self.cap
        self.n = min(self.n + 1, self.cap)

    def _order(self):
        if self.n < self.cap:
            return np.arange(self.n)
        return (np.arange(self.cap) + self.i) % self.cap

    def arrays(self):
        o = self._order()
        return self.data["t"][o], len(o)

    def get(self, k):
        return self.data[k][self._order()]

    def clear(self):
        self.n = self.i = 0


class Sandbox(pyglet.window.Window):
    def __init__(self, scene=None, world=None, size=(1280, 800), position=None, paused=False, status=None,
                 autosave_interval=60.0, offer_autosave=True, vsync=False):
        config = pyglet.gl.Config(major_version=3, minor_version=3, forward_compatible=True, double_buffer=True,
                                  red_size=8, green_size=8, blue_size=8, alpha_size=8, depth_size=0)
        super().__init__(size[0], size[1], "Stelkropp", resizable=True, config=config, vsync=vsync)
        if position is not None:
            self.set_location(*position)
        imgui.create_context()
        implot.create_context()
        io = imgui.get_io()
        io.set_ini_filename(None)
        io.config_windows_move_from_title_bar_only = True
        apply_style()
        self.gui = create_renderer(self)
        self.renderer = Renderer()
        fw, fh = self.get_framebuffer_size()
        self.camera = Camera(*self.get_size())
        self.overlays = Overlays()
        self.tool_options = ToolOptions()
        self.tools = {cls.name: cls(self) for cls in TOOLS}
        self.tool_names = [cls.name for cls in TOOLS]
        self.tool = self.tools["select"]
        self.tool_springs: set[int] = set()
        self.selection: list = []
        self.hovered = None
        self.cursor_px = np.array([size[0] * 0.6, size[1] * 0.5])
        self.cursor = np.zeros(2)
        self.messages: list = []
        self.scene_errors: list[str] = []
        self.fault = None
        self.running = not paused
        self.show_ui = True
        self.time_scale = 1.0
        self.accumulator = 0.0
        self.stats = Stats()
        self.frame_times = {"physics": 0.0, "upload": 0.0, "draw": 0.0, "ui": 0.0, "frame": 0.0}
        self.fps = 0.0
        self.frame_no = 0
        self.gl_errors: list[str] = []
        self.status_path = Path(status) if status else None
        self.control_path = None      # a file of JSON event lines dispatched into this window (tests)
        self._control_pos = 0
        self.ui_rects: dict[str, tuple] = {}
        self.info = {}
        self.rd_ids = np.zeros(0, np.int64)
        self._last_contacts = (0, 0.0)
        self.quadtree = np.zeros((0, 4))       # the last quadtree cells drawn (overlay Q)
        self.velocities = None                 # (N, 2) body velocities for the arrows (overlay V)
        self._vel_key = None
        self._panning = None
        self._mouse_tool_active = False
        self.physics_lock = threading.Lock()
        self.compiling_note = ""
        # the scene
        if world is None:
            world, path = self._initial_world(scene)
        else:
            path = None
        self.doc = Document(world, path)
        self.autosaver = Autosaver(interval=autosave_interval)
        crash = self.autosaver.previous_crash() if offer_autosave else None
        self.autosaver.begin_session(path)
        self.panels = Panels(self)
        if crash:
            self.panels.autosave_offer = crash
        self.warmup = Warmup(self.world, self.physics_lock).start()
        self._fitted = False
        self._update_caption()

    # -- the document -----------------------------------------------------------
    @property
    def world(self):
        return self.doc.world

    @property
    def refs(self):
        return self.doc.refs

    def _initial_world(self, scene):
        if scene is not None:
            try:
                return load_world(scene), Path(scene)
            except Exception as exc:  # noqa: BLE001
                self.scene_errors = format_scene_error(exc)
                print(f"stelkropp: could not load {scene}:", *self.scene_errors, sep="\n  ", file=sys.stderr)
                return demo_world(), None
        from .document import DEFAULT_SCENE
        if DEFAULT_SCENE.exists():
            try:
                return load_world(DEFAULT_SCENE), DEFAULT_SCENE
            except Exception as exc:  # noqa: BLE001
                self.scene_errors = format_scene_error(exc)
        return demo_world(), None

    def _update_caption(self):
        cap = f"Stelkropp - {self.doc.title}"
        if cap != getattr(self, "_caption", None):
            self._caption = cap
            self.set_caption(cap)

    def set_document(self, world, path, keep_camera=False):
        self.tool.cancel()
        self.tool_springs.clear()
        self.selection = []
        self.hovered = None
        self.doc = Document(world, path)
        self.fault = None
        self.accumulator = 0.0
        self.stats.clear()
        self.velocities = self._vel_key = None
        if not keep_camera:
            self.frame_scene()
        self.autosaver.set_origin(path)
        if not self.warmup.can_step(world.solver, world.integrator):
            self.warmup.prioritize(world.solver, world.integrator)

    def request_open(self, path):
        path = Path(path)
        if self.doc.dirty:
            self.panels.confirm(f"Open {path.name}?", lambda: self.open_scene(path),
                                lambda: self.save() and self.open_scene(path))
        else:
            self.open_scene(path)

    def open_scene(self, path) -> bool:
        path = Path(path)
        try:
            world = load_world(path)
        except Exception as exc:  # noqa: BLE001  (SceneError with problems, or an unreadable file)
            self.scene_errors = [f"{path.name}:"] + format_scene_error(exc)
            self.notify(f"could not load {path.name}: the current scene stays", error=True)
            return False
        self.scene_errors = []
        self.set_document(world, path)
        self.notify(f"opened {path.name}")
        return True

    def save(self, path=None) -> bool:
        path = Path(path) if path else self.doc.path
        if path is None:
            path = Path(self.panels.save_as_path or "scenes/untitled.json")
        self.tools["select"].end_joint()
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            self.world.save_scene(str(path))
        except Exception as exc:  # noqa: BLE001
            self.notify(f"save failed: {exc}", error=True)
            return False
        self.doc.mark_saved(path)
        self.autosaver.set_origin(path)
        self.notify(f"saved {path}")
        return True

    def request_reset(self):
        if self.doc.dirty:
            self.panels.confirm("Reset to the loaded state?", self.reset, lambda: self.save() and self.reset())
        else:
            self.reset()

    def reset(self):
        loaded = self.doc.loaded
        path = self.doc.path
        self.tool.cancel()
        meta = dict(scene_metadata(self.world))
        world = restore(loaded)
        scene_metadata(world).update(meta)    # name, description, camera: kept by a later save
        self.set_document(world, path, keep_camera=True)
        self.notify("reset to the loaded state")

    def restore_autosave(self, path, origin):
        try:
            world = load_world(path)
        except Exception as exc:  # noqa: BLE001
            self.scene_errors = ["autosave:"] + format_scene_error(exc)
            return
        self.set_document(world, Path(origin) if origin else None)
        self.doc.history.version += 1   # restored edits are unsaved
        self.notify("autosave restored (unsaved)")

    # -- edits -------------------------------------------------------------------
    def execute(self, cmd):
        self.doc.history.execute(self, cmd)

    def create(self, cmd):
        try:
            self.execute(cmd)
        except ValueError as exc:
            self.notify(f"refused: {exc}", error=True)
            return
        obj = getattr(cmd, "ref", None)
        if obj is not None:
            self.select(obj.obj)

    def drop_shape(self, name, sx, sy):
        p = self.camera.to_world(sx, sy)
        o = self.tool_options
        r = 0.5 * o.default_size
        shape = {"box": lambda: physics.Polygon.box(o.default_size, o.default_size),
                 "circle": lambda: physics.Circle(r),
                 "n-gon": lambda: physics.Polygon.regular(o.sides, r)}.get(name)
        if shape is not None:
            self.create(AddBody({"shape": shape(), **body_args(o, p)}, f"drop {name}"))

    def undo(self):
        self.tool.cancel()
        try:
            label = self.doc.history.undo(self)
        except ValueError as exc:
            self.notify(f"undo failed: {exc}", error=True)
            return
        self.notify(f"undo: {label}" if label else "nothing to undo")

    def redo(self):
        self.tool.cancel()
        try:
            label = self.doc.history.redo(self)
        except ValueError as exc:
            self.notify(f"redo failed: {exc}", error=True)
            return
        self.notify(f"redo: {label}" if label else "nothing to redo")

    def delete_selection(self):
        items = [s for s in self.selection if s.alive]
        bodies = [s for s in items if isinstance(s, physics.Body)]
        springs = [s for s in items if isinstance(s, physics.Spring) and not any(
            s.body_a is b or s.body_b is b for b in bodies)]
        cmds = [RemoveSpring(self, s) for s in springs]
        if bodies:
            cmds.append(RemoveBodies(self, bodies))
        if cmds:
            self.tool.cancel()
            self.execute(Group(cmds, "delete") if len(cmds) > 1 else cmds[0])

    def duplicate_selection(self):
        bodies = [s for s in self.selection if isinstance(s, physics.Body) and s.alive]
        if not bodies:
            return
        cmds = []
        for b in bodies:
            spec = body_spec(b)
            spec["name"] = None
            spec["position"] = (spec["position"][0] + 0.6, spec["position"][1] + 0.6)
            cmds.append(AddBody(spec, "duplicate"))
        self.execute(Group(cmds, "duplicate"))
        self.selection = [c.ref.obj for c in cmds]

    def toggle_static(self):
        bodies = [s for s in self.selection if isinstance(s, physics.Body) and s.alive]
        if bodies:
            self.tool.cancel()
            cmds = [SetProperty(self, b, "kind", "dynamic" if b.kind != "dynamic" else "static") for b in bodies]
            self.execute(Group(cmds, "toggle static/dynamic"))

    def switch_solver(self, mode):
        w = self.world

        def setter(m):
            w.solver = m
        try:
            self.execute(SetWorld(lambda: w.solver, setter, mode, "solver"))
        except (ValueError, ImportError) as exc:
            self.notify(f"solver {mode}: {exc}", error=True)
            return
        if not self.warmup.can_step(mode, w.integrator):
            self.warmup.prioritize(mode, w.integrator)
        self.notify(f"solver: {mode}")

    # -- selection ---------------------------------------------------------------
    def select(self, item, add=False):
        if item is None:
            self.selection = []
        elif add:
            if item in self.selection:
                self.selection.remove(item)
            else:
                self.selection.append(item)
        else:
            self.selection = [item]
        self.panels.edit_error = ""

    def deselect(self, item):
        self.selection = [s for s in self.selection if s is not item]
        if self.hovered is item:
            self.hovered = None

    def is_tool_spring(self, sp) -> bool:
        return sp.id in self.tool_springs

    def spring_near(self, p, px=7.0):
        springs = [s for s in self.world.springs if s.id not in self.tool_springs]
        best, bd = None, px / self.camera.scale
        p = np.asarray(p)
        for sp in springs:
            a, b = (np.array(e) for e in sp.endpoints())
            d = b - a
            t = np.clip(np.dot(p - a, d) / max(np.dot(d, d), 1e-12), 0, 1)
            dist = np.hypot(*(a + t * d - p))
            if dist < bd:
                best, bd = sp, dist
        return best

    def set_tool(self, name):
        if self.tool.name != name:
            self.tool.cancel()
            self.tool = self.tools[name]

    def notify(self, text, error=False):
        self.messages.append((text, error, time.monotonic()))
        if error:
            print(f"stelkropp: {text}", file=sys.stderr)

    def warmup_active(self) -> bool:
        return not self.warmup.ready

    def toggle_run(self):
        self.running = not self.running
        if self.running:
            self.fault = None

    def step_once(self):
        self.running = False
        self._step(1)

    def free_area(self) -> tuple[float, float]:
        """Pixels covered by panels at the left and right edges of the window: the scene is framed
        in the area between them.  Uses the panels' rectangles from the last frame (they can be
        moved), or their default places before the first frame with panels."""
        if not self.show_ui:
            return 0.0, 0.0
        rects = [self.ui_rects.get(k) for k in ("main_window", "stats_window")]
        if rects[0] is None:      # not drawn yet: the default layout
            return float(PANEL_W + 16), float(STATS_W + 16) if self.panels.show_stats else 0.0
        W = float(self.width)
        left = right = 0.0
        for r in rects:
            if r is None or r[3] - r[1] < 60:      # absent, or collapsed to its title bar
                continue
            x0, _, x1, _ = r
            if 0.5 * (x0 + x1) < 0.5 * W:
                left = max(left, x1 + 8.0)
            else:
                right = max(right, W - x0 + 8.0)
        return left, right

    def fit(self):
        """Frame every body in the free area between the panels (F)."""
        rd = self.world.render_data()
        if not len(rd.aabb):
            return
        box = rd.aabb[np.all(np.isfinite(rd.aabb), axis=1)]
        if not len(box):
            return
        left, right = self.free_area()
        self.camera.fit(box[:, :2].min(0), box[:, 2:].max(0), avoid_left=left, avoid_right=right)

    def scene_camera(self):
        """The scene file's camera block ``{"center": [x, y], "zoom": px per m}``, or None."""
        cam = scene_metadata(self.world).get("camera")
        try:
            center = np.asarray(cam["center"], dtype=np.float64).reshape(2)
            zoom = float(cam["zoom"])
        except (TypeError, KeyError, ValueError):
            return None
        if not (np.all(np.isfinite(center)) and math.isfinite(zoom) and zoom > 0):
            return None
        return center, zoom

    def frame_scene(self):
        """On opening a scene: its own camera if the file has one (centred in the free area),
        otherwise fit the scene into the free area."""
        cam = self.scene_camera()
        if cam is None:
            self.fit()
        else:
            left, right = self.free_area()
            self.camera.look_at(cam[0], cam[1], avoid_left=left, avoid_right=right)

    # -- physics -------------------------------------------------------------------
    def _step(self, n) -> float:
        """Take n steps if the kernels are ready and the lock is free; returns ms spent."""
        w = self.world
        if not self.warmup.can_step(w.solver, w.integrator):
            self.compiling_note = f"compiling {w.solver} ({w.integrator}) ..."
            return 0.0
        if not self.physics_lock.acquire(blocking=False):
            self.compiling_note = "compiling kernels ..."
            return 0.0
        self.compiling_note = ""
        t0 = time.perf_counter()
        try:
            for _ in range(n):
                self.tool.update(self.cursor)
                w.step()
        except physics.SimulationError as exc:
            self.fault = str(exc)
            self.running = False
            self.notify(f"simulation error (world reverted, paused): {exc}", error=True)
        finally:
            self.physics_lock.release()
        return (time.perf_counter() - t0) * 1e3

    def simulate(self, real_dt):
        w = self.world
        phys_ms = 0.0
        steps = 0
        if self.running:
            self.accumulator += min(real_dt, 0.25) * self.time_scale
            steps = int(self.accumulator / w.dt)
            if steps > MAX_STEPS_PER_FRAME:
                steps = MAX_STEPS_PER_FRAME
                self.accumulator = 0.0    # we cannot keep up: slow motion rather than a spiral
            else:
                self.accumulator -= steps * w.dt
            if steps:
                if self.overlays.velocities:
                    before = w.render_data()
                    x0, ids0, t0 = before.center.copy(), before.ids.copy(), w.time
                phys_ms = self._step(steps)
                if self.overlays.velocities:
                    # the arrows: each body's displacement over this frame's steps / the time
                    # stepped, from the render arrays (no per-body Python handles)
                    after = w.render_data()
                    if w.time > t0 and np.array_equal(after.ids, ids0):
                        self.velocities = (after.center - x0) / (w.time - t0)
                        self._vel_key = ("stepped", self.doc.history.version, w.steps, len(ids0))
                    else:
                        self.velocities = None
        return phys_ms, steps

    def body_velocities(self, rd):
        """Velocities for the arrow overlay, in render-data order.  While running, the displacement
        over the frame's steps (see ``simulate``); when nothing stepped (paused, or a body was just
        added/removed), read through the body handles once per change of the world -- that is the
        only case that touches Python objects per body, and it does not repeat every frame."""
        w = self.world
        if self._vel_key is not None and self._vel_key[0] == "stepped" and \
                self._vel_key[1:] == (self.doc.history.version, w.steps, len(rd.ids)):
            return self.velocities
        key = ("handles", self.doc.history.version, w.steps, rd.ids.tobytes())
        if key != self._vel_key or self.velocities is None:
            self.velocities = np.array([b.velocity for b in w.bodies], dtype=np.float64).reshape(-1, 2)
            self._vel_key = key
        return self.velocities

    def quadtree_cells(self):
        """``world.quadtree_cells()`` for the overlay (Q).  It shares the broad phase's scratch
        buffers with stepping, so it runs under the physics lock; while a background compile holds
        the lock, the last cells are drawn again."""
        if self.physics_lock.acquire(blocking=False):
            try:
                self.quadtree = self.world.quadtree_cells()
            except Exception as exc:  # noqa: BLE001  (a debug overlay must not take the sandbox down)
                self.overlays.quadtree = False
                self.notify(f"quadtree overlay off: {exc}", error=True)
            finally:
                self.physics_lock.release()
        return self.quadtree

    def sample_stats(self, phys_ms, steps):
        w = self.world
        if steps == 0 and self.stats.n and not self.frame_no % 1 == 0:
            return
        if self.frame_no % 6 == 0 or not self.stats.n:
            cs = w.contacts() if len(self.rd_ids) < 3000 or self.frame_no % 60 == 0 else []
            self._last_contacts = (len(cs), max((c.depth for c in cs), default=0.0))
            self.info = w.info()
        p = w.linear_momentum()
        self.stats.add(t=time.monotonic(), step_ms=phys_ms / max(steps, 1), ke=w.kinetic_energy(),
                       pe=w.potential_energy(), p=math.hypot(*p), pen=max(0.0, self._last_contacts[1]),
                       contacts=self._last_contacts[0])

    # -- frame ---------------------------------------------------------------------
    def frame(self, real_dt):
        t_start = time.perf_counter()
        io = imgui.get_io()
        io.delta_time = max(real_dt, 1e-4)
        ready = self.warmup.ready
        phys_ms = 0.0
        upload_ms = draw_ms = 0.0
        if ready:
            if not self._fitted:
                self._fitted = True
                self.frame_scene()
            phys_ms, steps = self.simulate(real_dt)
            self.sample_stats(phys_ms, steps)
            self.update_hover()
            rd = self.world.render_data()
            self.rd_ids = rd.ids
            decor = self.decor()
            velocities = self.body_velocities(rd) if self.overlays.velocities else None
            quadtree = self.quadtree_cells() if self.overlays.quadtree else None
            spring_ids = np.array([s.id for s in self.world.springs], dtype=np.int64) \
                if (decor.hidden_springs or decor.selected_springs) else None
            finite = np.all(np.isfinite(rd.vertices)) and np.all(np.isfinite(rd.center))
            if finite:
                self.renderer.build(rd, self.camera, self.overlays, decor, spring_ids, quadtree, velocities)
            upload_ms = self.renderer.last_upload_ms
        t_draw = time.perf_counter()
        fw, fh = self.get_framebuffer_size()
        if ready:
            self.renderer.draw(self.camera, fw, fh)
        else:
            GL.glViewport(0, 0, fw, fh)
            GL.glClearColor(0.06, 0.07, 0.095, 1.0)
            GL.glClear(GL.GL_COLOR_BUFFER_BIT)
        if PROFILE:
            GL.glFinish()
        draw_ms = (time.perf_counter() - t_draw) * 1e3   # + the buffer swap, added in run()
        t_ui = time.perf_counter()
        imgui.new_frame()
        if self.show_ui or not ready:
            self.panels.draw()
        if self.compiling_note and ready:
            self.overlay_note(self.compiling_note)
        imgui.render()
        self.gui.render(imgui.get_draw_data())
        if PROFILE:
            GL.glFinish()
        ui_ms = (time.perf_counter() - t_ui) * 1e3
        err = GL.glGetError()
        if err != GL.GL_NO_ERROR:
            self.gl_errors.append(f"frame {self.frame_no}: GL error 0x{err:x}")
        ft = self.frame_times
        a = 0.1
        for k, v in (("physics", phys_ms), ("upload", upload_ms), ("draw", draw_ms), ("ui", ui_ms),
                     ("frame", (time.perf_counter() - t_start) * 1e3)):
            ft[k] = (1 - a) * ft[k] + a * v
        self.last_frame = {"physics": phys_ms, "upload": upload_ms, "draw": draw_ms, "ui": ui_ms,
                           "frame": (time.perf_counter() - t_start) * 1e3}
        if real_dt > 0:
            self.fps = 0.9 * self.fps + 0.1 / real_dt if self.fps else 1.0 / real_dt
        if ready:
            self.autosaver.tick(self.doc, busy=self.tools["select"].joint is not None)
        self._update_caption()
        self.frame_no += 1

    def overlay_note(self, text):
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5 + PANEL_W * 0.5, 14),
                                  imgui.Cond_.always.value, imgui.ImVec2(0.5, 0.0))
        flags = (imgui.WindowFlags_.no_decoration | imgui.WindowFlags_.always_auto_resize |
                 imgui.WindowFlags_.no_inputs | imgui.WindowFlags_.no_saved_settings).value
        imgui.begin("##note", None, flags)
        imgui.text_colored(imgui.ImVec4(1.0, 0.8, 0.35, 1.0), text)
        imgui.end()

    def update_hover(self):
        if self.panels.over_ui or self._panning:
            self.hovered = None
            return
        try:
            self.hovered = self.world.query_point(tuple(self.cursor))
        except ValueError:
            self.hovered = None

    def decor(self) -> Decor:
        d = Decor()
        for s in self.selection:
            if not s.alive:
                continue
            if isinstance(s, physics.Body):
                d.selected_bodies.add(s.id)
            else:
                d.selected_springs.add(s.id)
        if self.hovered is not None and self.hovered.alive:
            d.hovered_body = self.hovered.id
        d.hidden_springs |= self.tool_springs
        self.tool.decorate(d, tuple(self.cursor))
        return d

    # -- status (tests, scripting) ---------------------------------------------------
    def write_status(self):
        if self.status_path is None:
            return
        w = self.world
        bodies = []
        if len(self.rd_ids) <= 300 and self.warmup.ready:
            for b in w.bodies:
                sp = self.camera.to_screen(b.position)
                bodies.append({"id": b.id, "name": b.name, "kind": b.kind, "position": b.position,
                               "screen": [float(sp[0]), float(self.height - sp[1])],
                               "shape": b.shape.kind, "density": b.density,
                               "vertices": 0 if isinstance(b.shape, physics.Circle) else len(b.shape.vertices)})
        st = {"frame": self.frame_no, "ready": self.warmup.ready, "warm_finished": self.warmup.finished,
              "warm_errors": self.warmup.errors, "running": self.running, "solver": w.solver,
              "n_bodies": len(w.bodies), "n_springs": len(w.springs), "bodies": bodies,
              "path": str(self.doc.path) if self.doc.path else None, "dirty": self.doc.dirty,
              "fault": self.fault, "scene_errors": self.scene_errors, "gl_errors": self.gl_errors[-20:],
              "messages": [m[0] for m in self.messages], "frame_times": self.frame_times, "fps": self.fps,
              "selection": [s.id for s in self.selection if s.alive], "tool": self.tool.name,
              "camera": {"center": self.camera.center.tolist(), "scale": self.camera.scale},
              "time": w.time, "steps": w.steps, "window": [self.width, self.height],
              "ui_rects": self.ui_rects, "show_ui": self.show_ui,
              "springs": [{"id": s.id, "a": s.body_a.id, "b": None if s.body_b is None else s.body_b.id}
                          for s in w.springs if s.id not in self.tool_springs] if len(self.rd_ids) <= 300 else [],
              "overlays": dict(vars(self.overlays)), "quadtree_cells": len(self.quadtree),
              "free_area": list(self.free_area()), "edit_error": self.panels.edit_error}
        tmp = self.status_path.with_suffix(".tmp")
        tmp.write_text(json.dumps(st))
        tmp.replace(self.status_path)

    # -- events ----------------------------------------------------------------------
    def on_resize(self, width, height):
        self.camera.resize(width, height)
        return pyglet.event.EVENT_HANDLED

    def on_draw(self):
        pass

    def on_close(self):
        if self.doc.dirty and not getattr(self, "force_close", False):
            self.panels.confirm("Quit Stelkropp?", self._really_close, lambda: self.save() and self._really_close())
            return pyglet.event.EVENT_HANDLED
        self._really_close()
        return pyglet.event.EVENT_HANDLED

    def _really_close(self):
        self.has_exit = True

    def _scene_mouse(self):
        io = imgui.get_io()
        return not (io.want_capture_mouse or self.panels.over_ui) and self.warmup.ready

    def on_mouse_motion(self, x, y, dx, dy):
        self.cursor_px = np.array([x, y], dtype=float)
        self.cursor = self.camera.to_world(x, y)

    def on_mouse_press(self, x, y, button, modifiers):
        self.on_mouse_motion(x, y, 0, 0)
        if not self._scene_mouse():
            return
        if button in (mouse.RIGHT, mouse.MIDDLE):
            self._panning = (x, y)
            return
        if button == mouse.LEFT:
            self._mouse_tool_active = True
            try:
                self.tool.press(tuple(self.cursor), button, modifiers)
            except ValueError as exc:
                self.notify(f"refused: {exc}", error=True)

    def on_mouse_drag(self, x, y, dx, dy, buttons, modifiers):
        self.on_mouse_motion(x, y, dx, dy)
        if self._panning is not None and buttons & (mouse.RIGHT | mouse.MIDDLE):
            self.camera.pan_pixels(dx, dy)
            self.cursor = self.camera.to_world(x, y)
            return
        if self._mouse_tool_active and buttons & mouse.LEFT:
            try:
                self.tool.drag(tuple(self.cursor))
            except ValueError as exc:
                self.notify(f"refused: {exc}", error=True)

    def on_mouse_release(self, x, y, button, modifiers):
        self.on_mouse_motion(x, y, 0, 0)
        if button in (mouse.RIGHT, mouse.MIDDLE):
            self._panning = None
            return
        if button == mouse.LEFT and self._mouse_tool_active:
            self._mouse_tool_active = False
            try:
                self.tool.release(tuple(self.cursor))
            except ValueError as exc:
                self.notify(f"refused: {exc}", error=True)

    def on_mouse_scroll(self, x, y, scroll_x, scroll_y):
        if not self._scene_mouse():
            return
        self.camera.zoom_at(x, y, 1.15 ** scroll_y)
        self.cursor = self.camera.to_world(x, y)

    def on_file_drop(self, x, y, paths):
        for p in paths:
            if str(p).lower().endswith(".json"):
                self.request_open(Path(p))
                return
        self.notify("drop a .json scene file", error=True)

    def on_key_press(self, symbol, modifiers):
        io = imgui.get_io()
        if io.want_capture_keyboard or not self.warmup.ready:
            return pyglet.event.EVENT_HANDLED
        ctrl = modifiers & (K.MOD_CTRL | K.MOD_COMMAND)
        shift = modifiers & K.MOD_SHIFT
        if self.tool.key(symbol):
            return pyglet.event.EVENT_HANDLED
        if ctrl and symbol == K.Z:
            self.redo() if shift else self.undo()
        elif ctrl and symbol == K.Y:
            self.redo()
        elif ctrl and symbol == K.S:
            self.save()
        elif ctrl and symbol == K.D:
            self.duplicate_selection()
        elif symbol == K.SPACE:
            self.toggle_run()
        elif symbol == K.S:
            self.step_once()
        elif symbol == K.R:
            self.request_reset()
        elif symbol == K.F:
            self.fit()
        elif symbol == K.H:
            self.show_ui = not self.show_ui
        elif symbol in (K.DELETE, K.BACKSPACE):
            self.delete_selection()
        elif symbol == K.T:
            self.toggle_static()
        elif symbol == K.C:
            self.overlays.contacts = not self.overlays.contacts
        elif symbol == K.B:
            self.overlays.aabbs = not self.overlays.aabbs
        elif symbol == K.Q:
            self.overlays.quadtree = not self.overlays.quadtree
        elif symbol == K.V:
            self.overlays.velocities = not self.overlays.velocities
        elif symbol == K.M:
            self.overlays.com = not self.overlays.com
        elif K._1 <= symbol <= K._6:
            self.set_tool(self.tool_names[symbol - K._1])
        elif symbol == K.ESCAPE:
            self.tool.cancel()
            self.select(None)
        return pyglet.event.EVENT_HANDLED

    def poll_control(self):
        """Dispatch events written as JSON lines to the control file, e.g.
        ``{"event": "on_file_drop", "args": [400, 300, ["/path/scene.json"]]}``: a driver for
        tests and scripts that goes through pyglet's own event dispatch."""
        if self.control_path is None or not self.control_path.exists():
            return
        with open(self.control_path) as f:
            f.seek(self._control_pos)
            text = f.read()
        if not text.endswith("\n"):
            text = text[: text.rfind("\n") + 1]
        self._control_pos += len(text.encode())
        for line in text.splitlines():
            if line.strip():
                ev = json.loads(line)
                self.dispatch_event(ev["event"], *ev.get("args", []))

    # -- the loop ---------------------------------------------------------------------
    def screenshot(self, path):
        fw, fh = self.get_framebuffer_size()
        GL.glPixelStorei(GL.GL_PACK_ALIGNMENT, 1)
        data = GL.glReadPixels(0, 0, fw, fh, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
        img = pyglet.image.ImageData(fw, fh, "RGBA", bytes(data))
        img.save(str(path))

    def run(self, frames=None, screenshot=None, exit_after=False, benchmark=None, fps_limit=60.0):
        """The main loop.  ``frames``: stop after this many frames once the scene is ready."""
        last = time.perf_counter()
        ready_frames = 0
        bench = []
        code = 0
        status_every = 5
        while not self.has_exit:
            self.dispatch_events()
            self.poll_control()
            now = time.perf_counter()
            real_dt, last = now - last, now
            if benchmark:
                real_dt = self.world.dt / max(self.time_scale, 1e-6)   # one step per frame, exactly
            try:
                self.frame(real_dt)
            except Exception as exc:  # noqa: BLE001
                import traceback
                traceback.print_exc()
                self.gl_errors.append(f"frame {self.frame_no}: {type(exc).__name__}: {exc}")
                if exit_after or benchmark:
                    code = 3
                    break
            if self.warmup.ready:
                ready_frames += 1
            target = frames if frames is not None else (benchmark + 10 if benchmark else None)
            done = target is not None and ready_frames >= target
            if done and screenshot:
                self.screenshot(screenshot)
            t_flip = time.perf_counter()
            self.flip()
            flip_ms = (time.perf_counter() - t_flip) * 1e3
            if getattr(self, "last_frame", None):
                # llvmpipe rasterises when the frame is swapped: count the swap as drawing
                self.last_frame["draw"] += flip_ms
                self.last_frame["frame"] += flip_ms
                self.frame_times["draw"] += 0.1 * flip_ms
                self.frame_times["frame"] += 0.1 * flip_ms
            if benchmark and self.warmup.ready and ready_frames > 10:
                bench.append(dict(self.last_frame))
            if self.frame_no % status_every == 0:
                self.write_status()
            if done and (exit_after or benchmark):
                break
            limit = fps_limit
            if not self.warmup.ready:
                limit = 8.0      # leave the interpreter to the compiler thread
            elif self.warmup.busy:
                limit = 20.0
            if limit and not (benchmark and self.warmup.ready):
                spare = 1.0 / limit - (time.perf_counter() - now)
                if spare > 0:
                    time.sleep(spare)
        self.write_status()
        if bench:
            self.report_benchmark(bench)
        if self.gl_errors:
            print("stelkropp: OpenGL/frame errors:", *self.gl_errors[:20], sep="\n  ", file=sys.stderr)
            code = code or 3
        self.autosaver.end_session()
        self.close()
        return code

    def report_benchmark(self, bench):
        keys = ("physics", "upload", "draw", "ui", "frame")
        med = {k: float(np.median([b[k] for b in bench])) for k in keys}
        mean = {k: float(np.mean([b[k] for b in bench])) for k in keys}
        n = len(self.world.bodies)
        print(f"benchmark: {len(bench)} frames, {n} bodies, solver {self.world.solver}")
        print("  median ms: " + "  ".join(f"{k} {med[k]:.2f}" for k in keys))
        print("  mean ms:   " + "  ".join(f"{k} {mean[k]:.2f}" for k in keys))
        print(f"  render-only frame (upload+draw+ui): {med['upload'] + med['draw'] + med['ui']:.2f} ms "
              f"= {1000.0 / max(1e-6, med['upload'] + med['draw'] + med['ui']):.0f} fps; "
              f"with physics: {1000.0 / max(1e-6, med['frame']):.0f} fps")
