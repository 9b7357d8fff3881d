"""Results streamed to a JSON-lines file as cases finish, so an interrupted sweep keeps what it
has and ``--resume`` runs only the missing cases (issue 19).  The one journal behind ``tune``
(journal.py), ``bench`` and ``bench.reliability``.

The file's first line is a header saying what the results belong to (the caller's: a scene hash,
step counts, the options); each later line is ``{"key": ..., "value": ...}``, appended and
flushed as its case finishes.  A line cut short by a kill is ignored on reading; a header that
differs from the caller's refuses the file rather than mixing another sweep's results in.
"""
from __future__ import annotations

import json
import os


class Records:
    """Finished cases of one sweep in the file at ``path``: ``done`` (key -> value) after opening,
    ``add(key, value)`` appends one.  ``encode``/``decode`` turn a value into JSON data and back.
    ValueError naming ``results`` if ``resume`` finds a file with another header; OSError if the
    file cannot be written."""

    def __init__(self, path, header: dict, resume: bool, encode=None, decode=None):
        self.path = os.fspath(path)
        self.header = dict(header)
        self._encode = encode or (lambda v: v)
        self._decode = decode or (lambda v: v)
        self.done: dict = {}
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
        if head != json.loads(json.dumps(self.header)):
            raise ValueError(f"results: {self.path} was written for another scene or other options "
                             "(another scene, step count or sample stride); remove it or run without --resume")
        for line in lines[1:]:
            try:
                rec = json.loads(line)
            except ValueError:  # the last line of a killed run may be cut short
                continue
            self.done[rec["key"]] = self._decode(rec["value"])

    def add(self, key, value) -> None:
        """Append a finished case and flush it to the file."""
        self.done[key] = value
        self._write({"key": key, "value": self._encode(value)})

    def _write(self, rec: dict) -> None:
        self._file.write(json.dumps(rec) + "\n")
        self._file.flush()

    def close(self) -> None:
        """Close the file (what was added is already on disk)."""
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False
