"""imgui panels: simulation, tools/palette, solver, inspector, scene, view, stats (implot)."""
from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
from imgui_bundle import imgui, implot

import physics

from .commands import RemoveBodies, RemoveSpring, SetProperty, SetWorld
from .document import scene_files

RED = imgui.ImVec4(1.0, 0.45, 0.42, 1.0)
AMBER = imgui.ImVec4(1.0, 0.8, 0.35, 1.0)
DIM = imgui.ImVec4(0.62, 0.66, 0.72, 1.0)
GREEN = imgui.ImVec4(0.5, 0.9, 0.6, 1.0)
PANEL_W = 340
STATS_W = 330
ENTER = imgui.InputTextFlags_.enter_returns_true.value


def apply_style():
    imgui.style_colors_dark()
    st = imgui.get_style()
    st.window_rounding = 6.0
    st.frame_rounding = 4.0
    st.grab_rounding = 4.0
    st.popup_rounding = 4.0
    st.window_border_size = 0.0
    # fewer, simpler triangles: llvmpipe pays per triangle far more than per pixel
    st.anti_aliased_lines = False
    st.anti_aliased_fill = False
    st.frame_padding = imgui.ImVec2(6, 3)
    st.item_spacing = imgui.ImVec2(6, 4)
    colors = {
        imgui.Col_.window_bg: (0.075, 0.085, 0.11, 0.94),
        imgui.Col_.header: (0.20, 0.33, 0.52, 0.55),
        imgui.Col_.header_hovered: (0.26, 0.42, 0.66, 0.8),
        imgui.Col_.header_active: (0.30, 0.48, 0.75, 1.0),
        imgui.Col_.button: (0.20, 0.33, 0.52, 0.65),
        imgui.Col_.button_hovered: (0.28, 0.45, 0.70, 0.9),
        imgui.Col_.frame_bg: (0.13, 0.15, 0.20, 1.0),
        imgui.Col_.title_bg_active: (0.12, 0.18, 0.28, 1.0),
        imgui.Col_.slider_grab: (0.40, 0.62, 0.95, 1.0),
        imgui.Col_.check_mark: (0.55, 0.78, 1.0, 1.0),
    }
    for k, v in colors.items():
        st.set_color_(k, imgui.ImVec4(*v))


class Panels:
    def __init__(self, app):
        self.app = app
        self.save_as_path = ""
        self.open_path = ""
        self.edit_error = ""
        self.palette_drag = None
        self.over_ui = False
        self.show_stats = True
        self.pending_confirm = None   # (message, on_discard, on_save)
        self.autosave_offer = None    # (path, mtime)

    # ------------------------------------------------------------------
    def draw(self):
        app = self.app
        io = imgui.get_io()
        app.ui_rects.pop("main_window", None)
        app.ui_rects.pop("stats_window", None)
        if app.warmup_active():
            self.progress_window()
            return
        self.main_window()
        if self.show_stats:
            self.stats_window()
        self.messages()
        self.scene_error_window()
        self.modals()
        self.palette_drop()
        self.over_ui = imgui.is_window_hovered(imgui.HoveredFlags_.any_window.value) or io.want_capture_mouse

    # -- compile progress -------------------------------------------------
    def progress_window(self):
        app = self.app
        io = imgui.get_io()
        w, h = io.display_size.x, io.display_size.y
        imgui.set_next_window_pos(imgui.ImVec2(w * 0.5, h * 0.5), imgui.Cond_.always.value, imgui.ImVec2(0.5, 0.5))
        imgui.set_next_window_size(imgui.ImVec2(460, 0), imgui.Cond_.always.value)
        flags = (imgui.WindowFlags_.no_decoration | imgui.WindowFlags_.no_move | imgui.WindowFlags_.no_saved_settings).value
        imgui.begin("##progress", None, flags)
        imgui.text("Stelkropp")
        imgui.text_colored(DIM, "Compiling the physics kernels (first launch only) ...")
        frac, label = app.warmup.progress()
        dots = "." * (1 + int(time.monotonic() * 2) % 3)
        imgui.progress_bar(frac, imgui.ImVec2(-1, 0), f"{100 * frac:.0f}%")
        imgui.text_colored(DIM, f"{label}{dots}  ({app.warmup.elapsed():.0f} s)")
        imgui.end()

    # -- the main side panel ------------------------------------------------
    def main_window(self):
        app = self.app
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(8, 8), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_size(imgui.ImVec2(PANEL_W, io.display_size.y - 16), imgui.Cond_.first_use_ever.value)
        imgui.begin(f"Stelkropp - {app.doc.title}###main", None, imgui.WindowFlags_.no_collapse.value)
        self.simulation_section()
        self.tools_section()
        self.inspector_section()
        self.solver_section()
        self.scene_section(open_=app.scene_errors != [])
        self.view_section()
        self.record_window("main_window")
        imgui.end()

    def record(self, key):
        """Remember the last item's screen rectangle (x0, y0, x1, y1; y down) for tests and scripts."""
        a, b = imgui.get_item_rect_min(), imgui.get_item_rect_max()
        self.app.ui_rects[key] = (a.x, a.y, b.x, b.y)

    def record_window(self, key):
        """Remember the current window's rectangle (the scene is framed beside the panels)."""
        a, b = imgui.get_window_pos(), imgui.get_window_size()
        self.app.ui_rects[key] = (a.x, a.y, a.x + b.x, a.y + b.y)

    def header(self, label, open_=True):
        flags = imgui.TreeNodeFlags_.default_open.value if open_ else 0
        return imgui.collapsing_header(label, flags)

    def simulation_section(self):
        app = self.app
        if not self.header("Simulation"):
            return
        if imgui.button("Pause (Space)" if app.running else "Play (Space)", imgui.ImVec2(110, 0)):
            app.toggle_run()
        imgui.same_line()
        if imgui.button("Step (S)"):
            app.step_once()
        imgui.same_line()
        if imgui.button("Reset (R)"):
            app.request_reset()
        w = app.world
        imgui.text_colored(DIM, f"t = {w.time:.2f} s   steps {w.steps}   bodies {len(app.rd_ids)}")
        ch, v = imgui.slider_float("time scale", app.time_scale, 0.05, 4.0, "%.2fx",
                                   imgui.SliderFlags_.logarithmic.value)
        if ch:
            app.time_scale = v
        ch, hz = imgui.input_float("step rate (Hz)", 1.0 / w.dt, 10.0, 60.0, "%.1f", ENTER)
        if ch:
            self.try_world("dt", 1.0 / hz if hz > 0 else -1.0, lambda v: setattr(w, "dt", v),
                           lambda: w.dt)
        g = list(w.gravity)
        ch, g = imgui.input_float2("gravity", g, "%.2f", ENTER)
        if ch:
            self.try_world("gravity", tuple(g), lambda v: setattr(w, "gravity", v), lambda: w.gravity)
        if app.fault:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(RED, f"Simulation error: {app.fault}")
            imgui.text_colored(DIM, "The world was reverted to the last good state and paused.")
            imgui.pop_text_wrap_pos()

    def try_world(self, label, value, setter, getter):
        app = self.app
        try:
            app.execute(SetWorld(getter, setter, value, label))
            self.edit_error = ""
        except (ValueError, KeyError) as exc:
            self.edit_error = str(exc)
            app.notify(f"refused: {exc}", error=True)

    # -- tools & palette -----------------------------------------------------
    def tools_section(self):
        app = self.app
        if not self.header("Tools"):
            return
        for i, name in enumerate(app.tool_names):
            if i % 3:
                imgui.same_line()
            active = app.tool.name == name
            if active:
                imgui.push_style_color(imgui.Col_.button.value, imgui.ImVec4(0.85, 0.55, 0.2, 0.9))
            if imgui.button(f"{name}##tool", imgui.ImVec2(100, 0)):
                app.set_tool(name)
            if active:
                imgui.pop_style_color()
            if name != "select" and name != "spring" and name != "polygon":
                if imgui.begin_drag_drop_source():
                    imgui.set_drag_drop_payload_py_id("STELK_SHAPE", i)
                    imgui.text(f"drop a {name} into the scene")
                    imgui.end_drag_drop_source()
                    self.palette_drag = name
        imgui.push_text_wrap_pos(0)
        imgui.text_colored(DIM, app.tool.help)
        imgui.text_colored(DIM, "Drag box / n-gon / circle buttons into the scene to drop one.")
        imgui.pop_text_wrap_pos()
        o = app.tool_options
        kinds = ["dynamic", "static", "kinematic"]
        ch, k = imgui.combo("new body kind", kinds.index(o.kind), kinds)
        if ch:
            o.kind = kinds[k]
        ch, v = imgui.slider_int("n-gon sides", o.sides, 3, 12)
        if ch:
            o.sides = v
        ch, v = imgui.slider_float("click size (m)", o.default_size, 0.2, 5.0, "%.2f")
        if ch:
            o.default_size = v
        ch, v = imgui.slider_float("restitution##new", o.restitution, 0.0, 1.0, "%.2f")
        if ch:
            o.restitution = v
        ch, v = imgui.slider_float("spring k##new", o.spring_stiffness, 1.0, 2000.0, "%.0f",
                                   imgui.SliderFlags_.logarithmic.value)
        if ch:
            o.spring_stiffness = v
        ch, v = imgui.slider_float("mouse joint Hz", o.joint_hertz, 0.5, 20.0, "%.1f")
        if ch:
            o.joint_hertz = v

    def palette_drop(self):
        """A palette button dragged out of the panels and released over the scene drops a body there."""
        if self.palette_drag is None:
            return
        if imgui.is_mouse_released(0):
            name = self.palette_drag
            self.palette_drag = None
            if not imgui.is_window_hovered(imgui.HoveredFlags_.any_window.value):
                mp = imgui.get_mouse_pos()
                h = imgui.get_io().display_size.y
                self.app.drop_shape(name, mp.x, h - mp.y)
        elif not imgui.is_mouse_down(0):
            self.palette_drag = None

    # -- inspector ------------------------------------------------------------
    def inspector_section(self):
        app = self.app
        if not self.header("Inspector"):
            return
        sel = [s for s in app.selection if s.alive]
        if not sel:
            imgui.text_colored(DIM, "Nothing selected: click a body or a spring.")
            return
        if len(sel) > 1:
            imgui.text(f"{len(sel)} items selected")
        item = sel[-1]
        if isinstance(item, physics.Body):
            self.body_inspector(item)
        else:
            self.spring_inspector(item)
        if self.edit_error:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(RED, self.edit_error)
            imgui.pop_text_wrap_pos()
            self.record("inspector:error")
        if imgui.button("Delete (Del)"):
            app.delete_selection()
        imgui.same_line()
        if imgui.button("Duplicate (Ctrl+D)"):
            app.duplicate_selection()
        if isinstance(item, physics.Body):
            imgui.same_line()
            if imgui.button("Static/Dynamic (T)"):
                app.toggle_static()

    def edit(self, item, field, value):
        try:
            self.app.execute(SetProperty(self.app, item, field, value))
            self.edit_error = ""
        except ValueError as exc:
            self.edit_error = f"refused: {exc}"
            self.app.notify(f"{field} {self.edit_error}", error=True)

    def body_inspector(self, b):
        shape = b.shape
        desc = f"circle r={shape.radius:.3g}" if isinstance(shape, physics.Circle) else \
            f"polygon, {len(shape.vertices)} vertices"
        imgui.text(f"Body {b.name or b.id}: {desc}")
        imgui.text_colored(DIM, f"mass {b.mass:.4g} kg   inertia {b.inertia:.4g}   {'awake' if b.awake else 'asleep'}")
        kinds = ["dynamic", "static", "kinematic"]
        ch, k = imgui.combo("kind", kinds.index(b.kind), kinds)
        if ch:
            self.edit(b, "kind", kinds[k])
        ch, v = imgui.input_float2("position", list(b.position), "%.3f", ENTER)
        if ch:
            self.edit(b, "position", tuple(v))
        ch, v = imgui.input_float("angle (deg)", math.degrees(b.angle), 5.0, 45.0, "%.2f", ENTER)
        if ch:
            self.edit(b, "angle", math.radians(v))
        ch, v = imgui.input_float2("velocity", list(b.velocity), "%.3f", ENTER)
        if ch:
            self.edit(b, "velocity", tuple(v))
        ch, v = imgui.input_float("angular vel.", b.angular_velocity, 0.5, 5.0, "%.3f", ENTER)
        if ch:
            self.edit(b, "angular_velocity", v)
        ch, v = imgui.input_float("density", b.density, 0.1, 1.0, "%.3f", ENTER)
        self.record("inspector:density")
        if ch:
            self.edit(b, "density", v)
        ch, v = imgui.input_float("restitution", b.restitution, 0.05, 0.2, "%.3f", ENTER)
        if ch:
            self.edit(b, "restitution", v)
        ch, v = imgui.input_float("static friction", b.static_friction, 0.05, 0.2, "%.3f", ENTER)
        if ch:
            self.edit(b, "friction", (v, b.dynamic_friction))
        ch, v = imgui.input_float("dynamic friction", b.dynamic_friction, 0.05, 0.2, "%.3f", ENTER)
        if ch:
            self.edit(b, "friction", (b.static_friction, v))
        ch, v = imgui.input_text("name", b.name or "", ENTER)
        if ch:
            self.edit(b, "name", v or None)

    def spring_inspector(self, sp):
        a = sp.body_a.name or sp.body_a.id
        bname = "world" if sp.body_b is None else (sp.body_b.name or sp.body_b.id)
        imgui.text(f"Spring {sp.name or sp.id}: {a} - {bname}")
        imgui.text_colored(DIM, f"length {sp.length:.3f} m")
        ch, v = imgui.input_float("stiffness", sp.stiffness, 10.0, 100.0, "%.2f", ENTER)
        if ch:
            self.edit(sp, "stiffness", v)
        ch, v = imgui.input_float("damping", sp.damping, 0.1, 1.0, "%.3f", ENTER)
        if ch:
            self.edit(sp, "damping", v)
        ch, v = imgui.input_float("rest length", sp.rest_length, 0.1, 1.0, "%.3f", ENTER)
        if ch:
            self.edit(sp, "rest_length", v)
        ch, v = imgui.input_float2("anchor a (local)", list(sp.anchor_a), "%.3f", ENTER)
        if ch:
            self.edit(sp, "anchor_a", tuple(v))
        label = "anchor b (world)" if sp.body_b is None else "anchor b (local)"
        ch, v = imgui.input_float2(label, list(sp.anchor_b), "%.3f", ENTER)
        if ch:
            self.edit(sp, "anchor_b", tuple(v))
        ch, v = imgui.input_text("name##spring", sp.name or "", ENTER)
        if ch:
            self.edit(sp, "name", v or None)

    # -- solver --------------------------------------------------------------
    def solver_section(self):
        app = self.app
        w = app.world
        if not self.header("Solver"):
            return
        modes = w.solvers
        opened = imgui.begin_combo("mode", w.solver)
        self.record("solver_combo")
        if opened:
            for m in modes:
                clicked, _ = imgui.selectable(m, m == w.solver)
                self.record(f"solver:{m}")
                if clicked and m != w.solver:
                    app.switch_solver(m)
            imgui.end_combo()
        try:
            from physics import solvers as _s  # description only (read-only)
            desc = _s.get(w.solver).description
        except Exception:  # noqa: BLE001
            desc = ""
        if desc:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(DIM, desc)
            imgui.pop_text_wrap_pos()
        settings = w.settings
        for name, decl in settings.declared().items():
            val = settings[name]
            label = f"{name}##{w.solver}"
            if isinstance(decl.default, bool):
                ch, v = imgui.checkbox(label, val)
            elif isinstance(decl.default, str):
                choices = list(decl.choices)
                ch, idx = imgui.combo(label, choices.index(val) if val in choices else 0, choices)
                v = choices[idx]
            elif isinstance(decl.default, int):
                lo = int(decl.lo) if decl.lo is not None else 0
                hi = int(decl.hi) if decl.hi is not None else max(100, 4 * int(decl.default))
                ch, v = imgui.slider_int(label, int(val), lo, hi)
            else:
                lo = float(decl.lo) if decl.lo is not None else 0.0
                hi = float(decl.hi) if decl.hi is not None else max(1.0, 4 * float(decl.default))
                flags = imgui.SliderFlags_.logarithmic.value if lo > 0 and hi / lo > 100 else 0
                ch, v = imgui.slider_float(label, float(val), lo, hi, "%.4g", flags)
            if decl.doc and imgui.is_item_hovered():
                imgui.set_tooltip(decl.doc)
            if ch:
                mode = w.solver
                self.try_world(f"{mode}.{name}", v,
                               lambda x, m=mode, n=name: w.settings_for(m).__setitem__(n, x),
                               lambda m=mode, n=name: w.settings_for(m)[n])
        if imgui.button("Defaults##solver"):
            for name, decl in settings.declared().items():
                if settings[name] != decl.default:
                    mode = w.solver
                    self.try_world(f"{mode}.{name}", decl.default,
                                   lambda x, m=mode, n=name: w.settings_for(m).__setitem__(n, x),
                                   lambda m=mode, n=name: w.settings_for(m)[n])
        for label, attr, options in (("integrator", "integrator", ("euler", "symplectic_euler", "rk4")),
                                     ("broad phase", "broadphase", ("auto", "sweep", "quadtree", "brute")),
                                     ("narrow phase", "narrowphase", ("sat", "gjk"))):
            opts = list(options)
            cur = getattr(w, attr)
            ch, k = imgui.combo(label, opts.index(cur) if cur in opts else 0, opts)
            if ch:
                self.try_world(attr, opts[k], lambda v, a=attr: setattr(w, a, v), lambda a=attr: getattr(w, a))
        ch, v = imgui.checkbox("sleeping", w.sleeping)
        if ch:
            self.try_world("sleeping", v, lambda x: setattr(w, "sleeping", x), lambda: w.sleeping)
        info = app.info
        if info.get("stages"):
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(DIM, "stages: " + " > ".join(info["stages"]))
            imgui.pop_text_wrap_pos()

    # -- scene ---------------------------------------------------------------
    def scene_section(self, open_=False):
        app = self.app
        if open_:
            imgui.set_next_item_open(True)
        if not self.header("Scene", open_=False):
            return
        doc = app.doc
        imgui.text(f"file: {doc.path if doc.path else '(none)'}")
        if doc.dirty:
            imgui.same_line()
            imgui.text_colored(AMBER, "unsaved edits")
        files = scene_files()
        if imgui.begin_list_box("##scenes", imgui.ImVec2(-1, min(8, max(2, len(files))) * 20 + 6)):
            for f in files:
                cur = doc.path is not None and Path(doc.path).resolve() == f.resolve()
                clicked, _ = imgui.selectable(f.name, cur, imgui.SelectableFlags_.allow_double_click.value)
                if clicked and imgui.is_mouse_double_clicked(0):
                    app.request_open(f)
                elif clicked:
                    self.open_path = str(f)
            imgui.end_list_box()
        ch, self.open_path = imgui.input_text("##openpath", self.open_path)
        imgui.same_line()
        if imgui.button("Open") and self.open_path:
            app.request_open(Path(self.open_path))
        if imgui.button("Save (Ctrl+S)"):
            app.save()
        imgui.same_line()
        if not self.save_as_path:
            self.save_as_path = str(doc.path) if doc.path else "scenes/my_scene.json"
        if imgui.button("Save as"):
            app.save(Path(self.save_as_path))
        imgui.same_line()
        imgui.set_next_item_width(-1)
        _, self.save_as_path = imgui.input_text("##saveas", self.save_as_path)
        imgui.text_colored(DIM, "Or drop a .json scene file onto the window.")
        if app.scene_errors:
            imgui.push_text_wrap_pos(0)
            imgui.text_colored(RED, "Could not load the scene (the current one stays):")
            for line in app.scene_errors[:30]:
                imgui.bullet_text(line)
            imgui.pop_text_wrap_pos()
            if imgui.small_button("dismiss##sceneerr"):
                app.scene_errors = []

    # -- view ----------------------------------------------------------------
    def view_section(self):
        app = self.app
        if not self.header("View", open_=False):
            return
        o = app.overlays
        for label, attr in (("contacts and normals (C)", "contacts"), ("AABBs (B)", "aabbs"),
                            ("quadtree (Q)", "quadtree"),
                            ("velocity arrows (V)", "velocities"), ("centres of mass (M)", "com"),
                            ("springs", "springs")):
            ch, v = imgui.checkbox(label, getattr(o, attr))
            self.record(f"overlay:{attr}")
            if ch:
                setattr(o, attr, v)
        ch, self.show_stats = imgui.checkbox("stats window", self.show_stats)
        if imgui.button("Fit scene (F)"):
            app.fit()
        imgui.text_colored(DIM, "Pan: right/middle drag.  Zoom: wheel.  Undo: Ctrl+Z, redo: Ctrl+Shift+Z.")

    # -- stats ---------------------------------------------------------------
    def stats_window(self):
        app = self.app
        io = imgui.get_io()
        W, H = io.display_size.x, io.display_size.y
        imgui.set_next_window_pos(imgui.ImVec2(W - 8, 8), imgui.Cond_.first_use_ever.value, imgui.ImVec2(1, 0))
        imgui.set_next_window_size(imgui.ImVec2(STATS_W, 490), imgui.Cond_.first_use_ever.value)
        imgui.set_next_window_bg_alpha(0.82)
        expanded, _ = imgui.begin("Stats###stats", None)
        if expanded:
            ft = app.frame_times
            imgui.text(f"{app.fps:5.1f} fps   frame {ft['frame']:.2f} ms")
            imgui.text_colored(DIM, f"physics {ft['physics']:.2f}  upload {ft['upload']:.2f}  "
                                    f"draw {ft['draw']:.2f}  ui {ft['ui']:.2f} ms")
            info = app.info
            imgui.text_colored(DIM, f"bodies {info.get('bodies', 0)}  awake {info.get('awake', 0)}  "
                                    f"springs {info.get('springs', 0)}  pairs {info.get('contacts', 0)}")
            s = app.stats
            t, n = s.arrays()
            if n > 1:
                t = t - t[-1]
                size = imgui.ImVec2(-1, 72)
                self.plot("step time (ms)", t, [("step", s.get("step_ms"))], size)
                self.plot("energy (J)", t, [("kinetic", s.get("ke")), ("potential", s.get("pe")),
                                            ("total", s.get("ke") + s.get("pe"))], size)
                self.plot("momentum (kg m/s)", t, [("|p|", s.get("p"))], size)
                self.plot("max penetration (m)", t, [("depth", s.get("pen"))], size)
                self.plot("contacts", t, [("contacts", s.get("contacts"))], size)
        self.record_window("stats_window")
        imgui.end()

    def plot(self, title, t, series, size):
        flags = (implot.Flags_.no_mouse_text | implot.Flags_.no_menus | implot.Flags_.no_box_select).value
        if len(series) == 1:
            flags |= implot.Flags_.no_legend.value
        if implot.begin_plot(title, size, flags):
            implot.setup_axes("", "", implot.AxisFlags_.no_tick_labels.value,
                              implot.AxisFlags_.auto_fit.value)
            implot.setup_axis_limits(implot.ImAxis_.x1.value, float(t[0]), 0.0, implot.Cond_.always.value)
            if len(series) > 1:
                implot.setup_legend(implot.Location_.north_east.value, implot.LegendFlags_.horizontal.value)
            # at most ~120 points per line: llvmpipe pays for every plotted segment
            k = max(1, len(t) // 120)
            for label, y in series:
                implot.plot_line(label, np.ascontiguousarray(t[::k], dtype=np.float64),
                                 np.ascontiguousarray(np.asarray(y)[::k], dtype=np.float64))
            implot.end_plot()

    # -- messages & modals ----------------------------------------------------
    def messages(self):
        app = self.app
        now = time.monotonic()
        msgs = [m for m in app.messages if now - m[2] < 6.0]
        app.messages[:] = msgs
        if not msgs:
            return
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5 + PANEL_W * 0.5, io.display_size.y - 12),
                                  imgui.Cond_.always.value, imgui.ImVec2(0.5, 1.0))
        imgui.set_next_window_bg_alpha(0.85)
        flags = (imgui.WindowFlags_.no_decoration | imgui.WindowFlags_.always_auto_resize |
                 imgui.WindowFlags_.no_saved_settings | imgui.WindowFlags_.no_focus_on_appearing |
                 imgui.WindowFlags_.no_nav | imgui.WindowFlags_.no_inputs).value
        imgui.begin("##messages", None, flags)
        for text, error, _ in msgs[-5:]:
            imgui.text_colored(RED if error else GREEN, text)
        imgui.end()

    def scene_error_window(self):
        """A load that failed: its problems, until dismissed (the current scene stays)."""
        app = self.app
        if not app.scene_errors:
            return
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5 + 0.5 * (PANEL_W - STATS_W),
                                               io.display_size.y - 48),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 1.0))
        imgui.set_next_window_size_constraints(imgui.ImVec2(300, 0), imgui.ImVec2(560, 400))
        flags = (imgui.WindowFlags_.always_auto_resize | imgui.WindowFlags_.no_saved_settings |
                 imgui.WindowFlags_.no_collapse).value
        imgui.begin("Scene not loaded###sceneerr", None, flags)
        imgui.push_text_wrap_pos(imgui.get_cursor_pos_x() + 520)
        imgui.text_colored(RED, "Could not load the scene; the current one stays.")
        for line in app.scene_errors[:20]:
            imgui.bullet_text(line)
        if len(app.scene_errors) > 20:
            imgui.text_colored(DIM, f"... and {len(app.scene_errors) - 20} more")
        imgui.pop_text_wrap_pos()
        if imgui.button("Dismiss"):
            app.scene_errors = []
        a, b = imgui.get_window_pos(), imgui.get_window_size()
        app.ui_rects["scene_errors"] = (a.x, a.y, a.x + b.x, a.y + b.y)
        imgui.end()

    def confirm(self, message, on_discard, on_save=None):
        self.pending_confirm = (message, on_discard, on_save)

    def modals(self):
        if self.pending_confirm is not None and not imgui.is_popup_open("Unsaved edits"):
            imgui.open_popup("Unsaved edits")
        io = imgui.get_io()
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5, io.display_size.y * 0.4),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 0.5))
        opened, _ = imgui.begin_popup_modal("Unsaved edits", None, imgui.WindowFlags_.always_auto_resize.value)
        if opened:
            msg, on_discard, on_save = self.pending_confirm or ("", None, None)
            imgui.text(msg)
            imgui.text_colored(AMBER, "The scene has unsaved edits.")
            if on_save is not None and imgui.button("Save, then continue"):
                self.pending_confirm = None
                imgui.close_current_popup()
                on_save()
                imgui.same_line()
            elif on_save is not None:
                imgui.same_line()
            if imgui.button("Discard edits"):
                self.pending_confirm = None
                imgui.close_current_popup()
                on_discard()
            imgui.same_line()
            if imgui.button("Cancel") or imgui.is_key_pressed(imgui.Key.escape):
                self.pending_confirm = None
                imgui.close_current_popup()
            imgui.end_popup()
        if self.autosave_offer is not None and not imgui.is_popup_open("Restore autosave?"):
            imgui.open_popup("Restore autosave?")
        imgui.set_next_window_pos(imgui.ImVec2(io.display_size.x * 0.5, io.display_size.y * 0.4),
                                  imgui.Cond_.appearing.value, imgui.ImVec2(0.5, 0.5))
        opened, _ = imgui.begin_popup_modal("Restore autosave?", None, imgui.WindowFlags_.always_auto_resize.value)
        if opened:
            path, when, origin = self.autosave_offer or (None, 0, None)
            imgui.text("Stelkropp did not exit cleanly last time.")
            imgui.text(f"An autosave from {time.strftime('%Y-%m-%d %H:%M', time.localtime(when))} exists"
                       + (f" (of {origin})." if origin else "."))
            if imgui.button("Restore it"):
                self.autosave_offer = None
                imgui.close_current_popup()
                self.app.restore_autosave(path, origin)
            imgui.same_line()
            if imgui.button("Discard it"):
                self.autosave_offer = None
                imgui.close_current_popup()
                self.app.autosaver.discard()
            imgui.end_popup()
