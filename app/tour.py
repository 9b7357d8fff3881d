"""``--tour SCENE ...``: after the launch scene, open each given scene in turn in the same window.

Each scene (the launch scene first) runs ``--frames`` frames once its kernels are ready (and, with
``--tour-seconds``, until its world has run that many simulated seconds, played at the time scale
that fits those seconds into the frames, as the simulation panel's slider would: the world steps
the same fixed ``dt`` whatever the scale, only fewer frames are drawn per simulated second); then its
last frame is saved as ``<stem>.png`` in the ``--screenshot`` folder, beside ``<stem>.json``, the
status the tests read (automation.status) with the OpenGL and scene errors of that scene alone.
The next scene is opened the way the scene panel opens one (SceneFiles.open_scene); after the last
the window exits.  One window for many scenes saves a process start and a kernel load per scene.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .automation import screenshot, status


def framing(app) -> dict:
    """Where the moving bodies are drawn: how many there are and how many have their centre inside
    the free area (window pixels), for scenes of any size (the status lists bodies only up to 300)."""
    rd = app.world.render_data()
    moving = rd.kind != 1
    pos = rd.center[moving]
    x0, y0, x1, y1 = app.free_rect()
    sp = app.camera.to_screen(pos) if len(pos) else np.zeros((0, 2))
    sx, sy = sp[:, 0], app.height - sp[:, 1]
    inside = int(np.count_nonzero((x0 <= sx) & (sx <= x1) & (y0 <= sy) & (sy <= y1)))
    return {"moving": int(len(pos)), "inside_free": int(inside)}


class Tour:
    def __init__(self, scenes, frames: int, out_dir, seconds: float = 0.0):
        self.queue = [Path(s) for s in scenes]
        self.frames = frames
        self.seconds = seconds
        self.out = Path(out_dir)
        self.out.mkdir(parents=True, exist_ok=True)
        self._gl0 = 0
        self._shot = None

    def attach(self, loop):
        loop.hooks.append(self)
        loop.stop_on_error = True
        # the slider's range is 0.05..4 (panels/simulation.py); a scene that cannot keep up plays
        # slower, and its screenshot waits for the seconds all the same (before_swap)
        # (opening a scene keeps the simulation's time scale: set once for every scene)
        loop.window.sim.time_scale = min(4.0, max(1.0, self.seconds * loop.fps_limit / max(self.frames, 1)))
        return self

    def _stem(self, window) -> str:
        path = window.editor.doc.path
        return Path(path).stem if path else "untitled"

    def before_swap(self, loop):
        played = loop.window.world.time >= self.seconds
        if self._shot is None and loop.ready_frames >= self.frames and played:
            self._shot = self.out / f"{self._stem(loop.window)}.png"
            screenshot(loop.window, self._shot)

    def after_swap(self, loop):
        if self._shot is None:
            return
        w = loop.window
        st = status(w)
        st["gl_errors"] = list(w.gl_errors[self._gl0:])
        st["scene_errors"] = list(w.files.errors)
        st["framing"] = framing(w)
        self._shot.with_suffix(".json").write_text(json.dumps(st))
        self._shot = None
        if not self.queue:
            loop.stop = True
            return
        self._gl0 = len(w.gl_errors)
        w.files.open_scene(self.queue.pop(0))
        loop.ready_frames = 0
