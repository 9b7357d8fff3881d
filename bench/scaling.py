"""Scaling with body count: free-standing columns of boxes, contacts per body constant."""
from __future__ import annotations

import gc

import numpy as np

from .cases import ScalingCase
from .engines import build
from .engines.ours import OursSim
from .scenes import BENCH_WORLD, columns
from .desc import with_world
from .timing import chunk_ratio, interleaved


def run_scaling_case(case) -> list[dict]:
    """Rows (one per engine) for ``case``: chunks of min(30, 3000 / n) steps, eight of them timed
    after two untimed."""
    n = case.n
    desc = with_world(columns(n), **BENCH_WORLD)
    sims = {"ours": OursSim(desc, solver=case.mode), **{e: build(e, desc) for e in case.engines}}
    chunk = int(min(30, max(3, 3000 // n)))
    first, chunks, done, err = interleaved(sims, 1 + chunk * 8, chunk, 1 + 2 * chunk)
    contacts = int(sims["ours"].world.info()["contacts"])
    rows = []
    for k, c in chunks.items():
        eng = "stelkropp" if k == "ours" else k
        r = dict(n=n, engine=eng, mode=case.mode if k == "ours" else k,
                 ms_step=float(np.median(c)) * 1e3 if c else None, chunks=len(c), status=err or "ok",
                 contacts=contacts if k == "ours" else None)
        if k == "ours":
            for e in case.engines:
                if e in chunks:
                    r[f"ratio_{e}"] = chunk_ratio(c, chunks[e])
        rows.append(r)
    return rows


def scaling(ns, mode, engines=(), progress=None) -> list[dict]:
    """Rows for every body count in ``ns`` (default-settings ``mode`` against ``engines``)."""
    rows = []
    for n in ns:
        if progress:
            progress.set_description(f"scaling: {n} bodies")
        rows += run_scaling_case(ScalingCase(n, mode, tuple(engines)))
        if progress:
            progress.update(1)
        gc.collect()
    return rows


def loglog_slope(rows, engine) -> float | None:
    """Slope of log ms/step against log n for ``engine`` (1.0: linear; None: under two points)."""
    pts = [(r["n"], r["ms_step"]) for r in rows if r["engine"] == engine and r.get("ms_step")]
    if len(pts) < 2:
        return None
    x, y = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return float(np.polyfit(x, y, 1)[0])
