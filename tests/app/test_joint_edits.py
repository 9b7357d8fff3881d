"""The sandbox's joint edits without a window: tools on an Editor, commands, undo/redo, delete,
duplicate, paste, reset snapshot and the drawing rows (no step: no kernel beyond picking's).

The real-window side (real input, pixels) is test_joint_tools.py; these pin down the bookkeeping
that is tedious to reach through the mouse: every parameter survives an undo of a delete, world
anchors move with a duplicate, the mouse drag's joint is never the user's.
"""
from __future__ import annotations

import math

import numpy as np

import pytest

import physics
from app.camera import Camera
from app.document import restore, snapshot
from app.editor import Editor
from app.joint_specs import joint_fields
from app.notices import Notices
from app.render.joints import joint_lines, joint_markers, joint_segments

pytestmark = pytest.mark.app


@pytest.fixture
def editor(display, monkeypatch):
    monkeypatch.setenv("DISPLAY", display)     # the select tool reads pyglet's modifier keys
    w = physics.World()
    w.add_body(physics.Polygon.box(16, 1), kind="static", position=(0, -0.5), name="ground")
    w.add_body(physics.Polygon.box(1.2, 1.2), position=(-4, 0.6), name="a")
    w.add_body(physics.Polygon.box(1.2, 1.2), position=(-3.6, 1.0), name="b")
    w.add_body(physics.Polygon.box(2.0, 0.5), position=(4, 1.2), name="chassis")
    w.add_body(physics.Circle(0.3), position=(4.6, 1.2), name="wheel")
    cam = Camera(1280, 800)
    cam.scale = 40.0
    return Editor(w, None, Notices(), cam)


def same(f1, f2):
    """Two joint_fields dicts equal, floats to 1e-12 (a body-frame anchor is stored relative to the
    centre of mass: adding it back can land an ulp off)."""
    assert f1.keys() == f2.keys()
    for k in f1:
        v1, v2 = f1[k], f2[k]
        if isinstance(v1, (float, tuple)):
            assert v2 == pytest.approx(v1, abs=1e-12), k
        else:
            assert v1 == v2, k
    return True


def named(ed, name):
    return next(b for b in ed.world.bodies if b.name == name)


def use(ed, tool, p, to=None):
    ed.set_tool(tool)
    ed.tool.press(p, 1, 0)
    if to is not None:
        ed.tool.drag(to)
        ed.tool.release(to)
    return ed.world.joints[-1] if ed.world.joints else None


def test_each_tool_makes_its_joint_over_the_bodies_under_the_pointer(editor):
    ed = editor
    a, b = named(ed, "a"), named(ed, "b")
    j = use(ed, "hinge", (-3.8, 0.8))              # a and b overlap there: b is on top
    assert (j.kind, j.body_a, j.body_b) == ("revolute", b, a) and j.anchor == pytest.approx((-3.8, 0.8))
    assert ed.selection == [j]
    j = use(ed, "motor", (-4.4, 0.2))              # a alone: pinned to the background
    assert (j.kind, j.body_a, j.body_b) == ("revolute", a, None)
    assert j.motor_speed == ed.tool_options.motor_speed and j.max_motor_torque == ed.tool_options.motor_torque
    j = use(ed, "fixate", (-3.8, 0.8))
    assert (j.kind, j.body_a, j.body_b) == ("weld", b, a)
    j = use(ed, "slider", (-4.4, 0.2), (-4.4, 2.2))
    assert j.kind == "prismatic" and j.axis == pytest.approx((0.0, 1.0)) and (j.lower, j.upper) == (0.0, pytest.approx(2.0))
    j = use(ed, "rope", (-4.4, 0.2), (-4.4, 3.2))
    assert (j.kind, j.body_b, j.min_length) == ("distance", None, None) and j.max_length == pytest.approx(3.0)
    j = use(ed, "wheel", (4.6, 1.2))
    assert (j.kind, j.body_a, j.body_b) == ("wheel", named(ed, "chassis"), named(ed, "wheel"))
    assert j.anchor_b == pytest.approx((4.6, 1.2)) and j.spring_hertz == ed.tool_options.wheel_hertz
    n = len(ed.world.joints)
    use(ed, "hinge", (0.0, 5.0))                   # nothing there: refused, said at the pointer
    use(ed, "hinge", (0.0, -0.5))                  # the static ground alone: nothing to hinge
    use(ed, "wheel", (-4.4, 0.2))                  # no circle
    assert len(ed.world.joints) == n and ed.hint_text()


def test_undo_redo_delete_and_edit_keep_every_parameter(editor):
    ed = editor
    j = use(ed, "motor", (-4.4, 0.2))
    assert ed.set_property(j, "lower_angle", -0.5) and ed.set_property(j, "break_force", 500.0)
    before = joint_fields(j)
    a = named(ed, "a")
    ed.select(a)
    ed.delete_selection()                          # the body takes its joint along
    assert not ed.world.joints
    ed.undo()
    (j2,) = ed.world.joints
    assert same(joint_fields(j2), before) and j2.body_a is named(ed, "a")
    ed.undo()                                      # the break force edit, then the limit, then the joint
    ed.undo()
    assert ed.world.joints[0].lower_angle is None
    ed.undo()
    assert not ed.world.joints
    for _ in range(3):
        ed.redo()
    assert same(joint_fields(ed.world.joints[0]), before)
    # a distance joint's length: the undo restores the rest length, not the distance now
    r = use(ed, "rope", (-4.4, 0.2), (-4.4, 3.2))
    rest = r.rest_length
    assert ed.set_property(r, "length", 1.0) and r.rest_length == 1.0
    ed.undo()
    assert r.rest_length == rest
    assert not ed.set_property(r, "max_length", -1.0) and "max_length" in ed.edit_error
    # geometry: the slider's axis turned and back (world coordinates, as the inspector edits it)
    sl = use(ed, "slider", (-4.4, 0.2), (-4.4, 2.2))
    assert ed.set_property(sl, "axis", (1.0, 0.0)) and sl.axis == pytest.approx((1.0, 0.0))
    ed.undo()
    assert sl.axis == pytest.approx((0.0, 1.0))
    # a joint deleted alone, and back
    ed.select(r)
    ed.delete_selection()
    assert all(x.kind != "distance" for x in ed.world.joints)
    ed.undo()
    assert any(x.kind == "distance" for x in ed.world.joints)


def test_duplicate_and_paste_take_the_joints_among_the_bodies(editor):
    ed = editor
    use(ed, "fixate", (-3.8, 0.8))                                # b welded to a
    use(ed, "rope", (-4.4, 0.2), (-4.4, 3.2))                     # a hung from the background
    ed.selection = [named(ed, "a"), named(ed, "b")]
    ed.duplicate_selection()
    assert len(ed.world.joints) == 4
    weld, rope = ed.world.joints[2], ed.world.joints[3]
    copies = set(ed.selection)
    assert weld.kind == "weld" and {weld.body_a, weld.body_b} == copies
    # the copy's rope hangs from its own point, beside the original's
    assert rope.anchor_b == pytest.approx((-4.4 + 0.6, 3.2 + 0.6))
    ed.undo()
    assert len(ed.world.joints) == 2 and len(ed.world.bodies) == 5
    ed.cursor = np.array([0.0, 6.0])
    ed.selection = [named(ed, "a"), named(ed, "b")]
    ed.copy_selection()
    ed.paste()
    assert len(ed.world.joints) == 4
    ed.undo()
    assert len(ed.world.joints) == 2


def test_mouse_drag_joint_is_the_tools_own(editor):
    ed = editor
    use(ed, "hinge", (-3.8, 0.8))
    ed.set_tool("select")
    a = named(ed, "a")
    ed.tool.press((-4.4, 0.2), 1, 0)
    mouse = ed.tool.joint
    assert mouse.kind == "mouse" and mouse.body_a is a and ed.tool_joints == {mouse.id}
    # Box2D's mouse-joint cap: 100 body weights in this mode, at least standard gravity's
    g = max(math.hypot(*ed.world.gravity), 9.81)
    assert ed.world.solver == "soft_step"
    assert mouse.max_force == pytest.approx(100.0 * a.mass * g) and mouse.hertz == ed.tool_options.joint_hertz
    ed.tool.drag((-4.4, 2.0))
    ed.tool.update(None)
    assert mouse.target == pytest.approx((-4.4, 2.0))
    # never saved in a snapshot, copied or taken along by a delete's undo
    snap = snapshot(ed.world, ed.tool_joints)
    assert [j["kind"] for j in snap["joints"]] == ["revolute"]
    assert [j.kind for j in restore(snap).joints] == ["revolute"]
    ed.tool.release((-4.4, 2.0))
    assert not ed.tool_joints and [j.kind for j in ed.world.joints] == ["revolute"]


def test_joints_are_drawn_and_picked_where_they_are(editor):
    ed = editor
    use(ed, "hinge", (-3.8, 0.8))
    use(ed, "slider", (-4.4, 0.2), (-4.4, 2.2))
    use(ed, "rope", (4.0, 1.2), (4.0, 4.2))
    use(ed, "wheel", (4.6, 1.2))
    rows = ed.world.render_data().joints
    row, p0, p1 = joint_segments(rows, 40.0)
    assert set(row.tolist()) == {0, 1, 2, 3}                      # every joint has lines
    # the slider's axis runs from its start to its upper limit, with ticks at both limits
    sl = row == 1
    ys = np.concatenate([p0[sl, 1], p1[sl, 1]])
    assert ys.min() == pytest.approx(0.2, abs=1e-9) and ys.max() == pytest.approx(2.2, abs=1e-9)
    assert len(joint_lines(rows, 40.0)) == 6 * len(row)
    assert len(joint_markers(rows, 40.0, hidden={ed.world.joints[0].id})) > 0
    hinge = ed.world.joints[0]
    assert ed.joint_near((-3.8 + 5 / 40, 0.8), lines=False) is hinge          # 5 px from the pin
    assert ed.joint_near((-3.8 + 12 / 40, 0.8), lines=False) is None
    assert ed.joint_near((4.0 + 3 / 40, 2.7)) is ed.world.joints[2]           # on the rope's line
    ed.set_tool("select")
    ed.tool.press((-3.8, 0.8), 1, 0)
    assert ed.selection == [hinge] and ed.tool.joint is None                  # the pin, not a drag
    d = ed.decor()
    assert d.selected_joints == {hinge.id} and d.motor_pins == {}
    motor = use(ed, "motor", (-4.4, 0.9))
    d = ed.decor()
    assert d.motor_pins == {motor.id: named(ed, "a").angle}
    marks = joint_markers(ed.world.render_data().joints, 40.0, motors=d.motor_pins).reshape(-1, 6, 14)
    assert marks[:, 0, 5].tolist().count(1.0) == 1              # one spoked disc: the motor's pin
