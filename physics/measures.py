"""Whole-world measures: energies and momenta of the dynamic bodies (vectorised, no kernel)."""
from __future__ import annotations

from .store import DYNAMIC

def _dynamic(world):
    n = world._store.bodies.n
    B = world._store.bodies.view
    return n, B, B.kind[:n] == DYNAMIC

def kinetic_energy(world) -> float:
    """Sum of 1/2 m v^2 + 1/2 I w^2 over the dynamic bodies (J)."""
    n, B, dyn = _dynamic(world)
    v2 = (B.v[:n] ** 2).sum(1)
    return float(0.5 * (B.m[:n] * v2 + B.inertia[:n] * B.w[:n] ** 2)[dyn].sum())

def potential_energy(world) -> float:
    """Gravitational (relative to the origin) plus elastic energy of the springs (J)."""
    n, B, dyn = _dynamic(world)
    pe = float(-(B.m[:n, None] * B.x[:n] @ world._gravity)[dyn].sum())
    for sp in world.springs:
        pe += 0.5 * sp.stiffness * (sp.length - sp.rest_length) ** 2
    return pe

def linear_momentum(world) -> tuple[float, float]:
    """Sum of m v over the dynamic bodies (kg m/s)."""
    n, B, dyn = _dynamic(world)
    p = (B.m[:n, None] * B.v[:n])[dyn].sum(0)
    return (float(p[0]), float(p[1]))

def angular_momentum(world, about) -> float:
    """Sum of m (r x v) + I w over the dynamic bodies about a world point (kg m^2/s)."""
    n, B, dyn = _dynamic(world)
    r = B.x[:n] - about
    L = B.m[:n] * (r[:, 0] * B.v[:n, 1] - r[:, 1] * B.v[:n, 0]) + B.inertia[:n] * B.w[:n]
    return float(L[dyn].sum())
