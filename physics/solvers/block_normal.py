"""Both normal points of a two-point manifold solved together (a 2x2 LCP).

Gauss-Seidel over the two points of a box face is asymmetric: the first
point takes the load, the box tilts, and a heavy box on a light one rocks and
walks.  The block solver of Box2D 2.x (Catto, "Iterative Dynamics with
Temporal Coherence", 2005 and the Box2D 2.x manual) solves both rows at once
by enumerating the four complementarity cases of
    lambda >= 0,  w = K lambda + g >= 0,  lambda . w = 0,
with K the 2x2 effective inverse mass and g the free relative normal speed
(old impulses removed) plus the bias.  For a soft row the per-point update
new = old - s m (v_n + bias) - (1 - s) old  equals  -s m (v_free + bias), and in
the block form lambda = -s K^-1 g with the mass scale s (s = 1 for rigid rows),
so one routine serves the rigid, soft and relax passes.  Ill-conditioned pairs
(nearly redundant points) return False and the caller falls back to
sequential rows.
"""
from __future__ import annotations

from .._jit import kernel
from .contact_prep import apply_impulse, cross, rel_velocity

MAX_CONDITION = 1000.0  # k11^2 / det above this: the points are (nearly) redundant


@kernel
def block_normal(B, C, k, a, b, nx, ny, bias0, bias1, ms):
    """Solve manifold k's two normal rows exactly; False if K is ill-conditioned."""
    ima = B.inv_m[a] + B.inv_m[b]
    iia = B.inv_i[a]
    iib = B.inv_i[b]
    ra0 = cross(C.ra[k, 0, 0], C.ra[k, 0, 1], nx, ny)
    rb0 = cross(C.rb[k, 0, 0], C.rb[k, 0, 1], nx, ny)
    ra1 = cross(C.ra[k, 1, 0], C.ra[k, 1, 1], nx, ny)
    rb1 = cross(C.rb[k, 1, 0], C.rb[k, 1, 1], nx, ny)
    k11 = ima + iia * ra0 * ra0 + iib * rb0 * rb0
    k22 = ima + iia * ra1 * ra1 + iib * rb1 * rb1
    k12 = ima + iia * ra0 * ra1 + iib * rb0 * rb1
    det = k11 * k22 - k12 * k12
    if not (k11 * k11 < MAX_CONDITION * det):
        return False
    old0 = C.jn[k, 0]
    old1 = C.jn[k, 1]
    dvx, dvy = rel_velocity(B, a, b, C.ra[k, 0, 0], C.ra[k, 0, 1], C.rb[k, 0, 0], C.rb[k, 0, 1])
    v0 = dvx * nx + dvy * ny
    dvx, dvy = rel_velocity(B, a, b, C.ra[k, 1, 0], C.ra[k, 1, 1], C.rb[k, 1, 0], C.rb[k, 1, 1])
    v1 = dvx * nx + dvy * ny
    # free speeds (this manifold's impulses removed) plus bias
    g0 = v0 - (k11 * old0 + k12 * old1) + bias0
    g1 = v1 - (k12 * old0 + k22 * old1) + bias1
    # case 1: both points push
    x0 = -ms * (k22 * g0 - k12 * g1) / det
    x1 = -ms * (k11 * g1 - k12 * g0) / det
    if not (x0 >= 0.0 and x1 >= 0.0):
        # case 2: only point 0 pushes, point 1 separates
        x0 = -ms * g0 / k11
        x1 = 0.0
        if not (x0 >= 0.0 and g1 + k12 * x0 >= 0.0):
            # case 3: only point 1
            x0 = 0.0
            x1 = -ms * g1 / k22
            if not (x1 >= 0.0 and g0 + k12 * x1 >= 0.0):
                # case 4: neither
                x1 = 0.0
                if not (g0 >= 0.0 and g1 >= 0.0):
                    return False
    C.jn[k, 0] = x0
    C.jn[k, 1] = x1
    d0 = x0 - old0
    d1 = x1 - old1
    apply_impulse(B, a, b, C.ra[k, 0, 0], C.ra[k, 0, 1], C.rb[k, 0, 0], C.rb[k, 0, 1], d0 * nx, d0 * ny)
    apply_impulse(B, a, b, C.ra[k, 1, 0], C.ra[k, 1, 1], C.rb[k, 1, 0], C.rb[k, 1, 1], d1 * nx, d1 * ny)
    return True
