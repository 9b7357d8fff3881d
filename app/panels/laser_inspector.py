"""The inspector's readout of a laser emitter picked with the laser tool: what its beam does as
last traced (its length up to the last surface it meets, its bounces, the bodies it hits in
turn), and where the emitter is and which way it points, both editable (undoable): a new user
picked an emitter and read "Nothing selected"."""
from __future__ import annotations

import math

from imgui_bundle import imgui

from ..laser_commands import AimLaser, MoveLaser, RemoveLaser
from ..lasers import moved_spec
from .base import record
from .number_typing import typed
from .style import DIM, ENTER


def selected_laser(app):
    """The emitter the laser tool picked last, while it is in the document and shown; else None."""
    lz = app.editor.tools["laser"].selected
    return lz if lz is not None and lz in app.editor.lasers.items and lz.shown else None


def _name(b) -> str:
    return b.name or f"body {b.id}"


def readout_lines(lz) -> list[str]:
    """The beam in words (the inspector's lines)."""
    r = lz.readout()
    hits = [_name(b) for b in r["hits"]]
    bounces = r["bounces"]
    lines = [f"beam {r['length']:.3f} m to its last hit, {bounces} bounce{'' if bounces == 1 else 's'}"
             if hits else "beam: hits nothing"]
    if hits:
        lines.append("hits " + ", then ".join(hits))
    if r["open"]:
        lines.append("then runs off into the open")
    return lines


def draw_laser(app, lz):
    ed = app.editor
    b = lz.body()
    imgui.text(f"Laser {'on ' + _name(b) if b is not None else 'fixed in the world'}")
    lines = readout_lines(lz)
    imgui.push_text_wrap_pos(0)
    for line in lines:
        imgui.text(line)
    imgui.pop_text_wrap_pos()
    record(app, "inspector:laser:readout")
    r = lz.readout()
    app.ui_values["inspector:laser"] = {"lines": lines, "length": r["length"], "bounces": r["bounces"],
                                        "hits": [x.id for x in r["hits"]]}
    p, d = lz.origin_direction()
    ch, v = imgui.input_float2("emitter (world)", [float(p[0]), float(p[1])], "%.3f", ENTER)
    ch = typed(app, "emitter", ch)
    record(app, "inspector:laser:point")
    if ch:
        ed.execute(MoveLaser(lz, moved_spec(ed.world, ed.refs, lz, v), lz.spec()))
    ch, deg = imgui.input_double("aim (deg)", math.degrees(math.atan2(d[1], d[0])), 5.0, 45.0, "%.2f", ENTER)
    ch = typed(app, "aim", ch)
    record(app, "inspector:laser:aim")
    if ch and math.isfinite(deg):
        turn = b.angle if b is not None else 0.0
        ed.execute(AimLaser(lz, math.radians(deg) - turn, lz.angle))
    imgui.push_text_wrap_pos(0)
    imgui.text_colored(DIM, "With the laser tool: drag the emitter to aim it, Ctrl+drag it to move it "
                            "(dropped on a body it rides with it).")
    imgui.pop_text_wrap_pos()
    if imgui.button("Delete laser (Del)"):
        ed.execute(RemoveLaser(lz))
        ed.notify("laser deleted (Ctrl+Z brings it back)")
