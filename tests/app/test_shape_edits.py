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
        self.editor = ed


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
