"""Autosave every minute to the user's cache directory; offer the autosave after a crash.

A session marker (``session.json`` with our pid) exists while the sandbox runs
and is removed on a clean exit; finding one from a dead process at start means
the last session crashed, and its autosave (if any) is offered.
"""
from __future__ import annotations

import json
import os
import time
from pathlib import Path


def cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "stelkropp"


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


class Autosaver:
    def __init__(self, interval: float = 60.0, directory: Path | None = None):
        self.dir = Path(directory) if directory else cache_dir()
        self.interval = interval
        self.file = self.dir / "autosave.json"
        self.marker = self.dir / "session.json"
        self.last = time.monotonic()
        self.last_version = None
        self.error = None

    def previous_crash(self):
        """(autosave path, mtime, original scene path) if the last session died with an autosave."""
        try:
            info = json.loads(self.marker.read_text())
        except (OSError, ValueError):
            return None
        pid = int(info.get("pid", -1))
        if pid != os.getpid() and _pid_alive(pid):
            return None   # another sandbox is running
        if self.file.exists():
            return self.file, self.file.stat().st_mtime, info.get("origin")
        return None

    def begin_session(self, origin=None):
        try:
            self.dir.mkdir(parents=True, exist_ok=True)
            self.marker.write_text(json.dumps({"pid": os.getpid(), "started": time.time(),
                                               "origin": str(origin) if origin else None}))
        except OSError as exc:
            self.error = str(exc)

    def set_origin(self, origin):
        self.begin_session(origin)

    def tick(self, doc, busy: bool = False) -> bool:
        """Autosave if the interval passed and the document has edits not saved yet."""
        now = time.monotonic()
        if now - self.last < self.interval or busy:
            return False
        self.last = now
        if not doc.dirty or doc.history.version == self.last_version:
            return False
        return self.save(doc)

    def save(self, doc) -> bool:
        try:
            self.dir.mkdir(parents=True, exist_ok=True)
            doc.world.save_scene(str(self.file), name=(doc.path.stem if doc.path else "untitled") + " (autosave)")
            self.last_version = doc.history.version
            self.error = None
            return True
        except Exception as exc:  # noqa: BLE001  (never crash the sandbox on an autosave)
            self.error = f"autosave failed: {exc}"
            return False

    def discard(self):
        for f in (self.file,):
            try:
                f.unlink()
            except OSError:
                pass

    def end_session(self):
        """Clean exit: no crash to report next time."""
        self.discard()
        try:
            self.marker.unlink()
        except OSError:
            pass
