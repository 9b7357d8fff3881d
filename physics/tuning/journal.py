"""Results streamed to a file as cases finish, so an interrupted sweep keeps what it has and
``--resume`` runs only the missing cases (issue 19).

The file is JSON lines: a header naming the scene (a hash of its data), the step count and the
sample stride, then one finished run per line, appended and flushed as it arrives.  A line cut
short by a kill is ignored on reading.  Runs are deterministic, so a stored run stands for a new
one (its seconds are the ones measured then).
"""
from __future__ import annotations

import hashlib
import json

import numpy as np

from .records import Records
from .runs import Run

_ARRAYS = ("positions", "angles", "kinetic", "potential", "speeds", "sizes", "links")
# 2: runs carry their constraint lengths (links, pins); a version-1 file is refused, not misread
VERSION = 2


def scene_hash(scene: dict) -> str:
    """A short hash of the scene data (keys sorted): what a results file belongs to."""
    return hashlib.sha1(json.dumps(scene, sort_keys=True).encode()).hexdigest()[:16]


def Journal(path, scene: dict, steps: int, stride: int, resume: bool) -> Records:
    """The tuner's runs of one sweep in a JSON-lines file at ``path`` (records.Records: ``done``,
    ``add(key, run)``).  ValueError naming ``results`` if ``resume`` finds a file made for another
    scene, step count or stride; OSError if it cannot be written."""
    header = {"stelkropp_tune": VERSION, "scene": scene_hash(scene), "steps": steps, "stride": stride}
    return Records(path, header, resume, encode=_rec, decode=_run)


def _rec(run: Run) -> dict:
    rec = {k: getattr(run, k) for k in ("key", "depth", "seconds", "steps", "error")}
    rec.update({k: getattr(run, k).tolist() for k in _ARRAYS})
    rec["pins"] = run.pins.tolist()
    return rec


def _run(rec: dict) -> Run:
    arrays = {k: np.asarray(rec[k], dtype=np.float64) for k in _ARRAYS}
    n = arrays["sizes"].shape[0]
    arrays["positions"] = arrays["positions"].reshape(-1, n, 2)
    arrays["angles"] = arrays["angles"].reshape(-1, n)
    arrays["speeds"] = arrays["speeds"].reshape(-1, n)
    pins = np.asarray(rec["pins"], dtype=bool)
    k = len(arrays["kinetic"])  # (reshape(-1, 0) is ambiguous: a scene without constraints)
    arrays["links"] = arrays["links"].reshape(k, len(pins))
    return Run(rec["key"], arrays["positions"], arrays["angles"], arrays["kinetic"], arrays["potential"],
               arrays["speeds"], rec["depth"], rec["seconds"], rec["steps"], rec["error"], arrays["sizes"],
               arrays["links"], pins)
