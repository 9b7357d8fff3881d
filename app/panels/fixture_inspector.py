"""The inspector's fixture part (issue 13): every fixture of a body listed in a scrolling list;
the picked one's material (density, restitution, friction) and filter (category and mask bits,
group, name) edited live through undoable commands (app.commands.SetFixture); a refused value
shows the core's reason.
Glue and unglue buttons sit here too (Ctrl+G, Ctrl+Shift+G)."""
from __future__ import annotations

from imgui_bundle import imgui

import physics

from ..commands import SetFixture
from ..editor import REFUSED
from ..gluing import glue_selection, unglue_selection
from .base import record, record_window
from .number_typing import typed
from .style import ENTER

LIST_ROWS = 8         # rows of the fixture list in view; more scroll


def shape_text(shape) -> str:
    """One line naming a shape and its size."""
    if isinstance(shape, physics.Circle):
        return f"circle r={shape.radius:.3g}"
    if isinstance(shape, physics.Capsule):
        return f"capsule r={shape.radius:.3g}, length {shape.length:.3g}"
    if shape.kind in ("segment", "chain_segment"):
        return shape.kind.replace("_", " ")
    r = f", rounded r={shape.radius:.3g}" if shape.radius > 0 else ""
    return f"polygon, {len(shape.vertices)} vertices{r}"


def body_text(b) -> str:
    fx = b.fixtures
    return shape_text(fx[0].shape) if len(fx) == 1 else f"{len(fx)} fixtures"


def set_fixture(app, body, index, field, value) -> bool:
    ed = app.editor
    value = ed.bounded(field, value)
    if value is REFUSED:
        return False
    return ed.try_edit(SetFixture(ed, body, index, field, value), f"fixture {index} {field}")


def parse_bits(text: str):
    """'0x3', '3' or '0b11' -> int; the text itself when it is not a number (the core refuses it
    with its own reason)."""
    try:
        return int(text.strip(), 0)
    except ValueError:
        return text


def draw_fixtures(section, b):
    """The Fixtures list of body ``b`` and the glue/unglue buttons."""
    app = section.app
    fx = b.fixtures
    sel_bodies = [s for s in app.editor.selection if isinstance(s, physics.Body) and s.alive]
    if len(sel_bodies) > 1:
        if imgui.button(f"Glue {len(sel_bodies)} bodies (Ctrl+G)"):
            glue_selection(app.editor)
        record(app, "inspector:glue")
    if len(fx) > 1 and len(sel_bodies) == 1:
        if imgui.button("Unglue (Ctrl+Shift+G)"):
            unglue_selection(app.editor)
        record(app, "inspector:unglue")
    opened = imgui.collapsing_header(f"Fixtures ({len(fx)})##fixtures")
    record(app, "inspector:fixtures")
    if not opened:
        return
    i = fixture_list(section, b)
    f = fx[i]
    imgui.text(f"fixture {i}: {shape_text(f.shape)}")
    fixture_fields(app, b, i, f)


def fixture_list(section, b) -> int:
    """Every fixture of ``b`` as a row of a scrolling list (a clipper submits only the rows in
    view: a long chain has thousands of segments); a click picks the one edited below.  Returns
    the picked index (the first fixture until one is clicked, or when the body changed)."""
    app = section.app
    fx = b.fixtures
    body_id, pick = getattr(section, "fixture_pick", (None, 0))
    if body_id != b.id or pick >= len(fx):
        pick = 0
    row_h = imgui.get_text_line_height_with_spacing()
    shown = min(len(fx), LIST_ROWS)
    imgui.begin_child("##fixture_list", imgui.ImVec2(0, shown * row_h + 2 * imgui.get_style().window_padding.y),
                      imgui.ChildFlags_.borders.value)
    record_window(app, "inspector:fixture_list")
    clipper = imgui.ListClipper()
    clipper.begin(len(fx), row_h)
    while clipper.step():
        for i in range(clipper.display_start, clipper.display_end):
            f = fx[i]
            label = f"{i}: {shape_text(f.shape)}" + (f" '{f.name}'" if f.name else "")
            if imgui.selectable(f"{label}##fx{i}", i == pick)[0]:
                pick = i
            record(app, f"inspector:fixture:{i}")
    clipper.end()
    imgui.end_child()
    section.fixture_pick = (b.id, pick)
    return pick


def fixture_fields(app, b, i, f):
    def num(label, field, value, step):
        ch, v = imgui.input_double(f"{label}##fx{i}", value, step, 10 * step, "%.3f", ENTER)
        ch = typed(app, label, ch)
        record(app, f"inspector:fixture:{i}:{field}")
        if ch:
            set_fixture(app, b, i, field, v)
    num("density", "density", f.density, 0.1)
    num("restitution", "restitution", f.restitution, 0.05)
    mu_s, mu_d = f.friction
    ch, v = imgui.input_float2(f"friction s/d##fx{i}", [mu_s, mu_d], "%.3f", ENTER)
    ch = typed(app, "friction s/d", ch)
    if ch:
        set_fixture(app, b, i, "friction", tuple(v))
    for field in ("category", "mask"):
        ch, text = imgui.input_text(f"{field}##fx{i}", hex(getattr(f, field)), ENTER)
        record(app, f"inspector:fixture:{i}:{field}")
        if ch:
            set_fixture(app, b, i, field, parse_bits(text))
    ch, v = imgui.input_int(f"group##fx{i}", f.group, 1, 10, ENTER)
    ch = typed(app, "group", ch, integer=True)
    if ch:
        set_fixture(app, b, i, "group", v)
    ch, v = imgui.input_text(f"name##fx{i}", f.name or "", ENTER)
    if ch:
        set_fixture(app, b, i, "name", v or None)
