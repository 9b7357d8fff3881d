"""Test and script automation, attached to the main loop only when asked for (``--status``,
``--control``, ``--frames``/``--screenshot``/``--exit``): a JSON status file of what the window
holds, a control file of JSON event lines dispatched through pyglet, and screenshots."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import physics
import pyglet
from OpenGL import GL
from physics import joint_params as jp

from .body_colors import rgb_to_hex
from .joint_specs import param_value
from .scenes import scene_files, user_scenes_dir

STATUS_EVERY = 2        # frames between status writes


def screenshot(window, path) -> None:
    """Save the back buffer (the frame just drawn, before the swap) as a PNG."""
    fw, fh = window.get_framebuffer_size()
    GL.glPixelStorei(GL.GL_PACK_ALIGNMENT, 1)
    data = GL.glReadPixels(0, 0, fw, fh, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
    pyglet.image.ImageData(fw, fh, "RGBA", bytes(data)).save(str(path))


def _bodies(app):
    out = []
    for b in app.world.bodies:
        sp = app.camera.to_screen(b.position)
        rgb = app.editor.color_of(b)
        out.append({"id": b.id, "name": b.name, "kind": b.kind, "position": b.position, "angle": b.angle,
                    "velocity": b.velocity, "angular_velocity": b.angular_velocity,
                    "screen": [float(sp[0]), float(app.height - sp[1])],
                    "shape": b.shape.kind, "density": b.density,
                    "vertices": 0 if isinstance(b.shape, physics.Circle) else len(b.shape.vertices),
                    "fixtures": [f.shape.kind for f in b.fixtures], "mass": b.mass,
                    "awake": b.awake, "color": None if rgb is None else rgb_to_hex(rgb)})
    return out


def _joints(app):
    """The user's joints (not the mouse drag's): ends, where they are drawn, parameters, readouts."""
    out = []
    for j in app.world.joints:
        if app.editor.is_tool_joint(j):
            continue
        sp = app.camera.to_screen(j.anchor_a)
        d = {"id": j.id, "kind": j.kind, "name": j.name, "a": j.body_a.id,
             "b": None if j.body_b is None else j.body_b.id, "anchor_a": j.anchor_a, "anchor_b": j.anchor_b,
             "screen": [float(sp[0]), float(app.height - sp[1])], "broken": j.broken,
             "reaction_force": j.reaction_force,
             "params": {n: param_value(j, n) for n in jp.PARAMS[j.kind]}}
        if "speed" in jp.KINDS[j.kind].readouts:
            d["speed"] = j.speed
        out.append(d)
    return out


def _offer(offer):
    return None if offer is None else {"path": str(offer[0]), "origin": offer[2]}


def status(app) -> dict:
    """Everything a test checks, as JSON-ready values (bodies and springs only up to 300 bodies)."""
    w, ed, small = app.world, app.editor, len(app.rd_ids) <= 300
    return {
        "frame": app.frame_no, "ready": app.warmup.ready, "warm_finished": app.warmup.finished,
        "joints_ready": app.warmup.joints_ready(w.solver, w.integrator),
        "progress": app.warmup.progress()[0], "kernels_compiled": app.warmup.kernels_compiled(),
        "t_gate": app.warmup.t_gate,
        "warm_errors": app.warmup.errors, "running": app.sim.running, "solver": w.solver,
        "solver_pending": app.mode_switch.describe(), "compiling_note": app.sim.compiling_note,
        "n_bodies": len(w.bodies), "n_springs": len(w.springs),
        "n_joints": len([j for j in w.joints if not ed.is_tool_joint(j)]), "n_tool_joints": len(ed.tool_joints),
        "bodies": _bodies(app) if small else [],     # store reads: no kernel (also while compiling)
        "path": str(ed.doc.path) if ed.doc.path else None, "dirty": ed.doc.dirty,
        "fault": app.sim.fault, "scene_errors": app.files.errors, "gl_errors": app.gl_errors[-20:],
        "messages": [m[0] for m in app.notices.items], "frame_times": app.times.avg, "fps": app.times.fps,
        "selection": [s.id for s in ed.selection if s.alive], "tool": ed.tool.name,
        "selected_joints": [s.id for s in ed.selection if s.alive and isinstance(s, physics.Joint)],
        "camera": {"center": app.camera.center.tolist(), "scale": app.camera.scale},
        "time": w.time, "steps": w.steps, "window": [app.width, app.height],
        "one_call": w._pipeline.one_call.P is not None,     # the world steps through the compiled driver
        "units_loaded": sorted(app.warmup.loaded),
        "ui_rects": app.ui_rects, "show_ui": app.show_ui,
        "springs": [{"id": s.id, "a": s.body_a.id, "b": None if s.body_b is None else s.body_b.id}
                    for s in w.springs if s.id not in ed.tool_springs] if small else [],
        "joints": _joints(app) if small and app.warmup.ready else [],
        "overlays": dict(vars(app.overlays)), "quadtree_cells": len(app.sim.quadtree),
        "free_rect": list(app.free_rect()), "edit_error": ed.edit_error, "status_every": STATUS_EVERY,
        "save_as": app.files.save_as_path, "dialog": app.panels.dialogs.open_title,
        "autosave_offer": _offer(app.panels.dialogs.autosave_offer),
        "user_scenes": [str(p) for p in scene_files(user_scenes_dir())],
        "ui_values": app.ui_values, "awake": int(np.count_nonzero(w.state()["awake"])) if app.warmup.ready else 0,
        "speed": app.sim.speed, "hint": app.editor.hint_text(), "scene_keys": app.input.scene_keys,
        "dt": w.dt, "time_scale": app.sim.time_scale, "gl_config": app.gl_config,
        "bound": {"lo": app.bound.lo.tolist(), "hi": app.bound.hi.tolist(), "enabled": app.bound.enabled,
                  "shown": app.bound.shown},
        "plots": [p.last for p in app.panels.stats.plots] if app.panels.show_stats else [],
        "compare": app.compare.describe(), "plot": app.panels.plot.describe(),
        "tracers": [{"body": t.ref.obj.id if t.ref.obj is not None else None, "local": t.local, "n": t.n,
                     "span": float(t.times[t.n - 1] - t.times[0]) if t.n else 0.0,
                     "last": t.points[t.n - 1].tolist() if t.n else None} for t in ed.tracers.items],
        "trail_seconds": ed.tracers.seconds, "snap": {"on": ed.snap.on, "grid": ed.snap.grid, "angle": ed.snap.angle},
        "follow": ed.follow.obj.id if ed.follow is not None and ed.follow.obj is not None else None,
        "clipboard": len(ed.clipboard["bodies"]) if ed.clipboard else 0, "context_menu": app.panels.context.shown,
"lasers": ed.lasers.describe(), "timeline": app.timeline.describe(),
        "compare_plots": [p.last for p in app.panels.stats.compare.plots] if app.compare.active else [],
    }


class Automation:
    """The hooks.  ``status_path``: written every STATUS_EVERY frames and at exit;
    ``control_path``: JSON lines such as ``{"event": "on_file_drop", "args": [400, 300, ["/a.json"]]}``;
    ``frames``: after this many ready frames, save ``screenshot`` (if given) and stop if ``exit_after``."""

    def __init__(self, status_path=None, control_path=None, frames=None, screenshot_path=None, exit_after=False):
        self.status_path = Path(status_path) if status_path else None
        self.control_path = Path(control_path) if control_path else None
        self.frames = frames
        self.screenshot_path = screenshot_path
        self.exit_after = exit_after
        self._control_pos = 0
        self._shot_taken = False

    def attach(self, loop):
        loop.hooks.append(self)
        if self.exit_after:
            loop.stop_on_error = True
        return self

    def _done(self, loop) -> bool:
        return self.frames is not None and loop.ready_frames >= self.frames

    def write_status(self, app):
        if self.status_path is None:
            return
        tmp = self.status_path.with_suffix(".tmp")
        tmp.write_text(json.dumps(status(app)))
        tmp.replace(self.status_path)

    def after_events(self, loop):
        """Dispatch the control file's new lines through pyglet's own event dispatch."""
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
                loop.window.dispatch_event(ev["event"], *ev.get("args", []))

    def before_swap(self, loop):
        if self.screenshot_path and not self._shot_taken and self._done(loop):
            screenshot(loop.window, self.screenshot_path)
            self._shot_taken = True

    def after_swap(self, loop):
        if loop.window.frame_no % STATUS_EVERY == 0:
            self.write_status(loop.window)
        if self.exit_after and self._done(loop):
            loop.stop = True

    def at_exit(self, loop):
        self.write_status(loop.window)
