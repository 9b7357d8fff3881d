"""Interleaved timing: several engines on the same scene, chunk by chunk in turn.

Every sim runs its scene in chunks of steps (ours, pymunk, pybox2d, ours, ...); chunks before
``warm`` steps are not timed.  ms/step is the median over the timed chunks and a ratio between
two engines is the median of their per-chunk ratios, so machine noise that hits every engine
within one round cancels.  The first step (numba compile or cache load) is timed apart.
"""
from __future__ import annotations

import gc
import time

import numpy as np


def interleaved(sims, steps, chunk, warm, budget_s=None):
    """Step every sim of the dict ``sims`` ``steps`` times, ``chunk`` steps at a time in turn.

    Returns (first-step seconds per sim, per-chunk seconds/step per sim for the chunks after
    ``warm`` steps, steps done, error text or None).  An exception in a sim stops the run and is
    reported, not raised; so is running past ``budget_s`` seconds.  The garbage collector is off
    while the chunks run (a collection inside one engine's chunk is noise)."""
    first, chunks = {}, {k: [] for k in sims}
    err = None
    t_start = time.perf_counter()
    for k, s in sims.items():
        t = time.perf_counter()
        try:
            s.step()
        except Exception as exc:
            return first, chunks, 0, f"{k}: {type(exc).__name__}: {exc}"
        first[k] = time.perf_counter() - t
    done = 1
    gc_was = gc.isenabled()
    gc.disable()
    try:
        while done < steps:
            c = min(chunk, steps - done)
            err = _round(sims, c, chunks if done >= warm else None)
            if err:
                break
            done += c
            if budget_s and time.perf_counter() - t_start > budget_s and done < steps:
                err = f"stopped after {done} steps: over the {budget_s:.0f} s budget"
                break
    finally:
        if gc_was:
            gc.enable()
    return first, chunks, done, err


def _round(sims, c, chunks):
    """One chunk of ``c`` steps of every sim in turn; seconds/step appended to ``chunks`` (None:
    warm-up, not kept).  Returns an error text when a sim raised."""
    for k, s in sims.items():
        t = time.perf_counter()
        try:
            for _ in range(c):
                s.step()
        except Exception as exc:
            return f"{k}: {type(exc).__name__}: {str(exc)[:200]}"
        el = (time.perf_counter() - t) / c
        if chunks is not None:
            chunks[k].append(el)
    return None


def chunk_ratio(a, b) -> float | None:
    """Median of the per-chunk ratios a[i] / b[i] over the chunks both have (None: no chunks)."""
    n = min(len(a), len(b))
    if n == 0:
        return None
    return float(np.median(np.array(a[:n]) / np.array(b[:n])))


def median_ms(chunks) -> float | None:
    """Median seconds/step of ``chunks`` in ms (None: no chunks)."""
    return float(np.median(chunks)) * 1e3 if chunks else None


def min_ms(chunks) -> float | None:
    """Fastest chunk's seconds/step in ms (None: no chunks)."""
    return float(np.min(chunks)) * 1e3 if chunks else None
