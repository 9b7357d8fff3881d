"""Carry each contact point's state over from the previous step (what warm starting needs).

Rows of both steps are sorted by key, so the previous row of a pair is found
by a merge walk (one pointer that only moves forward).  The carried state
(store/contacts.py CARRIED: accumulated impulses, penalty stick stretch and
approach memory) is copied per point only where the feature id matches: a
point made by other features is a different contact, and reusing its impulse
would inject energy (Catto, "Iterative dynamics with temporal coherence",
GDC 2005).  The row's graph colour (``colour``, constraints/colouring.py) is carried
whenever the key matches: the pair is the same pair, whatever its points.
"""
from __future__ import annotations

from ..._jit import kernel


@kernel(forceinline=True)
def seek(P, n_prev, ptr, key):
    """Advance ``ptr`` to the first previous row with key >= ``key``."""
    while ptr < n_prev and P.key[ptr] < key:
        ptr += 1
    return ptr


@kernel(forceinline=True)
def carry_over(C, row, P, n_prev, ptr):
    """Fill row ``row``'s carried point state from previous row ``ptr`` (if same key), else zero."""
    found = ptr < n_prev and P.key[ptr] == C.key[row]
    C.colour[row] = P.colour[ptr] if found else -1
    for p in range(2):
        C.jn[row, p] = 0.0
        C.jt[row, p] = 0.0
        C.stick[row, p] = 0.0
        C.approach[row, p] = 0.0
        if not found or p >= C.count[row]:
            continue
        for q in range(P.count[ptr]):
            if P.feature[ptr, q] == C.feature[row, p]:
                C.jn[row, p] = P.jn[ptr, q]
                C.jt[row, p] = P.jt[ptr, q]
                C.stick[row, p] = P.stick[ptr, q]
                C.approach[row, p] = P.approach[ptr, q]
                break


@kernel(forceinline=True)
def move_row(C, dst, src):
    """Row ``src`` of the contact table copied into row ``dst``: every field of
    store/contacts.py's CONTACT_FIELDS (tests/test_threads.py checks that none is missed)."""
    C.a[dst] = C.a[src]
    C.b[dst] = C.b[src]
    C.key[dst] = C.key[src]
    C.count[dst] = C.count[src]
    C.e[dst] = C.e[src]
    C.mu_s[dst] = C.mu_s[src]
    C.mu_d[dst] = C.mu_d[src]
    C.colour[dst] = C.colour[src]
    for p in range(2):
        C.normal[dst, p] = C.normal[src, p]
        C.point[dst, p, 0] = C.point[src, p, 0]
        C.point[dst, p, 1] = C.point[src, p, 1]
        C.depth[dst, p] = C.depth[src, p]
        C.feature[dst, p] = C.feature[src, p]
        C.jn[dst, p] = C.jn[src, p]
        C.jt[dst, p] = C.jt[src, p]
        C.stick[dst, p] = C.stick[src, p]
        C.approach[dst, p] = C.approach[src, p]
