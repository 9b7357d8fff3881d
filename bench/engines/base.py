"""The one interface every engine adapter implements: ``Sim``.

A ``Sim`` runs one scene description in one engine: ``step()`` advances by the description's
dt, ``state()`` reads centre-of-mass positions, angles, velocities and angular velocities in
the order of the description's bodies.  Everything else the benchmark measures (energy,
momentum, penetration) is computed from those, the same way for every engine.
"""
from __future__ import annotations

import math

import numpy as np

from ..desc import body_records


class Sim:
    """One engine running one scene: subclasses set ``engine`` and implement ``step`` and
    ``state``; ``recs`` (normalised body records), ``dt`` (s), ``dynamic`` (bool per body) and
    ``masses`` (kg) come from the description."""

    engine = ""
    settings_label = ""  # how the engine's solver is set up, for tables ("iterations 10")

    def __init__(self, desc):
        self.desc = desc
        self.recs = body_records(desc)
        self.dt = float(desc.get("world", {}).get("dt", 1 / 60))
        self.dynamic = np.array([r["kind"] == "dynamic" for r in self.recs])
        self.masses = np.array([r["shape"].mass_properties(r["density"])[0] for r in self.recs])

    def step(self):
        """Advance one time step of ``self.dt`` seconds."""
        raise NotImplementedError

    def state(self):
        """(com (n,2) m, angle (n,) rad, v (n,2) m/s, w (n,) rad/s) arrays, description order."""
        raise NotImplementedError

    def origins(self):
        """Body-origin positions (the frame the description's vertices are in), (n, 2) m."""
        com, ang, _, _ = self.state()
        out = np.empty_like(com)
        for i, r in enumerate(self.recs):
            c = r["shape"].centroid if hasattr(r["shape"], "centroid") else np.zeros(2)
            c = np.asarray(c, dtype=float)
            cs, sn = math.cos(ang[i]), math.sin(ang[i])
            out[i] = com[i] - (cs * c[0] - sn * c[1], sn * c[0] + cs * c[1])
        return out

    def kinetic_energy(self):
        """Kinetic energy of the dynamic bodies (J)."""
        _, _, v, w = self.state()
        inert = np.array([r["shape"].mass_properties(r["density"])[2] for r in self.recs])
        d = self.dynamic
        return float(0.5 * (self.masses[d] * (v[d] ** 2).sum(1) + inert[d] * w[d] ** 2).sum())

    def momentum(self):
        """Linear momentum of the dynamic bodies (kg m/s), shape (2,)."""
        _, _, v, _ = self.state()
        d = self.dynamic
        return (self.masses[d, None] * v[d]).sum(0)
