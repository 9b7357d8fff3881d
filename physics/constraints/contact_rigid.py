"""Rigid contact rows for sequential impulses (Catto, "Iterative Dynamics with
Temporal Coherence", GDC 2005; "Fast and Simple Physics using Sequential
Impulses", GDC 2006): the verbs warm start, bias, solve, restitution.

Each point is a velocity constraint  v_n + bias >= 0  on the accumulated
normal impulse (clamped >= 0) and a friction row whose accumulated impulse
is clamped to the Coulomb box |j_t| <= mu j_n.  The bias encodes:

- speculative points (depth < 0, a gap still open): bias = gap / dt, so the
  bodies may close the gap during the step but never pass it -- continuous
  collision for free (Catto, "Contacts", GDC 2013 / Box2D speculative margin);
- penetrating points with Baumgarte stabilisation: bias = -beta/dt *
  max(depth - slop, 0), capped at ``max_push`` m/s (Baumgarte 1972, Catto 2005).

``W`` is the solver's point scratch (constraints/point.py: arms, masses, vn0, mu,
and ``bias``); the accumulated impulses are the contact table's ``jn``/``jt``.
"""
from __future__ import annotations

from .._jit import kernel
from .block import block_mass, solve_block
from .point import apply_impulse, cross, rel_velocity


@kernel
def contact_bias(C, nc, W, inv_dt, beta, slop, max_push, baumgarte):
    """Velocity bias of every point into ``W.bias`` (see the module doc)."""
    for k in range(nc):
        for p in range(C.count[k]):
            d = C.depth[k, p]
            if d < 0.0:
                W.bias[k, p] = -d * inv_dt
            elif baumgarte:
                W.bias[k, p] = -min(beta * inv_dt * max(d - slop, 0.0), max_push)
            else:
                W.bias[k, p] = 0.0


@kernel
def warm_start_points(B, C, nc, W):
    """Apply every point's accumulated impulses (normal and friction) of the last step."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            jn = C.jn[k, p]
            jt = C.jt[k, p]
            px = jn * nx - jt * ny
            py = jn * ny + jt * nx
            apply_impulse(B, a, b, W.ra[k, p, 0], W.ra[k, p, 1], W.rb[k, p, 0], W.rb[k, p, 1], px, py)


@kernel
def solve_friction(B, C, W, k, a, b, nx, ny):
    """Tangent rows of manifold k: accumulated impulse clamped to mu * j_n (Coulomb)."""
    for p in range(C.count[k]):
        rax = W.ra[k, p, 0]
        ray = W.ra[k, p, 1]
        rbx = W.rb[k, p, 0]
        rby = W.rb[k, p, 1]
        dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
        vt = -dvx * ny + dvy * nx  # tangent t = (-ny, nx)
        limit = W.mu[k, p] * C.jn[k, p]
        old = C.jt[k, p]
        new = min(max(old - W.mass_t[k, p] * vt, -limit), limit)
        C.jt[k, p] = new
        j = new - old
        apply_impulse(B, a, b, rax, ray, rbx, rby, -j * ny, j * nx)


@kernel
def solve_normal(B, C, W, k, a, b, nx, ny):
    """Normal rows of manifold k: accumulated impulse clamped >= 0 (projected Gauss-Seidel)."""
    for p in range(C.count[k]):
        rax = W.ra[k, p, 0]
        ray = W.ra[k, p, 1]
        rbx = W.rb[k, p, 0]
        rby = W.rb[k, p, 1]
        dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
        vn = dvx * nx + dvy * ny
        old = C.jn[k, p]
        new = max(old - W.mass_n[k, p] * (vn + W.bias[k, p]), 0.0)
        C.jn[k, p] = new
        j = new - old
        apply_impulse(B, a, b, rax, ray, rbx, rby, j * nx, j * ny)


@kernel
def block_normal(B, C, W, k, a, b, nx, ny, bias0, bias1, ms):
    """Solve manifold k's two normal rows together (constraints/block.py); False if K is
    ill-conditioned or no complementarity case holds (the caller then solves them in turn)."""
    ima = B.inv_m[a] + B.inv_m[b]
    iia = B.inv_i[a]
    iib = B.inv_i[b]
    ra0 = cross(W.ra[k, 0, 0], W.ra[k, 0, 1], nx, ny)
    rb0 = cross(W.rb[k, 0, 0], W.rb[k, 0, 1], nx, ny)
    ra1 = cross(W.ra[k, 1, 0], W.ra[k, 1, 1], nx, ny)
    rb1 = cross(W.rb[k, 1, 0], W.rb[k, 1, 1], nx, ny)
    k11 = ima + iia * ra0 * ra0 + iib * rb0 * rb0
    k22 = ima + iia * ra1 * ra1 + iib * rb1 * rb1
    k12 = ima + iia * ra0 * ra1 + iib * rb0 * rb1
    ok, inv_det = block_mass(k11, k12, k22)
    if not ok:
        return False
    old0 = C.jn[k, 0]
    old1 = C.jn[k, 1]
    dvx, dvy = rel_velocity(B, a, b, W.ra[k, 0, 0], W.ra[k, 0, 1], W.rb[k, 0, 0], W.rb[k, 0, 1])
    v0 = dvx * nx + dvy * ny
    dvx, dvy = rel_velocity(B, a, b, W.ra[k, 1, 0], W.ra[k, 1, 1], W.rb[k, 1, 0], W.rb[k, 1, 1])
    v1 = dvx * nx + dvy * ny
    # free speeds (this manifold's impulses removed) plus bias
    g0 = v0 - (k11 * old0 + k12 * old1) + bias0
    g1 = v1 - (k12 * old0 + k22 * old1) + bias1
    solved, x0, x1 = solve_block(k11, k12, k22, inv_det, 1.0 / k11, 1.0 / k22, g0, g1, ms)
    if not solved:
        return False
    C.jn[k, 0] = x0
    C.jn[k, 1] = x1
    d0 = x0 - old0
    d1 = x1 - old1
    apply_impulse(B, a, b, W.ra[k, 0, 0], W.ra[k, 0, 1], W.rb[k, 0, 0], W.rb[k, 0, 1], d0 * nx, d0 * ny)
    apply_impulse(B, a, b, W.ra[k, 1, 0], W.ra[k, 1, 1], W.rb[k, 1, 0], W.rb[k, 1, 1], d1 * nx, d1 * ny)
    return True


@kernel
def solve_points(B, C, nc, W, block):
    """One PGS sweep: friction first, then normal, so the normal rows (which
    matter most for non-penetration) see the latest velocities (Catto 2006).
    With ``block`` a two-point manifold's normal rows are solved together."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        solve_friction(B, C, W, k, a, b, nx, ny)
        if not (block and C.count[k] == 2
                and block_normal(B, C, W, k, a, b, nx, ny, W.bias[k, 0], W.bias[k, 1], 1.0)):
            solve_normal(B, C, W, k, a, b, nx, ny)


@kernel
def restitution_points(B, C, nc, W, threshold):
    """Newton's law v_n' = -e v_n (seed eq. 13) for points that hit faster than ``threshold``.

    Only points that pushed this step (a non-zero accumulated normal impulse) bounce;
    a speculative point never reached does not."""
    for k in range(nc):
        e = C.e[k]
        if e == 0.0:
            continue
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            if W.vn0[k, p] > -threshold or C.jn[k, p] == 0.0:
                continue
            rax = W.ra[k, p, 0]
            ray = W.ra[k, p, 1]
            rbx = W.rb[k, p, 0]
            rby = W.rb[k, p, 1]
            dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
            vn = dvx * nx + dvy * ny
            old = C.jn[k, p]
            new = max(old - W.mass_n[k, p] * (vn + e * W.vn0[k, p]), 0.0)
            C.jn[k, p] = new
            j = new - old
            apply_impulse(B, a, b, rax, ray, rbx, rby, j * nx, j * ny)
