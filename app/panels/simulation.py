"""Simulation section: play/pause/step/reset, time scale, step rate, gravity, the last fault."""
from __future__ import annotations

from imgui_bundle import imgui

from ..field_bounds import checked_gravity
from .base import Section, record
from .number_typing import typed
from .style import AMBER, DIM, ENTER, RED
from .timeline import timeline_slider


class SimulationSection(Section):
    """``speed``: simulated seconds per real second, measured; amber when the sandbox cannot keep
    up with the time scale (more steps a frame are owed than it takes)."""
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
        self.play_state(app, sim)
        w = app.world
        timeline_slider(app, f"steps {w.steps}   bodies {len(app.rd_ids)}")
        ch, v = imgui.slider_float("time scale", sim.time_scale, 0.05, 4.0, "%.2fx",
                                   imgui.SliderFlags_.logarithmic.value)
        ch = typed(app, "time scale", ch)       # Ctrl+click types a value
        record(app, "sim:time_scale")
        if ch:
            sim.time_scale = v
        self.speed(sim)
        ch, hz = imgui.input_double("step rate (Hz)", 1.0 / w.dt, 10.0, 60.0, "%.1f", ENTER)
        ch = typed(app, "step rate", ch)
        record(app, "sim:step_rate")
        if ch:
            app.editor.set_step_rate(hz)
        g = list(w.gravity)
        ch, g = imgui.input_float2("gravity", g, "%.2f", ENTER)
        ch = typed(app, "gravity", ch)
        record(app, "sim:gravity")
        if ch:
            app.editor.set_world("gravity", tuple(g), lambda v: setattr(w, "gravity", checked_gravity(v)),
                                 lambda: w.gravity)
        if sim.fault:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(RED, f"Simulation error: {sim.fault}")
            imgui.text_colored(DIM, "The world was reverted to the last good state and paused.")
            imgui.pop_text_wrap_pos()

    @staticmethod
    def play_state(app, sim):
        """Before the kernels are loaded the scene does not step: say so under Play, in one line.
        The progress itself is the note above the scene (``notes.progress_window``): a second bar
        here said the same twice, and its lines pushed every field below down, to jump back up
        under the pointer once the kernels were in."""
        if not app.scene_wait.waiting(app.world):
            app.ui_values["play_state"] = "running" if sim.running else "paused"
            return
        app.ui_values["play_state"] = "waiting" if sim.running else "paused, compiling"
        imgui.text_colored(AMBER, "Plays once the kernels are compiled" if sim.running
                           else "Paused; Play waits for the kernels")
        record(app, "sim:play_state")

    @staticmethod
    def speed(sim):
        if not sim.running:
            return
        slow = sim.speed < 0.9 * sim.time_scale
        imgui.same_line()
        imgui.text_colored(AMBER if slow else DIM, f"runs {sim.speed:.2f}x")
        if slow and imgui.is_item_hovered():
            imgui.set_tooltip("The sandbox takes at most 4 steps a frame: at this step rate and "
                              "time scale the simulation runs slower than asked.")
