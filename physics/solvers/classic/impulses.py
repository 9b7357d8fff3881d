"""Impulse response of the seed (6.1, eqs. 10-16) with Coulomb friction (7.3, eqs. 23-27).

Runs after the force integration, on the points that penetrate (or touch
within the slop) at the integrated state.  Per point, with n from a to b and
v_r = v_bP - v_aP (eq. 14 with the bodies in that order):

- eq. 15: j = -(1 + e) v_r.n / (1/m_a + 1/m_b + (r_a x n)^2/I_a + (r_b x n)^2/I_b),
  applied as v_a -= j n / m_a, v_b += j n / m_b (eq. 10 as printed gives both
  the same sign, which would push b into a); w_i likewise with r_i x n (eq. 11).
  Static and kinematic bodies have zero inverse mass and inertia (eq. 16).
- Points are solved one after another and several times (``iterations``), each
  with the impulse accumulated and clamped to stay a push: stacks then get
  consistent impulses, which single-shot eq. 15 does not give.
- Restitution: the target is v_r.n' = -e v_c (eq. 13), only for impacts faster
  than the restitution threshold (slower contacts are resting: e = 0, or a box
  at rest would hop).  v_c is the approach speed at the moment of contact: the
  integrated velocity corrected by eq. 2 for the depth d gravity pulled the
  body into the other (v_c^2 = v_n^2 - 2 |g_n| d, clamped at 0; the report's
  |...| under the root would turn that deficit into speed).  Applying eq. 2
  before the bounce rather than after the push-out makes the rebound height
  come out right for every e, not just e = 1.
- Friction (eqs. 24-27): the tangential impulse that stops the sliding,
  -v_r.t / (1/m_a + 1/m_b + (r_a x t)^2/I_a + (r_b x t)^2/I_b) (eq. 27), is taken
  whole while it stays within mu_s j_n (static); beyond, the point slides and the
  impulse is mu_d j_n against the sliding (dynamic).  The accumulated normal
  impulse is j_r.

Each point's restitution target speed is ``P.target`` (the mode's point rows,
solvers/classic/contact_geometry.py); the accumulated impulses are the contact
table's ``jn``/``jt``.
"""
from __future__ import annotations

import math

from ..._jit import kernel
from ...constraints.point import apply_impulse, rel_velocity
from ...store import DYNAMIC
from .contact_geometry import IMPULSE, INACTIVE, depth_at


@kernel
def closing_gravity(B, a, b, gx, gy, nx, ny):
    """Part of gravity that accelerates b towards a along n (>= 0)."""
    gn = gx * nx + gy * ny
    acc = (gn if B.kind[b] == DYNAMIC else 0.0) - (gn if B.kind[a] == DYNAMIC else 0.0)
    return max(0.0, -acc)


@kernel
def activate_impulses(B, C, nc, P, R, slop, only_flagged, thr, gx, gy, energy_corr, stick):
    """Flag points touching after the integration; set targets, friction state, impact bodies."""
    for k in range(nc):
        a = C.a[k]
        b = C.b[k]
        nx = C.normal[k, 0]
        ny = C.normal[k, 1]
        for p in range(C.count[k]):
            if only_flagged and P.role[k, p] != IMPULSE:
                continue
            C.jn[k, p] = 0.0
            C.jt[k, p] = 0.0
            # resolved by an impulse: a penalty stick spring or approach memory ends here
            C.stick[k, p] = 0.0
            C.approach[k, p] = 0.0
            d, rax, ray, rbx, rby = depth_at(C, P, k, p, B.x, B.q, R.X0, R.Q0)
            if d < -slop:
                P.role[k, p] = INACTIVE
                continue
            P.role[k, p] = IMPULSE
            dvx, dvy = rel_velocity(B, a, b, P.ra[k, p, 0], P.ra[k, p, 1], P.rb[k, p, 0], P.rb[k, p, 1])
            vn = dvx * nx + dvy * ny
            vt = -dvx * ny + dvy * nx
            P.mu[k, p] = C.mu_s[k] if abs(vt) <= stick else C.mu_d[k]
            P.target[k, p] = 0.0
            if vn < -thr:  # an impact: bounce, and no position share for these bodies
                R.IMP[a] = 1
                R.IMP[b] = 1
                v2 = vn * vn
                if energy_corr and d > 0.0:  # eq. 2 on the approach
                    v2 = max(0.0, v2 - 2.0 * closing_gravity(B, a, b, gx, gy, nx, ny) * d)
                P.target[k, p] = C.e[k] * math.sqrt(v2)


@kernel
def normal_impulse(B, C, P, k, p, nx, ny):
    a = C.a[k]
    b = C.b[k]
    rax, ray, rbx, rby = P.ra[k, p, 0], P.ra[k, p, 1], P.rb[k, p, 0], P.rb[k, p, 1]
    dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
    vn = dvx * nx + dvy * ny
    old = C.jn[k, p]
    C.jn[k, p] = max(0.0, old + P.mass_n[k, p] * (P.target[k, p] - vn))  # eq. 15, accumulated
    dj = C.jn[k, p] - old
    apply_impulse(B, a, b, rax, ray, rbx, rby, dj * nx, dj * ny)


@kernel
def friction_impulse(B, C, P, k, p, nx, ny):
    a = C.a[k]
    b = C.b[k]
    rax, ray, rbx, rby = P.ra[k, p, 0], P.ra[k, p, 1], P.rb[k, p, 0], P.rb[k, p, 1]
    dvx, dvy = rel_velocity(B, a, b, rax, ray, rbx, rby)
    vt = -dvx * ny + dvy * nx
    old = C.jt[k, p]
    want = old - P.mass_t[k, p] * vt  # eq. 27: stop the sliding
    lim = P.mu[k, p] * C.jn[k, p]  # mu_d when the point was sliding already
    if P.mu[k, p] == C.mu_s[k] and abs(want) > lim:
        lim = C.mu_d[k] * C.jn[k, p]  # eq. 26: beyond mu_s j_r the point slides
    C.jt[k, p] = min(lim, max(-lim, want))
    dj = C.jt[k, p] - old
    apply_impulse(B, a, b, rax, ray, rbx, rby, -dj * ny, dj * nx)


@kernel
def solve_impulses(B, C, nc, P, iterations):
    for _ in range(iterations):
        for k in range(nc):
            nx = C.normal[k, 0]
            ny = C.normal[k, 1]
            for p in range(C.count[k]):
                if P.role[k, p] != IMPULSE:
                    continue
                normal_impulse(B, C, P, k, p, nx, ny)
                friction_impulse(B, C, P, k, p, nx, ny)


@kernel
def save_velocities(B, n, R):
    for i in range(n):
        R.VP[i, 0] = B.v[i, 0]
        R.VP[i, 1] = B.v[i, 1]
        R.WP[i] = B.w[i]
        R.IMP[i] = 0


@kernel
def position_share(B, n, R, s):
    """Move each body by s (v - v_before): the contact impulse acts as a constant force
    over the step, integrated the way the integrator would (s = dt (N+1)/2N for
    symplectic Euler over N sub-steps, dt (N-1)/2N explicit Euler, dt/2 RK4).  A resting
    body is then exactly in equilibrium with every integrator.  Bodies hit by an impact
    are left to the projection: a bounce is instantaneous, not a force over the step.
    """
    for i in range(n):
        if B.kind[i] != DYNAMIC or B.awake[i] == 0 or R.IMP[i] == 1:
            continue
        B.x[i, 0] += s * (B.v[i, 0] - R.VP[i, 0])
        B.x[i, 1] += s * (B.v[i, 1] - R.VP[i, 1])
        B.q[i] += s * (B.w[i] - R.WP[i])
