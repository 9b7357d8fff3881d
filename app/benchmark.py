"""``--benchmark-frames N``: N frames unthrottled, one physics step each, then the frame-time split
(docs/sandbox.md reports its figures)."""
from __future__ import annotations

import numpy as np


class FrameBenchmark:
    """Records the split of every frame after the first 10 ready ones; prints medians and means."""

    WARM = 10

    def __init__(self, frames: int):
        self.frames = frames
        self.samples: list[dict] = []

    def attach(self, loop):
        loop.hooks.append(self)
        loop.fixed_step = True
        loop.stop_on_error = True
        return self

    def after_swap(self, loop):
        w = loop.window
        if w.warmup.ready and loop.ready_frames > self.WARM and w.times.last:
            self.samples.append(dict(w.times.last))
        if loop.ready_frames >= self.frames + self.WARM:
            loop.stop = True

    def at_exit(self, loop):
        if self.samples:
            self.report(loop.window)

    def report(self, window):
        bench = self.samples
        keys = ("physics", "upload", "draw", "ui", "frame")
        med = {k: float(np.median([b[k] for b in bench])) for k in keys}
        mean = {k: float(np.mean([b[k] for b in bench])) for k in keys}
        n = len(window.world.bodies)
        print(f"benchmark: {len(bench)} frames, {n} bodies, solver {window.world.solver}")
        print("  median ms: " + "  ".join(f"{k} {med[k]:.2f}" for k in keys))
        print("  mean ms:   " + "  ".join(f"{k} {mean[k]:.2f}" for k in keys))
        render = med['upload'] + med['draw'] + med['ui']
        print(f"  render-only frame (upload+draw+ui): {render:.2f} ms "
              f"= {1000.0 / max(1e-6, render):.0f} fps; "
              f"with physics: {1000.0 / max(1e-6, med['frame']):.0f} fps")
