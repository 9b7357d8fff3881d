"""A glued (compound) body with the spring, tracer and laser tools, through real X input: two boxes
glued with Ctrl+G are one body, and each tool picks it by a click on either piece (not only the
piece at the body's origin) and works on it: a spring from each piece holds the body, a tracer on
the far piece draws its trail as the body swings, a beam aimed at each piece ends on the body,
and an emitter placed on the far piece rides with it."""
from __future__ import annotations

import json

import pytest

from test_compare import centre
from test_lasers import red
from test_tools import to_screen
from test_tracers import local_to_world, magenta

pytestmark = pytest.mark.app

# two 1 m boxes 2 m apart (centre to centre) above the ground: after the glue, piece a is at the
# compound's origin and piece b 2 m to its right
A, B = (-1.0, 2.5), (1.0, 2.5)


def glue_scene(path):
    data = {"format": "stelkropp.scene", "version": 2, "name": "glued", "world": {"sleeping": False},
            "camera": {"center": [0.0, 2.0], "zoom": 40.0},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
                       {"name": "a", "shape": {"box": [1, 1]}, "position": list(A)},
                       {"name": "b", "shape": {"box": [1, 1]}, "position": list(B)}]}
    path.write_text(json.dumps(data))
    return path


def pick_tool(app, name):
    app.click(*centre(app.status()["ui_rects"][f"tool:{name}"]))
    return app.wait(lambda s: s["tool"] == name, 10, f"the {name} tool")


def glue(app, st):
    """Select both boxes (click, shift-click) and glue them: the compound's status entry."""
    pick_tool(app, "select")
    app.click(*to_screen(st, A))
    app.settle()
    app.xdo("keydown", "shift")
    app.click(*to_screen(st, B))
    app.settle()
    app.xdo("keyup", "shift")
    app.wait(lambda s: len(s["selection"]) == 2, 10, "both boxes selected")
    app.key("ctrl+g")
    st = app.wait(lambda s: len(s["bodies"]) == 2, 10, "the glue")
    (g,) = [b for b in st["bodies"] if b["kind"] == "dynamic"]
    assert g["fixtures"] == ["polygon", "polygon"], g
    app.key("Escape")
    return g


def drag_to(app, st, p, q):
    app.drag(to_screen(st, p), to_screen(st, q), steps=8)
    app.xdo("mouseup", 1)


@pytest.mark.slow
def test_spring_tracer_and_laser_pick_a_glued_body_by_either_piece(launch, tmp_path):
    app = launch(glue_scene(tmp_path / "glued.json"), "--paused")
    st = app.wait_ready(10)
    g = glue(app, st)
    gid = g["id"]
    st = app.settle()
    # lasers fixed in the world, aimed at each piece: the right one from the right, the left one
    # from above; each beam ends on the compound at the piece's face
    pick_tool(app, "laser")
    drag_to(app, st, (4.0, 2.5), (3.0, 2.5))
    st = app.wait(lambda s: len(s["lasers"]) == 1, 10, "the first laser")
    drag_to(app, st, (-1.0, 5.5), (-1.0, 4.5))
    st = app.wait(lambda s: len(s["lasers"]) == 2 and all(lz["hits"] for lz in s["lasers"]), 10,
                  "the second laser and both beams traced")
    right, top = st["lasers"]
    assert right["hits"][0] == gid and top["hits"][0] == gid, st["lasers"]
    assert right["path"][1] == pytest.approx([1.5, 2.5], abs=0.05), "the beam must stop at piece b's right face"
    assert top["path"][1] == pytest.approx([-1.0, 3.0], abs=0.05), "the beam must stop at piece a's top"
    # an emitter placed on piece b rides on the compound
    drag_to(app, st, (1.2, 2.3), (1.2, 1.0))
    st = app.wait(lambda s: len(s["lasers"]) == 3, 10, "the emitter on piece b")
    on_b = st["lasers"][2]
    assert on_b["body"] == gid and on_b["local"] == pytest.approx([2.2, -0.2], abs=0.06), on_b
    # a tracer on piece b (the far one), at a point 2.3 m right of the compound's origin
    pick_tool(app, "tracer")
    app.click(*to_screen(st, (1.3, 2.7)))
    st = app.wait(lambda s: len(s["tracers"]) == 1, 10, "the tracer")
    assert st["tracers"][0]["body"] == gid and st["tracers"][0]["local"] == pytest.approx([2.3, 0.2], abs=0.06)
    # springs from each piece up to a world anchor: both on the compound
    pick_tool(app, "spring")
    drag_to(app, st, (-1.2, 2.7), (-1.5, 5.5))
    app.wait(lambda s: len(s["springs"]) == 1, 10, "the spring from piece a")
    drag_to(app, st, (1.2, 2.7), (2.5, 5.5))
    st = app.wait(lambda s: len(s["springs"]) == 2, 10, "the spring from piece b")
    assert [s["a"] for s in st["springs"]] == [gid, gid] and [s["b"] for s in st["springs"]] == [None, None]
    # play: the springs hold the body up (it does not fall to the ground) while it swings, the
    # tracer draws, and the emitter on piece b turns with the body
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["time"] > 2.0, 120, "2 s of play")
    img = app.screenshot("glued_tools")
    g = next(b for b in st["bodies"] if b["id"] == gid)
    assert g["position"][1] > 1.5, f"the springs do not hold the glued body: {g['position']}"
    tr = st["tracers"][0]
    assert tr["n"] > 30 and tr["span"] > 1.0, tr
    x, y = to_screen(st, tr["last"])
    box = (x - 120, y - 120, x + 120, y + 120)
    assert magenta(img, box) > 20, "no trail drawn near the tracer's point"
    on_b = st["lasers"][2]
    assert abs(g["angle"]) > 0.01, "the body did not swing: the riding emitter is not checked"
    assert on_b["path"][0] == pytest.approx(local_to_world(g, on_b["local"]), abs=0.02), \
        "the emitter on piece b does not ride with the glued body"
    x, y = to_screen(st, right["path"][0])
    assert red(img, x - 20, y) > 0, "the right laser's beam is not drawn"
    app.key("space")
    app.wait(lambda s: not s["running"], 10, "paused")


def named(st, name):
    return next(b for b in st["bodies"] if b["name"] == name)


@pytest.mark.slow
def test_a_tracer_and_a_laser_on_a_box_go_with_it_into_the_glued_body_and_back(launch, tmp_path):
    """Glue replaces the boxes by a new body: a tracer or an emitter on a box must move onto it at
    the same world point (as the box's springs and joints do), not stay on the deleted box
    (its trail stopped and its beam vanished); unglue hands them to the piece they are on, and
    undo puts them back on the box."""
    app = launch(glue_scene(tmp_path / "glued.json"), "--paused")
    st = app.wait_ready(10)
    b_id = named(st, "b")["id"]
    pick_tool(app, "tracer")
    app.click(*to_screen(st, (1.3, 2.7)))
    pick_tool(app, "laser")
    drag_to(app, st, (0.8, 2.3), (0.8, 1.0))     # from inside box b, aimed down at the ground
    st = app.wait(lambda s: len(s["tracers"]) == 1 and len(s["lasers"]) == 1 and s["lasers"][0]["hits"], 10,
                  "a tracer and an emitter on box b")
    assert st["tracers"][0]["body"] == b_id and st["lasers"][0]["body"] == b_id
    g = glue(app, st)
    st = app.settle()
    tr, lz = st["tracers"][0], st["lasers"][0]
    assert tr["body"] == g["id"] and tr["local"] == pytest.approx([2.3, 0.2], abs=0.06), tr
    assert lz["body"] == g["id"] and lz["shown"], lz
    assert lz["path"][0] == pytest.approx([0.8, 2.3], abs=0.06) and lz["path"][1] == pytest.approx([0.8, 0.0], abs=0.06)
    # unglue: both go to the part they are on (box b's place), at the same world points
    app.click(*to_screen(st, A))
    app.wait(lambda s: s["selection"] == [g["id"]], 10, "the glued body selected")
    app.key("ctrl+shift+g")
    st = app.wait(lambda s: len(s["bodies"]) == 3, 10, "the unglue")
    tr, lz = st["tracers"][0], st["lasers"][0]
    part = next(b for b in st["bodies"] if b["id"] == tr["body"])
    assert local_to_world(part, tr["local"]) == pytest.approx([1.3, 2.7], abs=0.06), (tr, part)
    assert lz["body"] == part["id"] and lz["path"][0] == pytest.approx([0.8, 2.3], abs=0.06), lz
    app.key("Escape")
    app.click(*to_screen(st, B))          # the part they went to is the one at box b's place
    app.wait(lambda s: s["selection"] == [part["id"]], 10, "box b's part selected")
    # undo both: back on box b, where they were placed
    app.key("ctrl+z")
    app.wait(lambda s: len(s["bodies"]) == 2, 10, "undo unglue")
    app.key("ctrl+z")
    st = app.wait(lambda s: len(s["bodies"]) == 3 and "b" in {q["name"] for q in s["bodies"]}, 10, "undo glue")
    b_id = named(st, "b")["id"]
    tr, lz = st["tracers"][0], st["lasers"][0]
    assert tr["body"] == b_id and tr["local"] == pytest.approx([0.3, 0.2], abs=0.06), tr
    assert lz["body"] == b_id and lz["path"][0] == pytest.approx([0.8, 2.3], abs=0.06), lz
    # the trail draws behind the box again: play and it grows
    app.xdo("mousemove", 700, 150)
    app.settle()
    app.key("space")
    st = app.wait(lambda s: s["time"] > 1.0, 60, "1 s of play")
    assert st["tracers"][0]["n"] > 20, st["tracers"][0]
