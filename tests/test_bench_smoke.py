"""Smoke test of the benchmark suite (``python -m bench``): the smallest configuration runs end to
end in-process and writes well-formed results.  No timing assertions: only structure, finiteness
and that the references ran on the identical scene."""
from __future__ import annotations

import csv
import json
import math

import pytest

# the references are part of the `bench` extra that .ci/run installs: a missing one is a failure
import Box2D  # noqa: F401,E402
import matplotlib  # noqa: F401,E402
import pymunk  # noqa: F401,E402

from box2d_ref import box2d_v3, sources_present  # noqa: E402

# Box2D v3 is built with cmake from its sources (tests/box2d_ref.py: on the machine and in CI); a
# clone without them runs the other references and skips test_box2d_v3_is_timed_beside_us
REFS = ("pymunk", "pybox2d") + (("box2d_v3",) if sources_present() else ())


@pytest.fixture(scope="module")
def results(tmp_path_factory):
    from bench import cli
    out = tmp_path_factory.mktemp("bench")
    assert cli.main(["--tiny", "--out", str(out), "--modes", "soft_step", "--no-compile"]) == 0
    return out, json.loads((out / "bench.json").read_text())


def _finite(x):
    return isinstance(x, (int, float)) and math.isfinite(x)


def test_files_written(results):
    out, _ = results
    for name in ("bench.json", "speed.csv", "scaling.csv", "accuracy.csv", "profile.csv",
                 "pareto_pyramid20.png", "scaling.png", "accuracy.png", "profile.png"):
        p = out / name
        assert p.exists() and p.stat().st_size > 0, name
    with open(out / "speed.csv") as f:
        rows = list(csv.DictReader(f))
    assert {r["engine"] for r in rows} == {"stelkropp", *REFS}


def test_speed_rows_and_ratios(results):
    _, res = results
    sp = res["speed"]
    ours = [r for r in sp if r["engine"] == "stelkropp"]
    assert ours and all(r["status"] == "ok" for r in ours)
    for r in ours:
        assert _finite(r["ms_step"]) and r["ms_step"] > 0
        assert _finite(r["ratio_pymunk"]) and r["ratio_pymunk"] > 0
        assert _finite(r["ratio_pybox2d"]) and r["ratio_pybox2d"] > 0
        if "box2d_v3" in REFS:  # Box2D v3 itself, timed interleaved in the same run, not estimated
            assert _finite(r["ratio_box2d_v3"]) and r["ratio_box2d_v3"] > 0
        assert _finite(r["first_step_s"])  # compile/first use reported apart from ms/step
        assert _finite(r["top_drift"]) and _finite(r["max_penetration"])
    for e in REFS:
        ref = [r for r in sp if r["engine"] == e]
        assert len(ref) == 1 and _finite(ref[0]["ms_step"]) and _finite(ref[0]["top_drift"])


def test_scaling_accuracy_profile_overhead(results):
    _, res = results
    sc = res["scaling"]
    assert {r["engine"] for r in sc} == {"stelkropp", *REFS}
    assert all(_finite(r["ms_step"]) for r in sc)
    acc = res["accuracy"]
    engines = {r["engine"] for r in acc}
    assert engines == {"stelkropp", *REFS}
    metrics = {r["metric"] for r in acc if r["engine"] == "stelkropp"}
    assert {"spring_period", "spring_energy_drift", "bounce_height", "incline_stick_slip", "incline_slide_accel",
            "elastic_collision_momentum", "many_body_momentum", "pile_time_to_rest"} <= metrics
    prof = res["profile"]["pyramid20"]["us_per_step"]
    assert all(_finite(v) and v >= 0 for v in prof.values())
    assert _finite(res["overhead"]["empty_world_us"])


def test_reference_scenes_match():
    """The three engines get the same bodies, masses and friction from one description."""
    import numpy as np

    from bench.desc import with_world
    from bench.engines import ENGINES, build
    from bench.scenes import pyramid
    d = with_world(pyramid(4), sleeping=False)
    ours, pm, b2 = (build(e, d) for e in ENGINES if e != "box2d_v3")
    assert np.allclose(ours.state()[0], pm.state()[0]) and np.allclose(ours.state()[0], b2.state()[0], atol=1e-6)
    if sources_present():  # Box2D v3 too where its sources are (always in CI)
        b3 = build("box2d_v3", d)
        assert np.allclose(ours.state()[0], b3.state()[0], atol=1e-6) and np.allclose(b3.masses[1:], 1.0)
    masses_pm = [b.mass for b in pm.bodies if b.body_type == b.DYNAMIC]
    masses_b2 = [b.mass for b in b2.bodies if b.type == 2]
    assert np.allclose(masses_pm, 1.0) and np.allclose(masses_b2, 1.0, rtol=1e-6)
    # pymunk multiplies friction: sqrt per shape gives the geometric mean of 0.6 and 0.6
    s = next(iter(pm.bodies[1].shapes))
    assert abs(s.friction ** 2 - 0.6) < 1e-12


def test_box2d_v3_is_timed_beside_us(results):
    """Box2D v3 ran on the identical scene, interleaved, with a finite ratio for every row."""
    box2d_v3()
    _, res = results
    ours = [r for r in res["speed"] if r["engine"] == "stelkropp"]
    assert ours and all(_finite(r["ratio_box2d_v3"]) and r["ratio_box2d_v3"] > 0 for r in ours)
    ref = [r for r in res["speed"] if r["engine"] == "box2d_v3"]
    assert len(ref) == 1 and _finite(ref[0]["ms_step"])


def test_a_reference_that_cannot_run_is_skipped_with_its_reason(tmp_path, monkeypatch, capsys):
    from bench import cli
    monkeypatch.setenv("STELKROPP_BOX2D_SRC", str(tmp_path))  # no Box2D sources there
    from bench.box2d import build as b2build
    monkeypatch.setattr(b2build, "_STATUS", {})
    assert cli.main(["--tiny", "--out", str(tmp_path / "o"), "--modes", "soft_step", "--no-compile",
                     "--parts", "speed", "--refs", "pymunk,box2d_v3"]) == 0
    res = json.loads((tmp_path / "o" / "bench.json").read_text())
    assert set(res["meta"]["engines_skipped"]) == {"box2d_v3"}
    assert "no Box2D v3 sources" in res["meta"]["engines_skipped"]["box2d_v3"]
    assert {r["engine"] for r in res["speed"]} == {"stelkropp", "pymunk"}
    assert "box2d_v3 skipped" in capsys.readouterr().err


def test_an_unknown_reference_is_refused():
    from bench import cli
    with pytest.raises(SystemExit):
        cli.options(cli.parser().parse_args(["--refs", "chipmunk9"]))


def test_docs_render(results):
    out, res = results
    from bench.report.docs import render_docs
    text = render_docs(res, str(out), out)
    assert "## Speed" in text and "pareto_pyramid20.png" in text and "python -m bench" in text
