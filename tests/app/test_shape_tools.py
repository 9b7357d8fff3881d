"""Compound bodies in the sandbox (issue 13, "The sandbox"), driven as a person would with real X
events: the polygon tool keeps a concave L (one body of convex pieces that rests on its long
side), the sketch tool turns a freehand stroke into a body (a crossing stroke gets a hint),
glue makes two boxes one body that falls as one, unglue splits it again, and undo takes each
step back.  The checks read the status file and the screenshots."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from sandbox_pixels import body_pixels

pytestmark = pytest.mark.app

W, H = 1280, 800
ZOOM = 40.0


def scene(path, bodies, world=None):
    data = {"format": "stelkropp.scene", "version": 2, "name": "shapes", "world": dict(world or {}),
            "camera": {"center": [0.0, 2.0], "zoom": ZOOM},
            "bodies": [{"name": "ground", "kind": "static", "shape": {"box": [24, 1]}, "position": [0, -0.5]},
                       *bodies]}
    path.write_text(json.dumps(data))
    return path


def to_screen(st, p):
    c, s = st["camera"]["center"], st["camera"]["scale"]
    return (W / 2 + (p[0] - c[0]) * s, H / 2 - (p[1] - c[1]) * s)


def pick_tool(app, name):
    x0, y0, x1, y1 = app.status()["ui_rects"][f"tool:{name}"]
    app.click((x0 + x1) / 2, (y0 + y1) / 2)
    return app.wait(lambda s: s["tool"] == name, 10, f"the {name} tool")


def new_bodies(st, before):
    ids = {b["id"] for b in before["bodies"]}
    return [b for b in st["bodies"] if b["id"] not in ids]


def shoelace(pts):
    x, y = np.asarray(pts, float).T
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


# an L lying on its long leg: 4 m along the ground, a 1 m x 1.5 m leg standing at its left end
L_OUTLINE = [(-2, 0.5), (2, 0.5), (2, 1.5), (-1, 1.5), (-1, 3.0), (-2, 3.0)]
L_AREA = 4 * 1 + 1 * 1.5                        # 5.5 m^2; its convex hull has 7.75 m^2
L_CENTROID_UP = (4 * 0.5 + 1.5 * 1.75) / L_AREA  # centroid height over the long side: 0.841 m


@pytest.mark.slow
def test_polygon_tool_keeps_a_concave_L_that_rests_on_its_long_side(launch, tmp_path):
    app = launch(scene(tmp_path / "l.json", []), "--paused")
    st0 = app.wait_ready(20)
    pick_tool(app, "polygon")
    for p in L_OUTLINE:
        app.click(*to_screen(st0, p))
        app.settle()
    app.key("Return")
    st = app.wait(lambda s: len(s["bodies"]) == 2, 20, "the L")
    (body,) = new_bodies(st, st0)
    # one body of convex pieces (not the hull): its mass is the L's area at density 1
    assert body["fixtures"] == ["polygon", "polygon"], body
    assert body["mass"] == pytest.approx(L_AREA, rel=0.03), "the hull's area would be 7.75"
    app.key("Escape")                   # deselected: drawn in its own colour
    app.settle()
    img = app.screenshot("l_drawn")
    # the notch (inside the hull, outside the L) is not filled; both legs are
    notch = to_screen(st, (0.5, 2.4))
    leg = to_screen(st, (-1.5, 2.4))
    foot = to_screen(st, (1.5, 1.0))
    assert body_pixels(img, int(notch[0]) - 6, int(notch[0]) + 6, int(notch[1]) - 6, int(notch[1]) + 6) == 0
    for q in (leg, foot):
        assert body_pixels(img, int(q[0]) - 6, int(q[0]) + 6, int(q[1]) - 6, int(q[1]) + 6) > 100
    # run: it falls 0.5 m and rests on its long side, centroid 0.841 m over the ground's top
    app.key("space")
    app.wait(lambda s: s["time"] > 3.0, 120, "3 s of simulation")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "the pause")
    b = next(q for q in st["bodies"] if q["id"] == body["id"])
    assert abs(math.remainder(b["angle"], 2 * math.pi)) < 0.02, b
    # 2 cm: the contact slop and the resting penetration of the soft contact (a few mm)
    assert b["position"][1] == pytest.approx(L_CENTROID_UP, abs=0.02), b
    assert math.hypot(*b["velocity"]) < 0.05, b
    app.screenshot("l_resting")
    # undo removes it
    app.key("ctrl+z")
    app.wait(lambda s: len(s["bodies"]) == 1, 10, "the undo")


def stroke(app, pts, steps=8):
    """Press at the first point, move through the others (``steps`` moves a leg), release."""
    app.xdo("mousemove", int(pts[0][0]), int(pts[0][1]))
    app.settle()
    app.xdo("mousedown", 1)
    app.settle()
    for a, b in zip(pts[:-1], pts[1:]):
        for i in range(1, steps + 1):
            app.xdo("mousemove", int(a[0] + (b[0] - a[0]) * i / steps), int(a[1] + (b[1] - a[1]) * i / steps))
    app.settle()
    app.xdo("mouseup", 1)
    app.settle()


def test_sketch_stroke_becomes_a_body_and_a_crossing_one_a_hint(launch, tmp_path):
    app = launch(scene(tmp_path / "s.json", []), "--paused")
    st0 = app.wait_ready(20)
    pick_tool(app, "sketch")
    # a concave arrow head, drawn as one closed stroke
    world = [(-3, 1), (3, 1), (3, 4), (0, 2.5), (-3, 4), (-3, 1)]
    stroke(app, [to_screen(st0, p) for p in world])
    st = app.wait(lambda s: len(s["bodies"]) == 2, 20, "the sketched body")
    (body,) = new_bodies(st, st0)
    assert len(body["fixtures"]) >= 2 and set(body["fixtures"]) == {"polygon"}, body
    area = abs(shoelace(world[:-1]))               # 13.5 m^2; RDP moves corners by < 3 px
    assert body["mass"] == pytest.approx(area, rel=0.05)
    app.key("Escape")
    app.settle()
    assert body_pixels(app.screenshot("sketch_body")) > 5000    # 13.5 m^2 at 1600 px/m^2
    # a bow tie crosses itself: no body, a hint, and the sandbox keeps running
    bow = [(-2, 5), (2, 7), (2, 5), (-2, 7), (-2, 5)]
    stroke(app, [to_screen(st0, p) for p in bow])
    st = app.wait(lambda s: s["hint"] is not None and "no body" in s["hint"], 10, "the hint")
    assert len(st["bodies"]) == 2
    app.screenshot("sketch_refused")
    app.key("ctrl+z")
    app.wait(lambda s: len(s["bodies"]) == 1, 10, "the undo")


@pytest.mark.slow
def test_glue_two_boxes_fall_as_one_then_unglue_and_undo(launch, tmp_path):
    boxes = [{"name": "a", "shape": {"box": [1, 1]}, "position": [-1.5, 3.0]},
             {"name": "b", "shape": {"box": [1, 1]}, "position": [1.5, 3.5], "friction": 0.3}]
    # sleeping off: a resting body that falls asleep is drawn dimmed, and the pixel checks below
    # look for the awake colour
    app = launch(scene(tmp_path / "g.json", boxes, {"sleeping": False}), "--paused")
    st0 = app.wait_ready(20)
    pick_tool(app, "select")
    app.click(*to_screen(st0, (-1.5, 3.0)))
    app.settle()
    app.xdo("keydown", "shift")
    app.click(*to_screen(st0, (1.5, 3.5)))
    app.settle()
    app.xdo("keyup", "shift")
    app.wait(lambda s: len(s["selection"]) == 2, 10, "two selected")
    app.key("ctrl+g")
    st = app.wait(lambda s: len(s["bodies"]) == 2, 10, "the glue")
    (glued,) = new_bodies(st, st0)
    assert glued["fixtures"] == ["polygon", "polygon"] and glued["mass"] == pytest.approx(2.0)
    app.key("Escape")
    app.settle()
    app.screenshot("glued")
    # run: one rigid body, so box a (0.5 m lower) lands first and the pair tips until b lands
    # too, as one: the two boxes keep their 3 m x 0.5 m offset in the body's frame
    app.key("space")
    app.wait(lambda s: s["time"] > 3.0, 120, "3 s of simulation")
    app.key("space")
    st = app.wait(lambda s: not s["running"], 10, "the pause")
    assert len(st["bodies"]) == 2
    g = next(q for q in st["bodies"] if q["id"] == glued["id"])
    assert g["position"][1] < 3.0 and math.hypot(*g["velocity"]) < 0.05, g
    img = app.screenshot("glued_resting")
    # the two boxes are drawn apart (the gap between them is empty)
    centre = to_screen(st, g["position"])       # the body origin is box a's centre
    ang = g["angle"]
    mid = (g["position"][0] + 1.5 * math.cos(ang) - 0.25 * math.sin(ang),
           g["position"][1] + 1.5 * math.sin(ang) + 0.25 * math.cos(ang))
    m = to_screen(st, mid)
    assert body_pixels(img, int(m[0]) - 4, int(m[0]) + 4, int(m[1]) - 4, int(m[1]) + 4) == 0
    assert body_pixels(img, int(centre[0]) - 6, int(centre[0]) + 6, int(centre[1]) - 6, int(centre[1]) + 6) > 50
    # unglue: one body per fixture, where the fixtures are
    app.click(*centre)
    app.wait(lambda s: s["selection"] == [glued["id"]], 10, "the glued body selected")
    app.key("ctrl+shift+g")
    st = app.wait(lambda s: len(s["bodies"]) == 3, 10, "the unglue")
    parts = new_bodies(st, {"bodies": [{"id": q["id"]} for q in st0["bodies"]] + [glued]})
    assert sorted(len(p["fixtures"]) for p in parts) == [1, 1]
    app.screenshot("unglued")
    # undo the unglue, then the glue: the original two boxes where they began
    app.key("ctrl+z")
    app.wait(lambda s: len(s["bodies"]) == 2, 10, "undo unglue")
    app.key("ctrl+z")
    st = app.wait(lambda s: len(s["bodies"]) == 3 and {"a", "b"} <= {q["name"] for q in s["bodies"]}, 10,
                  "undo glue")
    a = next(q for q in st["bodies"] if q["name"] == "a")
    assert a["fixtures"] == ["polygon"]
