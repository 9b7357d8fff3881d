"""The solver section's Find settings: the tuner's budget, metric and length, its progress and
Cancel, then the choice against the scene's settings now and Apply (app/find_settings.py)."""
from __future__ import annotations

from imgui_bundle import imgui

from physics.tuning import METRICS

from ..find_settings import Finder, apply_command, scene_copy
from .base import record, wrapped
from .number_typing import typed
from .style import DIM, ENTER, GREEN, RED

#: a few seconds on a small scene (issue 19's CLI default is 600 steps: minutes in the window)
DEFAULT_STEPS = 120
DEFAULT_BUDGET = 0.01
UNITS = {"energy_drift": "fraction"}   # every other metric is in metres


def _number(v, unit="") -> str:
    return "-" if v is None or v != v else f"{v:.3g}{' ' + unit if unit else ''}"


class FindSettings:
    """The widgets and the search they drive; ``finder`` runs it, ``app.ui_values['find']``
    reports its state for tests and scripts."""

    def __init__(self, app):
        self.app = app
        self.finder = Finder()
        self.metric = "trajectory"
        self.budget = DEFAULT_BUDGET
        self.steps = DEFAULT_STEPS
        self.applied = False          # the result on show has been applied
        self._state = "idle"          # the state last drawn: a change posts one notice
        app.editor.on_document.append(self._document)

    def _document(self, world, path, keep_camera):
        if not keep_camera:     # another scene (a reset keeps the scene, and the result)
            self.finder.discard()

    def tick(self):
        """Every frame, the section open or not: kill an overrunning cancel, post a notice when a
        search ends."""
        f = self.finder
        f.poll()
        if f.state != self._state:
            self._state = f.state
            self.changed(f)

    def draw(self):
        f = self.finder
        imgui.separator_text("Find settings")
        self.options(disabled=f.busy)
        if f.busy:
            self.running(f)
        else:
            if imgui.button("Find settings"):
                self.start()
            record(self.app, "find:start")
            if imgui.is_item_hovered():
                imgui.set_tooltip("Search every solver mode for the fastest settings whose error on this\n"
                                  "scene stays within the budget (in the background). It runs the scene\n"
                                  "as last opened or saved (what Reset returns to: save to include body\n"
                                  "edits) with the solver settings above, so those are its baseline.")
            self.outcome(f)
        self.app.ui_values["find"] = {
            "state": f.state, "progress": list(f.progress), "result": f.result, "error": f.error,
            "seconds": f.seconds, "applied": self.applied, "pid": f.pid,
            "compiling": f.is_compiling, "compiled": f.compiled,
            "options": {"metric": self.metric, "budget": self.budget, "steps": self.steps}}

    def options(self, disabled):
        imgui.begin_disabled(disabled)
        opened = imgui.begin_combo("metric##find", self.metric)
        record(self.app, "find:metric")
        if opened:
            for m in METRICS:
                if imgui.selectable(m, m == self.metric)[0]:
                    self.metric = m
                record(self.app, f"find:metric:{m}")
            imgui.end_combo()
        ch, v = imgui.input_float(f"budget ({UNITS.get(self.metric, 'm')})##find", self.budget, 0.0, 0.0,
                                  "%.4g", ENTER)
        ch = typed(self.app, "budget", ch)
        record(self.app, "find:budget")
        if ch and v > 0:
            self.budget = v
        ch, n = imgui.input_int("steps##find", self.steps, 60, 600, ENTER)
        ch = typed(self.app, "steps", ch, integer=True)
        record(self.app, "find:steps")
        if ch:
            self.steps = max(16, min(int(n), 6000))
        imgui.end_disabled()

    def start(self):
        ed = self.app.editor
        try:
            scene = scene_copy(ed)
            self.finder.start(scene, self.steps, self.metric, self.budget)
        except Exception as exc:  # noqa: BLE001  (the scene cannot be copied or the process not started)
            self.finder.state, self.finder.error = "error", f"could not start the search: {exc}"
            ed.notify(f"find settings: {self.finder.error}", error=True)
            return
        ed.notify(f"find settings: searching ({self.metric}, budget {self.budget:g}, {self.steps} steps)")

    def running(self, f):
        stage, done, total = f.progress
        frac = done / total if total else 0.0
        label = f"{stage}: {done} of {total}" if total else f"{stage}..."
        imgui.progress_bar(frac, imgui.ImVec2(-1, 0), label)
        record(self.app, "find:progress")
        if f.is_compiling:    # a cold cache: the run stands still while numba compiles its kernels
            wrapped(DIM, f"compiling kernels... ({f.compiled} done, now {f.kernel.rsplit('.', 1)[-1]}; "
                         "once, then cached)")
            record(self.app, "find:compiling")
        if f.state == "cancelling":
            imgui.text_colored(DIM, "cancelling (after the current run)...")
        elif imgui.button("Cancel##find"):
            f.cancel()
        record(self.app, "find:cancel")

    def changed(self, f):
        """A search ended (or began): say so once in the messages strip."""
        ed = self.app.editor
        self.applied = False
        if f.state == "error":
            ed.notify(f"find settings: {f.error}", error=True)
        elif f.state == "cancelled":
            ed.notify("find settings: cancelled, nothing applied")
        elif f.state == "done" and f.result is not None:
            c = f.result["choice"]
            ed.notify(f"find settings: {c['key'] if c else 'nothing fits the budget'} ({f.seconds:.1f} s)")

    def outcome(self, f):
        if f.state == "error":
            wrapped(RED, f"The tuner refused: {f.error}")
            return
        if f.state == "cancelled":
            imgui.text_colored(DIM, "Search cancelled: nothing applied.")
            return
        if f.state != "done" or f.result is None:
            return
        r = f.result
        unit = UNITS.get(r["metric"], "m")
        base = r["baseline"]
        if r["choice"] is None:
            best = r["best"]
            wrapped(RED, f"Nothing fits the budget {r['budget']:g} {unit} ({r['candidates']} candidates tried)."
                    + (f" The most accurate, {best['key']}, is off by {_number(best['error'], unit)}."
                       if best else "") + " Try a looser budget or more steps.")
            wrapped(DIM, r["note"])
            return
        c = r["choice"]
        wrapped(GREEN, f"Choice: {c['key']}")
        speed = base["seconds"] / c["seconds"] if c["seconds"] > 0 else float("inf")
        wrapped(DIM, f"error {_number(c['error'], unit)} (budget {r['budget']:g}); {speed:.2g}x the speed "
                f"of the settings now (their error {_number(base['error'], unit)}).")
        record(self.app, "find:choice")
        if imgui.is_item_hovered():
            imgui.set_tooltip(r["note"])
        if self.applied:
            imgui.text_colored(GREEN, "Applied (Ctrl+Z undoes).")
        elif imgui.button("Apply##find"):
            self.apply(c)
        record(self.app, "find:apply")
        imgui.same_line()
        if imgui.button("Dismiss##find"):
            f.discard()

    def apply(self, choice):
        ed = self.app.editor
        try:
            ed.execute(apply_command(ed.world, choice))
        except (ValueError, KeyError, ImportError) as exc:
            ed.notify(f"find settings: could not apply {choice['key']}: {exc}", error=True)
            return
        self.applied = True
        for cb in ed.on_mode:
            cb(ed.world.solver, ed.world.integrator)
        ed.notify(f"applied {choice['key']} (Ctrl+Z undoes)")
