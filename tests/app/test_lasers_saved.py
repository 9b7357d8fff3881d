"""Lasers and tracers are part of the scene: saved in the file's ``sandbox`` section and back
after reopening it, beams drawn and trails growing."""
from __future__ import annotations

import json

import pytest

from test_compare import centre
from test_lasers import red
from test_saving import scene_point
from test_tools import body, to_screen, tools_scene

pytestmark = pytest.mark.app


def use_tool(app, name):
    app.click(*centre(app.status()["ui_rects"][f"tool:{name}"]))
    return app.wait(lambda s: s["tool"] == name, 10, f"the {name} tool")


@pytest.mark.slow
def test_lasers_and_tracers_survive_save_and_reopen(launch, tmp_path):
    path = tools_scene(tmp_path / "tools.json")
    app = launch(path, "--paused")
    st = app.wait_ready(10)
    st = use_tool(app, "laser")
    app.drag(to_screen(st, (-7.0, 3.0)), to_screen(st, (-6.0, 2.0)))     # fixed, aimed at box a
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: len(s["lasers"]) == 1, 10, "the fixed laser")
    app.click(*to_screen(st, body(st, "b")["position"]))                  # riding on box b
    st = app.wait(lambda s: len(s["lasers"]) == 2, 10, "the laser on b")
    st = use_tool(app, "tracer")
    app.click(*to_screen(st, body(st, "c")["position"]))
    st = app.wait(lambda s: len(s["tracers"]) == 1, 10, "the tracer on c")
    app.xdo("mousemove", *scene_point(st))
    app.settle()
    app.key("ctrl+s")
    st = app.wait(lambda s: not s["dirty"] and "sandbox" in json.loads(path.read_text()), 20, "the save")
    saved = json.loads(path.read_text())["sandbox"]
    assert [lz["body"] for lz in saved["lasers"]] == [None, "b"], saved
    assert saved["lasers"][0]["point"] == pytest.approx([-7.0, 3.0], abs=0.05)
    assert [tr["body"] for tr in saved["tracers"]] == ["c"], saved
    app.close()
    # reopened in a new sandbox: the same lasers and tracer, the beam drawn, the trail growing
    app = launch(path, subdir="reopened")
    st = app.wait_ready(10)
    ids = {b["name"]: b["id"] for b in st["bodies"]}
    assert [lz["body"] for lz in st["lasers"]] == [None, ids["b"]], st["lasers"]
    assert [tr["body"] for tr in st["tracers"]] == [ids["c"]], st["tracers"]
    st = app.wait(lambda s: s["tracers"][0]["n"] > 10, 30, "the trail to grow")
    img = app.screenshot("reopened")
    path0 = st["lasers"][0]["path"]
    mid = to_screen(st, [(path0[0][0] + path0[1][0]) / 2, (path0[0][1] + path0[1][1]) / 2])
    assert red(img, *mid) > 3, "the fixed laser's beam is not drawn"
