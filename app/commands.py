"""Undo/redo: every edit and creation in the sandbox is a command.

Commands refer to bodies, springs and joints through :class:`Ref` holders, so a
body that is deleted and brought back by undo (as a new handle) is still the body
that later commands in the history talk about.
"""
from __future__ import annotations

import time

import numpy as np

import physics

from .fixture_specs import BODY_FIELDS, body_spec, make_body
from .joint_specs import joint_fields, make_joint, param_value


class Ref:
    """A stable reference to a body, spring or joint across delete/undo cycles."""
    __slots__ = ("obj",)

    def __init__(self, obj):
        self.obj = obj


class Refs:
    """Handle id -> Ref, kept per world (bodies, springs and joints number their ids apart)."""

    def __init__(self):
        self._bodies: dict[int, Ref] = {}
        self._springs: dict[int, Ref] = {}
        self._joints: dict[int, Ref] = {}

    def _table(self, item):
        if isinstance(item, physics.Spring):
            return self._springs
        return self._joints if isinstance(item, physics.Joint) else self._bodies

    def of(self, item) -> Ref:
        table = self._table(item)
        r = table.get(item.id)
        if r is None:
            r = table[item.id] = Ref(item)
        return r

    def rebind(self, ref: Ref, item) -> None:
        ref.obj = item
        self._table(item)[item.id] = ref


SPRING_FIELDS = ("anchor_a", "anchor_b", "stiffness", "damping", "rest_length", "name")


def spring_spec(sp, refs: Refs) -> dict:
    return {"a": refs.of(sp.body_a), "b": None if sp.body_b is None else refs.of(sp.body_b),
            **{f: getattr(sp, f) for f in SPRING_FIELDS}}


def joint_spec(j, refs: Refs) -> dict:
    return {"kind": j.kind, "a": refs.of(j.body_a), "b": None if j.body_b is None else refs.of(j.body_b),
            "fields": joint_fields(j)}


def make_joint_from(world, spec: dict):
    return make_joint(world, spec["kind"], spec["a"].obj, None if spec["b"] is None else spec["b"].obj,
                      spec["fields"])


def make_spring(world, spec: dict):
    return world.add_spring(spec["a"].obj, None if spec["b"] is None else spec["b"].obj,
                            anchor_a=spec["anchor_a"], anchor_b=spec["anchor_b"], stiffness=spec["stiffness"],
                            damping=spec["damping"], rest_length=spec["rest_length"], name=spec["name"])


class Command:
    label = ""
    #: made by the sandbox itself (the world bound's removals), not by the user: it can be undone,
    #: but it does not make the document unsaved
    automatic = False
    stamp = 0          # set by History when recorded (which edit the document is at)

    def do(self, app) -> None:
        raise NotImplementedError

    def undo(self, app) -> None:
        raise NotImplementedError

    def merge(self, other) -> bool:
        return False

    def changes_nothing(self) -> bool:
        """True for a setting set to the value it has (Enter in a field left as it was, or emptied:
        imgui then keeps the old value): not an edit, so the scene is not marked unsaved."""
        return False


def same_value(a, b) -> bool:
    """Would setting ``b`` where ``a`` is change nothing?  Numbers and vectors compare by value
    (a tuple typed over a float32 array), anything else with ``==``."""
    try:
        x, y = np.asarray(a), np.asarray(b)
        if x.dtype.kind in "biuf" and y.dtype.kind in "biuf":
            return x.shape == y.shape and bool(np.array_equal(x, y))
        return type(a) is type(b) and bool(a == b)
    except (TypeError, ValueError):
        return False


class AddBody(Command):
    def __init__(self, spec: dict, label="create body"):
        self.spec = spec
        self.ref: Ref | None = None
        self.label = label

    def do(self, app):
        b = make_body(app.world, self.spec)
        if self.ref is None:
            self.ref = app.refs.of(b)
        else:
            app.refs.rebind(self.ref, b)

    def undo(self, app):
        b = self.ref.obj
        self.spec = body_spec(b)
        app.deselect(b)
        app.world.remove(b)


class RemoveBodies(Command):
    """Delete bodies and the springs and joints attached to them (not the tools' own)."""

    def __init__(self, app, bodies):
        self.refs = [app.refs.of(b) for b in bodies]
        self.label = f"delete {len(self.refs)} bodies" if len(self.refs) != 1 else "delete body"
        self.specs = []
        self.springs = []
        self.joints = []

    def do(self, app):
        objs = {r.obj for r in self.refs}
        self.specs = [body_spec(r.obj) for r in self.refs]
        self.springs = [(app.refs.of(sp), spring_spec(sp, app.refs)) for sp in app.world.springs
                        if (sp.body_a in objs or sp.body_b in objs) and not app.is_tool_spring(sp)]
        self.joints = [(app.refs.of(j), joint_spec(j, app.refs)) for j in app.world.joints
                       if (j.body_a in objs or j.body_b in objs) and not app.is_tool_joint(j)]
        for r, _ in self.joints:
            app.deselect(r.obj)
        for r in self.refs:
            app.deselect(r.obj)
            app.world.remove(r.obj)

    def undo(self, app):
        for r, spec in zip(self.refs, self.specs):
            app.refs.rebind(r, make_body(app.world, spec))
        for r, spec in self.springs:
            app.refs.rebind(r, make_spring(app.world, spec))
        for r, spec in self.joints:
            app.refs.rebind(r, make_joint_from(app.world, spec))


class AddSpring(Command):
    label = "create spring"

    def __init__(self, spec: dict):
        self.spec = spec
        self.ref: Ref | None = None

    def do(self, app):
        sp = make_spring(app.world, self.spec)
        if self.ref is None:
            self.ref = app.refs.of(sp)
        else:
            app.refs.rebind(self.ref, sp)

    def undo(self, app):
        sp = self.ref.obj
        self.spec = spring_spec(sp, app.refs)
        app.deselect(sp)
        app.world.remove(sp)


class RemoveSpring(Command):
    label = "delete spring"

    def __init__(self, app, sp):
        self.ref = app.refs.of(sp)
        self.spec = None

    def do(self, app):
        self.spec = spring_spec(self.ref.obj, app.refs)
        app.deselect(self.ref.obj)
        app.world.remove(self.ref.obj)

    def undo(self, app):
        app.refs.rebind(self.ref, make_spring(app.world, self.spec))


class AddJoint(Command):
    """Create a joint from a ``joint_spec``-shaped dict (kind, a, b Refs, add_joint fields)."""

    def __init__(self, spec: dict, label=None):
        self.spec = spec
        self.ref: Ref | None = None
        self.label = label or f"create {spec['kind']} joint"

    def do(self, app):
        j = make_joint_from(app.world, self.spec)
        if self.ref is None:
            self.ref = app.refs.of(j)
        else:
            app.refs.rebind(self.ref, j)

    def undo(self, app):
        j = self.ref.obj
        self.spec = joint_spec(j, app.refs)
        app.deselect(j)
        app.world.remove(j)


class RemoveJoint(Command):
    label = "delete joint"

    def __init__(self, app, j):
        self.ref = app.refs.of(j)
        self.spec = None

    def do(self, app):
        self.spec = joint_spec(self.ref.obj, app.refs)
        app.deselect(self.ref.obj)
        app.world.remove(self.ref.obj)

    def undo(self, app):
        app.refs.rebind(self.ref, make_joint_from(app.world, self.spec))


class SetProperty(Command):
    """``item.field = value`` (a body, spring or joint).  Consecutive edits of one field merge."""

    def __init__(self, app, item, field: str, value, old=None):
        self.ref = app.refs.of(item)
        self.field = field
        self.new = value
        if old is None:    # a distance joint's `length` reads the distance now; its parameter is the rest length
            old = param_value(item, field) if isinstance(item, physics.Joint) else getattr(item, field)
        self.old = old
        self.t = time.monotonic()
        self.label = f"set {field}"

    def do(self, app):
        setattr(self.ref.obj, self.field, self.new)   # ValueError propagates: nothing changed

    def undo(self, app):
        setattr(self.ref.obj, self.field, self.old)

    def changes_nothing(self) -> bool:
        return same_value(self.old, self.new)

    def merge(self, other) -> bool:
        if (isinstance(other, SetProperty) and other.ref is self.ref and other.field == self.field
                and other.t - self.t < 1.5):
            self.new = other.new
            self.t = other.t
            return True
        return False


class SetWorld(Command):
    """A world-level setting: solver, integrator, gravity, a solver setting ..."""

    def __init__(self, getter, setter, value, label):
        self.getter, self.setter = getter, setter
        self.new = value
        self.old = getter()
        self.label = label
        self.t = time.monotonic()

    def do(self, app):
        self.setter(self.new)

    def undo(self, app):
        self.setter(self.old)

    def changes_nothing(self) -> bool:
        return same_value(self.old, self.new)

    def merge(self, other) -> bool:
        if isinstance(other, SetWorld) and other.label == self.label and other.t - self.t < 1.5:
            self.new = other.new
            self.t = other.t
            return True
        return False


class SetFixture(Command):
    """``fixture.field = value`` on the ``index``-th fixture of a body (held by its Ref, so the
    edit survives the body being deleted and brought back).  Consecutive edits merge."""

    def __init__(self, app, body, index: int, field: str, value):
        self.ref = app.refs.of(body)
        self.index, self.field, self.new = index, field, value
        self.old = getattr(body.fixtures[index], field)
        self.t = time.monotonic()
        self.label = f"set fixture {index} {field}"

    def do(self, app):
        setattr(self.ref.obj.fixtures[self.index], self.field, self.new)   # ValueError: nothing changed

    def undo(self, app):
        setattr(self.ref.obj.fixtures[self.index], self.field, self.old)

    def changes_nothing(self) -> bool:
        return same_value(self.old, self.new)

    def merge(self, other) -> bool:
        if (isinstance(other, SetFixture) and other.ref is self.ref and (other.index, other.field) ==
                (self.index, self.field) and other.t - self.t < 1.5):
            self.new, self.t = other.new, other.t
            return True
        return False


class Group(Command):
    def __init__(self, commands, label):
        self.commands = list(commands)
        self.label = label

    def do(self, app):
        done = []
        try:
            for c in self.commands:
                c.do(app)
                done.append(c)
        except Exception:
            for c in reversed(done):
                c.undo(app)
            raise

    def undo(self, app):
        for c in reversed(self.commands):
            c.undo(app)


class History:
    def __init__(self, limit: int = 500):
        self.done: list[Command] = []
        self.undone: list[Command] = []
        self.limit = limit
        self.version = 0   # bumps on every change (caches and the timeline watch it)
        self._stamps = 0   # each user's edit (and each merge into one) gets a new stamp

    def execute(self, app, cmd: Command) -> None:
        """Run a command and record it; a ValueError from the core leaves nothing recorded, nor
        does a setting that changes nothing."""
        if cmd.changes_nothing():
            return
        cmd.do(app)
        self.undone.clear()
        if self.done and self.done[-1].merge(cmd):
            cmd = self.done[-1]          # its content changed: a new stamp below
        else:
            self.done.append(cmd)
            if len(self.done) > self.limit:
                self.done.pop(0)
        self._stamps += 1
        cmd.stamp = self._stamps
        self.version += 1

    def undo(self, app) -> str | None:
        if not self.done:
            return None
        cmd = self.done.pop()
        cmd.undo(app)
        self.undone.append(cmd)
        self.version += 1
        return cmd.label

    def redo(self, app) -> str | None:
        if not self.undone:
            return None
        cmd = self.undone.pop()
        cmd.do(app)
        self.done.append(cmd)
        self.version += 1
        return cmd.label

    def state(self) -> int:
        """Which of the user's edits the document is at: the stamp of the newest one not undone
        (0: none).  Undo back to a saved state makes it clean again; the sandbox's own edits
        (``automatic``) do not count."""
        return next((c.stamp for c in reversed(self.done) if not c.automatic), 0)

    def clear(self):
        self.done.clear()
        self.undone.clear()
