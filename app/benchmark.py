"""``--benchmark-frames N``: N frames unthrottled, one physics step each, then the frame-time split
(docs/sandbox.md reports its figures)."""
from __future__ import annotations

import time

import numpy as np


class FrameBenchmark:
    """Records the split of every frame after the first 10 ready ones; prints medians and means."""

    WARM = 10

    def __init__(self, frames: int):
        self.frames = frames
        self.samples: list[dict] = []
        self.cpu0 = None       # process CPU time (s, every thread: ours and llvmpipe's) at the first sample
        self.cpu_ms = 0.0      # process CPU ms per recorded frame

    def attach(self, loop):
        loop.hooks.append(self)
        loop.fixed_step = True
        loop.stop_on_error = True
        return self

    def after_swap(self, loop):
        w = loop.window
        if w.warmup.ready and loop.ready_frames > self.WARM and w.times.last:
            self.samples.append(dict(w.times.last))
            if self.cpu0 is None:
                self.cpu0 = time.process_time()
            elif len(self.samples) > 1:
                self.cpu_ms = (time.process_time() - self.cpu0) * 1e3 / (len(self.samples) - 1)
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
        print(f"benchmark: {len(bench)} frames, {n} bodies, solver {window.world.solver}, "
              f"load average {load_average()}")
        print("  median ms: " + "  ".join(f"{k} {med[k]:.2f}" for k in keys))
        print("  mean ms:   " + "  ".join(f"{k} {mean[k]:.2f}" for k in keys))
        print("  median parts ms: " + "  ".join(f"{k} {v:.2f}" for k, v in parts(bench).items()))
        # CPU time is the work itself: other jobs on the cores stretch the wall times, not this
        print(f"  process CPU per frame (all threads, llvmpipe's too): {self.cpu_ms:.2f} ms")
        render = med['upload'] + med['draw'] + med['ui']
        print(f"  render-only frame (upload+draw+ui): {render:.2f} ms "
              f"= {1000.0 / max(1e-6, render):.0f} fps; "
              f"with physics: {1000.0 / max(1e-6, med['frame']):.0f} fps")


def parts(bench) -> dict:
    """Medians of the finer split: draw without the swap (GL calls), the swap (where llvmpipe
    rasterises the scene and imgui), the Plot tab's imgui building (part of ui), and the rest
    of the frame (stats sampling, the world-bound check, hover, autosave)."""
    def med(f):
        return float(np.median([f(b) for b in bench]))
    return {"draw-calls": med(lambda b: b["draw"] - b.get("swap", 0.0)),
            "swap": med(lambda b: b.get("swap", 0.0)),
            "plot-ui": med(lambda b: b.get("plot", 0.0)),
            "other": med(lambda b: b["frame"] - b["physics"] - b["upload"] - b["draw"] - b["ui"])}


def load_average() -> str:
    """The 1, 5 and 15 minute load averages (other jobs on the machine slow llvmpipe's threads)."""
    try:
        return " ".join(open("/proc/loadavg").read().split()[:3])
    except OSError:
        return "unknown"
