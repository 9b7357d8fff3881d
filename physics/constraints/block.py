"""Both normal rows of a two-point manifold solved together (a 2x2 LCP).

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
so one routine serves the rigid, soft and relax passes of every solver.
Ill-conditioned pairs (nearly redundant points) are left to sequential rows.
"""
from __future__ import annotations

from .._jit import kernel

MAX_CONDITION = 1000.0  # k11^2 / det above this: the points are (nearly) redundant


@kernel(forceinline=True, error_model="numpy")
def block_mass(k11, k12, k22):
    """(well conditioned, 1 / det K) of K = [[k11, k12], [k12, k22]]."""
    det = k11 * k22 - k12 * k12
    if k11 * k11 < MAX_CONDITION * det:
        return True, 1.0 / det
    return False, 0.0


@kernel(forceinline=True)
def solve_block(k11, k12, k22, inv_det, inv_k11, inv_k22, g0, g1, ms):
    """(solved, lambda0, lambda1) of the 2x2 LCP with free speeds g (bias included).

    ``inv_k11``/``inv_k22`` are the single-point effective masses 1/k11, 1/k22.
    Not solved (False) when no case satisfies the complementarity conditions.
    """
    # case 1: both points push
    x0 = -ms * (k22 * g0 - k12 * g1) * inv_det
    x1 = -ms * (k11 * g1 - k12 * g0) * inv_det
    if not (x0 >= 0.0 and x1 >= 0.0):
        # case 2: only point 0 pushes, point 1 separates
        x0 = -ms * g0 * inv_k11
        x1 = 0.0
        if not (x0 >= 0.0 and g1 + k12 * x0 >= 0.0):
            # case 3: only point 1
            x0 = 0.0
            x1 = -ms * g1 * inv_k22
            if not (x1 >= 0.0 and g0 + k12 * x1 >= 0.0):
                # case 4: neither
                x1 = 0.0
                if not (g0 >= 0.0 and g1 >= 0.0):
                    return False, 0.0, 0.0
    return True, x0, x1
