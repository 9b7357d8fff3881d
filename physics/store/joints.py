"""The joint table: one row per joint, every kind in the same fields.

Conventions (issue 14): angles, translations, speeds and motor speeds are body
``a``'s relative to body ``b`` (or to the world when ``b == -1``), counter-
clockwise and along the axis positive.  Anchors are stored relative to each
body's centre of mass in that body's frame (for ``b == -1``, ``lb`` is the world
point); the axis of a prismatic or wheel joint is a unit vector in ``a``'s frame.
Optional parameters (limits, break thresholds) are NaN when unset.

Rows: every joint has up to ``ROWS`` scalar constraint rows, and ``impulse``
holds each row's accumulated impulse (N s or N m s) over ``JointTable.span``
seconds: three equality rows (EQ0..EQ2: the point, angle or perpendicular
rows that hold the joint together; a motor or mouse joint's own rows), then a
spring, a motor and the lower and upper limit rows.  What the parameter fields
mean per kind (``physics/joint_params.py`` declares the kinds and names them for users):

=========  =========================================================================
revolute   lower/upper angle, motor_speed + max_motor (torque), hertz + zeta (spring)
prismatic  axis, lower/upper translation, motor_speed + max_motor (force), hertz + zeta
weld       hertz (linear), hertz2 (angular), zeta (damping ratio); 0 hertz = rigid
distance   length (rest), lower/upper = min/max length, hertz + zeta (spring)
wheel      axis (suspension), hertz + zeta (suspension spring), motor_speed + max_motor
           (torque), lower/upper translation
motor      offset (a's origin in b's frame), ref (angular offset), max_motor (force),
           max_torque
mouse      lb (the target, a world point), hertz + zeta, max_motor (force)
=========  =========================================================================
"""
from __future__ import annotations

import numpy as np

from ..joint_params import KINDS, JOINT_KINDS
from .table import Table, f8, i1, i4, i8
from .table_view import view_class

#: a kind's code (``J.kind``) is its place in the declaration (physics/joint_params.py)
CODE = {k: i for i, k in enumerate(JOINT_KINDS)}
REVOLUTE, PRISMATIC, WELD, DISTANCE, WHEEL, MOTOR, MOUSE = (
    CODE[k] for k in ("revolute", "prismatic", "weld", "distance", "wheel", "motor", "mouse"))
#: per code, for compiled code (numba freezes global arrays as constants): the equality rows
#: that hold the kind together, and whether its motor drives the relative angle
EQUALITY = np.array([d.equality for d in KINDS.values()], np.int64)
ANGULAR_MOTOR = np.array([d.motor == "angular" for d in KINDS.values()], np.bool_)

ROWS = 7
EQ0, EQ1, EQ2, SPRING, MOTOR_ROW, LOWER, UPPER = range(ROWS)

# flags
COLLIDE = 1   # the joined bodies still collide with each other
BROKEN = 2    # exceeded its break force or torque: out of the solve

JOINT_FIELDS = {
    "kind": ((), i1),
    "a": ((), i4),             # body slot
    "b": ((), i4),             # body slot, or -1 for the world
    "la": ((2,), f8),          # anchor on a, relative to a's centre of mass (a's frame)
    "lb": ((2,), f8),          # anchor on b likewise, or the world point when b == -1
    "axis": ((2,), f8),        # unit axis in a's frame (prismatic, wheel)
    "ref": ((), f8),           # reference angle q_a - q_b at rest (motor joint: angular offset)
    "lower": ((), f8),         # lower limit (angle, translation or min length); NaN = none
    "upper": ((), f8),         # upper limit; NaN = none
    "length": ((), f8),        # distance joint rest length (m)
    "motor_speed": ((), f8),   # rad/s or m/s
    "max_motor": ((), f8),     # N m or N (motor and mouse joints: max force); 0 = motor off
    "max_torque": ((), f8),    # motor joint's max torque (N m)
    "hertz": ((), f8),         # spring frequency (Hz); weld: linear
    "zeta": ((), f8),          # spring damping ratio
    "hertz2": ((), f8),        # weld: angular frequency (Hz)
    "offset": ((2,), f8),      # motor joint: linear offset as given (b's body coordinates)
    "break_force": ((), f8),   # N; NaN = unbreakable
    "break_torque": ((), f8),  # N m; NaN = unbreakable
    "flags": ((), i4),         # COLLIDE | BROKEN
    "impulse": ((ROWS,), f8),  # accumulated impulse of each row over JointTable.span
    "force": ((2,), f8),       # reaction force on a in the last step (N)
    "torque": ((), f8),        # reaction torque on a about its anchor in the last step (N m)
    "id": ((), i8),
}
Joints = view_class("Joints", JOINT_FIELDS, "joints")


LOW_NONE = 1 << 62  # ``JointTable.low`` when no row was edited alone


class JointTable(Table):
    """The joint rows, with what their impulses mean and a topology version.

    ``span``/``span_step``: as ContactBuffer's, the time span the accumulated
    impulses stand for and the step that may use them unscaled (see :meth:`adopt`).
    ``version`` is bumped on every change that alters which rows exist or which
    bodies they join (add, remove, break, a parameter that adds or drops a row), so
    the solvers rebuild their row structures only then.  ``base`` is the version of the
    last such change other than adding or editing one joint (:meth:`changed`), and ``low``
    the lowest row edited alone (:meth:`edited`) since its reader last set it to ``LOW_NONE``:
    while ``base`` stands, the rows below ``low`` are as they were, and new joints come after.
    """

    def __init__(self, cap: int = 16):
        super().__init__(JOINT_FIELDS, Joints, cap)
        self.span = 0.0
        self.span_step = -1
        self.version = 0
        self.base = 0
        self.low = LOW_NONE
        self.broken_last_step: list[int] = []  # ids of the joints that broke in the last step
        self._reported: set[int] = set()

    def add(self):
        oid, s = super().add()
        v = self.view
        for k in ("lower", "upper", "break_force", "break_torque"):
            getattr(v, k)[s] = np.nan
        self.version += 1
        return oid, s

    def remove(self, oid):
        out = super().remove(oid)
        self.changed()
        return out

    def changed(self) -> None:
        """A change of the rows other than an added or edited joint (see the class doc)."""
        self.version += 1
        self.base = self.version

    def edited(self, slot: int) -> None:
        """Row ``slot`` changed which rows it has or which bodies it joins."""
        self.version += 1
        self.low = min(self.low, slot)

    def adopt(self, span: float, step: int) -> None:
        """Make the accumulated impulses mean impulse over ``span`` seconds for ``step``
        (rescaled when another mode or step length wrote them for this step, dropped when
        they are older: a warm start is only a first guess)."""
        r = self.adopt_factor(span, step)
        n = self.n
        if r != 1.0 and n:
            self.view.impulse[:n] *= r

    def adopt_factor(self, span: float, step: int) -> float:
        """What :meth:`adopt` multiplies the impulses by (1 keeps them, 0 drops them), with the
        span recorded as adopt does; the step driver applies the factor itself."""
        r = 1.0
        if self.span_step == step:
            if self.span != span and self.span > 0.0:
                r = span / self.span
        else:
            r = 0.0
        self.span = span
        self.span_step = step + 1
        return r

    def note_broken(self) -> None:
        """After a step in which joints broke: remember which, and rebuild the row structures."""
        n = self.n
        v = self.view
        ids = [int(i) for i in v.id[:n][(v.flags[:n] & BROKEN) != 0]]
        self.broken_last_step = [i for i in ids if i not in self._reported]
        self._reported.update(self.broken_last_step)
        self.changed()

    def remap_removed_body(self, removed: int, moved_from: int) -> None:
        """Renumber the body that moved into slot ``removed`` (its joints are gone already)."""
        n = self.n
        v = self.view
        v.a[:n][v.a[:n] == moved_from] = removed
        v.b[:n][v.b[:n] == moved_from] = removed
        self.changed()
