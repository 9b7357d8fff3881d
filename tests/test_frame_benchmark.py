"""The frame benchmark's split (app/benchmark.py, issue 16): medians of each part, the swap and the
Plot tab's share taken out of draw and ui, the rest of the frame, the load average and the
process CPU time per frame.  Synthetic frames with known medians; no window."""
from __future__ import annotations

from types import SimpleNamespace

from app.benchmark import FrameBenchmark, load_average, parts


def frame(physics, upload, draw, ui, swap, plot, other):
    # draw includes the swap (the loop adds it); frame = the parts + the rest
    return dict(physics=physics, upload=upload, draw=draw, ui=ui, swap=swap, plot=plot,
                frame=physics + upload + draw + ui + other)


def test_parts_are_medians_of_each_frames_split():
    bench = [frame(2, 1, 20, 3, 18, 1, 0.5), frame(2, 1, 10, 3, 9, 1, 1.5), frame(2, 1, 30, 3, 27, 1, 1.0)]
    p = parts(bench)
    assert p == {"draw-calls": 2.0, "swap": 18.0, "plot-ui": 1.0, "other": 1.0}


def test_frames_without_swap_or_plot_count_them_as_zero():
    p = parts([dict(physics=1, upload=1, draw=4, ui=1, frame=8)])
    assert p == {"draw-calls": 4.0, "swap": 0.0, "plot-ui": 0.0, "other": 1.0}


def test_samples_after_warmup_until_the_count_then_the_report(capsys):
    times = SimpleNamespace(last=None)
    window = SimpleNamespace(warmup=SimpleNamespace(ready=True), times=times,
                             world=SimpleNamespace(bodies=[0] * 7, solver="soft_step"))
    loop = SimpleNamespace(window=window, ready_frames=0, stop=False, hooks=[])
    fb = FrameBenchmark(3).attach(loop)
    assert loop.fixed_step and loop.stop_on_error and loop.hooks == [fb]
    for k in range(1, 40):
        loop.ready_frames = k
        times.last = frame(k, 1, 5, 2, 4, 0.5, 1)
        fb.after_swap(loop)
        if loop.stop:
            break
    # frames 11, 12, 13 are recorded (the first WARM = 10 ready ones are not), then the loop stops
    assert loop.ready_frames == FrameBenchmark.WARM + 3 and [s["physics"] for s in fb.samples] == [11, 12, 13]
    assert fb.cpu_ms >= 0.0
    fb.at_exit(loop)
    out = capsys.readouterr().out
    assert "benchmark: 3 frames, 7 bodies, solver soft_step, load average " in out
    assert "median ms: physics 12.00  upload 1.00  draw 5.00  ui 2.00  frame 21.00" in out
    assert "median parts ms: draw-calls 1.00  swap 4.00  plot-ui 0.50  other 1.00" in out
    assert "process CPU per frame" in out


def test_load_average_is_three_numbers_or_unknown():
    la = load_average()
    assert la == "unknown" or [float(v) >= 0 for v in la.split()] == [True] * 3
