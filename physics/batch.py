"""Vectorised validation for the batch API: body ids to slots, per-row arrays, the row to blame.

Every row is checked before anything is written, so a refused call changes nothing; the
ValueError names the argument and the first bad row (``forces[3]: must be finite ...``).
"""
from __future__ import annotations

import numpy as np


def slots_of(world, ids) -> np.ndarray:
    """Slots of the bodies with these ids ((k,) whole numbers), by a sorted search (no Python loop)."""
    a = np.asarray(ids)
    if a.ndim != 1 or (a.size and a.dtype.kind not in "iu"):
        raise ValueError(f"ids: expected a 1-d array of body ids (whole numbers), got shape {a.shape} "
                         f"of {a.dtype}")
    st = world._store.bodies
    have = st.view.id[: st.n]
    order = np.argsort(have, kind="stable")
    pos = np.searchsorted(have[order], a)
    pos = np.minimum(pos, max(st.n - 1, 0))
    ok = (st.n > 0) & (have[order][pos] == a) if st.n else np.zeros(a.shape, bool)
    if not np.all(ok):
        k = int(np.nonzero(~ok)[0][0])
        raise ValueError(f"ids[{k}]: no body with id {int(a[k])} in this world")
    return order[pos].astype(np.intp)


def rows(value, k: int, field: str, width: int = 2) -> np.ndarray:
    """A finite (k, width) float array (or (k,) for width 0: one number per row); one row
    broadcasts.  ValueError naming ``field`` and the first non-finite row."""
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: expected numbers, got {type(value).__name__}") from None
    shape = (k,) if width == 0 else (k, width)
    try:
        a = np.broadcast_to(a, shape)
    except ValueError:
        raise ValueError(f"{field}: expected shape {shape}, got {a.shape}") from None
    return finite_rows(a, field)


def finite_rows(a: np.ndarray, field: str, what: str = "must be finite") -> np.ndarray:
    """``a`` if every row is finite, else ValueError naming ``field`` and the first bad row."""
    bad = ~np.isfinite(a) if a.ndim == 1 else ~np.isfinite(a).all(axis=1)
    if np.any(bad):
        k = int(np.nonzero(bad)[0][0])
        raise ValueError(f"{field}[{k}]: {what}, got {np.asarray(a[k]).tolist()}")
    return a


def cross(r: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Row-wise 2-d cross product r x f (the torque of f at lever r), in Body.apply_force's order."""
    return r[:, 0] * f[:, 1] - r[:, 1] * f[:, 0]


def wake_slots(world, slots: np.ndarray) -> None:
    """Wake these bodies and their sleeping islands (World._touched for many slots at once)."""
    B = world._bodies.view
    n = world._bodies.n
    lab = B.island[slots]
    mask = np.isin(B.island[:n], lab[lab >= 0])
    mask[slots] = True
    B.awake[:n][mask] = 1
    B.sleep_t[:n][mask] = 0.0
    B.island[:n][mask] = -1
    world._pipeline.invalidate()
