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

from . import compile_units, framing, preview, scrub_marks
from .autosave import Autosaver
from .bound import WorldBound
from .bound_removal import remove_escapees
from .camera import Camera
from .compare import Comparison
from .compare_view import CompareView
from .editor import Editor
from .files import SceneFiles
from .gl_config import create_window
from .input import SceneInput
from .mode_switch import PendingSwitch
from .notices import Notices
from .probes import Recorder
from .panels import Panels, apply_style
from .panels.notes import overlay_note, progress_window
from .render import Overlays, Renderer
from .scene_wait import SceneWait
from .scenes import initial_world
from .sensors import SensorView
from .simulation import Simulation
from .stats import FrameTimes, StatsSampler
from .timeline import Timeline
from .warmup import Warmup

PROFILE = bool(os.environ.get("STELKROPP_PROFILE"))
BOUND_COLOR = (1.0, 0.62, 0.25, 0.55)     # the world bound's outline   # glFinish after each part: honest frame split


class Sandbox(pyglet.window.Window):
    """``Sandbox(scene=path)`` (or ``world=``): the editor window.  ``paused`` starts paused;
    ``offer_autosave`` offers a crashed session's autosave."""

    def __init__(self, scene=None, world=None, size=(1280, 800), position=None, paused=False,
                 autosave_interval=60.0, offer_autosave=True, vsync=False):
        # 4x multisampled when the driver offers it, else the plain config (gl_config.py)
        self.gl_config = create_window(lambda config: super(Sandbox, self).__init__(
            size[0], size[1], "Stelkropp", resizable=True, config=config, vsync=vsync))
        self.gl_config["samples"] = int(GL.glGetIntegerv(GL.GL_SAMPLES))   # what the framebuffer has
        if position is not None:
            self.set_location(*position)
        imgui_ctx = imgui.create_context()
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
        self.ui_values: dict[str, object] = {}   # what some widgets show (the status file reports it)
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
        self.bound = WorldBound()
        self._scene_pending = "new"     # the next frame frames the scene (and, once ready, sets the bound)
        lock = threading.Lock()
        self.warmup = Warmup(world, lock)
        preview.hold(world)             # released by the first ready frame
        self.sim = Simulation(self.editor, self.warmup, self.notices, paused=paused, lock=lock)
        self.mode_switch = PendingSwitch(self.editor, self.warmup)   # a mode picked before it is compiled
        self.scene_wait = SceneWait(self.warmup)  # what the open scene's steps wait for (the note)
        self.timeline = Timeline()                # snapshots while playing: the timeline slider
        self.timeline.mark_of = lambda: scrub_marks.mark(self.editor.doc)
        self.sim.after_step = self._after_step
        self.sensors = SensorView()               # sensor fixtures, drawn translucent and lit
        self.autosaver = Autosaver(interval=autosave_interval)
        self.files = SceneFiles(self.editor, self.autosaver, lambda *a: self.panels.ask(*a))
        self.files.errors = errors
        self.compare = Comparison(self)           # live solver comparison (off until started)
        self.compare_view = CompareView(self)
        self.recorder = Recorder()                # plot anything: the chosen quantities
        crash = self.autosaver.previous_crash() if offer_autosave else None
        self.autosaver.begin_session(path)
        self.panels = Panels(self, imgui_ctx)
        if crash:
            self.panels.dialogs.autosave_offer = crash
        self.input = SceneInput(self)
        self.push_handlers(self.input)
        self.gui = create_renderer(self)      # after: imgui's handlers see every event before ours
        self.editor.on_document.append(self._document_changed)
        self.editor.on_mode.append(self._mode_changed)
        self.warmup.start()
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
        if not self.warmup.ready:
            preview.hold(world)        # a scene opened while the kernels compile: picked from numpy
        self.sim.reset()
        self.timeline.clear()                     # a reset or another scene: nothing to go back to
        self.sampler.clear()
        self.recorder.clear(keep_series=keep_camera)     # a reset keeps what is plotted
        if keep_camera:
            self.recorder.rebind(world, self.editor.refs)
        self._scene_pending = "reset" if keep_camera else "new"
        self.autosaver.set_origin(path)
        self._mode_changed(world.solver, world.integrator)

    def _mode_changed(self, solver, integrator):
        bp = compile_units.broadphase_of(self.world)
        if not self.warmup.can_step(solver, integrator, bp):
            self.warmup.prioritize(solver, integrator, bp)

    # -- where the scene is shown ------------------------------------------------------
    def panel_rects(self):
        """The panels' rectangles from the last frame (they can be moved), or their default places
        before the first frame with panels; none while the panels are hidden (H)."""
        if not self.show_ui:
            return []
        if "main_window" not in self.ui_rects:
            return self.panels.default_rects(self.width, self.height)
        return framing.panel_rects(self.ui_rects)

    def free_regions(self):
        return framing.free_regions(self.panel_rects(), self.width, self.height)

    def free_rect(self):
        """The largest free area beside the panels (window pixels, y down): scenes open framed in it."""
        return framing.best_region(self.free_regions())

    def fit(self):
        """Frame the scene's content in the free area (F): the bodies inside the world bound."""
        framing.fit(self.camera, self.bound.content(self.world.render_data()), self.free_regions())

    def frame_scene(self):
        framing.frame_scene(self.camera, self.world, self.free_regions())

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
            preview.release(self.world)     # the kernels are loaded: the world's own render data
            self.prepare_scene()
            self.keep_timeline()
            self.mode_switch.update()       # a picked mode whose kernels are now loaded: switch
            phys_ms, steps = self.sim.advance(real_dt, velocities=self.overlays.velocities)
            rd = self.check_bound() if steps else None
            self.sampler.sample(self.world, phys_ms, steps, self.frame_no)
            t_cmp = time.perf_counter()
            self.compare.update(phys_ms, steps)
            self.recorder.sample(self.world)
            self.editor.tracers.sample(self.world)
            self.editor.lasers.update(self.world)
            phys_ms += (time.perf_counter() - t_cmp) * 1e3
            self.follow_camera()
            self.input.update_hover()
            upload_ms = self.build_scene(rd)
        else:
            upload_ms = self.preview_scene()
        t_draw = time.perf_counter()
        fw, fh = self.get_framebuffer_size()
        if ready:
            self.compare_view.draw(fw, fh)
        else:
            self.renderer.draw(self.camera, fw, fh)
        if PROFILE:
            GL.glFinish()
        draw_ms = (time.perf_counter() - t_draw) * 1e3   # + the buffer swap, added by the loop
        t_ui = time.perf_counter()
        self.panels.plot.ms = 0.0
        self.draw_ui(ready)
        if PROFILE:
            GL.glFinish()
        ui_ms = (time.perf_counter() - t_ui) * 1e3
        err = GL.glGetError()
        if err != GL.GL_NO_ERROR:
            self.gl_errors.append(f"frame {self.frame_no}: GL error 0x{err:x}")
        self.times.record(real_dt, physics=phys_ms, upload=upload_ms, draw=draw_ms, ui=ui_ms,
                          frame=(time.perf_counter() - t_start) * 1e3, plot=self.panels.plot.ms)
        if ready:
            self.editor.sync_app_data()     # the autosave keeps colours, lasers and tracers too
            self.autosaver.tick(self.editor.doc, busy=self.editor.tools["select"].joint is not None)
        self._update_caption()
        if self.frame_no == 1:
            self.warmup.frame_drawn()      # the second frame began after the first one's swap
        self.frame_no += 1

    def keep_timeline(self):
        """Clear the timeline if an edit (or the mouse drag's joint) changed the topology; while
        playing, a snapshot of the state before this frame's steps when one is due."""
        w = self.world
        sig = (self.editor.doc.history.version, len(self.rd_ids), len(w.joints), len(w.springs))
        if self.timeline.watch(w, sig, transient=bool(self.editor.tool_joints)):
            self.notices.notify("timeline cleared: the bodies or joints changed")
        if self.sim.running:
            self.timeline.record(w)

    def _after_step(self, world):
        if self.sim.running:       # a single step (S) from a paused moment does not record
            self.timeline.record(world)
        else:                      # but it is the new future of a scrubbed moment
            self.timeline.drop_future()
        self.panels.stats.contacts.rate.on_step(world)   # the selected body's hits (stats readout)

    def preview_scene(self) -> float:
        """Before the kernels are ready: the scene as it stands (not stepping), framed, from numpy
        render data (``app.preview``), which every pick and frame asks too; returns the upload ms."""
        preview.hold(self.world)       # each frame: a scene opened meanwhile is a new world
        if self._scene_pending == "new":
            framing.frame_scene(self.camera, self.world, self.free_regions())
            self._scene_pending = "framed"
        self.input.update_hover()
        return self.build_scene(sim_overlays=False)

    def prepare_scene(self):
        """The first ready frame of a new document: the world bound from the scene's extent and
        the camera; after a reset only who is inside the bound (the view and the bound stay)."""
        if self._scene_pending is None:
            return
        rd = self.world.render_data()
        if self._scene_pending == "framed":      # framed by the preview: the same render data
            self.bound.fit_scene(rd)
        elif self._scene_pending == "new":
            self.bound.fit_scene(rd)
            self.frame_scene()
        else:
            self.bound.rebase(rd)
        self._scene_pending = None

    def check_bound(self):
        """Remove the moving bodies that crossed the world bound this frame; returns the render
        data to draw."""
        rd = self.world.render_data()
        return self.world.render_data() if remove_escapees(self, rd) else rd

    def follow_camera(self):
        """Keep the followed body (L) at the middle of the free area."""
        ref = self.editor.follow
        if ref is None:
            return
        b = ref.obj
        if b is None or not b.alive:
            self.editor.follow = None
            return
        self.camera.look_at(b.center_of_mass, self.camera.scale, self.free_rect())

    def build_scene(self, rd=None, sim_overlays=True) -> float:
        """The world's render data -> the renderer's vertex buffers; returns the upload ms.
        ``sim_overlays``: False before the kernels are ready (no velocity or quadtree overlays)."""
        rd = self.world.render_data() if rd is None else rd
        self.rd_ids = rd.ids
        decor = self.editor.decor()
        decor.trails = self.editor.tracers.segments()
        if sim_overlays:       # lit sensors need the overlap query's kernels (compiled by the warmup)
            decor.sensors = self.sensors.states(self.world, (self.editor.doc.history.version, len(rd.ids),
                                                             id(self.world)))
        if self.bound.shown:
            for a, b in self.bound.outline():
                decor.segments.append((a, b, 1.5, BOUND_COLOR))
        velocities = self.sim.body_velocities(rd) if self.overlays.velocities and sim_overlays else None
        quadtree = self.sim.quadtree_cells(self._quadtree_failed) if self.overlays.quadtree and sim_overlays \
            else None
        spring_ids = np.array([s.id for s in self.world.springs], dtype=np.int64) \
            if (decor.hidden_springs or decor.selected_springs) else None
        if np.all(np.isfinite(rd.vertices)) and np.all(np.isfinite(rd.center)):
            self.renderer.build(rd, self.camera, self.overlays, decor, spring_ids, quadtree, velocities)
        if sim_overlays:       # the rivals' render data needs the kernels; they do not step before
            self.compare_view.build()
        return self.renderer.last_upload_ms

    def _quadtree_failed(self, exc):
        self.overlays.quadtree = False
        self.notices.notify(f"quadtree overlay off: {exc}", error=True)

    def draw_ui(self, ready):
        imgui.new_frame()
        self.panels.numbers.begin_frame()
        self.ui_rects.pop("progress", None)       # drawn again below while the kernels compile
        self.ui_values.pop("progress", None)
        self.ui_values.pop("progress_head", None)
        waiting = self.scene_wait.waiting(self.world)
        if self.show_ui:
            self.panels.draw()
        elif waiting:
            progress_window(self)         # the panels hidden (H): the wait is still said
        self.panels.numbers.end_frame()
        if ready:
            self.compare_view.labels()
        if self.sim.compiling_note and not waiting:      # else the progress note says it
            overlay_note(self, self.sim.compiling_note)
        imgui.render()
        self.panels.hits.refresh()       # where the panels are now: the next events are routed by it
        self.input.after_frame()
        self.gui.render(imgui.get_draw_data())

    # -- window events ---------------------------------------------------------------
    def on_resize(self, width, height):
        self.camera.resize(width, height)
        return pyglet.event.EVENT_HANDLED

    def on_draw(self):
        pass

    def on_close(self):
        if getattr(self, "force_close", False):
            self._really_close()
        else:
            self.files.confirm_unsaved("Quit Stelkropp?", self._really_close)
        return pyglet.event.EVENT_HANDLED

    def _really_close(self):
        self.has_exit = True
