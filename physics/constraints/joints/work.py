"""The solvers' joint scratch and its upkeep (Python; kernels receive the arrays).

``JointScratch`` holds per joint the body rows it joins (``ab``: the world is row
n), the prepared constants ``F``, the row geometry ``G`` (layout.py) and the
equality block's factors ``K`` (rows.block_factors), whether it is on this step,
its row mask and whether its equality rows stay sequential (``seq``); per body
the step-start positions ``X0``/``Q0`` and the body rows ``SB`` of modes that
have none of their own.  ``JointWork.update`` grows the
arrays and rebuilds the global system (system/topology.py) and the list of
body pairs that must not collide only when the joint table's version or the
kinds of the joined bodies changed.
"""
from __future__ import annotations

import numpy as np

from ...store.joints import BROKEN, COLLIDE, LOW_NONE, ROWS
from ...store.table import allocate
from ...store.table_view import view_class
from ..body_rows import NB
from .kinds import kinds_changed
from .layout import NF, NG
from .system.extend import extend, new_structures_only
from .system.topology import build, empty_system

#: per joint (the table's rows), then per body (arrays of their own: one row per body)
PER_JOINT = {"ab": ((2,), np.int64), "F": ((NF,), np.float64), "G": ((ROWS, NG), np.float64),
             "K": ((7,), np.float64),
             "on": ((), np.int64), "mask": ((), np.int64), "seq": ((), np.int64)}
PER_BODY = {"X0": ((2,), np.float64), "Q0": ((), np.float64), "SB": ((NB,), np.float64)}
JointScratch = view_class("JointScratch", {**PER_JOINT, **{k: (*e, "own") for k, e in PER_BODY.items()}},
                          "joint_scratch")


def _scratch(jcap, bcap):
    """Zeroed scratch for ``jcap`` joints and ``bcap`` body rows: compiled code receives the
    per-joint columns as two arrays (store/table_view.py)."""
    per_body = {k: np.zeros((bcap,) + shp, dt) for k, (shp, dt) in PER_BODY.items()}
    return JointScratch(**allocate(PER_JOINT, jcap), **per_body)


class JointWork:
    """Scratch arrays, the global system and the collision exclusions of one world's joints."""

    def __init__(self):
        self.W = _scratch(16, 64)
        self.S = empty_system(16)
        self.exclude = np.zeros(0, np.int64)
        self._key = None
        self._base = None  # the joint table's ``base`` and joint count at the last rebuild
        self._kinds = np.full(32, -2, np.int64)  # the joined bodies' kinds at the last rebuild

    def update(self, store):
        """(W, S) ready for a step of ``store``; rebuilt only where something changed."""
        nj = store.joints.n
        n = store.bodies.n
        jcap, bcap = len(self.W.on), len(self.W.Q0)
        if nj > jcap or n + 1 > bcap:
            seq = self.W.seq
            self.W = _scratch(max(nj, 2 * jcap) if nj > jcap else jcap,
                              max(n + 1, 2 * bcap) if n + 1 > bcap else bcap)
            self.W.seq[: len(seq)] = seq  # the only column kept from step to step
            self._key = None
        if len(self._kinds) < 2 * nj:
            kinds, self._kinds = self._kinds, np.full(4 * nj, -2, np.int64)
            self._kinds[: len(kinds)] = kinds
        flat = (*store.joints.arrays.flat, *store.bodies.arrays.flat)
        nj0 = self._base[1] if self._base else 0
        moved = kinds_changed(*flat, min(nj, nj0), self._kinds)  # of the joints the system has
        if nj > nj0:  # the added joints' bodies, for the next time (they are a change of key)
            kinds_changed(*flat, nj, self._kinds)
        key = (store.joints.version, nj)
        if moved or key != self._key:
            self._rebuild(store, nj, nj0 if not moved and self._base else None)
            self._key = key
        return self.W, self.S

    def _rebuild(self, store, nj, nj0):
        """The system and the exclusions again; ``nj0`` (None: build it all): the joints the
        system has, after which only joints may have been added: their system is then placed
        after the one there is (system/extend.py)."""
        J = store.joints.view
        kinds = store.bodies.view.kind[: store.bodies.n]
        jcap = len(self.W.on)
        T = store.joints
        if (nj0 is not None and self._base[0] == T.base and T.low >= nj0 and nj0 < nj
                and new_structures_only(J, nj0, nj, kinds)):
            self.S, seq = extend(self.S, J, nj0, nj, kinds, jcap)
            self.W.seq[nj0:nj] = seq[nj0:nj]
        else:
            self.S, seq = build(J, nj, kinds, jcap)
            self.W.seq[:] = seq[: len(self.W.seq)]
        self._base = (T.base, nj)
        T.low = LOW_NONE
        keep = (J.b[:nj] >= 0) & ((J.flags[:nj] & (COLLIDE | BROKEN)) == 0)
        a = J.a[:nj][keep].astype(np.int64)
        b = J.b[:nj][keep].astype(np.int64)
        self.exclude = np.unique((np.minimum(a, b) << 32) | np.maximum(a, b))

    @property
    def global_rows(self) -> int:
        """Rows in the global system (0: every joint is solved by sequential rows)."""
        return int(self.S.dims[0])


def joint_work(store) -> JointWork:
    """The store's joint scratch, created on first use."""
    if store.joint_work is None:
        store.joint_work = JointWork()
    return store.joint_work


def joint_args(store, span: float, step: int, rows=None):
    """(J, W, S) for a mode's kernel, impulses made to mean ``span`` seconds; Nones without joints
    (the kernels are then compiled without any joint code).  ``rows``: the mode's own body rows
    (n + 1 of them), which the joints then share; otherwise W.SB."""
    if store.joints.n == 0:
        return None, None, None
    W, S = joint_work(store).update(store)
    store.joints.adopt(span, step)
    if rows is not None:
        W = W._replace(SB=rows)
    return store.joints.view, W, S


def after_step(store, broken: int) -> None:
    """Record the joints that broke in the step (their rows are gone: the system is rebuilt)."""
    if broken:
        store.joints.note_broken()
    elif store.joints.broken_last_step:
        store.joints.broken_last_step = []
