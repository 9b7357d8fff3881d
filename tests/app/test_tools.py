"""Creation tools, edits, overlays and the camera, driven as a person would: real X events (xdotool).

The scene is paused so bodies stay where the tools put them; every check reads the sandbox's
status file (what the world holds) and a screenshot (what is drawn).
"""
from __future__ import annotations

import json

import numpy as np
import pytest

from sandbox_pixels import body_pixels, orange_pixels, purple_pixels, red_text_pixels, yellow_pixels

pytestmark = pytest.mark.app

W, H = 1280, 800
CAMERA = {"center": [0.0, 2.0], "zoom": 40.0}


def tools_scene(path, camera=True):
    """Ground, boxes a and b on it, box c hanging from a world anchor by a spring."""
    data = {
        "format": "stelkropp.scene", "version": 1, "name": "tools",
        "bodies": [
            {"name": "ground", "kind": "static", "shape": {"box": [16, 1]}, "position": [0, -0.5]},
            {"name": "a", "shape": {"box": [1.2, 1.2]}, "position": [-4, 0.6]},
            {"name": "b", "shape": {"box": [1.2, 1.2]}, "position": [4, 0.6]},
            {"name": "c", "shape": {"box": [1.0, 1.0]}, "position": [0, 3.0]},
        ],
        "springs": [{"name": "hang", "a": "c", "b": None, "anchor_a": [0, 0.5], "anchor_b": [0, 5.5],
                     "stiffness": 80.0, "damping": 1.0, "rest_length": 1.5}],
    }
    if camera:
        data["camera"] = CAMERA
    path.write_text(json.dumps(data))
    return path


def body(st, name):
    return next(b for b in st["bodies"] if b["name"] == name)


def to_screen(st, p):
    """World point -> X screen pixel (y down), from the camera in the status."""
    c, s = st["camera"]["center"], st["camera"]["scale"]
    return (W / 2 + (p[0] - c[0]) * s, H / 2 - (p[1] - c[1]) * s)


def new_bodies(st, before):
    ids = {b["id"] for b in before["bodies"]}
    return [b for b in st["bodies"] if b["id"] not in ids]


def test_scene_camera_fit_and_quadtree_overlay(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(20)
    # the scene file's camera: its zoom, its centre in the middle of the free area beside the panels
    fx0, fy0, fx1, fy1 = st["free_rect"]
    main, stats = st["ui_rects"]["main_window"], st["ui_rects"]["stats_window"]
    assert fx0 >= main[2] and (fy1 <= stats[1] or fx1 <= stats[0]), (st["free_rect"], main, stats)
    assert (fx1 - fx0) * (fy1 - fy0) > 0.4 * W * H, "the free area is small"
    assert st["camera"]["scale"] == pytest.approx(CAMERA["zoom"])
    cx, cy = to_screen(st, CAMERA["center"])
    assert cx == pytest.approx(0.5 * (fx0 + fx1), abs=1.0) and cy == pytest.approx(0.5 * (fy0 + fy1), abs=1.0)
    # F fits every body into the free area (not under the panels)
    app.xdo("mousemove", 640, 300)
    app.key("f")
    st = app.wait(lambda s: s["camera"]["scale"] != CAMERA["zoom"], 10, "the camera to fit")
    xs = [b["screen"][0] for b in st["bodies"]]
    ground = body(st, "ground")
    half = 8.0 * st["camera"]["scale"]                  # the ground is the widest body (16 m)
    assert ground["screen"][0] - half > fx0 - 2 and ground["screen"][0] + half < fx1 + 2, (st["camera"], st["free_rect"])
    assert half > 0.7 * (fx1 - fx0) / 2, "the fitted scene does not fill the free area"
    assert min(xs) > fx0 and max(xs) < fx1
    ys = [b["screen"][1] for b in st["bodies"]]
    assert min(ys) > fy0 and max(ys) < fy1
    # the quadtree overlay (Q): cells from world.quadtree_cells(), drawn as outlines
    before = app.screenshot("no_quadtree")
    app.key("q")
    st = app.wait(lambda s: s["overlays"]["quadtree"] and s["quadtree_cells"] > 0, 10, "the quadtree overlay")
    app.frames(3)
    img = app.screenshot("quadtree")
    x0, y0, x1, y1 = map(int, st["free_rect"])
    assert purple_pixels(img, x0, y0, x1, y1) > 300 + purple_pixels(before, x0, y0, x1, y1)
    app.key("q")
    st = app.wait(lambda s: not s["overlays"]["quadtree"], 10, "the overlay off")
    assert not st["gl_errors"] and not st["fault"]


def test_polygon_ngon_circle_tools_and_undo(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st0 = app.wait_ready(20)
    n0 = st0["n_bodies"]
    # polygon: click five points (the last one notches the outline), Enter keeps the concave
    # outline as drawn (issue 13: no silent convex hull), the body placed at its area centroid
    app.key("3")
    app.frames(2)
    corners = [(-3.0, 4.0), (-1.0, 4.2), (-0.8, 5.8), (-2.8, 6.0), (-2.0, 5.0)]   # the last is interior
    for p in corners:
        app.click(*to_screen(st0, p))
        app.frames(2)
    app.key("Return")
    st = app.wait(lambda s: s["n_bodies"] == n0 + 1, 10, "the polygon")
    (poly,) = new_bodies(st, st0)
    assert poly["shape"] == "polygon", poly
    P = np.array(corners)
    Q = np.roll(P, -1, axis=0)
    cross = P[:, 0] * Q[:, 1] - Q[:, 0] * P[:, 1]          # shoelace: centroid of the outline's area
    centroid = ((P + Q) * cross[:, None]).sum(axis=0) / (3.0 * cross.sum())
    assert np.allclose(poly["position"], centroid, atol=0.05)
    assert not np.allclose(centroid, np.mean(corners[:4], axis=0), atol=0.05)  # the hull's would differ
    img = app.screenshot("polygon")
    sx, sy = map(int, poly["screen"])
    assert orange_pixels(img, sx - 25, sy - 25, sx + 25, sy + 25) > 1200, "the polygon is not drawn"
    # n-gon: drag out the radius from the centre (sides from the palette: 6)
    app.key("4")
    app.frames(2)
    c = to_screen(st0, (2.5, 5.0))
    app.drag(c, (c[0] + 48, c[1]), steps=8)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_bodies"] == n0 + 2, 10, "the n-gon")
    ngon = [b for b in new_bodies(st, st0) if b["id"] != poly["id"]][0]
    assert ngon["shape"] == "polygon" and ngon["vertices"] == 6, ngon
    # circle
    app.key("5")
    app.frames(2)
    c2 = to_screen(st0, (5.0, 5.0))
    app.drag(c2, (c2[0] + 30, c2[1] + 10), steps=8)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_bodies"] == n0 + 3, 10, "the circle")
    circ = [b for b in new_bodies(st, st0) if b["id"] not in (poly["id"], ngon["id"])][0]
    assert circ["shape"] == "circle", circ
    app.frames(3)
    img = app.screenshot("shapes")
    for b, label in ((ngon, "n-gon"), (circ, "circle")):
        sx, sy = map(int, b["screen"])
        assert body_pixels(img[sy - 25:sy + 25], sx - 25, sx + 25) + \
            orange_pixels(img, sx - 25, sy - 25, sx + 25, sy + 25) > 1000, f"the {label} is not drawn"
    assert orange_pixels(img, int(c2[0]) - 20, int(c2[1]) - 20, int(c2[0]) + 20, int(c2[1]) + 20) > 600
    # undo each creation, newest first; redo brings the last back
    for n in (n0 + 2, n0 + 1, n0):
        app.key("ctrl+z")
        st = app.wait(lambda s, n=n: s["n_bodies"] == n, 10, f"undo to {n} bodies")
    assert {b["id"] for b in st["bodies"]} == {b["id"] for b in st0["bodies"]}
    app.frames(3)
    img = app.screenshot("undone")
    sx, sy = map(int, poly["screen"])
    assert orange_pixels(img, sx - 25, sy - 25, sx + 25, sy + 25) == 0, "the undone polygon is still drawn"
    assert not st["gl_errors"] and not st["fault"]


def test_spring_tool_delete_toggle_static_undo(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st0 = app.wait_ready(20)
    n0, s0 = st0["n_bodies"], st0["n_springs"]
    a, b = body(st0, "a"), body(st0, "b")
    mid = ((a["screen"][0] + b["screen"][0]) / 2, a["screen"][1])
    band = (int(a["screen"][0]) + 40, int(mid[1]) - 12, int(b["screen"][0]) - 40, int(mid[1]) + 12)
    no_spring = yellow_pixels(app.screenshot("no_spring"), *band)
    # spring: drag from body a to body b
    app.key("6")
    app.frames(2)
    app.drag(a["screen"], b["screen"], steps=20)
    app.xdo("mouseup", 1)
    st = app.wait(lambda s: s["n_springs"] == s0 + 1, 10, "the new spring")
    new = [s for s in st["springs"] if s["id"] not in {q["id"] for q in st0["springs"]}]
    assert len(new) == 1 and {new[0]["a"], new[0]["b"]} == {a["id"], b["id"]}, st["springs"]
    app.key("Escape")                                   # deselect: the coil in its own colour
    app.frames(3)
    img = app.screenshot("spring")
    assert yellow_pixels(img, *band) > no_spring + 150, "the spring is not drawn between the bodies"
    app.key("ctrl+z")
    st = app.wait(lambda s: s["n_springs"] == s0, 10, "undo of the spring")
    # toggle static (T) on a selected body, and undo
    app.key("1")
    app.frames(2)
    app.click(*b["screen"])
    st = app.wait(lambda s: s["selection"] == [b["id"]], 10, "b selected")
    app.key("t")
    st = app.wait(lambda s: body(s, "b")["kind"] == "static", 10, "b static")
    app.key("ctrl+z")
    st = app.wait(lambda s: body(s, "b")["kind"] == "dynamic", 10, "b dynamic again")
    # delete (Del) a selected body, and undo
    app.click(*a["screen"])
    st = app.wait(lambda s: s["selection"] == [a["id"]], 10, "a selected")
    app.key("Delete")
    st = app.wait(lambda s: s["n_bodies"] == n0 - 1, 10, "a deleted")
    assert all(q["name"] != "a" for q in st["bodies"])
    app.key("ctrl+z")
    st = app.wait(lambda s: s["n_bodies"] == n0, 10, "a back")
    assert body(st, "a")["position"] == pytest.approx(a["position"])
    # delete the body a spring holds: the spring goes with it, nothing breaks; undo restores both
    c = body(st, "c")
    before = app.screenshot("hanging")
    hang = (int(c["screen"][0]) - 12, int(c["screen"][1]) - 110, int(c["screen"][0]) + 12, int(c["screen"][1]) - 30)
    assert yellow_pixels(before, *hang) > 100, "the scene's spring is not drawn"
    app.click(*c["screen"])
    app.wait(lambda s: s["selection"] == [c["id"]], 10, "c selected")
    app.key("Delete")
    st = app.wait(lambda s: s["n_bodies"] == n0 - 1 and s["n_springs"] == s0 - 1, 10, "c and its spring deleted")
    app.key("space")                                     # run a while: no crash, no fault
    st0_steps = st["steps"]
    st = app.wait(lambda s: s["steps"] > st0_steps + 30, 30, "stepping after the delete")
    assert not st["fault"] and not st["gl_errors"]
    img = app.screenshot("deleted")
    assert yellow_pixels(img, *hang) < 20, "the deleted spring is still drawn"
    app.key("space")
    app.key("ctrl+z")
    st = app.wait(lambda s: s["n_bodies"] == n0 and s["n_springs"] == s0, 10, "undo of the delete")
    assert not st["gl_errors"] and not st["fault"]


def test_invalid_inspector_edit_is_refused(launch, tmp_path):
    app = launch(tools_scene(tmp_path / "tools.json"), "--paused")
    st = app.wait_ready(20)
    b = body(st, "b")
    app.click(*b["screen"])
    st = app.wait(lambda s: s["selection"] == [b["id"]] and "inspector:density" in s["ui_rects"], 10,
                  "b in the inspector")
    d0 = body(st, "b")["density"]
    x0, y0, x1, y1 = st["ui_rects"]["inspector:density"]
    app.click(x0 + 40, (y0 + y1) / 2)                    # the text field (the whole text is selected)
    app.frames(3)
    app.key("ctrl+a", "BackSpace", "minus", "2", "Return")
    st = app.wait(lambda s: s["edit_error"], 10, "the refusal")
    assert "refused" in st["edit_error"] and "density" in st["edit_error"].lower(), st["edit_error"]
    assert any("refused" in m for m in st["messages"])
    assert body(st, "b")["density"] == d0 and not st["dirty"]
    app.wait(lambda s: "refusal" in s["ui_rects"], 10, "the refusal beside the field")
    st = app.settle()
    img = app.screenshot("refused")
    ex0, ey0, ex1, ey1 = map(int, st["ui_rects"]["refusal"])
    assert red_text_pixels(img, ex0, ey0, ex1, ey1) > 30, "the refusal is not shown beside the field"
    assert abs(ey0 - y0) < 10, "the refusal is not at the field's height"
    assert not st["gl_errors"] and not st["fault"]
