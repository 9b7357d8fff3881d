"""Plot anything: the quantities of a body or spring that can be recorded, and the recorder that
samples the chosen ones every frame the world moves, for the Plot window and its CSV export.

Quantities read through the public handles (a few per frame, whatever the world's size).  A
series holds a :class:`app.commands.Ref`, so it follows its body through delete and undo; a body
that is gone records NaN (a gap in the plot, an empty CSV cell).
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

import physics


def _speed(b):
    return math.hypot(*b.velocity)


def _kinetic(b):
    """1/2 m v^2 + 1/2 I w^2 (J); static and kinematic bodies count as 0, as in world.kinetic_energy."""
    if b.kind != "dynamic":
        return 0.0
    vx, vy = b.velocity
    return 0.5 * b.mass * (vx * vx + vy * vy) + 0.5 * b.inertia * b.angular_velocity ** 2


def _potential(b):
    """-m g . x_com (J, relative to the origin), as in world.potential_energy."""
    if b.kind != "dynamic":
        return 0.0
    g, c = b.world.gravity, b.center_of_mass
    return -b.mass * (g[0] * c[0] + g[1] * c[1])


def spring_tension(sp) -> float:
    """The spring's pull (N, > 0 stretched): k (L - L0) + c dL/dt with dL/dt the relative
    velocity of the anchors along the axis (the core's force, physics/constraints/springs/force.py)."""
    pa, pb = (np.array(p) for p in sp.endpoints())
    d = pa - pb
    length = float(np.hypot(*d))
    if length < 1e-12:
        return 0.0
    va = np.array(sp.body_a.velocity_at(tuple(pa)))
    vb = np.zeros(2) if sp.body_b is None else np.array(sp.body_b.velocity_at(tuple(pb)))
    rate = float(np.dot(va - vb, d / length))
    return sp.stiffness * (length - sp.rest_length) + sp.damping * rate


#: name -> (unit, reader) for bodies and springs; the Plot window groups series by unit
BODY_QUANTITIES = {
    "x": ("m", lambda b: b.position[0]),
    "y": ("m", lambda b: b.position[1]),
    "speed": ("m/s", _speed),
    "angle": ("rad", lambda b: b.angle),
    "angular velocity": ("rad/s", lambda b: b.angular_velocity),
    "kinetic energy": ("J", _kinetic),
    "potential energy": ("J", _potential),
}
SPRING_QUANTITIES = {
    "force": ("N", spring_tension),
    "length": ("m", lambda sp: sp.length),
}


def quantities_of(item) -> dict:
    """The quantities a body or spring offers (TypeError for anything else)."""
    if isinstance(item, physics.Body):
        return BODY_QUANTITIES
    if isinstance(item, physics.Spring):
        return SPRING_QUANTITIES
    raise TypeError(f"item: a Body or Spring has quantities, not {type(item).__name__}")


class Series:
    """One recorded quantity: ``label`` (e.g. "box 3: speed"), ``unit``, values aligned with
    the recorder's times (NaN before it was added or while its item is gone)."""

    def __init__(self, ref, quantity, label, unit, cap, index=0):
        self.ref = ref
        self.index = index        # the item's place in world.bodies / world.springs (found again after a reset)
        self.quantity = quantity
        self.label = label
        self.unit = unit
        self.values = np.full(cap, np.nan)


class Recorder:
    """Samples every series once per frame in which world time moved (``cap`` samples kept)."""

    def __init__(self, cap: int = 3000):
        self.cap = cap
        self.t = np.zeros(cap)
        self.n = 0
        self.i = 0
        self.series: list[Series] = []
        self._last_time = None

    def has(self, item, quantity, refs) -> bool:
        ref = refs.of(item)
        return any(s.ref is ref and s.quantity == quantity for s in self.series)

    def toggle(self, item, quantity, refs, world) -> bool:
        """Record ``quantity`` of ``item`` (a body or spring of ``world``), or stop if it is
        recorded; returns whether it is now.  ValueError names an unknown quantity."""
        qs = quantities_of(item)
        if quantity not in qs:
            raise ValueError(f"quantity: {item.__class__.__name__} has no {quantity!r}; choose one of {list(qs)}")
        ref = refs.of(item)
        for s in self.series:
            if s.ref is ref and s.quantity == quantity:
                self.series.remove(s)
                return False
        name = item.name or f"{'body' if isinstance(item, physics.Body) else 'spring'} {item.id}"
        items = world.bodies if isinstance(item, physics.Body) else world.springs
        index = next((k for k, x in enumerate(items) if x.id == item.id), 0)
        self.series.append(Series(ref, quantity, f"{name}: {quantity}", qs[quantity][0], self.cap, index))
        return True

    def remove(self, series):
        self.series.remove(series)

    def rebind(self, world, refs):
        """After a reset: each series follows the body or spring at its place in the new world
        (the reset world is rebuilt from the loaded scene in the same order)."""
        for s in self.series:
            body = isinstance(s.ref.obj, physics.Body)
            items = world.bodies if body else world.springs
            s.ref = refs.of(items[s.index]) if s.index < len(items) else s.ref

    def clear(self, keep_series=True):
        """Forget the samples (a reset or a new document); ``keep_series=False`` drops the choices too."""
        self.n = self.i = 0
        self._last_time = None
        for s in self.series:
            s.values[:] = np.nan
        if not keep_series:
            self.series = []

    def sample(self, world):
        """Record every series at ``world.time`` if it moved since the last sample."""
        if not self.series or world.time == self._last_time:
            return
        self._last_time = world.time
        self.t[self.i] = world.time
        for s in self.series:
            item = s.ref.obj
            ok = item is not None and item.alive
            s.values[self.i] = float(quantities_of(item)[s.quantity][1](item)) if ok else np.nan
        self.i = (self.i + 1) % self.cap
        self.n = min(self.n + 1, self.cap)

    def _order(self):
        return np.arange(self.n) if self.n < self.cap else (np.arange(self.cap) + self.i) % self.cap

    def times(self):
        """Sample times (world seconds), oldest first."""
        return self.t[self._order()]

    def values(self, series):
        return series.values[self._order()]

    def groups(self):
        """{unit: [series]} in the order the units first appear (one plot per unit)."""
        out: dict[str, list] = {}
        for s in self.series:
            out.setdefault(s.unit, []).append(s)
        return out

    def export_csv(self, path) -> Path:
        """Write the recorded samples as CSV: a time column, then one column per series (header
        "label (unit)"; empty cells where there was no value).  OSError if it cannot be written."""
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        t = self.times()
        cols = [self.values(s) for s in self.series]
        tmp = path.with_suffix(path.suffix + ".tmp")
        with open(tmp, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["time (s)"] + [f"{s.label} ({s.unit})" for s in self.series])
            for k in range(len(t)):
                w.writerow([repr(float(t[k]))] + ["" if math.isnan(c[k]) else repr(float(c[k])) for c in cols])
        tmp.replace(path)
        return path
