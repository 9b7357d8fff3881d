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
import os

import numpy as np

from .runs import Run

_ARRAYS = ("positions", "angles", "kinetic", "potential", "speeds", "sizes")


def scene_hash(scene: dict) -> str:
    """A short hash of the scene data (keys sorted): what a results file belongs to."""
    return hashlib.sha1(json.dumps(scene, sort_keys=True).encode()).hexdigest()[:16]


class Journal:
    """Finished runs of one sweep in a JSON-lines file at ``path``: ``done`` (key -> Run) after
    opening; ``add`` appends one.  ValueError naming ``results`` if ``resume`` finds a file made for
    another scene, step count or stride; OSError if it cannot be written."""

    def __init__(self, path, scene: dict, steps: int, stride: int, resume: bool):
        self.path = os.fspath(path)
        self.header = {"stelkropp_tune": 1, "scene": scene_hash(scene), "steps": steps, "stride": stride}
        self.done: dict[str, Run] = {}
        if resume and os.path.exists(self.path):
            self._read()
            self._file = open(self.path, "a", encoding="utf-8")
        else:
            self._file = open(self.path, "w", encoding="utf-8")
            self._write(self.header)

    def _read(self) -> None:
        with open(self.path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        try:
            head = json.loads(lines[0])
        except (ValueError, IndexError):
            head = None
        if head != self.header:
            raise ValueError(f"results: {self.path} was written for another scene, step count or sample "
                             "stride; remove it or run without --resume")
        for line in lines[1:]:
            try:
                rec = json.loads(line)
            except ValueError:  # the last line of a killed run may be cut short
                continue
            self.done[rec["key"]] = _run(rec)

    def add(self, run: Run) -> None:
        """Append a finished run and flush it to the file."""
        self.done[run.key] = run
        rec = {k: getattr(run, k) for k in ("key", "depth", "seconds", "steps", "error")}
        rec.update({k: getattr(run, k).tolist() for k in _ARRAYS})
        self._write(rec)

    def _write(self, rec: dict) -> None:
        self._file.write(json.dumps(rec) + "\n")
        self._file.flush()

    def close(self) -> None:
        """Close the file (what was added is already on disk)."""
        self._file.close()


def _run(rec: dict) -> Run:
    arrays = {k: np.asarray(rec[k], dtype=np.float64) for k in _ARRAYS}
    n = arrays["sizes"].shape[0]
    arrays["positions"] = arrays["positions"].reshape(-1, n, 2)
    arrays["angles"] = arrays["angles"].reshape(-1, n)
    arrays["speeds"] = arrays["speeds"].reshape(-1, n)
    return Run(rec["key"], arrays["positions"], arrays["angles"], arrays["kinetic"], arrays["potential"],
               arrays["speeds"], rec["depth"], rec["seconds"], rec["steps"], rec["error"], arrays["sizes"])
