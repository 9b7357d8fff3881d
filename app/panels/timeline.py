"""The timeline slider of the Simulation section: drag it to see the world as it was up to a
minute of simulated time ago (``app.timeline``); Play continues from the moment shown."""
from __future__ import annotations

from imgui_bundle import imgui

from ..scrub_marks import scrubbed
from .style import DIM


def scrub(app, t):
    """Show the world at simulated time ``t`` (the snapshot at or before it), paused.  The
    trails, the stats series and the plotted quantities start again from there (their time
    would run backwards otherwise)."""
    app.sim.running = False
    app.sim.accumulator = 0.0
    shown = app.timeline.scrub(app.world, t)
    if shown is None:
        app.notices.notify("timeline: nothing to go back to (an edit changed the bodies or joints)", error=True)
        return
    scrubbed(app.editor.doc, app.timeline.mark_at_cursor())     # the edits it undid are no longer unsaved
    for tr in app.editor.tracers.items:
        tr.clear()
    app.editor.tracers._last_time = None
    app.sampler.clear()
    app.recorder.clear(keep_series=True)


def timeline_slider(app, info: str):
    """The time line of the Simulation section: ``t = ...`` as a slider over the snapshots' time
    range (while there are any) followed by ``info``; plain text before the first play, so the
    section keeps its height (the panels below stay where they were)."""
    tl = app.timeline
    rng = tl.range()
    app.ui_values["timeline"] = None
    if rng is None or rng[1] <= rng[0]:
        imgui.text_colored(DIM, f"t = {app.world.time:.2f} s   {info}")
        return
    hi = max(rng[1], app.world.time)        # the grab shows the world's time, past the newest snapshot too
    t = min(max(app.world.time, rng[0]), hi)
    imgui.set_next_item_width(150)
    ch, v = imgui.slider_float("##timeline", t, rng[0], hi, "t = %.2f s")
    a, b = imgui.get_item_rect_min(), imgui.get_item_rect_max()
    app.ui_rects["sim:timeline"] = (a.x, a.y, b.x, b.y)
    app.ui_values["timeline"] = t
    if imgui.is_item_hovered():
        imgui.set_tooltip(f"timeline: drag back through the last {rng[1] - rng[0]:.1f} s (up to {tl.span:.0f} s)\n"
                          "Play continues from the moment shown")
    if ch:
        scrub(app, v)
    imgui.same_line()
    imgui.text_colored(DIM, info)
