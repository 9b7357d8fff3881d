"""Warm-start impulses across a change of solver mode.

Contact rows carry accumulated impulses from step to step, but what they mean
depends on the mode that wrote them: ``sequential_impulse`` stores the impulse
of a whole step (dt), ``soft_step`` that of one sub-step (dt / substeps), and
the seed modes use the fields in their own ways.  Re-applying another mode's
impulses as if they were one's own kicks a resting pile (4x too much load after
sequential_impulse -> soft_step).  Each mode that warm starts calls ``adopt``
before solving: impulses written by a known mode are rescaled to the caller's
time span; impulses of unknown origin (a mode that does not record itself)
are dropped, which costs only one cold step (Catto 2005: warm starting is only
an initial guess).
"""
from __future__ import annotations


def adopt(world, span: float) -> None:
    """Make ``world._contacts.cur``'s impulses mean impulse over ``span`` seconds."""
    c = world._contacts
    tag = getattr(world, "_impulse_tag", None)
    if tag is not None and tag[1] == world.steps:
        prev_span = tag[0]
        if prev_span != span and c.n:
            r = span / prev_span
            c.cur.jn[: c.n] *= r
            c.cur.jt[: c.n] *= r
    elif c.n:
        c.cur.jn[: c.n] = 0.0
        c.cur.jt[: c.n] = 0.0
    # the next step sees these impulses (span) if nobody else steps in between
    world._impulse_tag = (span, world.steps + 1)
