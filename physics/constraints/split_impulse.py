"""Split impulses: position correction that leaves no momentum behind.

Baumgarte feeds the push-out into the real velocities, so a resolved
overlap keeps moving the bodies apart (jitter, bouncing stacks).  Split
impulses solve the same non-penetration rows a second time on separate
*pseudo-velocities* (v_p, w_p), integrate positions by them and throw them
away (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005, sec. 6;
also the "bias velocities" of Chipmunk).  Per point the target is
  v_p,n >= beta/dt * max(depth - slop, 0)   (capped at ``max_push`` m/s),
with an accumulated pseudo impulse clamped >= 0, projected Gauss-Seidel as
for the velocity rows.
"""
from __future__ import annotations

from .._jit import kernel
from ..store import STATIC
from .point import cross


@kernel
def reset_pseudo(n, VP, WP):
    for i in range(n):
        VP[i, 0] = 0.0
        VP[i, 1] = 0.0
        WP[i] = 0.0


@kernel
def _pseudo_impulse(B, VP, WP, a, b, rax, ray, rbx, rby, px, py):
    """Like apply_impulse, on the pseudo-velocities: P on b, -P on a."""
    VP[a, 0] -= B.inv_m[a] * px
    VP[a, 1] -= B.inv_m[a] * py
    WP[a] -= B.inv_i[a] * cross(rax, ray, px, py)
    VP[b, 0] += B.inv_m[b] * px
    VP[b, 1] += B.inv_m[b] * py
    WP[b] += B.inv_i[b] * cross(rbx, rby, px, py)


@kernel
def solve_split(B, C, nc, W, VP, WP, JP, inv_dt, beta, slop, max_push):
    """One sweep over the pseudo-velocity rows (only overlapping points take part)."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            target = min(beta * inv_dt * (C.depth[k, p] - slop), max_push)
            if target <= 0.0:
                continue
            rax = W.ra[k, p, 0]
            ray = W.ra[k, p, 1]
            rbx = W.rb[k, p, 0]
            rby = W.rb[k, p, 1]
            dvx = (VP[b, 0] - WP[b] * rby) - (VP[a, 0] - WP[a] * ray)
            dvy = (VP[b, 1] + WP[b] * rbx) - (VP[a, 1] + WP[a] * rax)
            vn = dvx * nx + dvy * ny
            old = JP[k, p]
            new = max(old - W.mass_n[k, p] * (vn - target), 0.0)
            JP[k, p] = new
            j = new - old
            _pseudo_impulse(B, VP, WP, a, b, rax, ray, rbx, rby, j * nx, j * ny)


@kernel
def integrate_pseudo(B, n, dt, VP, WP):
    """Move positions by the pseudo-velocities (then they are discarded)."""
    for i in range(n):
        if B.kind[i] == STATIC or B.awake[i] == 0:
            continue
        B.x[i, 0] += dt * VP[i, 0]
        B.x[i, 1] += dt * VP[i, 1]
        B.q[i] += dt * WP[i]


@kernel
def zero_rows(JP, nc):
    for k in range(nc):
        JP[k, 0] = 0.0
        JP[k, 1] = 0.0
