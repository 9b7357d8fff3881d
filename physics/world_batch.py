"""World's batch API: write velocities, forces and impulses of many bodies at once (a part of World).

Each call validates every row first (batch.py), then writes with numpy, in the same floating
point order as the per-body methods (Body.velocity, apply_force, apply_torque, apply_impulse,
apply_angular_impulse), so a batch equals the loop it replaces to the bit.  Rows naming the
same body add up in row order.
"""
from __future__ import annotations

import numpy as np

from .batch import cross, finite_rows, rows, slots_of, wake_slots
from .validate import finite_num, finite_vec


def _accumulate(base, slots, delta):
    """base[slots] + delta, rows of one slot added in order (np.add.at), for the check first."""
    out = base.copy()
    np.add.at(out, slots, delta)
    return out


class BatchMixin:
    """The batch half of :class:`~physics.World` (see world.py for the state it uses)."""

    def set_velocities(self, ids, v, w=None) -> None:
        """Set the velocity (m/s, (k, 2) or one pair for all) and, with ``w``, the angular velocity
        (rad/s, (k,) or one number) of the bodies with these ids; wakes them.  ValueError naming the
        first bad row (unknown id, non-finite value); nothing changes then."""
        s = slots_of(self, ids)
        vv = rows(v, len(s), "v")
        ww = None if w is None else rows(w, len(s), "w", width=0)
        B = self._bodies.view
        B.v[s] = vv
        if ww is not None:
            B.w[s] = ww
        wake_slots(self, s)

    def apply_forces(self, ids, f, points=None, torques=None) -> None:
        """Add forces (N, (k, 2)) for the next step at world ``points`` (default: each centre of
        mass) and torques (N m, (k,)) to the bodies with these ids; wakes them.  ValueError naming
        the first bad row (unknown id, non-finite, or a sum that would overflow); nothing changes then."""
        s = slots_of(self, ids)
        k = len(s)
        ff = rows(f, k, "f")
        B = self._bodies.view
        lever = None if points is None else cross(rows(points, k, "points") - B.x[s], ff)
        tq = None if torques is None else rows(torques, k, "torques", width=0)
        nf = _accumulate(B.f, s, ff)
        nt = B.tau.copy()  # apply_force's lever torque first, then apply_torque's (their order)
        for part in (lever, tq):
            if part is not None:
                np.add.at(nt, s, part)
        finite_rows(nf[s], "f", "the accumulated force would overflow")
        finite_rows(nt[s], "torques", "the accumulated torque would overflow")
        B.f[:] = nf
        B.tau[:] = nt
        wake_slots(self, s)

    def apply_impulses(self, ids, j, points=None, angular=None) -> None:
        """Change the momentum of the bodies with these ids at once by impulses (N s, (k, 2)) at
        world ``points`` (default: centres of mass) and angular impulses (N m s, (k,)); wakes them.
        ValueError naming the first bad row (unknown id, non-finite, overflow); nothing changes then."""
        s = slots_of(self, ids)
        k = len(s)
        jj = rows(j, k, "j")
        B = self._bodies.view
        dv = B.inv_m[s, None] * jj
        lever = None if points is None else B.inv_i[s] * cross(rows(points, k, "points") - B.x[s], jj)
        spin = None if angular is None else B.inv_i[s] * rows(angular, k, "angular", width=0)
        nv = _accumulate(B.v, s, dv)
        nw = B.w.copy()  # apply_impulse's lever first, then apply_angular_impulse's (their order)
        for part in (lever, spin):
            if part is not None:
                np.add.at(nw, s, part)
        finite_rows(nv[s], "j", "the velocity would overflow")
        finite_rows(nw[s], "angular", "the angular velocity would overflow")
        B.v[:] = nv
        B.w[:] = nw
        wake_slots(self, s)

    def explode(self, center, radius: float, impulse: float) -> None:
        """Push every dynamic body whose centre of mass is within ``radius`` (m) of ``center``
        away from it with an impulse (N s) falling off linearly from ``impulse`` at the centre
        to 0 at ``radius``, applied at the centre of mass (no spin), as Box2D v3's b2World_Explode
        does with zero falloff.  A body exactly at the centre is not pushed (no direction).
        ValueError for a non-finite centre or a negative radius or impulse."""
        c = finite_vec(center, "center")
        r = finite_num(radius, "radius", lo=0.0)
        mag = finite_num(impulse, "impulse", lo=0.0)
        n = self._bodies.n
        B = self._bodies.view
        d = B.x[:n] - c
        dist = np.hypot(d[:, 0], d[:, 1])
        hit = np.nonzero((dist < r) & (dist > 0.0) & (B.inv_m[:n] > 0.0))[0]
        if not len(hit):
            return
        scale = mag * (1.0 - dist[hit] / r) / dist[hit]
        self.apply_impulses(B.id[hit], d[hit] * scale[:, None])
