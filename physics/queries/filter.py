"""The query filter: a query is a fixture-like (category, mask) pair (Box2D v3's b2QueryFilter)."""
from __future__ import annotations

from .._jit import kernel


@kernel(inline="always")
def accepts(F, f, category, mask):
    """Does fixture f pass a query of ``category``/``mask`` (each side's category in the other's mask)?"""
    return (F.category[f] & mask) != 0 and (F.mask[f] & category) != 0
