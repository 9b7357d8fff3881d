"""The sandbox's compound-body edits without a window (issue 13): the new tools on an Editor,
glue/unglue and fixture edits through the undo history, copy and reset keeping every fixture,
and the drawing rows (no step: no kernel).  test_shape_tools.py drives the same with real input."""
from __future__ import annotations

import numpy as np
import pytest

import physics
from app.camera import Camera
from app.document import restore, snapshot
from app.editor import Editor
from app.gluing import glue_selection, unglue_selection
from app.notices import Notices
from app.panels.fixture_inspector import parse_bits, set_fixture
from app.preview import render_data
from app.render.parts import ARC, Parts

pytestmark = pytest.mark.app

L = [(-2, 0.5), (2, 0.5), (2, 1.5), (-1, 1.5), (-1, 3.0), (-2, 3.0)]


@pytest.fixture
def editor(display, monkeypatch):
    monkeypatch.setenv("DISPLAY", display)
    w = physics.World()
    w.add_body(physics.Polygon.box(16, 1), kind="static", position=(0, -0.5), name="ground")
    w.add_body(physics.Polygon.box(1, 1), position=(-3, 2), name="a")
    w.add_body(physics.Polygon.box(1, 1), position=(3, 2.5), angle=0.4, name="b")
    cam = Camera(1280, 800)
    cam.scale = 40.0
    return Editor(w, None, Notices(), cam)


class FakeApp:
    def __init__(self, ed):
        from types import SimpleNamespace

        from app.panels.number_typing import NumberTyping
        self.editor = ed
        self.panels = SimpleNamespace(numbers=NumberTyping(self))  # the panels' number-field typing


def named(ed, name):
    return next(b for b in ed.world.bodies if b.name == name)


def test_polygon_tool_makes_one_concave_body(editor):
    from pyglet.window import key as K
    editor.set_tool("polygon")
    for p in L:
        editor.tool.press(p, 1, 0)
    assert editor.tool.key(K.ENTER)
    b = editor.world.bodies[-1]
    assert len(b.fixtures) == 2 and b.mass == pytest.approx(5.5, rel=1e-12)   # 4 x 1 + 1 x 1.5
    editor.undo()
    assert len(editor.world.bodies) == 3
    editor.redo()
    assert len(editor.world.bodies[-1].fixtures) == 2                          # undo/redo keep the pieces


def test_polygon_tool_refuses_a_crossing_outline_and_keeps_the_points(editor):
    from pyglet.window import key as K
    editor.set_tool("polygon")
    for p in [(0, 0), (2, 2), (2, 0), (0, 2)]:
        editor.tool.press(p, 1, 0)
    editor.tool.key(K.ENTER)
    assert len(editor.world.bodies) == 3 and len(editor.tool.points) == 4
    assert "no body" in editor.hint_text()


def test_sketch_tool_stroke_and_bad_stroke(editor):
    editor.set_tool("sketch")
    t = editor.tool
    pts = [(-3, 1), (3, 1), (3, 4), (0, 2.5), (-3, 4), (-3, 1.02)]
    t.press(pts[0], 1, 0)
    for a, b in zip(pts[:-1], pts[1:]):
        for s in np.linspace(0, 1, 30)[1:]:
            t.drag(tuple(np.array(a) + s * (np.array(b) - a)))
    t.release(pts[-1])
    b = editor.world.bodies[-1]
    assert len(editor.world.bodies) == 4 and len(b.fixtures) >= 2
    assert b.mass == pytest.approx(13.5, rel=0.01)        # 18 m^2 minus the 4.5 m^2 notch
    t.press((0, 0), 1, 0)
    t.release((0, 0))                                      # a dot: a hint, no body
    assert len(editor.world.bodies) == 4 and editor.hint_text()


def test_capsule_and_ground_tools(editor):
    editor.set_tool("capsule")
    editor.tool.press((0, 3), 1, 0)
    editor.tool.drag((2, 3))
    editor.tool.release((2, 3))
    cap = editor.world.bodies[-1]
    assert isinstance(cap.shape, physics.Capsule) and cap.position == pytest.approx((1, 3))
    assert cap.shape.length == pytest.approx(2.0) and cap.shape.radius == editor.tool_options.capsule_radius
    editor.set_tool("ground")
    for p in [(-6, 0), (0, 1), (6, 0)]:
        editor.tool.press(p, 1, 0)
    assert editor.tool.right_click((6, 0))
    g = editor.world.bodies[-1]
    assert g.kind == "static" and len(g.fixtures) == 2
    assert all(f.shape.kind == "chain_segment" for f in g.fixtures)
    assert g.fixtures[0].shape.vertices[0][0] > g.fixtures[0].shape.vertices[1][0]   # right to left
    assert not editor.tool.right_click((0, 0))             # no points: the context menu's


def test_glue_unglue_undo_redo(editor):
    a, b = named(editor, "a"), named(editor, "b")
    b.fixtures[0].category = 0x4
    editor.selection = [a, b]
    glue_selection(editor)
    assert len(editor.world.bodies) == 2
    g = editor.world.bodies[-1]
    assert [f.category for f in g.fixtures] == [1, 4] and g.mass == pytest.approx(2.0)
    editor.selection = [g]
    unglue_selection(editor)
    assert len(editor.world.bodies) == 3 and all(len(x.fixtures) == 1 for x in editor.world.bodies)
    editor.undo()
    assert len(editor.world.bodies) == 2 and len(editor.world.bodies[-1].fixtures) == 2
    editor.undo()
    a2, b2 = named(editor, "a"), named(editor, "b")
    assert a2.position == pytest.approx((-3, 2)) and b2.angle == pytest.approx(0.4)
    assert b2.fixtures[0].category == 4
    editor.redo()
    assert len(editor.world.bodies) == 2


def test_glue_needs_two_bodies(editor):
    editor.selection = [named(editor, "a")]
    glue_selection(editor)
    assert len(editor.world.bodies) == 3
    unglue_selection(editor)                                 # one fixture: nothing to split
    assert len(editor.world.bodies) == 3


def test_fixture_edits_validated_and_undoable(editor):
    app = FakeApp(editor)
    g = editor.world.add_body([physics.Polygon.box(1, 1), physics.Circle(0.5, offset=(2, 0))], position=(0, 4))
    m0 = g.mass
    assert set_fixture(app, g, 1, "density", 3.0)
    assert g.mass == pytest.approx(1 + 3 * np.pi * 0.25)
    assert not set_fixture(app, g, 1, "density", -1.0) and "refused" in editor.edit_error
    assert set_fixture(app, g, 0, "mask", parse_bits("0x3")) and g.fixtures[0].mask == 3
    assert not set_fixture(app, g, 0, "category", parse_bits("zz"))
    editor.undo()
    assert g.fixtures[0].mask == (1 << 64) - 1
    editor.undo()
    assert g.mass == pytest.approx(m0)


def test_reset_and_paste_keep_fixtures(editor):
    g = editor.world.add_body(physics.decompose(L), position=(0, 5))
    g.fixtures[1].friction = (0.1, 0.05)
    w2 = restore(snapshot(editor.world))
    g2 = w2.bodies[-1]
    assert len(g2.fixtures) == 2 and g2.fixtures[1].friction == (0.1, 0.05)
    editor.selection = [g]
    editor.copy_selection()
    editor.paste()
    assert len(editor.world.bodies[-1].fixtures) == 2


def test_parts_draw_each_fixture(editor):
    w = editor.world
    w.add_body([physics.Polygon.box(1, 1), physics.Circle(0.3, offset=(1, 0)), physics.Capsule((0, 1), (1, 1), 0.2),
                physics.Polygon.box(1, 1, radius=0.1)], position=(0, 6))
    w.add_body(physics.Chain([(5, 0), (0, 1), (-5, 0)]), kind="static", position=(0, -2))
    rd = render_data(w)
    p = Parts(rd)
    # 3 plain boxes + the compound's box, then the capsule (2 x ARC points) and the rounded box (4 x ARC)
    assert sorted(p.vcount.tolist()) == [4, 4, 4, 4, 2 * ARC, 4 * ARC]
    assert len(p.circle_body) == 1 and len(p.line_body) == 2
    np.testing.assert_allclose(p.circle_centre[0], (1.0, 6.0), atol=1e-12)   # origin (0, 6) + its offset


def world_ends(w):
    """Every spring's and joint's bodies (by name) and world anchors, in creation order."""
    def nm(b):
        return None if b is None else b.name
    springs = [(nm(s.body_a), nm(s.body_b), s.body_a.local_to_world(s.anchor_a),
                s.anchor_b if s.body_b is None else s.body_b.local_to_world(s.anchor_b), s.rest_length)
               for s in w.springs]
    joints = [(j.kind, nm(j.body_a), nm(j.body_b), j.anchor_a, j.anchor_b) for j in w.joints]
    return springs, joints


def exact_state(w):
    """What undo must bring back exactly: bodies, springs and joints as their specs' numbers."""
    from app.joint_specs import joint_fields
    bodies = sorted((b.name or "", tuple(b.position), b.angle, len(b.fixtures)) for b in w.bodies)
    springs = [(s.body_a.name, None if s.body_b is None else s.body_b.name, s.anchor_a, s.anchor_b, s.stiffness,
                s.rest_length) for s in w.springs]
    joints = [(j.kind, j.body_a.name, None if j.body_b is None else j.body_b.name, joint_fields(j)) for j in w.joints]
    return bodies, springs, joints


def jointed(editor):
    """a, b (turned 0.4) and the ground held by a spring and a joint of every kind that has geometry."""
    w = editor.world
    g, a, b = named(editor, "ground"), named(editor, "a"), named(editor, "b")
    w.add_spring(a, g, anchor_a=(0.3, 0.4), anchor_b=(-3, 0.5), stiffness=50.0, name="s_ag")
    w.add_spring(a, b, anchor_a=(-0.2, 0.1), anchor_b=(0.1, 0.2), name="s_ab")          # a-b: dropped by glue
    hinge = w.add_joint("revolute", a, g, anchor=a.local_to_world((0.4, -0.2)), name="hinge")
    hinge.reference_angle = 0.1                                   # the angle reads 0.3, not 0
    w.add_joint("prismatic", b, None, anchor=b.local_to_world((0.2, 0.3)), axis=(1.0, 0.0), lower=-1.0, upper=1.0,
                name="slider")
    w.add_joint("wheel", a, g, anchor=a.local_to_world((0.1, -0.4)), axis=(0.0, 1.0), name="wheel")
    w.add_joint("distance", a, None, anchor_a=a.local_to_world((0.5, 0.5)), anchor_b=(-3, 6), name="rope")
    w.add_joint("motor", a, g, linear_offset=(-2.7, 2.6), angular_offset=0.25, name="motor")
    w.add_joint("weld", a, b, anchor=(0, 2), name="weld")         # a-b: dropped by glue
    return a, b, g


def test_glue_keeps_springs_and_joints_at_their_world_points(editor):
    w = editor.world
    a, b, g = jointed(editor)
    before_exact = exact_state(w)
    springs0, joints0 = world_ends(w)
    readouts0 = {j.name: (j.angle if j.kind in ("revolute", "motor") else j.translation if j.kind == "prismatic"
                          else j.rest_length if j.kind == "distance" else None) for j in w.joints}
    hinge_ref = editor.refs.of(w.joints[0])
    a_pos, a_angle = np.array(a.position), a.angle
    editor.selection = [b, a]                      # b first: the compound takes b's frame, so a's parts move frame
    glue_selection(editor)
    c = editor.world.bodies[-1]
    assert c.name == "b" and len(w.springs) == 1 and len(w.joints) == 5
    label = editor.doc.history.done[-1].label
    assert label == "glue 2 bodies; kept 1 spring and 5 joints; dropped 1 spring and 1 joint between glued bodies"
    assert "dropped" in editor.notices.items[-1][0]
    springs1, joints1 = world_ends(w)
    # the same ends, with every glued body now the compound "b", at the same world points
    rename = {"a": "b"}
    expect_s = [(rename.get(x, x), rename.get(y, y), pa, pb, r) for x, y, pa, pb, r in springs0 if {x, y} != {"a", "b"}]
    expect_j = [(k, rename.get(x, x), rename.get(y, y), pa, pb) for k, x, y, pa, pb in joints0 if k != "weld"]
    assert len(springs1 + joints1) == len(expect_s + expect_j)
    for got, want in zip(springs1 + joints1, expect_s + expect_j):
        assert [v for v in got if isinstance(v, (str, type(None)))] == [v for v in want if isinstance(v, (str, type(None)))]
        for gv, wv in zip(got, want):
            if isinstance(wv, tuple) and got[0] != "motor":      # a motor's "anchor" is its body's origin
                np.testing.assert_allclose(gv, wv, atol=1e-12)
    # what the joints measure between their bodies reads as before (reference angle, axis, length corrected)
    for j in w.joints:
        if readouts0[j.name] is not None:
            now = j.angle if j.kind in ("revolute", "motor") else j.translation if j.kind == "prismatic" else j.rest_length
            assert now == pytest.approx(readouts0[j.name], abs=1e-12), j.name
    slider = next(j for j in w.joints if j.kind == "prismatic")
    np.testing.assert_allclose(slider.axis, (1.0, 0.0), atol=1e-12)
    wheel = next(j for j in w.joints if j.kind == "wheel")                   # on a: its axis turned into b's frame
    np.testing.assert_allclose(wheel.axis, (0.0, 1.0), atol=1e-12)
    # the motor's target: with the compound there, a's old origin and angle sit at a's old target
    m = next(j for j in w.joints if j.kind == "motor")
    target_angle = g.angle + m.angular_offset
    target_x = np.array(g.local_to_world(m.linear_offset))
    off_a = np.array(c.world_to_local(a_pos))
    rc = np.array([[np.cos(target_angle), -np.sin(target_angle)], [np.sin(target_angle), np.cos(target_angle)]])
    np.testing.assert_allclose(rc @ off_a + target_x, g.local_to_world((-2.7, 2.6)), atol=1e-12)
    assert target_angle + (a_angle - c.angle) == pytest.approx(g.angle + 0.25, abs=1e-12)
    assert hinge_ref.obj.alive and hinge_ref.obj.body_a is c       # the history's Ref follows the joint
    editor.undo()
    assert "dropped" in editor.notices.items[-1][0]
    assert exact_state(w) == before_exact
    assert hinge_ref.obj.alive and hinge_ref.obj.body_a.name == "a" and hinge_ref.obj.reference_angle == 0.1
    editor.redo()
    assert world_ends(w)[1][0][1] == "b" and len(w.joints) == 5 and hinge_ref.obj.body_a is w.bodies[-1]
    editor.undo()
    assert exact_state(w) == before_exact


def test_unglue_keeps_springs_and_joints_on_the_part_they_hold(editor):
    w = editor.world
    g = named(editor, "ground")
    c = w.add_body([physics.Polygon.box(1, 1), physics.Circle(0.5, offset=(2, 0))], position=(0, 4), angle=0.3,
                   name="c")
    w.add_spring(c, None, anchor_a=(2.2, 0.1), anchor_b=(2, 8), name="s")          # in the circle
    w.add_joint("revolute", c, g, anchor=c.local_to_world((-0.3, 0.3)), name="pin")  # in the box
    # outside both parts, nearer the circle (0.4 m) than the box (1.55 m)
    w.add_joint("distance", g, c, anchor_a=(0, 0), anchor_b=c.local_to_world((2.0, 0.9)), name="rope")
    before_exact = exact_state(w)
    springs0, joints0 = world_ends(w)
    editor.selection = [c]
    unglue_selection(editor)
    box, disc = (next(b for b in w.bodies if b.alive and b.fixtures[0].shape.kind == k and b.name != "ground"
                      and b.position == pytest.approx((0, 4))) for k in ("polygon", "circle"))
    s, = w.springs
    pin, rope = w.joints
    assert s.body_a is disc and pin.body_a is box and rope.body_b is disc
    springs1, joints1 = world_ends(w)
    for got, want in zip(springs1 + joints1, springs0 + joints0):
        for gv, wv in zip(got, want):
            if isinstance(wv, tuple):
                np.testing.assert_allclose(gv, wv, atol=1e-12)
    assert "kept 1 spring and 2 joints" in editor.notices.items[-1][0]
    editor.undo()
    assert exact_state(w) == before_exact


class _Section:
    def __init__(self, app):
        self.app = app


def test_inspector_lists_every_fixture(editor):
    """A body of 100 fixtures: all 100 rows reachable by scrolling the list with the mouse wheel
    (it used to stop at 64), on an imgui context with no window; a click picks the one edited."""
    from imgui_bundle import imgui
    from app.panels.fixture_inspector import draw_fixtures
    squares = [physics.Polygon([(x, 0), (x + 0.5, 0), (x + 0.5, 0.5), (x, 0.5)]) for x in range(100)]
    b = editor.world.add_body(squares, position=(0, 8))
    editor.selection = [b]
    app = FakeApp(editor)
    app.ui_rects = {}
    section = _Section(app)
    ctx = imgui.create_context()
    try:
        io = imgui.get_io()
        io.set_ini_filename(None)                     # no imgui.ini left in the working directory
        io.display_size = imgui.ImVec2(400, 800)
        io.backend_flags |= imgui.BackendFlags_.renderer_has_textures.value   # fonts without a GL texture
        seen = set()

        def frame(mouse=None, down=None, wheel=0.0):
            if mouse is not None:
                io.add_mouse_pos_event(*mouse)
            if down is not None:
                io.add_mouse_button_event(0, down)
            if wheel:
                io.add_mouse_wheel_event(0.0, wheel)
            io.delta_time = 1 / 60
            imgui.new_frame()
            imgui.set_next_window_pos(imgui.ImVec2(0, 0))
            imgui.set_next_window_size(imgui.ImVec2(400, 800))
            imgui.begin("inspector")
            draw_fixtures(section, b)
            imgui.end()
            imgui.render()
            seen.update(int(k.split(":")[2]) for k in app.ui_rects if k.count(":") == 2 and k[-1].isdigit()
                        and k.startswith("inspector:fixture:"))

        def click(key):
            x0, y0, x1, y1 = app.ui_rects[key]
            for down in (True, False):
                frame(mouse=((x0 + x1) / 2, (y0 + y1) / 2), down=down)
            frame()

        frame()
        click("inspector:fixtures")                    # open the Fixtures header
        assert "inspector:fixture_list" in app.ui_rects and len(seen) < 100   # a clipped list, not all at once
        x0, y0, x1, y1 = app.ui_rects["inspector:fixture_list"]
        for _ in range(200):
            if 99 in seen:
                break
            frame(mouse=((x0 + x1) / 2, (y0 + y1) / 2), wheel=-1.0)
        assert seen == set(range(100))
        click("inspector:fixture:99")
        assert section.fixture_pick == (b.id, 99)
        assert "inspector:fixture:99:density" in app.ui_rects
    finally:
        imgui.destroy_context(ctx)


def test_compare_ghost_draws_each_fixture(editor):
    """A comparison lane's ghost (app.render.ghost) draws a compound body's every fixture as the
    scene does, not one shape per body: the box, the offset circle at its own centre, the
    capsule's rounded outline and a segment's line; the static ground left out in ghost view."""
    from app.render.ghost import lane_arrays
    w = editor.world
    w.add_body([physics.Polygon.box(1, 1), physics.Circle(0.3, offset=(1, 0)), physics.Capsule((0, 1), (1, 1), 0.2),
                physics.Segment((-1, 0), (-1, 1))], position=(0, 6))
    polys, discs_, lines = lane_arrays(render_data(w), (1.0, 0.5, 0.0, 1.0), scale=40.0)
    visible = polys[:, 10] > 0                     # line alpha: the static ground's is 0 in ghost view
    # a fan is 3 vertices per edge: boxes a, b and the compound's box (4 edges each), its capsule (2 x ARC)
    assert visible.sum() == 3 * (3 * 4 + 2 * ARC)
    # one disc (a 6-vertex quad) of radius 0.3 about the circle fixture's centre (1, 6), not the body's (0, 6)
    assert discs_.shape == (6, 14) and np.all(discs_[:, 4] == np.float32(0.3))
    np.testing.assert_allclose(discs_[:, 0:2].mean(axis=0), (1.0, 6.0), atol=1e-6)
    # the segment: one line quad (6 vertices) around x = -1 in the lane colour
    assert lines.shape == (6, 7) and np.all(lines[:, 3:7] == np.float32([1.0, 0.5, 0.0, 1.0]))
    np.testing.assert_allclose(lines[:, 0].mean(), -1.0, atol=1e-6)
