"""Rigid contact rows for sequential impulses (Catto, "Iterative Dynamics with
Temporal Coherence", GDC 2005; "Fast and Simple Physics using Sequential
Impulses", GDC 2006).

Each point is a velocity constraint  v_n + bias >= 0  on the accumulated
normal impulse (clamped >= 0) and a friction row whose accumulated impulse
is clamped to the Coulomb box |j_t| <= mu j_n.  The bias encodes:

- speculative points (depth < 0, a gap still open): bias = gap / dt, so the
  bodies may close the gap during the step but never pass it -- continuous
  collision for free (Catto, "Contacts", GDC 2013 / Box2D speculative margin);
- penetrating points with Baumgarte stabilisation: bias = -beta/dt *
  max(depth - slop, 0), capped at ``max_push`` m/s (Baumgarte 1972, Catto 2005).
"""
from __future__ import annotations

from .._jit import kernel
from .block_normal import block_normal
from .contact_prep import apply_impulse, rel_velocity


@kernel
def contact_bias(C, nc, inv_dt, beta, slop, max_push, baumgarte):
    """Velocity bias of every point into ``C.bias`` (see the module doc)."""
    for k in range(nc):
        for p in range(C.count[k]):
            d = C.depth[k, p]
            if d < 0.0:
                C.bias[k, p] = -d * inv_dt
            elif baumgarte:
                C.bias[k, p] = -min(beta * inv_dt * max(d - slop, 0.0), max_push)
            else:
                C.bias[k, p] = 0.0


@kernel
def solve_friction(B, C, k, a, b, nx, ny):
    """Tangent rows of manifold k: accumulated impulse clamped to mu * j_n (Coulomb)."""
    for p in range(C.count[k]):
        rax = C.ra[k, p, 0]
        ray = C.ra[k, p, 1]
        rbx = C.rb[k, p, 0]
        rby = C.rb[k, p, 1]
        dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
        vt = -dvx * ny + dvy * nx  # tangent t = (-ny, nx)
        limit = C.mu[k, p] * C.jn[k, p]
        old = C.jt[k, p]
        new = min(max(old - C.mass_t[k, p] * vt, -limit), limit)
        C.jt[k, p] = new
        j = new - old
        apply_impulse(B, a, b, rax, ray, rbx, rby, -j * ny, j * nx)


@kernel
def solve_normal(B, C, k, a, b, nx, ny):
    """Normal rows of manifold k: accumulated impulse clamped >= 0 (projected Gauss-Seidel)."""
    for p in range(C.count[k]):
        rax = C.ra[k, p, 0]
        ray = C.ra[k, p, 1]
        rbx = C.rb[k, p, 0]
        rby = C.rb[k, p, 1]
        dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
        vn = dvx * nx + dvy * ny
        old = C.jn[k, p]
        new = max(old - C.mass_n[k, p] * (vn + C.bias[k, p]), 0.0)
        C.jn[k, p] = new
        j = new - old
        apply_impulse(B, a, b, rax, ray, rbx, rby, j * nx, j * ny)


@kernel
def solve_velocities(B, C, nc, block):
    """One PGS sweep: friction first, then normal, so the normal rows (which
    matter most for non-penetration) see the latest velocities (Catto 2006).
    With ``block`` a two-point manifold's normal rows are solved together."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        solve_friction(B, C, k, a, b, nx, ny)
        if not (block and C.count[k] == 2 and block_normal(B, C, k, a, b, nx, ny, C.bias[k, 0], C.bias[k, 1], 1.0)):
            solve_normal(B, C, k, a, b, nx, ny)
