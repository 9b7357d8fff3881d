"""Issue 42 item 16, honest progress: the first launch counts the work actually left (units in the
cache count for nothing, a unit's count falls as its kernels compile) and names what it waits for."""
from __future__ import annotations

import json

from app import compile_progress as cp


def test_only_the_units_left_count_and_are_named(tmp_path):
    path = tmp_path / "kernel_counts.json"
    path.write_text(json.dumps({"units": {"narrow": 40, "solve:soft_step:euler": 50}}))
    counts = cp.KernelCounts(path)
    compiled = {"narrow": 10, "solve:soft_step:euler": 50}
    finished = {"solve:soft_step:euler"}
    frac, done, left, waiting = cp.progress(
        ["narrow", "solve:soft_step:euler", "frame"], lambda u: compiled.get(u, 0),
        finished.__contains__, {"narrow": "sat_polygons"}, counts)
    # narrow: 40 expected, 10 compiled -> 30 left; frame: nothing compiled, the default count
    assert (done, left) == (60, 30 + cp.DEFAULT_COUNTS["frame"])
    assert frac == done / (done + left)
    assert waiting == ["the narrow phase (sat_polygons)", "the frame's kernels (geometry, islands, drawing)"]
    line = cp.describe(done, left, waiting, loading=False)
    assert line.startswith(f"~{left} kernels left") and "waiting for the narrow phase" in line


def test_a_unit_past_its_count_still_leaves_work_until_it_finishes(tmp_path):
    counts = cp.KernelCounts(tmp_path / "none.json")     # no file: the defaults by kind
    frac, done, left, waiting = cp.progress(["guard"], lambda u: 99, lambda u: False, {}, counts)
    assert left == 1 and frac < 1.0 and waiting == ["the step's guard"]
    frac, done, left, waiting = cp.progress(["guard"], lambda u: 99, lambda u: True, {}, counts)
    assert left == 0 and frac == 1.0 and waiting == []
    assert cp.describe(done, left, waiting, loading=True) == "loading the compiled kernels"


def test_counts_are_saved_per_unit_only_from_a_cold_launch(tmp_path):
    path = tmp_path / "kernel_counts.json"
    counts = cp.KernelCounts(path)
    counts.save({"narrow": 3})                    # a warm cache: too few to be a count
    assert not path.exists()
    counts.save({"narrow": 41, "frame": 24, "guard": 0})
    assert cp.KernelCounts(path).units == {"narrow": 41, "frame": 24}
    path.write_text(json.dumps({"total": 133}))    # the old format: ignored, the defaults serve
    assert cp.KernelCounts(path).expected("narrow") == cp.DEFAULT_COUNTS["narrow"]
