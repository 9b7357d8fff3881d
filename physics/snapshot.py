"""World snapshots: the complete dynamic state of a world, copied out and written back.

A step reads (and a restore must therefore put back) more than the bodies' positions and
velocities:

* every row of the body, fixture, spring and joint tables and the vertex pool (kinds,
  masses, user forces, sleep timers and island labels, joint impulses and break flags, ...),
  plus each fixture handle's shape (``Body.set_shape`` keeps the fixture's id);
* both contact tables with their per-point carried state (``jn``/``jt`` warm starts,
  penalty ``stick``/``approach``) and the span bookkeeping that decides whether the next
  solve rescales or drops them (store/contacts.py ``adopt``); the joints' likewise;
* the world's settings (gravity, dt, solver, integrator, tolerances, every mode's
  parameters), its time and step counter;
* the pipeline's memory between steps: whether the world was all asleep (a sleeping world
  skips the step), the island label counter, the energy guard's reference and the step
  context (the last step's dt, which ``contacts()`` scales soft_step's impulses by).

Per-step scratch (solver row arrays, the broad phase's sort order, the joint system) is not
kept: every step rebuilds it from the tables, and the joint system is rebuilt after a
restore (the joint table's version is bumped).  There is no random number generator.

A restore needs the same bodies, fixtures, springs and joints (by id) as the snapshot:
adding or removing any since raises ValueError naming what differs.  Their order in the
tables may differ (a removal swaps rows) and is restored.
"""
from __future__ import annotations

import math

import numpy as np

from . import solvers
from .store import CONTACT_FIELDS

#: the world's private setting attributes a step reads (restored without their setters, which
#: would wake bodies and so change the state being restored)
WORLD_FIELDS = ("_gravity", "_dt", "_solver_name", "_integrator", "_broadphase", "_narrowphase",
                "_sleeping", "_linear_slop", "_speculative_distance", "_sleep_linear", "_sleep_angular",
                "_time_to_sleep", "_max_pairs", "_energy_guard", "_time", "steps")
#: the energy guard's memory between steps (physics/step/energy_guard.py)
GUARD_FIELDS = ("last", "e0", "s0", "push", "active", "start")
TABLES = ("bodies", "fixtures", "springs", "joints")


class Snapshot:
    """The dynamic state of a :class:`~physics.World` at one moment (``world.snapshot()``).

    Plain data (numpy arrays, numbers, shapes): it pickles, and it does not refer to the
    world it came from.  Pass it to :meth:`~physics.World.restore` to go back to that moment.
    ``time`` and ``steps`` are the world's at the moment it was taken.
    """

    __slots__ = ("tables", "next_ids", "verts", "contacts", "joint_meta", "shapes", "world", "settings",
                 "pipeline", "guard", "events")

    @property
    def time(self) -> float:
        """The world's simulated time (s) when the snapshot was taken."""
        return float(self.world["_time"])

    @property
    def steps(self) -> int:
        """The world's step counter when the snapshot was taken."""
        return int(self.world["steps"])

    def __getstate__(self):
        return {k: getattr(self, k) for k in self.__slots__}

    def __setstate__(self, state):
        for k, v in state.items():
            setattr(self, k, v)

    def __repr__(self):
        n = len(self.tables["bodies"]["id"])
        return f"<Snapshot t={self.time:.3f} steps={self.steps} bodies={n}>"


def _rows(table) -> dict:
    n = table.n
    return {k: a[:n].copy() for k, a in table.arrays.items()}


def take(world) -> Snapshot:
    """Copy the dynamic state of ``world`` into a new Snapshot."""
    st = world._store
    snap = Snapshot()
    snap.tables = {name: _rows(getattr(st, name)) for name in TABLES}
    snap.next_ids = {name: getattr(st, name)._next_id for name in TABLES}
    vp = st.verts
    snap.verts = ({k: a[: vp.top].copy() for k, a in vp.arrays.items()}, vp.top, vp.live)
    c = st.contacts
    snap.contacts = ({k: getattr(c.cur, k)[: c.n].copy() for k in CONTACT_FIELDS},
                     {k: getattr(c.prev, k)[: c.n_prev].copy() for k in CONTACT_FIELDS},
                     c.n, c.n_prev, c.span, c.span_step)
    j = st.joints
    snap.joint_meta = (j.span, j.span_step, list(j.broken_last_step), set(j._reported))
    snap.shapes = {fid: fx._shape for fid, fx in world._fixture_handles.items()}
    snap.world = {k: getattr(world, k) for k in WORLD_FIELDS}
    snap.world["_gravity"] = np.array(world._gravity)
    snap.settings = {name: dict(vals.values) for name, vals in world._settings.items()}
    p = world._pipeline
    snap.pipeline = (p.n_awake, int(p._islands.label[0]), p.ctx.array.copy())
    snap.guard = {k: getattr(p._guard, k, math.nan) for k in GUARD_FIELDS}
    snap.events = p.events.state()  # touching and overlap sets: the next step's events follow from them
    return snap


def check(world, snap) -> None:
    """ValueError naming each table whose ids differ between ``world`` and ``snap``."""
    if not isinstance(snap, Snapshot):
        raise ValueError(f"restore: expected a Snapshot from world.snapshot(), got {type(snap).__name__}")
    problems = []
    for name in TABLES:
        t = getattr(world._store, name)
        now = set(int(i) for i in t.arrays["id"][: t.n])
        then = set(int(i) for i in snap.tables[name]["id"])
        if now != then:
            added, gone = sorted(now - then), sorted(then - now)
            what = [f"{len(added)} added (ids {added[:5]})"] if added else []
            what += [f"{len(gone)} removed (ids {gone[:5]})"] if gone else []
            problems.append(f"{name}: {', '.join(what)}")
    if problems:
        raise ValueError("restore: the world's topology changed since the snapshot (" + "; ".join(problems)
                         + "); a snapshot restores only into a world with the same bodies, fixtures, "
                         "springs and joints")


def _put_rows(table, rows: dict, next_id: int) -> None:
    n = len(rows["id"])
    for k, a in rows.items():
        table.arrays[k][:n] = a
    table.slot_of = {int(i): s for s, i in enumerate(rows["id"])}
    table._next_id = max(table._next_id, next_id)  # ids of rows removed since stay retired


def _put_verts(pool, snap) -> None:
    arrays, top, live = snap.verts
    if top > len(pool.arrays["local"]):
        pool.arrays = {k: np.zeros((top,) + a.shape[1:], a.dtype) for k, a in pool.arrays.items()}
        pool.view = type(pool.view)(**pool.arrays)
    for k, a in arrays.items():
        pool.arrays[k][:top] = a
    pool.top, pool.live = top, live


def _put_contacts(c, snap) -> None:
    cur, prev, n, n_prev, span, span_step = snap.contacts
    c.ensure(max(n, n_prev))
    for tab, rows, k in ((c.cur, cur, n), (c.prev, prev, n_prev)):
        for name, a in rows.items():
            getattr(tab, name)[:k] = a
    c.n, c.n_prev, c.span, c.span_step = n, n_prev, span, span_step


def _put_settings(world, snap) -> None:
    for k, v in snap.world.items():
        setattr(world, k, v.copy() if isinstance(v, np.ndarray) else v)
    world._mode = solvers.get(world._solver_name)
    for name in set(world._settings) | set(snap.settings):
        vals = world._settings_store(name)
        saved = snap.settings.get(name, {k: s.default for k, s in vals.decl.items()})
        vals.values.clear()  # in place: ModeSettings views hold this dict
        vals.values.update(saved)
        vals.version += 1  # the step reloads (and re-derives) the mode's parameter record


def restore(world, snap: Snapshot) -> None:
    """Write ``snap`` back into ``world`` (ValueError, and nothing changed, if the topology differs)."""
    check(world, snap)
    st = world._store
    _put_settings(world, snap)
    for name in TABLES:
        _put_rows(getattr(st, name), snap.tables[name], snap.next_ids[name])
    _put_verts(st.verts, snap)
    _put_contacts(st.contacts, snap)
    j = st.joints
    j.span, j.span_step, broken, reported = snap.joint_meta
    j.broken_last_step, j._reported = list(broken), set(reported)
    j.changed()  # the solvers rebuild their joint rows and system from the restored table
    for fid, shape in snap.shapes.items():
        world._fixture_handles[fid]._shape = shape
    p = world._pipeline
    p.dirty = True
    p._dt = None  # the step context is rewritten in full
    p.invalidate()  # queries rebuild their tree
    p.n_awake, p._islands.label[0], ctx = snap.pipeline
    p.ctx.array[0] = ctx[0]  # the last step's dt: what views.contacts scales impulses by
    for k, v in snap.guard.items():
        setattr(p._guard, k, v)
    p.events.put(getattr(snap, "events", ((), (), {})))  # the events of the step before are cleared
    world._n_sensors = int(np.count_nonzero(st.fixtures.view.sensor[: st.fixtures.n]))
