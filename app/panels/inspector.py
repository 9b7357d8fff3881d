"""Inspector section: every property of the selected body, spring or joint, edited live (undoable)."""
from __future__ import annotations

import math

from imgui_bundle import imgui

import physics

from .base import Section, record
from .number_typing import typed
from .fixture_inspector import body_text, draw_fixtures
from .joint_inspector import draw_joint
from .laser_inspector import draw_laser, selected_laser
from .plot_tab import probe_checkboxes
from ..render.colors import PALETTE
from .style import DIM, ENTER

MAX_MASS = 1e9          # kg: beyond this the solvers' mass ratios break down long before
# A refusal is shown beside its field (panels/refusal.py), not in the panel, so no field moves.
# The number fields here and in the joint and fixture inspectors are doubles (input_double): a
# float32 field turned a typed 1e30 into 1.0000000150474662e+30 in the refusal, and 1e300 into inf.


def wrap_degrees(deg: float) -> float:
    """An angle in degrees wrapped into [-180, 180] (a spinning body's angle grows without bound)."""
    return math.remainder(deg, 360.0) if math.isfinite(deg) else deg


class InspectorSection(Section):
    title = "Inspector"
    fixture_pick = (None, 0)     # (body id, fixture index) picked in the Fixtures list (fixture_inspector)

    def draw(self):
        app, ed = self.app, self.app.editor
        app.ui_values.pop("inspector:body", None)
        sel = [s for s in ed.selection if s.alive]
        laser = selected_laser(app)
        if not sel and laser is not None:
            draw_laser(app, laser)
            return
        if not sel:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(DIM, "Nothing selected: click a body, a spring or a joint's pin.")
            imgui.pop_text_wrap_pos()
            return
        if len(sel) > 1:
            imgui.text(f"{len(sel)} items selected")
        item = sel[-1]
        if isinstance(item, physics.Body):
            self.body(item)
        elif isinstance(item, physics.Joint):
            draw_joint(self, item)
        else:
            self.spring(item)
        if imgui.button("Delete (Del)"):
            ed.delete_selection()
        imgui.same_line()
        if imgui.button("Duplicate (Ctrl+D)"):
            ed.duplicate_selection()
        if isinstance(item, physics.Body):       # on its own line: three buttons do not fit
            if imgui.button("Static/Dynamic (T)"):
                ed.toggle_static()

    def edit(self, item, field, value):
        self.app.editor.set_property(item, field, value)

    def set_mass(self, b, kg):
        """The body's mass through its density (mass = density x area): every fixture's density
        scaled alike, so the mass is where it was within the body."""
        ed = self.app.editor
        if not (math.isfinite(kg) and 0 < kg <= MAX_MASS):
            ed.refuse(f"mass: must be more than 0 and at most {MAX_MASS:g} kg (got {kg:g} kg)")
            ed.notify(f"refused: {ed.edit_error}", error=True)
            return
        self.edit(b, "density", b.density * kg / b.mass)

    def body(self, b):
        self.app.ui_values["inspector:body"] = b.id       # which body the inspector shows (tests)
        imgui.text(f"Body {b.name or b.id}: {body_text(b)}")
        imgui.text_colored(DIM, f"mass {b.mass:.4g} kg   inertia {b.inertia:.4g}   {'awake' if b.awake else 'asleep'}")
        probe_checkboxes(self.app, b)          # near the top: the panel may not show its end
        self.colour(b)
        kinds = ["dynamic", "static", "kinematic"]
        ch, k = imgui.combo("kind", kinds.index(b.kind), kinds)
        if ch:
            self.edit(b, "kind", kinds[k])
        ch, v = imgui.input_float2("position", list(b.position), "%.3f", ENTER)
        ch = typed(self.app, "position", ch)
        if ch:
            self.edit(b, "position", tuple(v))
        shown = wrap_degrees(math.degrees(b.angle))
        self.app.ui_values["inspector:angle"] = shown
        ch, v = imgui.input_double("angle (deg)", shown, 5.0, 45.0, "%.2f", ENTER)
        ch = typed(self.app, "angle", ch)
        record(self.app, "inspector:angle")
        if ch:
            self.edit(b, "angle", math.radians(wrap_degrees(v)))
        ch, v = imgui.input_float2("velocity", list(b.velocity), "%.3f", ENTER)
        ch = typed(self.app, "velocity", ch)
        record(self.app, "inspector:velocity")
        if ch:
            self.edit(b, "velocity", tuple(v))
        ch, v = imgui.input_double("angular vel.", b.angular_velocity, 0.5, 5.0, "%.3f", ENTER)
        ch = typed(self.app, "angular velocity", ch)
        record(self.app, "inspector:angular_velocity")
        if ch:
            self.edit(b, "angular_velocity", v)
        ch, v = imgui.input_double("density", b.density, 0.1, 1.0, "%.3f", ENTER)
        ch = typed(self.app, "density", ch)
        record(self.app, "inspector:density")
        if ch:
            self.edit(b, "density", v)
        if b.mass > 0:        # a static or kinematic body has no mass to set
            ch, v = imgui.input_double("mass (kg)", b.mass, 0.1, 1.0, "%.4g", ENTER)
            ch = typed(self.app, "mass", ch)
            record(self.app, "inspector:mass")
            if ch:
                self.set_mass(b, v)
        ch, v = imgui.input_double("restitution", b.restitution, 0.05, 0.2, "%.3f", ENTER)
        ch = typed(self.app, "restitution", ch)
        if ch:
            self.edit(b, "restitution", v)
        ch, v = imgui.input_double("static friction", b.static_friction, 0.05, 0.2, "%.3f", ENTER)
        ch = typed(self.app, "static friction", ch)
        if ch:
            self.edit(b, "friction", (v, b.dynamic_friction))
        ch, v = imgui.input_double("dynamic friction", b.dynamic_friction, 0.05, 0.2, "%.3f", ENTER)
        ch = typed(self.app, "dynamic friction", ch)
        if ch:
            self.edit(b, "friction", (b.static_friction, v))
        ch, v = imgui.input_text("name", b.name or "", ENTER)
        if ch:
            self.edit(b, "name", v or None)
        draw_fixtures(self, b)

    def colour(self, b):
        """The body's own fill colour: a palette swatch, any colour (the editor), or the default."""
        ed = self.app.editor
        own = ed.color_of(b)
        for k, hexstr in enumerate(PALETTE):
            rgb = tuple(int(hexstr[i:i + 2], 16) / 255.0 for i in (1, 3, 5))
            if k:
                imgui.same_line(0, 3)
            if imgui.color_button(f"##swatch{k}", imgui.ImVec4(*rgb, 1.0), 0, imgui.ImVec2(20, 20)):
                ed.set_color(b, rgb)
            record(self.app, f"inspector:swatch:{k}")
        shown = own if own is not None else (0.31, 0.56, 0.84)
        imgui.same_line(0, 6)
        ch, rgb = imgui.color_edit3("##colour", list(shown), imgui.ColorEditFlags_.no_inputs.value)
        if ch:
            ed.set_color(b, rgb)
        if own is not None:
            imgui.same_line()
            if imgui.small_button("default##colour"):
                ed.set_color(b, None)

    def spring(self, sp):
        a = sp.body_a.name or sp.body_a.id
        bname = "world" if sp.body_b is None else (sp.body_b.name or sp.body_b.id)
        imgui.text(f"Spring {sp.name or sp.id}: {a} - {bname}")
        imgui.text_colored(DIM, f"length {sp.length:.3f} m")
        probe_checkboxes(self.app, sp)
        ch, v = imgui.input_double("stiffness", sp.stiffness, 10.0, 100.0, "%.2f", ENTER)
        ch = typed(self.app, "stiffness", ch)
        if ch:
            self.edit(sp, "stiffness", v)
        ch, v = imgui.input_double("damping", sp.damping, 0.1, 1.0, "%.3f", ENTER)
        ch = typed(self.app, "damping", ch)
        if ch:
            self.edit(sp, "damping", v)
        ch, v = imgui.input_double("rest length", sp.rest_length, 0.1, 1.0, "%.3f", ENTER)
        ch = typed(self.app, "rest length", ch)
        if ch:
            self.edit(sp, "rest_length", v)
        ch, v = imgui.input_float2("anchor a (local)", list(sp.anchor_a), "%.3f", ENTER)
        ch = typed(self.app, "anchor a", ch)
        if ch:
            self.edit(sp, "anchor_a", tuple(v))
        label = "anchor b (world)" if sp.body_b is None else "anchor b (local)"
        ch, v = imgui.input_float2(label, list(sp.anchor_b), "%.3f", ENTER)
        ch = typed(self.app, "anchor b", ch)
        if ch:
            self.edit(sp, "anchor_b", tuple(v))
        ch, v = imgui.input_text("name##spring", sp.name or "", ENTER)
        if ch:
            self.edit(sp, "name", v or None)
