"""The inspector's joint part: the joint's readouts (angle or translation or length, speed, motor
torque/force, reaction force and torque of the last step), every parameter of its kind and where
it holds (anchor, axis), edited live through undoable commands.  The parameter list is physics/joint_params.py's, so a
parameter the core adds shows up here without an edit."""
from __future__ import annotations

import math

from imgui_bundle import imgui

from physics import joint_params as jp

from ..joint_specs import param_value
from .base import record
from .number_typing import typed
from .style import DIM, ENTER, RED

#: step and fast step of a number field, by the parameter's rule
STEPS = {"num": (0.1, 1.0), "nonneg": (0.1, 1.0), "limit": (0.05, 0.5), "length": (0.05, 0.5)}
#: units of the readouts the inspector shows (a speed's follows what it measures)
UNITS = {"angle": "rad", "translation": "m", "length": "m", "motor_torque": "N m", "motor_force": "N"}


def readout_rows(kind: str) -> tuple:
    """(label, attribute, unit) of the readouts shown for ``kind``, from its declaration
    (physics/joint_params.py): its coordinate, its speed, its motor's torque or force."""
    d = jp.KINDS[kind]
    rows = [(d.coordinate, d.coordinate, UNITS[d.coordinate])] if d.coordinate else []
    if "speed" in d.readouts:
        rows.append(("speed", "speed", "rad/s" if d.motor == "angular" else "m/s"))
    rows += [(r.replace("_", " "), r, UNITS[r]) for r in ("motor_torque", "motor_force") if r in d.readouts]
    return tuple(rows)


def body_label(b):
    return "world" if b is None else str(b.name or b.id)


def readouts(j):
    """The joint's state after the last step, one dim line each; the reaction force shown with its
    magnitude (what a break_force is compared with)."""
    for label, attr, unit in readout_rows(j.kind):
        imgui.text_colored(DIM, f"{label}: {getattr(j, attr):.4g} {unit}")
    fx, fy = j.reaction_force
    imgui.text_colored(DIM, f"reaction force: ({fx:.4g}, {fy:.4g}) N  |F| {math.hypot(fx, fy):.4g} N")
    imgui.text_colored(DIM, f"reaction torque: {j.reaction_torque:.4g} N m")
    if j.broken:
        imgui.text_colored(RED, "broken: the reaction exceeded its break threshold")


def coordinate(j) -> float:
    """The joint's coordinate now: what its limits bound (angle, translation or length)."""
    return getattr(j, jp.KINDS[j.kind].coordinate)


def optional_number(app, j, name, value, rule, key):
    """A parameter that may be unset (None: no limit): a checkbox to set it, then its field."""
    ed = app.editor
    ch, on = imgui.checkbox(f"##set:{name}", value is not None)
    record(app, f"{key}:set")
    if imgui.is_item_hovered():
        imgui.set_tooltip(f"{name}: {'unset it' if value is not None else 'set it'}")
    if ch:     # a limit switched on starts where the joint is now (so it holds it there, not jumps)
        ed.set_property(j, name, coordinate(j) if on else None)
        return
    imgui.same_line()
    if value is None:
        imgui.text_colored(DIM, f"{name}: none")
        return
    small, big = STEPS[rule]
    ch, v = imgui.input_double(name, value, small, big, "%.4g", ENTER)
    ch = typed(app, name, ch)
    record(app, key)
    if ch:
        ed.set_property(j, name, v)


def parameter(app, j, name, p):
    ed = app.editor
    key = f"inspector:joint:{name}"
    value = param_value(j, name)
    if p.rule == "vec":
        ch, v = imgui.input_float2(name, list(value), "%.4g", ENTER)
        ch = typed(app, name, ch)
        record(app, key)
        if ch:
            ed.set_property(j, name, tuple(v))
    elif p.rule in ("limit", "length") and name != "length":
        optional_number(app, j, name, value, p.rule, key)
    else:
        small, big = STEPS[p.rule]
        ch, v = imgui.input_double(name, value, small, big, "%.4g", ENTER)
        ch = typed(app, name, ch)
        record(app, key)
        if ch:
            ed.set_property(j, name, v)
    if imgui.is_item_hovered():
        imgui.set_tooltip(p.doc)


#: the geometry the inspector moves, where a kind has it (world coordinates; the joint re-anchors there)
WORLD_GEOMETRY = ("anchor", "axis", "anchor_a", "anchor_b")


def geometry(app, j):
    """Where the joint holds (world point), and its axis: edited like the parameters."""
    for name in (g for g in WORLD_GEOMETRY if g in jp.GEOMETRY[j.kind]):
        ch, v = imgui.input_float2(f"{name} (world)", list(getattr(j, name)), "%.4g", ENTER)
        ch = typed(app, name, ch)
        record(app, f"inspector:joint:{name}")
        if ch:
            app.editor.set_property(j, name, tuple(v))


def common(app, j):
    """collide_connected, the break thresholds and the name: what every kind has."""
    ed = app.editor
    ch, v = imgui.checkbox("collide connected", j.collide_connected)
    record(app, "inspector:joint:collide_connected")
    if ch:
        ed.set_property(j, "collide_connected", v)
    for name in ("break_force", "break_torque"):
        value = getattr(j, name)
        ch, on = imgui.checkbox(f"##set:{name}", value is not None)
        if ch:
            ed.set_property(j, name, 1000.0 if on else None)
            continue
        imgui.same_line()
        if value is None:
            imgui.text_colored(DIM, f"{name}: unbreakable")
            continue
        ch, v = imgui.input_double(name, value, 10.0, 100.0, "%.4g", ENTER)
        ch = typed(app, name, ch)
        record(app, f"inspector:joint:{name}")
        if ch:
            ed.set_property(j, name, v)
    ch, v = imgui.input_text("name##joint", j.name or "", ENTER)
    if ch:
        ed.set_property(j, "name", v or None)


def draw_joint(section, j):
    """The whole joint part of the inspector for joint ``j``."""
    app = section.app
    imgui.text(f"Joint {j.name or j.id}: {j.kind}, {body_label(j.body_a)} - {body_label(j.body_b)}")
    record(app, "inspector:joint")
    readouts(j)
    for name, p in jp.PARAMS[j.kind].items():
        parameter(app, j, name, p)
    geometry(app, j)
    common(app, j)
