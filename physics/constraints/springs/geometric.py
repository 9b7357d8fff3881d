"""A spring's geometric stiffness: the stiffness of its turning axis and turning arms.

A spring pulling with tension T along u between anchors p_a = x_a + R(q_a) l_a
and p_b has energy E(p_a - p_b).  Its Hessian in the bodies' coordinates has,
besides the material part k J^T J along the axis (the soft constraint row of
substep.py), two geometric parts (e.g. Baraff & Witkin, "Large Steps in Cloth
Simulation", SIGGRAPH 1998, sec. 5; Choi & Ko 2002 on dropping the unstable
part):

- the axis turning: (T / L) g g^T, g the Jacobian of the relative anchor
  velocity across the axis, n = perp(u): a transverse spring of stiffness T/L;
- the arms turning: d^2 p / dq^2 = -r, so body i's angle sees the stiffness
  f_i . r_i (f_i the spring's force on i): positive when the force pulls the
  anchor away from the centre of mass (a box hanging from an anchor 0.2 m off
  its centre: T r / I, with T = 2e3 N and I = 1.7e-5 kg m^2 a frequency of
  5e3 rad/s, omega h = 20 at 240 Hz sub-steps).

Frozen for a sub-step, the axis and arms treat these modes explicitly
(symplectic Euler: unstable once omega h > 2), which is how a 10 g box on a
k = 1e4 spring went from 5 kJ to 1e102 J (issue 20).  Where they are stiff for
the sub-step they become rows of the implicit system (implicit.py) with zero
violation (the force at the current state is the axis row's) and
gamma = 1 / (h^2 k_g): linearised backward Euler on the geometric stiffness.
Only the positive parts are kept (a compressed spring's transverse term and a
force pushing an anchor towards its centre are unstable physically, negative
stiffness that backward Euler cannot be given); where the modes are soft they
stay explicit, so slow swings are not damped.
"""
from __future__ import annotations

import numpy as np

from ..._jit import kernel
from ..point import cross
from .implicit import DIAG, JAW, JAX, JAY, JBW, JBX, JBY, RHS, row_mass, row_speed

# per spring, filled by substep._geometry: axis, arms (world frame), length, stretch, tension
GEO_FIELDS = 9
UX, UY, RAX, RAY, RBX, RBY, LEN, STRETCH, TENSION = range(GEO_FIELDS)


@kernel
def rates(B, S, k, G):
    """(transverse stiffness T/L, angular stiffness of a, of b), each >= 0 (the kept parts)."""
    t = G[k, TENSION]
    kn = max(0.0, t / G[k, LEN])
    # force on a is +T u (towards b), on b -T u
    ka = max(0.0, t * (G[k, UX] * G[k, RAX] + G[k, UY] * G[k, RAY])) if B.inv_i[S.a[k]] > 0.0 else 0.0
    kb = 0.0
    if S.b[k] >= 0 and B.inv_i[S.b[k]] > 0.0:
        kb = max(0.0, -t * (G[k, UX] * G[k, RBX] + G[k, UY] * G[k, RBY]))
    return kn, ka, kb


@kernel
def transverse_mass(B, S, k, G):
    """1/m_eff across the axis: inv_m_a + inv_m_b + inv_i (r x n)^2 at both ends."""
    nx = -G[k, UY]
    ny = G[k, UX]
    a = S.a[k]
    b = S.b[k]
    w = B.inv_m[a] + B.inv_i[a] * cross(G[k, RAX], G[k, RAY], nx, ny) ** 2
    if b >= 0:
        w += B.inv_m[b] + B.inv_i[b] * cross(G[k, RBX], G[k, RBY], nx, ny) ** 2
    return w


@kernel
def rate(B, S, k, G):
    """trace(W K_geo) of spring k: a bound on its geometric omega^2 (the stability test's)."""
    kn, ka, kb = rates(B, S, k, G)
    out = kn * transverse_mass(B, S, k, G) + ka * B.inv_i[S.a[k]]
    if S.b[k] >= 0:
        out += kb * B.inv_i[S.b[k]]
    return out


@kernel
def _row(B, rows, bod, gam, r, a, b, stiff, h):
    """Finish row r (Jacobians set) as a zero-violation soft row of stiffness ``stiff``."""
    bod[r, 0] = a
    bod[r, 1] = b
    gam[r] = 1.0 / (h * h * stiff)
    rows[r, DIAG] = row_mass(B, rows, bod, r) + gam[r]
    rows[r, RHS] = -row_speed(B.v, B.w, rows, bod, r)
    return r + 1


@kernel
def add_rows(B, S, k, G, h, rows, bod, gam, r):
    """Append spring k's geometric rows from row r on; returns the next free row."""
    kn, ka, kb = rates(B, S, k, G)
    a = S.a[k]
    b = S.b[k]
    if kn > 0.0:
        nx = -G[k, UY]
        ny = G[k, UX]
        rows[r, JAX] = -nx
        rows[r, JAY] = -ny
        rows[r, JAW] = -cross(G[k, RAX], G[k, RAY], nx, ny)
        rows[r, JBX] = nx
        rows[r, JBY] = ny
        rows[r, JBW] = cross(G[k, RBX], G[k, RBY], nx, ny)
        r = _row(B, rows, bod, gam, r, a, b, kn, h)
    for i, ki in ((a, ka), (b, kb)):
        if ki > 0.0:
            rows[r, JAX] = 0.0
            rows[r, JAY] = 0.0
            rows[r, JAW] = 1.0
            r = _row(B, rows, bod, gam, r, i, np.int64(-1), ki, h)  # not a literal: one _row
    return r
