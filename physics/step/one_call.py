"""The step as one compiled call, where the world's mode has a driver (soft_step's: driver.py).

``OneCall.step`` packs the world's arrays (pack.py) once per change of structure, calls the
driver once per step and does in Python only what compiled code cannot: grow an array and call
again, raise a refused step, run the user's callbacks.  The Python work per step does not grow
with the scene.  A world the driver does not cover (another mode, sensors, a user pair filter,
the quadtree broad phase) steps through the pipeline's stages.  The colouring's scratch is the
pack's ``wide``.
"""
from __future__ import annotations

import math
import time

import numpy as np

from .._jit import direct
from ..collision import broadphase
from ..collision.broadphase.limit import check_pairs
from ..collision.narrowphase.kernel import manifold_scratch
from ..constraints.joints.work import after_step, joint_work
from ..constraints.rotation_cap import PIVOT_COLUMNS
from ..errors import SimulationError
from .. import threads
from ..store.table import GENERATION
from . import soft_driver as drv
from .energy_bound import E_OUT, LIMIT_OUT
from .active import Active
from .pack import new_pack, pack_signature
from .soft_driver import (
    D_CADOPT,
    D_GMAG,
    D_GROWTH,
    D_JADOPT,
    S_BROKEN,
    S_CPAR,
    S_EPAR,
    S_KBAD,
    S_LIMIT,
    S_N,
    S_NA,
    S_NAWAKE,
    S_NB,
    S_NC,
    S_NEED,
    S_NF,
    S_NJ,
    S_NPAIRS,
    S_NS,
    S_NT,
    S_NTOUCH,
    S_SLEEP,
    S_STEP,
    S_SWEEP,
    S_GEOM,
    S_NROWS,
    soft_world_step,
)

_BROAD = ("brute", "sweep")  # the broad phases the driver runs (the quadtree steps through the pipeline)
_NO_LINKS = np.zeros((0, 3), np.int64)

#: Whether a world whose driver is not compiled in this process compiles it at its next step
#: (True), or steps through the pipeline's stages until something else has compiled or loaded it
#: (False: the sandbox, whose compile units bring the driver in while the scene already plays;
#: both paths give the same bits).  ``compile_on_demand`` sets it.
_ON_DEMAND = [True]


_clock = time.perf_counter  # (the step reads it twice: one global lookup, not two attribute reads)


def compile_on_demand(on: bool) -> bool:
    """Set whether a world compiles its step driver when it first needs it (the default) or steps
    without it until it is compiled; returns the previous setting."""
    was = _ON_DEMAND[0]
    _ON_DEMAND[0] = bool(on)
    return was


def splits(world) -> bool:
    """Whether the world's driver is built with its split loops: more than one thread here and
    enough bodies or fixtures that a loop would split (threads.SPLIT_SIZE).  The count itself is
    read at each step (the context's ``threads``)."""
    s = world._store
    return threads.usable(world._threads) > 1 and max(s.bodies.n, s.fixtures.n) >= threads.SPLIT_SIZE


class OneCall:
    """The pack of one world and the Python side of its driver."""

    def __init__(self):
        self.P = None
        self.key = None
        self._par = None  # the mode's parameters the key was made with (Pipeline.params)
        self.enabled = True  # False: every step goes through the pipeline's stages (tests compare)
        self.S, self.D, self.T = drv.empty_state()
        self._keys = ()  # the touching sets' arrays in the pack (to notice a replaced one)
        self._sort = (np.zeros(0, np.int64), np.zeros(0, np.int64))  # the pairs' keys and order
        self._scratch = None  # the narrow phase's manifold scratch
        self._V0 = None  # soft_step's start-velocity scratch
        self.active = Active()  # the step's lists of moving bodies and fixtures (active.py)
        self.sweep = None  # the sweep broad phase's scratch in the pack (empty: brute force)
        self.wide = None  # the colouring's scratch in the pack
        self._dt = None  # the step length and the mode's settings version the slots were set for
        self._version = None
        self._h = 0.0  # the sub-step the impulses are carried at
        self._call = None  # the driver compiled for the pack's type (_jit.direct)
        self._waiting = None  # (pack type, driver overloads) while its driver is not compiled
        self._step = -1  # the step count and adopt factors the pack's slots hold
        self._cadopt = self._jadopt = -1.0

    # -- whether and what --------------------------------------------------
    @staticmethod
    def usable(world, pl, par) -> bool:
        """Whether the driver covers this world as it is now."""
        return (world._mode.name == "soft_step" and world._pair_filter is None and world._n_sensors == 0
                and not pl.events.sensors.active
                and broadphase.resolve(world.broadphase, world._store.fixtures.n) in _BROAD)

    @staticmethod
    def _key(world, pl) -> tuple:
        """What the pack, the mode's parameters and the choice of path depend on: every attribute
        read directly, since this runs once per step (store/table.py: GENERATION counts replaced
        table arrays; the third entry the version of the mode's settings, -1 before they exist).
        The second entry counts the pipeline's steps (a world waiting for its driver makes them)."""
        s = world._store
        mode = world._mode
        vals = world._settings.get(mode.name)
        return (pl.edits, pl.python_steps, -1 if vals is None else vals.version, mode, GENERATION[0], s.joints.version,
                s.contacts.full, world._max_pairs, world._pair_filter is None, world._n_sensors,
                pl.events.sensors.active, world._broadphase, world._threads)

    def build(self, world, pl, now: bool = False) -> None:
        """A pack of the world's arrays as they are, with room for the step's rows; with
        ``compile_on_demand`` off and the driver for it not compiled, none (unless ``now``: a
        step the driver began must end in it)."""
        s = world._store
        mode = world._mode
        n, nj = s.bodies.n, s.joints.n
        c = s.contacts
        ck, tr, isl, guard = pl._checkpoint, pl.events.contacts, pl._islands, pl._guard
        ck.ensure(n)
        if n + 1 > len(mode.SB):  # one more row: the world, for joints
            mode._alloc(2 * n + 2)
        if c.capacity > len(mode.R):
            mode.R = np.zeros((c.capacity, mode.R.shape[1]))
        mode.coloured.ensure(s, c.capacity)  # the driver asks for more room when it needs it
        self.wide = wide = mode.coloured.pack_fields()
        tr.scratch(c.capacity)
        if n > len(isl.parent):
            isl.parent = np.zeros(2 * n, dtype=np.int64)
            isl.min_t = np.zeros(2 * n)
        links, JF, JI, JW, JS, kinds, exclude = _NO_LINKS, None, None, None, None, None, pl._no_keys
        if nj:
            if nj > len(isl._links):
                isl._links = np.zeros((2 * nj, 3), dtype=np.int64)
            work = joint_work(s)
            W, JS = work.update(s)
            links, JW, kinds, exclude = isl._links, W._replace(SB=mode.SB), work._kinds, work.exclude
            JF, JI = s.joints.arrays.flat
        if len(self._sort[0]) < len(pl._pairs):
            self._sort = (np.zeros(len(pl._pairs), np.int64), np.zeros(len(pl._pairs), np.int64))
        if self._scratch is None:
            self._scratch = manifold_scratch()
        S = self.S  # the structure's slots; the step's own (S_STEP, S_SLEEP) are step()'s
        S[S_N], S[S_NF], S[S_NS], S[S_NJ] = n, s.fixtures.n, s.springs.n, nj
        S[S_NC], S[S_NTOUCH], S[S_LIMIT] = c.n, tr.n, world.max_pairs
        S[S_CPAR] = S[S_EPAR] = 0  # the pack's first tables are the current ones
        self._dt = None  # the settings are written again before the next call
        self._keys = (tr.keys, tr._keys2)
        swept = broadphase.resolve(world.broadphase, s.fixtures.n) == "sweep"
        S[S_SWEEP] = swept
        S[S_GEOM] = 1  # a new pack follows an edit: every fixture's geometry is computed once
        self.sweep = self._sweep(s.fixtures.n if swept else 0, len(pl._pairs) if swept else 0)
        values = (pl.ctx.array, pl.params(world).array, S, self.D, self.T, guard.G,
            *s.bodies.arrays.flat, *s.fixtures.arrays.flat, *s.verts.arrays.flat,
            *s.springs.arrays.flat, *c.cur_cols.flat, *c.prev_cols.flat, pl._pairs, exclude,
            *self._sort, self._scratch,
            ck.X, ck.Q, ck.V, ck.W, ck.bad, ck.why, ck.cluster, guard.start, guard.end,
            tr.keys, tr._keys2, tr.begin, tr._begin2, tr._absent, tr._absent2,
            isl.parent, isl.min_t, isl.label, links, mode.R, mode.SB, self._v0(len(mode.SB)),
            JF, JI, JW, JS, kinds, s.springs.arrays.flat[0] if s.springs.n else None,
            1 if c.full else None, self.sweep, wide, 1 if splits(world) else None, self._lists(s, ck))
        self._waiting = None
        if not (_ON_DEMAND[0] or now):
            sig = pack_signature(values)
            compiled = soft_world_step.overloads
            if sig not in compiled:  # the pipeline steps it until the driver is here
                self.P, self._waiting = None, (sig, len(compiled))
                return
        self.P = P = new_pack(*values)
        self._call = direct(soft_world_step, P)

    def _sweep(self, nf: int, npairs: int) -> tuple:
        """The sweep's scratch for ``nf`` fixtures and ``npairs`` pairs (sweep_pairs' sizes): the
        last pack's while the fixture count is the same (its kept order is a permutation of the
        slots, which the next sweep repairs; sorting it afresh after every grow of a buffer cost a
        waking wall a full sort a step), else with a fresh order.  Under brute force it is empty
        (0, 0), of the same types: the pack's type, and so the compiled driver, is the same for
        both broad phases."""
        i4 = np.int32
        old = self.sweep
        if old is not None and nf > 0 and len(old[1]) == nf:
            tmp = old[7] if len(old[7]) == npairs else np.empty((npairs, 2), i4)
            return (*old[:7], tmp, old[8])
        return (np.full(2, -1, np.int64), np.arange(nf, dtype=i4), np.empty(nf), np.empty(nf, i4),
                np.empty(nf, i4), np.empty(nf + 2, i4), np.empty(6 * nf, i4), np.empty((npairs, 2), i4),
                np.empty(nf + 1, i4))

    def _lists(self, s, ck) -> tuple:
        """The pack's ``active`` field: the step's lists (active.py) and the checkpoint's rows."""
        self.active.ensure(s.bodies.n, s.fixtures.n)
        return self.active.fields(ck.rows, ck.mark)

    def _v0(self, rows: int) -> np.ndarray:
        """soft_step's start-velocity and pivot scratch, ``rows`` long."""
        if self._V0 is None or len(self._V0) < rows:
            self._V0 = np.empty((rows, PIVOT_COLUMNS))
        return self._V0

    # -- the step ------------------------------------------------------------
    def step(self, world, pl, dt: float) -> bool:
        """One step through the driver; False (nothing done) when it does not cover the world.

        This runs once per step of every small world, so it reads attributes directly and
        writes a slot of the pack only when its value changed (a numpy item write costs about
        as much as the rest of a one-body step's Python)."""
        if not self.enabled:
            return False
        key = self._key(world, pl)
        if key == self.key:
            par = self._par  # nothing it depends on changed (Pipeline.params would return it as is)
        else:
            self._par = par = pl.params(world)
            key = self._key(world, pl)  # (params may have fitted the settings to the scene anew)
            if self._waiting is None or key[0] != self.key[0] or key[2:] != self.key[2:]:
                self.P = self._waiting = None
                if self.usable(world, pl, par):
                    self.build(world, pl)
            # else only the pipeline's own steps since (key[1]): the same pack type to wait for
            self.key = key
        if self.P is None and not self._arrived(world, pl):
            return False
        if pl.dirty or dt != self._dt or par.version != self._version:
            self._settings(world, pl, par, dt)
        s = world._store
        steps = world.steps
        if steps != self._step:  # the driver counts accepted steps itself
            self.S[S_STEP] = self._step = steps
        h = self._h
        c = s.contacts
        if c.span_step == steps and c.span == h:  # adopt_factor's usual case, without its call
            c.span_step = steps + 1
            r = 1.0
        else:
            r = c.adopt_factor(h, steps)
        if r != self._cadopt:
            self.D[D_CADOPT] = self._cadopt = r
        r = s.joints.adopt_factor(h, steps) if s.joints.n else 1.0
        if r != self._jadopt:
            self.D[D_JADOPT] = self._jadopt = r
        t0 = _clock()
        code = self._call(self.P)
        while drv.OK < code < drv.NONFINITE:
            self._grow(world, pl, code)
            code = self._call(self.P)
        elapsed = _clock() - t0
        if code != drv.OK:
            self._refused(world, pl, code)  # raises
        self._step = steps + 1
        self._accepted(world, pl, dt, elapsed)
        return True

    def _arrived(self, world, pl) -> bool:
        """While the world waits for its driver (``compile_on_demand`` off): has it been compiled
        or loaded since?  Then the pack is built and the driver steps from now on.  The driver's
        overloads are looked up only when their number changed."""
        w = self._waiting
        if w is None:
            return False
        compiled = soft_world_step.overloads
        if len(compiled) == w[1]:
            return False
        if w[0] not in compiled:
            self._waiting = (w[0], len(compiled))
            return False
        self.build(world, pl)
        return self.P is not None

    def _settings(self, world, pl, par, dt: float) -> None:
        """The world's settings into the step context and the pack's slots: on a change of the step
        length, of the mode's settings or of a world setting (they mark the pipeline dirty)."""
        pl.refresh_settings(world, dt)
        world._mode.derive(pl.ctx, par, world._store)
        self._h = par.get("h")
        self._dt, self._version = dt, par.version
        self.S[S_SLEEP] = world.sleeping
        self.S[S_GEOM] = 1  # the step length or the speculative distance may have changed the boxes
        self.D[D_GROWTH] = world.energy_guard
        self.D[D_GMAG] = math.hypot(world._gravity[0], world._gravity[1])

    def _grow(self, world, pl, code: int) -> None:
        """Make room for what the driver found short (or raise what is over the limit)."""
        s = world._store
        need = int(self.S[S_NEED])
        if code == drv.TOO_MANY_PAIRS:
            try:
                check_pairs(need, world.max_pairs, s.fixtures.n)
            except SimulationError as err:
                pl.refuse(world, err, "collide")
        elif code == drv.GROW_PAIRS:
            pl._pairs = np.empty((2 * need + 64, 2), np.int32)
        elif code == drv.GROW_ROWS:
            s.contacts.reserve(max(need, int(self.S[S_NTOUCH])), world.max_pairs)
        elif code == drv.NEED_FULL:
            s.contacts.full = True
        elif code == drv.JOINT_KINDS:
            joint_work(s)._key = None  # the system is rebuilt for the bodies' new kinds
        elif code == drv.GROW_BLOCKS:
            world._mode.coloured.grow(need)
        geometry = self.S[S_GEOM]  # room grew, nothing was edited: the step's lists and boxes stand
        self.build(world, pl, now=True)
        self.S[S_GEOM] = geometry
        self._par = pl.params(world)
        self.key = self._key(world, pl)

    def _refused(self, world, pl, code: int) -> None:
        world._store.contacts.swap(int(self.S[S_NC]))  # the driver swapped the tables: so do the handles
        pl._checkpoint.listed(int(self.S[S_NROWS]))  # the step saved only its rows
        self.S[S_GEOM] = 1  # the state goes back: the lists and the sleepers' sums anew
        if code == drv.NONFINITE:
            pl._fail(world, pl._checkpoint.slots(int(self.S[S_KBAD])))
        g = pl._guard
        pl._gained(world, float(g.G[E_OUT]), float(g.G[LIMIT_OUT]))

    def _accepted(self, world, pl, dt: float, elapsed: float) -> None:
        S = self.S.tolist()  # the slots read once
        world._store.contacts.swap(S[S_NC])  # the driver swapped the tables: so do the handles
        if world._store.joints.n:
            after_step(world._store, S[S_BROKEN])
        pl.n_awake = S[S_NAWAKE] if world._sleeping else -1
        pl.npairs = S[S_NPAIRS]
        pl.profile.defer(self.T, elapsed)
        world._time += dt
        world.steps += 1
        world.fault = None
        ev = pl.events
        ev._sensed = False
        ev.commit(world, S[S_NT], S[S_NB], S[S_NA])
        if ev.contacts.keys is not self._keys[S[S_EPAR]]:  # the merge kept sleeping ends: new arrays
            self.key = None
