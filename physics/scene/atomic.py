"""Atomic file writes: a temporary file in the target's folder, fsync, rename over the target.

A crash leaves the old file or the new one, never half of either.  What a
crash can leave is the temporary file itself; its name carries the writer's
process id (``.NAME.<pid>.<random>.tmp``), so the next save to the same name
removes the ones whose writer no longer runs.  Saving through a symbolic link
writes the link's target and keeps the link.  The temporary name is
shortened to fit the folder's NAME_MAX, so any file name that is legal can
be saved.
"""
from __future__ import annotations

import os
import secrets

from .file_kind import check_writable_target

_SUFFIX = ".tmp"
# temporary files this process is writing right now (another thread may be saving the same name)
_IN_FLIGHT: set = set()


def write_atomic(path, text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically, keeping the old file's permissions.

    Raises OSError (the old file untouched, no temporary file left) if it cannot be written,
    file_kind.NotRegularFile (an OSError) if ``path`` is a folder, FIFO, device or socket.
    """
    target = os.path.realpath(scene_path(path))  # through symlinks: replace the target, keep the link
    check_writable_target(target)  # a FIFO or device must not be replaced by the rename
    folder, name = os.path.split(target)
    prefix = _temp_prefix(folder, name)
    _remove_stale(folder, prefix)
    fd, tmp = _create_temp(folder, prefix)
    _IN_FLIGHT.add(tmp)
    try:
        try:  # the temporary file is private (0600); the scene keeps the old file's mode
            mode = os.stat(target).st_mode & 0o777
        except FileNotFoundError:
            mode = 0o644
        os.chmod(tmp, mode)
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as f:
            fd = None  # the file object owns it now
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, target)
    except BaseException:
        if fd is not None:
            os.close(fd)
        _unlink(tmp)
        raise
    finally:
        _IN_FLIGHT.discard(tmp)
    _sync_folder(folder)


def scene_path(path) -> str:
    """``path`` (str, bytes or os.PathLike) as a str (bytes decoded as the file system does, so any
    name round-trips); TypeError naming what was given for anything else (an int would be taken
    for an open file descriptor)."""
    if not isinstance(path, (str, bytes, os.PathLike)):
        raise TypeError(f"path: expected a str, bytes or os.PathLike file name, got {type(path).__name__}")
    return os.fsdecode(os.fspath(path))


def _temp_prefix(folder: str, name: str) -> str:
    """``.NAME.`` shortened (at a character boundary) so ``.NAME.<pid>.<8 hex>.tmp`` fits NAME_MAX."""
    try:
        limit = os.pathconf(folder, "PC_NAME_MAX")
    except (OSError, ValueError):
        limit = 255
    room = limit - len(f"..{'0' * 10}.{'0' * 8}{_SUFFIX}")  # pids have at most 10 digits
    while len(os.fsencode(name)) > room:
        name = name[:-1]
    return f".{name}."


def _create_temp(folder: str, prefix: str):
    while True:
        tmp = os.path.join(folder, f"{prefix}{os.getpid()}.{secrets.token_hex(4)}{_SUFFIX}")
        try:
            return os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600), tmp
        except FileExistsError:
            continue


def _remove_stale(folder: str, prefix: str) -> None:
    """Remove temporary files of earlier saves to this name whose writer has died (kill -9, power loss
    leaves no chance to clean up); a live writer's file is left alone."""
    try:
        names = os.listdir(folder)
    except OSError:
        return
    for n in names:
        if not (n.startswith(prefix) and n.endswith(_SUFFIX)):
            continue
        pid, _, token = n[len(prefix):-len(_SUFFIX)].partition(".")
        path = os.path.join(folder, n)
        if pid.isdigit() and len(token) == 8 and not _alive(int(pid), path):
            _unlink(path)


def _alive(pid: int, path: str) -> bool:
    """Whether the process that made temporary file ``path`` may still be writing it."""
    if pid == os.getpid():
        return path in _IN_FLIGHT
    if os.name != "posix":
        return True  # no harmless "does it exist" signal elsewhere (os.kill terminates on Windows)
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, OSError):
        return True  # exists but is not ours, or cannot tell: leave it
    return True


def _unlink(path: str) -> None:
    try:
        os.unlink(path)
    except OSError:
        pass


def _sync_folder(folder: str) -> None:
    """Make the rename itself durable (POSIX: fsync the directory); best effort."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)
