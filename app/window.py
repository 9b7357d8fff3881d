"""The sandbox window: builds the parts (editor, simulation, renderer, panels, input) and draws one
frame at a time.  The main loop is ``app.loop``; test automation attaches to it from outside."""
from __future__ import annotations

import os
import threading
import time

import numpy as np
import pyglet
from imgui_bundle import imgui, implot
from imgui_bundle.python_backends.pyglet_backend import create_renderer
from OpenGL import GL

from . import framing
from .autosave import Autosaver
from .camera import Camera
from .editor import Editor
from .files import SceneFiles
from .input import SceneInput
from .notices import Notices
from .panels import PANEL_W, STATS_W, Panels, apply_style
from .panels.notes import overlay_note
from .render import Overlays, Renderer
from .scenes import initial_world
from .simulation import Simulation
from .stats import FrameTimes, StatsSampler
from .warmup import Warmup

PROFILE = bool(os.environ.get("STELKROPP_PROFILE"))   # glFinish after each part: honest frame split


class Sandbox(pyglet.window.Window):
    """``Sandbox(scene=path)`` (or ``world=``): the editor window.  ``paused`` starts paused;
    ``offer_autosave`` offers a crashed session's autosave."""

    def __init__(self, scene=None, world=None, size=(1280, 800), position=None, paused=False,
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
        self.renderer = Renderer()
        self.camera = Camera(*self.get_size())
        self.overlays = Overlays()
        self.notices = Notices()
        self.show_ui = True
        self.ui_rects: dict[str, tuple] = {}
        self.gl_errors: list[str] = []
        self.frame_no = 0
        self.rd_ids = np.zeros(0, np.int64)
        self.times = FrameTimes()
        self.sampler = StatsSampler()
        errors = []
        if world is None:
            world, path, errors = initial_world(scene)
        else:
            path = None
        self.editor = Editor(world, path, self.notices, self.camera)
        lock = threading.Lock()
        self.warmup = Warmup(world, lock)
        self.sim = Simulation(self.editor, self.warmup, self.notices, paused=paused, lock=lock)
        self.autosaver = Autosaver(interval=autosave_interval)
        self.files = SceneFiles(self.editor, self.autosaver, lambda *a: self.panels.confirm(*a))
        self.files.errors = errors
        crash = self.autosaver.previous_crash() if offer_autosave else None
        self.autosaver.begin_session(path)
        self.panels = Panels(self)
        if crash:
            self.panels.dialogs.autosave_offer = crash
        self.input = SceneInput(self)
        self.push_handlers(self.input)
        self.gui = create_renderer(self)      # after: imgui's handlers see every event before ours
        self.editor.on_document.append(self._document_changed)
        self.editor.on_mode.append(self._mode_changed)
        self.warmup.start()
        self._fitted = False
        self._caption = None
        self._update_caption()

    @property
    def world(self):
        return self.editor.world

    def _update_caption(self):
        cap = f"Stelkropp - {self.editor.doc.title}"
        if cap != self._caption:
            self._caption = cap
            self.set_caption(cap)

    def _document_changed(self, world, path, keep_camera):
        self.sim.reset()
        self.sampler.clear()
        if not keep_camera:
            self.frame_scene()
        self.autosaver.set_origin(path)
        self._mode_changed(world.solver, world.integrator)

    def _mode_changed(self, solver, integrator):
        if not self.warmup.can_step(solver, integrator):
            self.warmup.prioritize(solver, integrator)

    # -- where the scene is shown ------------------------------------------------------
    def free_area(self) -> tuple[float, float]:
        """Pixels covered by panels at the left and right edges (see ``framing.free_area``)."""
        default = (float(PANEL_W + 16), float(STATS_W + 16) if self.panels.show_stats else 0.0)
        return framing.free_area(self.ui_rects, self.width, self.show_ui, default)

    def fit(self):
        """Frame every body in the free area between the panels (F)."""
        framing.fit(self.camera, self.world, self.free_area())

    def frame_scene(self):
        framing.frame_scene(self.camera, self.world, self.free_area())

    # -- one frame -------------------------------------------------------------------
    def frame(self, real_dt):
        """Step (if running), draw the scene and the panels; ``real_dt`` is the real time since
        the last frame (s)."""
        t_start = time.perf_counter()
        io = imgui.get_io()
        io.delta_time = max(real_dt, 1e-4)
        ready = self.warmup.ready
        phys_ms = upload_ms = 0.0
        if ready:
            if not self._fitted:
                self._fitted = True
                self.frame_scene()
            phys_ms, steps = self.sim.advance(real_dt, velocities=self.overlays.velocities)
            self.sampler.sample(self.world, phys_ms, steps, self.frame_no, len(self.rd_ids))
            self.input.update_hover()
            upload_ms = self.build_scene()
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
        draw_ms = (time.perf_counter() - t_draw) * 1e3   # + the buffer swap, added by the loop
        t_ui = time.perf_counter()
        self.draw_ui(ready)
        if PROFILE:
            GL.glFinish()
        ui_ms = (time.perf_counter() - t_ui) * 1e3
        err = GL.glGetError()
        if err != GL.GL_NO_ERROR:
            self.gl_errors.append(f"frame {self.frame_no}: GL error 0x{err:x}")
        self.times.record(real_dt, physics=phys_ms, upload=upload_ms, draw=draw_ms, ui=ui_ms,
                          frame=(time.perf_counter() - t_start) * 1e3)
        if ready:
            self.autosaver.tick(self.editor.doc, busy=self.editor.tools["select"].joint is not None)
        self._update_caption()
        self.frame_no += 1

    def build_scene(self) -> float:
        """The world's render data -> the renderer's vertex buffers; returns the upload ms."""
        rd = self.world.render_data()
        self.rd_ids = rd.ids
        decor = self.editor.decor()
        velocities = self.sim.body_velocities(rd) if self.overlays.velocities else None
        quadtree = self.sim.quadtree_cells(self._quadtree_failed) if self.overlays.quadtree else None
        spring_ids = np.array([s.id for s in self.world.springs], dtype=np.int64) \
            if (decor.hidden_springs or decor.selected_springs) else None
        if np.all(np.isfinite(rd.vertices)) and np.all(np.isfinite(rd.center)):
            self.renderer.build(rd, self.camera, self.overlays, decor, spring_ids, quadtree, velocities)
        return self.renderer.last_upload_ms

    def _quadtree_failed(self, exc):
        self.overlays.quadtree = False
        self.notices.notify(f"quadtree overlay off: {exc}", error=True)

    def draw_ui(self, ready):
        imgui.new_frame()
        if self.show_ui or not ready:
            self.panels.draw()
        if self.sim.compiling_note and ready:
            overlay_note(self.sim.compiling_note)
        imgui.render()
        self.gui.render(imgui.get_draw_data())

    # -- window events ---------------------------------------------------------------
    def on_resize(self, width, height):
        self.camera.resize(width, height)
        return pyglet.event.EVENT_HANDLED

    def on_draw(self):
        pass

    def on_close(self):
        if self.editor.doc.dirty and not getattr(self, "force_close", False):
            self.panels.confirm("Quit Stelkropp?", self._really_close,
                                lambda: self.files.save() and self._really_close())
            return pyglet.event.EVENT_HANDLED
        self._really_close()
        return pyglet.event.EVENT_HANDLED

    def _really_close(self):
        self.has_exit = True
