"""Tools section: one button per tool (drag a droppable tool's button into the scene to drop a
body), the active tool's help, and the palette options for new bodies."""
from __future__ import annotations

from imgui_bundle import imgui

from physics import joint_params as jp

from ..tools.any_joint import KINDS as JOINT_TOOL_KINDS
from .base import Section, record
from .number_typing import typed
from .style import DIM


class ToolsSection(Section):
    title = "Tools"

    def __init__(self, app):
        super().__init__(app)
        self.palette_drag = None     # the tool whose button is being dragged into the scene

    def draw(self):
        ed = self.app.editor
        per_row = 5           # eighteen tools in four rows: the inspector below stays on screen
        gap = imgui.get_style().item_spacing.x
        width = (imgui.get_content_region_avail().x - (per_row - 1) * gap) / per_row
        for i, name in enumerate(ed.tool_names):
            if i % per_row:
                imgui.same_line()
            active = ed.tool.name == name
            if active:
                imgui.push_style_color(imgui.Col_.button.value, imgui.ImVec4(0.85, 0.55, 0.2, 0.9))
            if imgui.button(f"{name}##tool", imgui.ImVec2(width, 0)):
                ed.set_tool(name)
            record(self.app, f"tool:{name}")
            if active:
                imgui.pop_style_color()
            if ed.tools[name].droppable:
                if imgui.begin_drag_drop_source():
                    imgui.set_drag_drop_payload_py_id("STELK_SHAPE", i)
                    imgui.text(f"drop a {name} into the scene")
                    imgui.end_drag_drop_source()
                    self.palette_drag = name
        imgui.push_text_wrap_pos(0)
        imgui.text_colored(DIM, ed.tool.help)
        if ed.tool.droppable:  # only beside the tools it is about: the inspector below stays on screen
            imgui.text_colored(DIM, "Drag box / n-gon / circle buttons into the scene to drop one.")
        imgui.pop_text_wrap_pos()
        self.options(ed.tool_options)
        self.joint_options(ed.tool_options, ed.tool.name)
        self.snapping(ed.snap)

    def snapping(self, snap):
        """Grid and angle snapping (G): creation tools and the selection handles."""
        ch, snap.on = imgui.checkbox("snap (G)", snap.on)
        record(self.app, "tools:snap")
        imgui.same_line()
        imgui.set_next_item_width(60)
        ch1, g = imgui.input_float("m##snapgrid", snap.grid, 0, 0, "%.2f", imgui.InputTextFlags_.enter_returns_true.value)
        ch1 = typed(self.app, "snap grid", ch1)
        imgui.same_line()
        imgui.set_next_item_width(50)
        ch2, a = imgui.input_float("deg##snapangle", snap.angle, 0, 0, "%.0f", imgui.InputTextFlags_.enter_returns_true.value)
        ch2 = typed(self.app, "snap angle", ch2)
        if ch1 or ch2:
            try:
                snap.set_steps(g, a)
            except ValueError as exc:
                self.app.editor.notify(f"refused: {exc}", error=True)

    def options(self, o):
        kinds = ["dynamic", "static", "kinematic"]
        ch, k = imgui.combo("new body kind", kinds.index(o.kind), kinds)
        if ch:
            o.kind = kinds[k]
        ch, v = imgui.slider_int("n-gon sides", o.sides, 3, 12)
        ch = typed(self.app, "n-gon sides", ch, integer=True)      # Ctrl+click types a value
        if ch:
            o.sides = v
        ch, v = imgui.slider_float("click size (m)", o.default_size, 0.2, 5.0, "%.2f")
        ch = typed(self.app, "click size", ch)
        if ch:
            o.default_size = v
        ch, v = imgui.slider_float("restitution##new", o.restitution, 0.0, 1.0, "%.2f")
        ch = typed(self.app, "restitution", ch)
        if ch:
            o.restitution = v
        ch, v = imgui.slider_float("spring k##new", o.spring_stiffness, 1.0, 2000.0, "%.0f",
                                   imgui.SliderFlags_.logarithmic.value)
        ch = typed(self.app, "spring k", ch)
        if ch:
            o.spring_stiffness = v
        ch, v = imgui.slider_float("mouse joint Hz", o.joint_hertz, 0.5, 20.0, "%.1f")
        ch = typed(self.app, "mouse joint Hz", ch)
        if ch:
            o.joint_hertz = v

    def joint_options(self, o, tool):
        """The joint tools' options, shown while one of them is active."""
        if tool == "motor":
            ch, v = imgui.slider_float("motor speed", o.motor_speed, -20.0, 20.0, "%.2f")
            ch = typed(self.app, "motor speed", ch)
            record(self.app, "tools:motor_speed")
            if ch:
                o.motor_speed = v
            ch, v = imgui.slider_float("motor torque", o.motor_torque, 0.0, 2000.0, "%.1f",
                                       imgui.SliderFlags_.logarithmic.value)
            ch = typed(self.app, "motor torque", ch)
            if ch:
                o.motor_torque = v
        elif tool == "wheel":
            ch, v = imgui.slider_float("suspension Hz", o.wheel_hertz, 0.0, 20.0, "%.1f")
            ch = typed(self.app, "suspension Hz", ch)
            if ch:
                o.wheel_hertz = v
            ch, v = imgui.slider_float("susp. damping", o.wheel_damping_ratio, 0.0, 2.0, "%.2f")
            ch = typed(self.app, "suspension damping", ch)
            if ch:
                o.wheel_damping_ratio = v
        elif tool == "slider":
            _, o.slider_limits = imgui.checkbox("limit travel to the drag", o.slider_limits)
        elif tool == "joint":
            self.joint_kinds(o)

    def joint_kinds(self, o):
        """The joint tool's kind: one button per declared kind (physics/joint_params.py), three a row."""
        for i, kind in enumerate(JOINT_TOOL_KINDS):
            if i % 3:
                imgui.same_line()
            if imgui.radio_button(f"{kind}##joint_kind", o.joint_kind == kind):
                o.joint_kind = kind
            record(self.app, f"tools:joint_kind:{kind}")
            if imgui.is_item_hovered():
                imgui.set_tooltip(jp.KINDS[kind].doc)

    def drop(self):
        """A palette button dragged out of the panels and released over the scene drops a body there
        (called after every window is drawn, so 'over a window' is this frame's answer)."""
        if self.palette_drag is None:
            return
        if imgui.is_mouse_released(0):
            name = self.palette_drag
            self.palette_drag = None
            if not imgui.is_window_hovered(imgui.HoveredFlags_.any_window.value):
                mp = imgui.get_mouse_pos()
                h = imgui.get_io().display_size.y
                app = self.app
                app.editor.drop_shape(name, app.camera.to_world(mp.x, h - mp.y))
        elif not imgui.is_mouse_down(0):
            self.palette_drag = None
