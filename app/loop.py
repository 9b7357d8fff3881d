"""The main loop: events, one frame, the buffer swap, frame pacing.

Hooks (objects in ``MainLoop.hooks``) may define any of ``after_events(loop)``,
``before_swap(loop)``, ``after_swap(loop)`` and ``at_exit(loop)``; test automation and the frame
benchmark attach this way, so the production window knows nothing of them.  A hook ends the loop
by setting ``loop.stop = True``.
"""
from __future__ import annotations

import sys
import time
import traceback


class MainLoop:
    """Runs ``window`` (a Sandbox) until it closes.  ``fps_limit``: frames per second when idle."""

    def __init__(self, window, fps_limit: float = 60.0):
        self.window = window
        self.fps_limit = fps_limit
        self.hooks: list = []
        self.ready_frames = 0          # frames drawn since the scene's kernels were ready
        self.stop = False
        self.stop_on_error = False     # a frame that raises ends the run with status 3
        self.fixed_step = False        # benchmark: one physics step per frame, no throttle
        self.code = 0

    def _hooks(self, name):
        for h in self.hooks:
            fn = getattr(h, name, None)
            if fn is not None:
                fn(self)

    def _throttle(self, started):
        w = self.window
        limit = self.fps_limit
        if w.warmup.busy:
            # this process compiles or loads: each OpenGL call gives up the interpreter lock and
            # waits for it, so leave it to the warmup (4 fps while nothing steps, 20 after)
            limit = 20.0 if w.warmup.ready else 4.0
        elif not w.warmup.ready:
            limit = 30.0     # the helper processes compile on both cores: the panels need little
        if limit and not (self.fixed_step and w.warmup.ready):
            spare = 1.0 / limit - (time.perf_counter() - started)
            if spare > 0:
                time.sleep(spare)

    def run(self) -> int:
        """Loop until the window closes or a hook stops it; returns the exit status (3: an
        OpenGL or frame error happened)."""
        w = self.window
        last = time.perf_counter()
        while not w.has_exit:
            w.dispatch_events()
            self._hooks("after_events")
            now = time.perf_counter()
            real_dt, last = now - last, now
            if self.fixed_step:
                real_dt = w.world.dt / max(w.sim.time_scale, 1e-6)   # one step per frame, exactly
            try:
                w.frame(real_dt)
            except Exception as exc:  # noqa: BLE001
                traceback.print_exc()
                w.gl_errors.append(f"frame {w.frame_no}: {type(exc).__name__}: {exc}")
                if self.stop_on_error:
                    self.code = 3
                    break
            if w.warmup.ready:
                self.ready_frames += 1
            self._hooks("before_swap")
            t_flip = time.perf_counter()
            w.flip()
            w.times.add_swap((time.perf_counter() - t_flip) * 1e3)
            self._hooks("after_swap")
            if self.stop:
                break
            self._throttle(now)
        self._hooks("at_exit")
        if w.gl_errors:
            print("stelkropp: OpenGL/frame errors:", *w.gl_errors[:20], sep="\n  ", file=sys.stderr)
            self.code = self.code or 3
        w.autosaver.end_session()
        w.warmup.close()
        w.panels.close()
        w.close()
        return self.code
