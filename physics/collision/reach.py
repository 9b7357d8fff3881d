"""Whether two bodies can meet within a step: the pair test the narrow phase starts with, which
the step's broad phase also applies, so that pairs the narrow phase would drop unseen are never
sorted or handed over."""
from __future__ import annotations

from .._jit import kernel
from ..geometry.norm import length


@kernel(forceinline=True)
def may_touch(B, a, b, dt, spec):
    """Can the bounding circles come within ``spec`` during the step (linear motion)?

    The pair margin sizes speculative rows by the relative speed, but a row is
    a half-plane: it stops any approach along its normal beyond the gap, even
    when the true motion passes by.  Two bodies flying side by side 3 m apart
    at 1000 m/s (16.7 m per step) would get a row as soon as one stops, and the
    other is deflected by a ghost impulse.  This conservative time-of-impact
    test (closest approach of the relative centre path, a segment, to the
    origin against r_a + r_b; rotation never leaves the bounding circle) drops
    only pairs that cannot meet within the step, so a head-on impact between
    two fast bodies keeps its speculative rows, unlike a cap on the margin.
    """
    cx = B.x[b, 0] - B.x[a, 0]
    cy = B.x[b, 1] - B.x[a, 1]
    dx = (B.v[b, 0] - B.v[a, 0]) * dt
    dy = (B.v[b, 1] - B.v[a, 1]) * dt
    dd = dx * dx + dy * dy
    t = 0.0
    if dd > 0.0:
        t = min(1.0, max(0.0, -(cx * dx + cy * dy) / dd))
    reach = B.bound_r[a] + B.bound_r[b] + spec
    # written so that a non-finite motion (overflowing speeds) keeps the pair: the finite
    # check after the step must see what it does
    return not (length(cx + t * dx, cy + t * dy) > reach)
