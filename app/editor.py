"""The editor state: the open document, the selection and hover, the tools, and the edits
(every change goes through a command, so it can be undone).  No windowing or drawing here."""
from __future__ import annotations

import time

import numpy as np

import physics
from physics import joint_params as jp

from .body_colors import SetColor, checked_rgb, from_metadata, to_metadata
from .clipboard import Paste, copy_bodies, paste_offset, selected_bodies
from .commands import Group, RemoveBodies, RemoveJoint, RemoveSpring, SetProperty, SetWorld
from .document import Document
from .field_bounds import checked
from .lasers import Lasers
from .picking import joint_near
from .render.decor import Decor
from .snapping import Snap
from .tools import TOOLS, ToolOptions
from .tracers import Tracers

#: the step rates the sandbox accepts (Hz): below 10 Hz contacts at walking speeds tunnel; above
#: 1000 Hz a frame (at most 4 steps) covers under 7 ms of simulated time, a slide show
STEP_RATE = (10.0, 1000.0)
HINT_SECONDS = 5.0
REFUSED = object()         # what Editor.bounded returns for a value out of its field's bounds
MOTOR_PINS_MAX = 500      # more joints than this: motors are drawn as plain pins (a Python loop a frame)


def motor_pins(world) -> dict:
    """{joint id: angle of the body its motor turns} for the joints whose angular motor is on
    (hinges, wheels: a wheel's motor turns body_b, the hub; the others' body_a)."""
    joints = world.joints
    if len(joints) > MOTOR_PINS_MAX:
        return {}
    return {j.id: (j.body_b.angle if j.kind == "wheel" else j.body_a.angle) for j in joints
            if jp.KINDS[j.kind].motor == "angular" and j.max_motor_torque > 0}


class Editor:
    """What the user is editing.  ``camera`` is read for on-screen distances (click radii);
    ``notices`` receives messages.  ``on_document(world, path, keep_camera)`` callbacks run when
    a new document replaces the current one, ``on_mode(solver, integrator)`` after a mode switch."""

    def __init__(self, world, path, notices, camera):
        self.notices = notices
        self.camera = camera
        self.doc = Document(world, path)
        self.selection: list = []
        self.hovered = None
        self.cursor = np.zeros(2)              # the world point under the pointer (m)
        self.tool_springs: set[int] = set()    # springs the tools made: not the user's
        self.tool_joints: set[int] = set()     # joints the tools made (the mouse drag's): not the user's
        self.tool_options = ToolOptions()
        self.colors = from_metadata(world, self.doc.refs)   # Ref -> (r, g, b): bodies' own colours
        self.snap = Snap()                     # grid and angle snapping (G)
        self.clipboard = None                  # what Ctrl+C copied (app.clipboard.copy_bodies)
        self.follow = None                     # Ref of the body the camera follows (L), or None
        self.tracers = Tracers()               # trails behind points of bodies (tracer tool, context menu)
        self.lasers = Lasers()                 # the laser tool's emitters and their beams
        self.tracers.from_metadata(world, self.doc.refs)      # those the scene file has
        self.lasers.from_metadata(world, self.doc.refs)
        self.tools = {cls.name: cls(self) for cls in TOOLS}
        self.tool_names = [cls.name for cls in TOOLS]
        self.tool = self.tools["select"]
        self.edit_error = ""                   # the last refused edit, shown beside its field
        self.on_refusal: list = []             # called on a refusal (the panels note which field)
        self._hint = None                      # (text, world point, time, error) shown at the pointer
        self.on_document: list = []
        self.on_mode: list = []
        self.mode_gate = None                  # asked before a mode, integrator or broad phase change

    @property
    def world(self):
        return self.doc.world

    @property
    def refs(self):
        return self.doc.refs

    def notify(self, text, error=False):
        self.notices.notify(text, error)

    def hint(self, text, at=None, error=True):
        """Say why an input was refused (or what was done instead) next to where the user is
        looking: world point ``at`` (default: the pointer), for HINT_SECONDS; also a message."""
        p = np.array(self.cursor if at is None else at, dtype=np.float64)
        self._hint = (text, p, time.monotonic(), error)
        self.notify(text, error)

    def current_hint(self):
        """(text, world point, is_error) of the hint still shown, or None."""
        h = self._hint
        if h is None or time.monotonic() - h[2] > HINT_SECONDS:
            return None
        return h[0], h[1], h[3]

    def hint_text(self):
        h = self.current_hint()
        return h[0] if h else None

    def set_document(self, world, path, keep_camera=False):
        """Replace the document (open, reset, restore); the history starts empty."""
        self.tool.cancel()
        self.tool_springs.clear()
        self.tool_joints.clear()
        self.selection = []
        self.hovered = None
        self.follow = None
        self.edit_error = ""           # a refusal in the last scene says nothing about this one
        self.doc = Document(world, path)
        self.colors = from_metadata(world, self.doc.refs)   # the file's colours (a reset's too)
        self.tracers.reset(world, self.doc.refs, keep=keep_camera)   # a reset clears the trails
        self.lasers.reset(world, self.doc.refs, keep=keep_camera)    # a reset keeps the lasers
        for cb in self.on_document:
            cb(world, path, keep_camera)

    # -- edits -------------------------------------------------------------------
    def execute(self, cmd):
        """Run and record a command; ValueError from the core propagates with nothing changed."""
        self.doc.history.execute(self, cmd)

    def create(self, cmd):
        """Run a creating command, select what it made; a refusal becomes a message."""
        try:
            self.execute(cmd)
        except ValueError as exc:
            self.hint(f"refused: {exc}")
            return
        obj = getattr(cmd, "ref", None)
        if obj is not None:
            self.select(obj.obj)

    def set_world(self, label, value, setter, getter) -> bool:
        """A world-level setting through an undoable command; a refusal is shown, not raised."""
        try:
            self.execute(SetWorld(getter, setter, value, label))
            self.edit_error = ""
            return True
        except (ValueError, KeyError) as exc:
            self.refused(exc)
            return False

    def refused(self, exc) -> None:
        """A refused edit: beside the field and as a message."""
        self.refuse(str(exc))
        self.notify(f"refused: {exc}", error=True)

    def bounded(self, field, value):
        """``value`` if the sandbox's bounds for ``field`` take it (``field_bounds.checked``), else
        REFUSED, the refusal shown."""
        try:
            return checked(field, value)
        except ValueError as exc:
            self.refused(exc)
            return REFUSED

    def set_property(self, item, field, value) -> bool:
        """``item.field = value`` for a body, spring or joint, undoable; a refusal (the sandbox's
        bounds first: ``bounded``) is shown, not raised."""
        value = self.bounded(field, value)
        if value is REFUSED:
            return False
        return self.try_edit(SetProperty(self, item, field, value), field)

    def try_edit(self, cmd, label: str) -> bool:
        """Run an editing command; a refusal sets ``edit_error`` and is shown as ``label``'s, not raised."""
        try:
            self.execute(cmd)
            self.edit_error = ""
            return True
        except ValueError as exc:
            self.refuse(f"refused: {exc}")
            self.notify(f"{label} {self.edit_error}", error=True)
            return False

    def refuse(self, text, at=None):
        """Show ``text`` beside the field just drawn, or beside the field at window rect ``at``."""
        self.edit_error = text
        for cb in self.on_refusal:
            cb(at)

    def drop_shape(self, name, p):
        """A palette button dropped at world point ``p``: the tool's default body there."""
        tool = self.tools.get(name)
        if tool is not None and tool.droppable:
            tool.drop(p)

    def undo(self):
        self.tool.cancel()
        try:
            label = self.doc.history.undo(self)
        except ValueError as exc:
            self.notify(f"undo failed: {exc}", error=True)
            return
        self.notify(f"undo: {label}" if label else "nothing to undo")

    def redo(self):
        self.tool.cancel()
        try:
            label = self.doc.history.redo(self)
        except ValueError as exc:
            self.notify(f"redo failed: {exc}", error=True)
            return
        self.notify(f"redo: {label}" if label else "nothing to redo")

    def delete_selection(self):
        items = [s for s in self.selection if s.alive]
        bodies = [s for s in items if isinstance(s, physics.Body)]

        def free(s):        # not going with a deleted body anyway
            return not any(s.body_a is b or s.body_b is b for b in bodies)
        springs = [s for s in items if isinstance(s, physics.Spring) and free(s)]
        joints = [s for s in items if isinstance(s, physics.Joint) and free(s)]
        cmds = [RemoveSpring(self, s) for s in springs] + [RemoveJoint(self, j) for j in joints]
        if bodies:
            cmds.append(RemoveBodies(self, bodies))
        if cmds:
            self.tool.cancel()
            self.execute(Group(cmds, "delete") if len(cmds) > 1 else cmds[0])

    def duplicate_selection(self):
        """Ctrl+D: a copy of the selected bodies beside them, with the springs and joints among
        them (or to the world) copied too; the copy is selected."""
        bodies = selected_bodies(self.selection)
        if not bodies:
            return
        self.tool.cancel()
        cmd = Paste(copy_bodies(self.world, bodies, self.tool_springs, self.tool_joints), (0.6, 0.6), "duplicate")
        self.execute(cmd)
        self.selection = cmd.bodies()

    def copy_selection(self):
        """Ctrl+C: the selected bodies and the springs among them to the clipboard."""
        bodies = selected_bodies(self.selection)
        if not bodies:
            self.hint("nothing to copy: select bodies first (click, shift-click or drag a box)", error=False)
            return
        self.clipboard = copy_bodies(self.world, bodies, self.tool_springs, self.tool_joints)
        self.notify(f"copied {len(bodies)} bod{'y' if len(bodies) == 1 else 'ies'} (Ctrl+V pastes at the pointer)")

    def paste(self):
        """Ctrl+V: the clipboard's copy with its centre at the pointer (snapped), selected."""
        if not self.clipboard:
            self.hint("nothing to paste: copy bodies with Ctrl+C first", error=False)
            return
        cmd = Paste(self.clipboard, paste_offset(self.clipboard, self.snap.point(self.cursor)))
        try:
            self.execute(cmd)
        except ValueError as exc:
            self.hint(f"paste refused: {exc}")
            return
        self.selection = cmd.bodies()

    def toggle_follow(self):
        """L: the camera follows the selected body (again: stops)."""
        if self.follow is not None:
            self.follow = None
            self.notify("camera: no longer following")
            return
        bodies = selected_bodies(self.selection)
        if not bodies:
            self.hint("select a body for the camera to follow", error=False)
            return
        self.follow = self.refs.of(bodies[-1])
        self.notify(f"camera follows {bodies[-1].name or bodies[-1].id} (L again: stop)")

    def toggle_static(self):
        bodies = [s for s in self.selection if isinstance(s, physics.Body) and s.alive]
        if bodies:
            self.tool.cancel()
            cmds = [SetProperty(self, b, "kind", "dynamic" if b.kind != "dynamic" else "static") for b in bodies]
            self.execute(Group(cmds, "toggle static/dynamic"))

    def switch_solver(self, mode, now=False):
        """Switch the solver mode (undoable).  The switch wakes every body: a sleeping pile would
        otherwise show nothing of the new mode (until the core wakes the world itself).
        ``mode_gate(mode)`` is asked first unless ``now``: True if it holds the switch (the
        window's ``app.mode_switch``: a mode not compiled yet switches once it is ready; the
        integrator and the broad phase ask it the same way)."""
        if not now and self.mode_gate is not None and self.mode_gate(mode):
            return
        w = self.world
        if mode == w.solver:
            return

        def setter(m):
            w.solver = m
            w.wake_all()
        try:
            self.execute(SetWorld(lambda: w.solver, setter, mode, "solver"))
        except (ValueError, ImportError) as exc:
            self.notify(f"solver {mode}: {exc}", error=True)
            return
        for cb in self.on_mode:
            cb(mode, w.integrator)
        self.notify(f"solver: {mode}")
        self._say_unused_integrator()

    def set_integrator(self, name, now=False) -> bool:
        """The integrator (undoable), asking ``mode_gate`` first as ``switch_solver`` does."""
        return self._set_stepping("integrator", name, now)

    def set_broadphase(self, name, now=False) -> bool:
        """The broad phase (undoable), asking ``mode_gate`` first as ``switch_solver`` does."""
        return self._set_stepping("broadphase", name, now)

    def _set_stepping(self, attr, value, now) -> bool:
        """A world setting that picks the compiled step (integrator, broad phase): unless ``now``,
        ``mode_gate`` may hold it until its kernels are loaded (True: held, or nothing to do)."""
        if not now and self.mode_gate is not None and self.mode_gate(**{attr: value}):
            return True
        w = self.world
        if getattr(w, attr) == value:
            return True
        done = self.set_world(attr, value, lambda v: setattr(w, attr, v), lambda: getattr(w, attr))
        if done and attr == "integrator":
            self._say_unused_integrator()
        return done

    def _say_unused_integrator(self) -> None:
        """Where the open mode integrates its own way, say that the integrator picked does nothing
        in it (the core warns on the console; the user looks at the window)."""
        w = self.world
        if physics.solvers.unused_integrator(w.solver, w.integrator):
            mode = physics.solvers.get(w.solver)
            self.notify(f"{w.solver} does not use integrator {w.integrator}: it integrates its own way "
                        f"({mode.integration[1]})")

    def set_step_rate(self, hz) -> bool:
        """The step rate in Hz (dt = 1/hz), within STEP_RATE; out of range is refused with a message."""
        lo, hi = STEP_RATE
        if not (isinstance(hz, (int, float)) and lo <= hz <= hi):
            self.refuse(f"step rate must be between {lo:g} and {hi:g} Hz (got {hz:g} Hz)")
            self.notify(f"refused: {self.edit_error}", error=True)
            return False
        w = self.world
        return self.set_world("dt", 1.0 / hz, lambda v: setattr(w, "dt", v), lambda: w.dt)

    # -- selection and tools -----------------------------------------------------------
    def select(self, item, add=False):
        """Select ``item`` (None: nothing); ``add`` toggles it in the current selection.  A laser
        emitter picked before is let go (the inspector shows one thing)."""
        self.tools["laser"].selected = None
        if item is None:
            self.selection = []
        elif add:
            if item in self.selection:
                self.selection.remove(item)
            else:
                self.selection.append(item)
        else:
            self.selection = [item]
        self.edit_error = ""

    def deselect(self, item):
        self.selection = [s for s in self.selection if s is not item]
        if self.hovered is item:
            self.hovered = None

    def is_tool_spring(self, sp) -> bool:
        return sp.id in self.tool_springs

    def is_tool_joint(self, j) -> bool:
        return j.id in self.tool_joints

    def joint_near(self, p, lines=True):
        """The user's joint at world point ``p`` (its pin within a few pixels, or with ``lines``
        its drawn lines), or None."""
        return joint_near(self.world, p, self.camera.scale, self.tool_joints, lines)

    def spring_near(self, p, px=7.0):
        """The user's spring closest to world point ``p`` within ``px`` screen pixels, or None."""
        springs = [s for s in self.world.springs if s.id not in self.tool_springs]
        best, bd = None, px / self.camera.scale
        p = np.asarray(p)
        for sp in springs:
            a, b = (np.array(e) for e in sp.endpoints())
            d = b - a
            t = np.clip(np.dot(p - a, d) / max(np.dot(d, d), 1e-12), 0, 1)
            dist = np.hypot(*(a + t * d - p))
            if dist < bd:
                best, bd = sp, dist
        return best

    def set_tool(self, name):
        if self.tool.name != name:
            self.tool.cancel()
            self.tool = self.tools[name]

    def set_color(self, body, rgb):
        """Give ``body`` its own fill colour (r, g, b in [0, 1]; None: the palette's again).
        Undoable; ValueError names the field if a component is out of range."""
        rgb = None if rgb is None else checked_rgb(rgb)
        if rgb != self.colors.get(self.refs.of(body)):
            self.execute(SetColor(self, body, rgb))

    def sync_app_data(self):
        """Before a save: the colours, lasers and tracers go where the scene saver reads them
        (world.metadata)."""
        to_metadata(self.world, self.colors)
        self.lasers.to_metadata(self.world)
        self.tracers.to_metadata(self.world)

    def color_of(self, body):
        return self.colors.get(self.refs.of(body))

    def decor(self) -> Decor:
        """Selection, hover and the active tool's previews for this frame's drawing."""
        d = Decor()
        for s in self.selection:
            if not s.alive:
                continue
            if isinstance(s, physics.Body):
                d.selected_bodies.add(s.id)
            elif isinstance(s, physics.Joint):
                d.selected_joints.add(s.id)
            else:
                d.selected_springs.add(s.id)
        if self.hovered is not None and self.hovered.alive:
            d.hovered_body = self.hovered.id
        d.colors = {r.obj.id: c for r, c in self.colors.items() if r.obj is not None and r.obj.alive}
        d.hidden_springs |= self.tool_springs
        d.hidden_joints |= self.tool_joints
        d.motor_pins = motor_pins(self.world)
        self.lasers.decorate(d, self.tools["laser"].selected)
        self.tool.decorate(d, tuple(self.cursor))
        return d
