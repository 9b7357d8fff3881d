"""Solver section: the mode and its settings, integrator, broad and narrow phase, sleeping."""
from __future__ import annotations

import time

from imgui_bundle import imgui

from physics import options

from .. import reliability

from .base import Section, record
from .number_typing import typed
from .find_settings import FindSettings
from .style import AMBER, DIM

# the choices that pick the compiled step wait for its kernels (``app.mode_switch``); the others
# are set at once
STEP_CHOICES = (("integrator", "integrator", options.INTEGRATORS),
                ("broad phase", "broadphase", options.BROADPHASES))
WORLD_CHOICES = (("narrow phase", "narrowphase", options.NARROWPHASES),)
PENDING_LABEL = "  (compiling: switches when ready)"


def mode_description(mode: str) -> str:
    """The solver mode's one-line summary from ``physics.options`` (its own description if the
    core has no summary), or ''."""
    summary = getattr(options, "SOLVER_SUMMARIES", {}).get(mode)
    if summary:
        return summary
    try:
        from physics import solvers as _s  # description only (read-only)
        return _s.get(mode).description
    except Exception:  # noqa: BLE001
        return ""


def setting_widget(label, decl, val):
    """The widget for one declared solver setting: (changed, value)."""
    if isinstance(decl.default, bool):
        return imgui.checkbox(label, val)
    if isinstance(decl.default, str):
        choices = list(decl.choices)
        ch, idx = imgui.combo(label, choices.index(val) if val in choices else 0, choices)
        return ch, choices[idx]
    if isinstance(decl.default, int):
        lo = int(decl.lo) if decl.lo is not None else 0
        hi = int(decl.hi) if decl.hi is not None else max(100, 4 * int(decl.default))
        return imgui.slider_int(label, int(val), lo, hi)
    lo = float(decl.lo) if decl.lo is not None else 0.0
    hi = float(decl.hi) if decl.hi is not None else max(1.0, 4 * float(decl.default))
    flags = imgui.SliderFlags_.logarithmic.value if lo > 0 and hi / lo > 100 else 0
    return imgui.slider_float(label, float(val), lo, hi, "%.4g", flags)


class SolverSection(Section):
    """The mode, its settings and the world's other solver choices; then Find settings (the tuner)."""
    title = "Solver"

    def __init__(self, app):
        super().__init__(app)
        self.find = FindSettings(app)

    def draw(self):
        app, ed = self.app, self.app.editor
        w = app.world
        pending = app.mode_switch.mode
        opened = imgui.begin_combo("mode", w.solver)
        record(app, "solver_combo")
        if opened:
            for m in w.solvers:
                label = f"{m}{PENDING_LABEL}###{m}" if m == pending else m
                clicked, _ = imgui.selectable(label, m == w.solver)
                record(app, f"solver:{m}")
                if clicked and (m != w.solver or pending):
                    ed.switch_solver(m)      # the running mode again cancels a pending mode
            imgui.end_combo()
        self.pending(app, w)
        desc = " ".join(t for t in (mode_description(w.solver), reliability.summary(w.solver)) if t)
        app.ui_values["solver_description"] = desc
        if desc:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(DIM, desc)
            imgui.pop_text_wrap_pos()
            record(app, "solver_description")
        self.settings(w)
        for label, attr, choices in STEP_CHOICES:
            self.step_choice(app, w, label, attr, choices)
        for label, attr, choices in WORLD_CHOICES:
            opts = list(choices)
            cur = getattr(w, attr)
            ch, k = imgui.combo(label, opts.index(cur) if cur in opts else 0, opts)
            if ch:
                ed.set_world(attr, opts[k], lambda v, a=attr: setattr(w, a, v), lambda a=attr: getattr(w, a))
        ch, v = imgui.checkbox("sleeping", w.sleeping)
        if ch:
            ed.set_world("sleeping", v, lambda x: setattr(w, "sleeping", x), lambda: w.sleeping)
        info = app.sampler.info
        if info.get("stages"):
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(DIM, "stages: " + " > ".join(info["stages"]))
            imgui.pop_text_wrap_pos()
        # what the settings are now (tests and scripts check an apply or an undo against it)
        app.ui_values["solver_settings"] = {"solver": w.solver, "settings": w.settings.to_dict(),
                                            "integrator": w.integrator, "dt": w.dt}
        self.find.draw()

    @staticmethod
    def step_choice(app, w, label, attr, choices):
        """The integrator or broad phase combo: a value whose kernels are not loaded waits for
        them (``Editor.set_integrator``/``set_broadphase`` ask ``app.mode_switch``) and is listed
        as compiling; the running value again cancels it."""
        ed = app.editor
        cur = getattr(w, attr)
        pending = app.mode_switch.choice.get(attr)
        opened = imgui.begin_combo(label, cur)
        record(app, f"{attr}_combo")
        if opened:
            for v in choices:
                text = f"{v}{PENDING_LABEL}###{v}" if v == pending else v
                clicked, _ = imgui.selectable(text, v == cur)
                record(app, f"{attr}:{v}")
                if clicked and (v != cur or pending is not None):
                    (ed.set_integrator if attr == "integrator" else ed.set_broadphase)(v)
            imgui.end_combo()

    @staticmethod
    def pending(app, w):
        """A mode, integrator or broad phase picked before its kernels are compiled
        (``app.mode_switch``): which, how far its compile is, that the running one goes on until
        then, and a way to stay."""
        ms = app.mode_switch
        if not ms.active:
            app.ui_values.pop("solver_pending", None)
            app.ui_rects.pop("solver_pending", None)
            return
        frac, label = ms.progress()
        running = ms.running_label()
        head = f"{ms.label()}: compiling, {100 * frac:.0f} % ({running} runs until then)"
        top, width = imgui.get_cursor_screen_pos(), imgui.get_content_region_avail().x
        imgui.push_text_wrap_pos(0)
        imgui.text_colored(AMBER, head)
        imgui.progress_bar(frac, imgui.ImVec2(-1, 0), f"{100 * frac:.0f}%")
        imgui.text_colored(DIM, f"{time.monotonic() - ms.since:.0f} s: {label}")
        imgui.pop_text_wrap_pos()
        if imgui.small_button(f"Stay with {running}##pending"):
            ms.cancel(f"{running} stays: the switch to {ms.label()} is cancelled")
        record(app, "solver_pending_cancel")
        app.ui_rects["solver_pending"] = (top.x, top.y, top.x + width, imgui.get_item_rect_max().y)
        app.ui_values["solver_pending"] = head

    def set_setting(self, w, name, value):
        mode = w.solver
        self.app.editor.set_world(f"{mode}.{name}", value,
                                  lambda x, m=mode, n=name: w.settings_for(m).__setitem__(n, x),
                                  lambda m=mode, n=name: w.settings_for(m)[n])

    def hand_back(self, w, name):
        """Forget the user's value of a setting the world chooses from the scene, undoably."""
        mode = w.solver
        mine = w.settings_for(mode)

        def put(x, n=name):
            if x is None:
                del mine[n]
            else:
                mine[n] = x
        self.app.editor.set_world(f"{mode}.{name}", None, put, lambda n=name: mine[n] if mine.is_set(n) else None)

    def settings(self, w):
        settings = w.settings
        chosen = settings.chosen()  # what the world chose from the scene (solvers/soft_step/fit.py)
        self.app.ui_values["solver_chosen"] = {k: f"{v} ({why})" for k, (v, why) in chosen.items()}
        for name, decl in settings.declared().items():
            ch, v = setting_widget(f"{name}##{w.solver}", decl, settings[name])
            record(self.app, f"setting:{name}")
            ch = typed(self.app, name, ch, integer=isinstance(decl.default, int))
            if decl.doc and imgui.is_item_hovered():
                imgui.set_tooltip(decl.doc)
            if ch:
                self.set_setting(w, name, v)
        for name in settings.declared():  # below the fields, so that none moves when a line goes
            if name not in chosen:
                self.app.ui_rects.pop(f"solver_chosen:{name}", None)
                continue
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(DIM, f"{name} {chosen[name][0]} chosen for this scene: {chosen[name][1]}; "
                                    "set it to override")
            imgui.pop_text_wrap_pos()
            record(self.app, f"solver_chosen:{name}")
        fitted = settings.fitted()
        pressed = imgui.button("Defaults##solver")
        record(self.app, "solver_defaults")
        if pressed:
            for name, decl in settings.declared().items():
                if name in fitted:  # back to the world's own choice
                    if settings.is_set(name):
                        self.hand_back(w, name)
                elif settings[name] != decl.default:
                    self.set_setting(w, name, decl.default)
