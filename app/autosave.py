"""Autosave every minute to the user's cache directory; offer the autosave after a crash.

Each running sandbox has its own session marker (``session-<pid>.json``, naming its pid) and its
own autosave (``autosave-<pid>.json``); a clean exit removes both.  At start, a marker whose
process is dead means that session crashed, and its autosave (if any) is offered.  A marker of
a sandbox that is still running is never offered: its autosave is that instance's work.
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
        self.file = self.dir / f"autosave-{os.getpid()}.json"
        self.marker = self.dir / f"session-{os.getpid()}.json"
        self.last = time.monotonic()
        self.last_version = None
        self.error = None

    def previous_crash(self):
        """(autosave path, mtime, original scene path) of the newest session that died with an
        autosave, or None.  Running sessions (their pid is alive) are skipped."""
        found = []
        for marker in self.dir.glob("session-*.json"):
            try:
                info = json.loads(marker.read_text())
            except (OSError, ValueError):
                continue
            pid = int(info.get("pid", -1))
            if pid != os.getpid() and _pid_alive(pid):
                continue   # another sandbox is running: not a crash
            autosave = marker.with_name("autosave-" + marker.name[len("session-"):])
            if autosave.exists():
                found.append((autosave.stat().st_mtime, autosave, info.get("origin"), marker))
        if not found:
            return None
        mtime, autosave, origin, marker = max(found, key=lambda f: f[0])
        self.crashed_marker = marker
        return autosave, mtime, origin
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
            doc.world.save_scene(str(self.file), name=_title(doc.path) + " (autosave)")
            self.last_version = doc.history.version
            self.error = None
            return True
        except Exception as exc:  # noqa: BLE001  (never crash the sandbox on an autosave)
            self.error = f"autosave failed: {exc}"
            return False

    def discard(self, path=None):
        """Delete an autosave (default: this session's) and, for a crashed one, its marker."""
        files = [self.file] if path is None else [Path(path), getattr(self, "crashed_marker", None)]
        for f in files:
            try:
                if f is not None:
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


def _title(path) -> str:
    """The scene's title from its file name: a name that is not UTF-8 reaches Python with lone
    surrogates (surrogateescape), which a scene file cannot hold, so those bytes become U+FFFD."""
    if path is None:
        return "untitled"
    return path.stem.encode("utf-8", "surrogateescape").decode("utf-8", "replace")
