"""Issue 16, "First launch": on a cold kernel cache the scene is drawn (not stepping) before any kernel
is compiled, and the compile progress moves.  A real window under Xvfb with an empty cache
directory of its own; the test stops the sandbox once the progress has moved (the times to drawn
and playing are measured by ``python -m bench.launch``, not asserted here)."""
from __future__ import annotations

import pytest

from sandbox_pixels import ROOT, body_pixels

pytestmark = pytest.mark.app

# a cold compile of the first kernels on a loaded 2-core machine takes minutes
COMPILE_TIMEOUT = 900


def test_cold_launch_draws_the_scene_first_and_the_progress_moves(launch, tmp_path):
    cold = tmp_path / "empty-cache"
    # NUMBA_CACHE_DIR too: this process may have imported physics, which sets it for its own cache
    app = launch(ROOT / "scenes" / "default.json",
                 env={"STELKROPP_CACHE_DIR": str(cold), "NUMBA_CACHE_DIR": str(cold / "numba")})
    st0 = app.wait(lambda s: s.get("frame", 0) >= 4, 120, "the first frames")
    assert not st0["ready"], "a cold cache cannot be ready before its first frames"
    assert st0["steps"] == 0 and st0["time"] == 0.0
    img = app.screenshot("cold_first_frames")
    # the scene is drawn (the default scene's bodies fill thousands of pixels) before its kernels
    st = app.status()
    assert not st["ready"], "the screenshot must be taken while the kernels compile"
    assert body_pixels(img, 0, 1280, 0, 660) > 3000
    # the progress readout moves while nothing is ready yet: kernels are counted as they compile
    p0, k0 = st["progress"], st["kernels_compiled"]
    assert p0 < 0.5, "a cold cache: most of the scene's kernels are still to compile"
    st1 = app.wait(lambda s: s["kernels_compiled"] >= k0 + 3 or s["ready"], COMPILE_TIMEOUT,
                   "three more kernels compiled")
    assert st1["ready"] or st1["progress"] > p0
    assert 0.0 <= st1["progress"] <= 1.0
    assert not st1["warm_errors"]
    # the progress window (its yellow bar) is drawn where the status file says, at the top of
    # the free area (the panels beside it work meanwhile: tests/app/test_first_launch.py)
    img1 = app.screenshot("cold_progress")
    st2 = app.status()
    if not st2["ready"]:
        x0, y0, x1, y1 = (int(v) for v in st2["ui_rects"]["progress"])
        bar = img1[y0:y1, x0:x1]
        yellow = (bar[..., 0] > 200) & (bar[..., 1] > 150) & (bar[..., 2] < 80)
        assert yellow.sum() > 50


def test_preview_render_data_matches_the_kernels():
    """The numpy render data drawn before the kernels exist equals the world's own (every shipped
    scene), so the first frame shows the scene exactly as the first ready frame will."""
    import numpy as np

    import physics
    from app.preview import render_data
    hinged = physics.World()  # a joint's drawing rows too (no shipped scene has joints yet)
    arm = hinged.add_body(physics.Polygon.box(2, 0.2), position=(1, 0))
    hinged.add_joint("revolute", arm, None, anchor=(0, 0), lower_angle=-0.5, upper_angle=0.5)
    scenes = sorted(p for p in (ROOT / "scenes").glob("*.json") if p.name != "stelkropp.schema.json")
    for path in [*scenes, None]:
        w = physics.load_scene(path) if path is not None else hinged
        path = path or ROOT / "hinged"
        mine = render_data(w)
        theirs = w.render_data()
        for name, a, b in zip(mine._fields, mine, theirs):
            if name in ("contact_points", "contact_normals"):
                assert len(a) == 0
                continue
            if getattr(a, "dtype", None) is not None and a.dtype.names:  # a table (the joints' rows)
                assert a.dtype == b.dtype and len(a) == len(b), f"{path.name}: {name}"
                for f in a.dtype.names:
                    np.testing.assert_allclose(a[f], b[f], rtol=0, atol=1e-12, err_msg=f"{path.name}: {name}.{f}")
                continue
            np.testing.assert_allclose(a, b, rtol=0, atol=1e-12, err_msg=f"{path.name}: {name}")


def test_the_joint_stage_holds_up_only_scenes_with_joints(tmp_path, monkeypatch):
    """The joint stage is the largest compile unit (182 CPU s cold, app/warmup.py): a scene
    without joints plays before it (it is the first background unit, for the mouse drag), a
    scene with joints waits for it."""
    import threading

    import physics
    from app import compile_units
    from app.warmup import Warmup
    monkeypatch.setenv("STELKROPP_BACKGROUND_COMPILE", "1")
    monkeypatch.setattr(compile_units, "cached", lambda unit: False)     # a cold cache
    plain = physics.load_scene(ROOT / "scenes" / "default.json")
    assert not plain.joints
    w = Warmup(plain, threading.Lock(), helper=False)
    assert w.joints == compile_units.joints_unit(plain.solver, plain.integrator)
    assert w.joints not in w.after_final and w.background[0] == w.joints
    hinged = physics.World()
    arm = hinged.add_body(physics.Polygon.box(2, 0.2), position=(1, 0))
    hinged.add_joint("revolute", arm, None, anchor=(0, 0))
    w2 = Warmup(hinged, threading.Lock(), helper=False)
    assert w2.after_final == [w2.joints] and w2.joints not in w2.background
    # without background compiles the open mode's joint stage is still the helper's first
    monkeypatch.setenv("STELKROPP_BACKGROUND_COMPILE", "0")
    # (and the open scene's one-call step, which it plays without meanwhile)
    assert Warmup(plain, threading.Lock(), helper=False).background == [w.joints, w.final]


class _FakeHelper:
    """Stands in for app.compile_helper.CompileHelper: units finish when the test says so."""

    def __init__(self, on_change):
        self.on_change, self.queue, self.done, self.failed = on_change, [], set(), {}
        self.label, self.alive, self.current, self.unit_kernels = "", True, None, {}

    def start(self):
        return self

    def push(self, unit, first=False):
        if unit not in self.queue and unit not in self.done:
            self.queue.insert(0, unit) if first else self.queue.append(unit)

    def claim(self, unit):
        if unit in self.queue:
            self.queue.remove(unit)
            return True
        return unit not in self.done

    def settled(self, unit):
        return unit in self.done or unit in self.failed

    def kernels_for(self, units):
        return 0

    def busy(self):
        return bool(self.queue)

    def close(self):
        pass

    def finish(self, unit):
        if unit in self.queue:
            self.queue.remove(unit)
        self.done.add(unit)
        self.on_change()


def _wait_for(cond, seconds=5.0):
    import threading
    for _ in range(int(seconds / 0.01)):
        if cond():
            return True
        threading.Event().wait(0.01)
    return cond()


def test_the_joint_stage_the_helper_finishes_after_the_gate_is_loaded(monkeypatch):
    """A scene without joints plays before the helper has compiled its mode's joint stage (the
    mouse drag's); when the helper finishes it later, this process loads it without being asked,
    so the first drag does not wait (ci15: it was loaded only if it was in the cache at the gate,
    and the window tests' wait_ready, which waits for it, timed out)."""
    import threading

    import physics
    from app import compile_units, warmup
    monkeypatch.setenv("STELKROPP_BACKGROUND_COMPILE", "1")
    monkeypatch.setattr(compile_units, "cached", lambda unit: False)
    monkeypatch.setattr(compile_units, "mark", lambda unit: None)
    ran = []
    monkeypatch.setattr(compile_units, "run", lambda unit: ran.append(unit))
    monkeypatch.setattr(warmup, "CompileHelper", _FakeHelper)
    w = warmup.Warmup(physics.load_scene(ROOT / "scenes" / "default.json"), threading.Lock())
    w.frame_drawn()
    w.start()
    # both halves in the helpers (this process only loads); the one-call step is not the gate's
    for helper, units in ((w.second, w.mine), (w.helper, w.theirs)):
        for u in units:
            assert _wait_for(lambda: u in helper.queue or w.ready), u
            helper.finish(u)
    assert _wait_for(lambda: w.ready), "the gate did not open"
    assert not w.joints_ready(w.solver, w.integrator) and w.joints not in ran
    w.helper.finish(w.joints)
    assert _wait_for(lambda: w.joints_ready(w.solver, w.integrator)), "the helper's joint stage was not loaded"
    assert w.joints in ran
    # the one-call step: the helper's next background unit, loaded here once it has it
    assert w.final in w.helper.queue and w.final not in ran
    w.helper.finish(w.final)
    assert _wait_for(lambda: w.final in ran), "the helper's one-call step was not loaded"


def test_the_gate_takes_the_narrow_kernel_the_scene_needs(monkeypatch):
    """The narrow phase has a lean kernel (SAT, sharp polygons and circles) and the whole one
    (GJK, rounded shapes, chains), compiled apart: the gate takes the open scene's, the other is
    a background unit, and a world that comes to need it (GJK chosen, a capsule drawn) waits for
    it (``narrow_ready``) instead of compiling it in the window's step."""
    import threading

    import physics
    from app import compile_units
    from app.warmup import Warmup
    monkeypatch.setattr(compile_units, "cached", lambda unit: False)
    plain = physics.load_scene(ROOT / "scenes" / "default.json")
    assert compile_units.narrow_unit(plain) == "narrow"
    w = Warmup(plain, threading.Lock(), helper=False)
    assert "narrow" in w.theirs and "narrow:full" not in w.theirs and "narrow:full" in w.background
    assert not w.narrow_ready("narrow")          # nothing before the gate
    plain.narrowphase = "gjk"
    assert compile_units.narrow_unit(plain) == "narrow:full"
    w2 = Warmup(plain, threading.Lock(), helper=False)
    assert "narrow:full" in w2.theirs and "narrow" in w2.background and w2.final.endswith(":full")
    plain.narrowphase = "sat"
    plain.add_body(physics.Capsule((-0.5, 0), (0.5, 0), 0.2), position=(0, 20))
    assert compile_units.narrow_unit(plain) == "narrow:full"
    # after the gate the scene's kernel is loaded, the other one only once it is wanted
    monkeypatch.setattr(compile_units, "run", lambda unit: None)
    monkeypatch.setattr(compile_units, "mark", lambda unit: None)
    w.frame_drawn()
    w.start()
    for _ in range(300):
        if w.ready:
            break
        threading.Event().wait(0.01)
    assert w.narrow_ready("narrow") and not w.narrow_ready("narrow:full")
    w.want_unit("narrow:full")
    for _ in range(300):
        if w.narrow_ready("narrow:full"):
            break
        threading.Event().wait(0.01)
    assert w.narrow_ready("narrow:full")


def test_a_rival_mode_loads_while_the_scene_steps(monkeypatch):
    """The gate's units hold the physics lock (nothing steps before the scene can run); after it,
    a mode switched to (a comparison's rival) loads without it, so the main world keeps stepping
    ("the main world stalls while a rival mode compiles")."""
    import threading

    import physics
    from app import compile_units
    from app.warmup import Warmup
    lock = threading.Lock()
    held, release = {}, threading.Event()

    def fake_run(unit):
        held[unit] = lock.locked()
        if unit.startswith("solve:impulse"):
            release.wait(30)
    monkeypatch.setattr(compile_units, "run", fake_run)
    monkeypatch.setattr(compile_units, "cached", lambda unit: False)
    monkeypatch.setattr(compile_units, "mark", lambda unit: None)
    w = Warmup(physics.load_scene(ROOT / "scenes" / "default.json"), lock, helper=False)
    w.frame_drawn()
    w.start()
    w.thread.join(0.0)
    for _ in range(300):
        if w.ready:
            break
        threading.Event().wait(0.01)
    assert w.ready and all(held[u] for u in w.mine), held
    assert w.final not in held  # the one-call step is not the gate's: the scene plays without it
    w.prioritize("impulse", w.integrator)
    for _ in range(300):
        if any(u.startswith("solve:impulse") for u in held):
            break
        threading.Event().wait(0.01)
    rival = next(u for u in held if u.startswith("solve:impulse"))
    assert not held[rival] and lock.acquire(blocking=False), "the rival's load holds the physics lock"
    lock.release()
    assert not w.can_step("impulse", w.integrator)
    release.set()
    for _ in range(300):
        if w.can_step("impulse", w.integrator):
            break
        threading.Event().wait(0.01)
    assert w.can_step("impulse", w.integrator)


def test_the_three_mode_questions_name_a_mode_alike(monkeypatch):
    """``prioritize``, ``mode_units`` and ``can_step`` agree on a mode's key: an integrator setting
    a mode does not use (soft_step integrates its own way) names the mode's default-integrator
    kernels, and the broad phase is the open scene's unless given."""
    import threading

    import physics
    from app import compile_units
    from app.warmup import Warmup
    monkeypatch.setattr(compile_units, "cached", lambda unit: False)
    w = Warmup(physics.load_scene(ROOT / "scenes" / "default.json"), threading.Lock(), helper=False)
    default = physics.options.DEFAULT_INTEGRATOR
    other = next(i for i in physics.options.INTEGRATORS if i != default)
    assert w.mode_units("soft_step", other) == w.mode_units("soft_step", default)
    assert w.mode_units("impulse", other) != w.mode_units("impulse", default)
    assert f"broad:{w.broadphase}" in w.mode_units("impulse", other)
    w._ready = True
    w.warmed.add(("soft_step", default, w.broadphase))
    assert w.can_step("soft_step", other) and not w.can_step("impulse", other)
    w.prioritize("soft_step", other)
    assert not w._wanted, "a loaded mode is not asked for again"
    w.prioritize("impulse", other, first=True)
    assert w._wanted == [("impulse", other, w.broadphase)]
