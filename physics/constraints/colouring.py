"""Graph colouring of the contact manifolds (Box2D v3's constraint_graph.c, b2AssignJointColor /
b2AddContactToGraph), done every step after the narrow phase, a pair keeping its colour while it
touches (the contact table's ``colour``, carried by the narrow phase like the warm-start impulses).

No two manifolds of one colour share a body that moves, so the rows of a colour can be solved
side by side (constraints/contact_wide.py) in any order and give the same answer.  Bodies
that do not move (inverse mass and inertia zero: static, kinematic) do not count: a pass never
changes their velocity, so two rows reading one of them do not conflict.

Greedy first fit in the table's order, as Box2D v3: a manifold between two moving bodies takes
the lowest of the first DYNAMIC_COLOURS colours free at both bodies; one against a fixed body
the highest free colour below OVERFLOW (never 0), so the contacts that carry a pile's weight
to the ground are solved last in every pass and have the last word.  Measured over Box2D v3's
samples (docs/reliability.md): with them first (the lowest free colour from 1 up) the tiny
pyramid's top moved 3.65 box sizes in 10 s and overlap recovery pushed at 3.93 m/s; last, 0.70
and 3.55 (Box2D v3: 1.33 and 3.42), with friction_pass "faces_in_relax" (contact_soft.py;
without it pyramid 20's top crept 0.076 m in 10 s, with it 0.025).  A manifold that finds none goes to the OVERFLOW colour, whose
manifolds are then solved one after the other (still correct, only not side by side).  A colour set
per body is one bit mask, so the stage costs two passes over the manifolds and one over the
bodies, with no per-colour tables to clear.

Colours persist, as in Box2D v3 (a contact is added to the graph when it begins touching and
removed when it stops): the first pass keeps every carried colour that is still valid (in its
range, free at its moving bodies; checked, so a body that changed kind or a stale table can
never break the colouring), the second gives the rest (new pairs, and overflow ones, which try
again) a free colour.  Recolouring from scratch every step instead lets one contact
coming or going shift the colours, and so the Gauss-Seidel order, of the manifolds after it.
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel

COLOURS = 24                  # B2_GRAPH_COLOR_COUNT
OVERFLOW = COLOURS - 1        # B2_OVERFLOW_INDEX
DYNAMIC_COLOURS = COLOURS - 4  # B2_DYNAMIC_COLOR_COUNT
LANES = 8                     # manifolds per block (contact_wide.py): each colour padded to this
COUNT = COLOURS + 1           # bstart's manifold counts per colour start here (colour_contacts)
RUNS = COUNT + 2 * COLOURS    # bstart's number of colours in use, then their solve-order indices
FLAGS = RUNS + 1 + COLOURS    # bstart's copy of the test flags below, for the passes
BSTART = FLAGS + 1            # bstart's length
#: test flags (colour_contacts' ``force``): every manifold in the overflow colour (Box2D v3's
#: B2_FORCE_OVERFLOW: the table's order, one manifold at a time); every colour's lanes solved one
#: after another instead of side by side (the same numbers, since no two lanes of a colour share
#: a moving body); the manifolds prepared through the rows ``R`` and packed, the path of a step
#: with a bouncy contact (the same numbers as prepare_wide)
FORCE_OVERFLOW, IN_TURN, VIA_ROWS = 1, 2, 4


@kernel(forceinline=True)
def _lowest_free(taken, lo, hi):
    """The lowest colour in lo..hi-1 not in the bit set ``taken``; OVERFLOW when none is."""
    one = np.uint64(1)
    free = ~taken & ((one << np.uint64(hi)) - one) & ~((one << np.uint64(lo)) - one)
    if free == 0:
        return OVERFLOW
    c = 0
    while free & one == 0:  # the lowest set bit (at most hi shifts)
        free >>= one
        c += 1
    return c


@kernel(forceinline=True)
def _highest_free(taken, lo, hi):
    """The highest colour in lo..hi-1 not in the bit set ``taken``; OVERFLOW when none is."""
    one = np.uint64(1)
    c = hi - 1
    while c >= lo:  # at most hi - lo shifts
        if (taken >> np.uint64(c)) & one == 0:
            return c
        c -= 1
    return OVERFLOW


@kernel(forceinline=True)
def _kept(c, ma, mb, taken):
    """May a manifold keep its carried colour ``c``: in the range of its kind, free at its bodies?"""
    if c < 0 or c == OVERFLOW:
        return False
    if ma and mb:
        return c < DYNAMIC_COLOURS and (taken >> np.uint64(c)) & np.uint64(1) == 0
    if ma or mb:
        return c >= 1 and (taken >> np.uint64(c)) & np.uint64(1) == 0
    return c == 1


@kernel(entry=True, runtime=True)
def colour_contacts(ca, cb, nc, inv_m, inv_i, n, used, colour, order, bstart, force=0):
    """Colour the manifolds 0..nc-1 (bodies ``ca``/``cb``) and lay them out in blocks.

    ``used`` (n uint64, scratch): the colours taken at each body.  ``colour[k]`` (in and out,
    the contact table's column): the colour carried from the previous step, -1 for a new pair;
    a valid one is kept, the others get a free one (the lowest for two moving bodies, the
    highest with a fixed one).  ``force``: the test flags above.  Writes ``order`` (slot ->
    manifold, -1 for padding; colour by colour, overflow first as Box2D solves it first, each
    colour padded to whole blocks of LANES, the overflow colour's solved lane after lane:
    contact_coloured.py's ``seq``) and ``bstart`` (BSTART long: COLOURS + 1 block offsets, the
    r-th colour in solve order is blocks bstart[r]..bstart[r + 1]; each colour's manifold
    count at COUNT + c; scratch; at RUNS the number of colours in use, then their r in solve
    order, so a pass visits only those; at FLAGS ``force``).  Returns the number of slots used
    (a multiple of LANES; ``order`` must hold at least nc * LANES).
    """
    for k in range(nc):  # only the manifolds' bodies are read: a sleeping world costs nothing here
        used[ca[k]] = 0
        used[cb[k]] = 0
    count = bstart[COUNT:COUNT + COLOURS]  # (views into the scratch: no allocation per step)
    fill = bstart[COUNT + COLOURS:]
    count[:] = 0
    bstart[FLAGS] = force
    overflow_all = (force & FORCE_OVERFLOW) != 0
    one = np.uint64(1)
    for sweep in range(2):  # 0: keep the carried colours that are still valid; 1: colour the rest
        for k in range(nc):
            a = ca[k]
            b = cb[k]
            ma = inv_m[a] > 0.0 or inv_i[a] > 0.0  # moves (an array passed to an inlined helper
            mb = inv_m[b] > 0.0 or inv_i[b] > 0.0  # would cost reference counting per manifold)
            taken = (used[a] if ma else np.uint64(0)) | (used[b] if mb else np.uint64(0))
            if sweep == 0:
                c = np.int64(colour[k])
                if overflow_all or not _kept(c, ma, mb, taken):
                    colour[k] = -1
                    continue
            elif colour[k] >= 0:
                continue
            else:
                c = OVERFLOW
                if overflow_all:
                    pass
                elif ma and mb:
                    c = _lowest_free(taken, 0, DYNAMIC_COLOURS)
                elif ma or mb:
                    c = _highest_free(taken, 1, OVERFLOW)
                else:
                    c = 1  # two fixed bodies: nothing to conflict with (any colour would do)
            if c != OVERFLOW:
                bit = one << np.uint64(c)
                if ma:
                    used[a] |= bit
                if mb:
                    used[b] |= bit
            colour[k] = c
            count[c] += 1
    # solve order: the overflow colour first (its blocks lane after lane), then 0, 1, ...
    slot = 0
    runs = 0
    for r in range(COLOURS):
        c = OVERFLOW if r == 0 else r - 1
        bstart[r] = slot // LANES
        fill[c] = slot  # the colour's first slot, then its next free one
        slot += (count[c] + LANES - 1) // LANES * LANES
        if count[c] > 0:
            bstart[RUNS + 1 + runs] = r
            runs += 1
    bstart[COLOURS] = slot // LANES
    bstart[RUNS] = runs
    for j in range(slot):
        order[j] = -1
    for k in range(nc):
        c = colour[k]
        order[fill[c]] = k
        fill[c] += 1
    return slot
