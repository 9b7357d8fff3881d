"""Simulation section: play/pause/step/reset, time scale, step rate, gravity, the last fault."""
from __future__ import annotations

from imgui_bundle import imgui

from .base import Section
from .style import DIM, ENTER, RED


class SimulationSection(Section):
    title = "Simulation"

    def draw(self):
        app, sim = self.app, self.app.sim
        if imgui.button("Pause (Space)" if sim.running else "Play (Space)", imgui.ImVec2(110, 0)):
            sim.toggle_run()
        imgui.same_line()
        if imgui.button("Step (S)"):
            sim.step_once()
        imgui.same_line()
        if imgui.button("Reset (R)"):
            app.files.request_reset()
        w = app.world
        imgui.text_colored(DIM, f"t = {w.time:.2f} s   steps {w.steps}   bodies {len(app.rd_ids)}")
        ch, v = imgui.slider_float("time scale", sim.time_scale, 0.05, 4.0, "%.2fx",
                                   imgui.SliderFlags_.logarithmic.value)
        if ch:
            sim.time_scale = v
        ch, hz = imgui.input_float("step rate (Hz)", 1.0 / w.dt, 10.0, 60.0, "%.1f", ENTER)
        if ch:
            app.editor.set_world("dt", 1.0 / hz if hz > 0 else -1.0, lambda v: setattr(w, "dt", v),
                                 lambda: w.dt)
        g = list(w.gravity)
        ch, g = imgui.input_float2("gravity", g, "%.2f", ENTER)
        if ch:
            app.editor.set_world("gravity", tuple(g), lambda v: setattr(w, "gravity", v), lambda: w.gravity)
        if sim.fault:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(RED, f"Simulation error: {sim.fault}")
            imgui.text_colored(DIM, "The world was reverted to the last good state and paused.")
            imgui.pop_text_wrap_pos()
