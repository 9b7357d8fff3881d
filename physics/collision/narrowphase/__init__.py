"""Narrow phase: contact manifolds for the broad phase's pairs.

Modules: ``support`` (support mappings), ``simplex`` + ``gjk`` (distance,
van den Bergen 1999), ``epa`` (penetration depth), ``sat`` (separating axes),
``manifold`` (reference/incident clipping, feature ids), ``circles``,
``rounded`` (rounded polygons, capsules and segments: cores swept by a radius), ``chain``
(one-sided chain segments with ghost vertices),
``pair`` (one polygon pair by either method), ``carry`` (per-point state
carried from the previous step), ``kernel`` (a run of pairs) and ``collide`` (the whole pass, split
between threads).  The single-pair
entries (``sat_query``, ``gjk_distance``, ``epa``, ``polygon_collide``, ``circle_circle``, ``polygon_circle``) take
plain vertex arrays in world coordinates for tests and tools.
"""
from __future__ import annotations

from .circles import circle_circle, polygon_circle
from .epa import epa
from .gjk import gjk_distance
from .collide import collide_flat, collide_kernel
from .limit import check_rows
from .pair import GJK, METHODS, SAT, polygon_collide
from .sat import sat_query

__all__ = ["collide", "sat_query", "gjk_distance", "epa", "polygon_collide",
           "circle_circle", "polygon_circle", "SAT", "GJK", "METHODS"]


def collide(ctx, B, F, V, pairs, npairs, contacts, limit: int = 1_000_000) -> int:
    """Manifolds for the fixture pairs ``pairs[:npairs]`` into ``contacts.cur``; returns the row count.

    ``B``, ``F``, ``V``: the body, fixture and vertex tables' columns (``Table.arrays``).
    ``ctx`` is the step context (dt, speculative distance, narrow-phase code).
    The previous step's rows become ``contacts.prev`` and carry their point
    state (impulses for warm starting) over to the new ones.  More than ``limit`` rows
    (world.max_pairs) raise SimulationError at the 'collide' stage (limit.py).
    """
    check_rows(int(npairs), limit)  # refused before the tables change (limit.py)
    contacts.swap()
    contacts.ensure(int(npairs), limit)
    # the lean kernel (SAT; sharp polygons and circles: kernel._manifold) until a pair needs more
    lean = not contacts.full and ctx.get("narrowphase") == SAT
    tables = (*B.flat, *F.flat, *V.flat, pairs, int(npairs), *contacts.cur_cols.flat, *contacts.prev_cols.flat,
              int(contacts.n_prev))
    n = -1
    if lean:
        n = collide_flat(ctx.array, *tables, None)
    if n < 0:
        if lean:
            contacts.full = True    # this world has such pairs: the whole kernel from now on
        n = collide_flat(ctx.array, *tables, 1)
    contacts.n = int(n)
    return contacts.n
