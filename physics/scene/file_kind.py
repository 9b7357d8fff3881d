"""What kind of file a path names, for refusing anything but regular files.

Saving renames a temporary file over its target: over a FIFO or a device (``--out /dev/null``
run as root) that replaces the special file itself.  Reading a FIFO with no writer blocks
forever, and reading a device such as /dev/zero never ends.  So scene files are read and
written only when they are regular files (or do not exist yet, for writing).
"""
from __future__ import annotations

import errno
import os
import stat

_KINDS = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO (named pipe)"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISSOCK, "a socket"))


def kind_name(mode: int) -> str | None:
    """'a FIFO (named pipe)', ... for a stat mode that is not a regular file; None for one."""
    if stat.S_ISREG(mode):
        return None
    for test, name in _KINDS:
        if test(mode):
            return name
    return "not a regular file"


class NotRegularFile(OSError):
    """A scene path that exists but is a folder, FIFO, device or socket."""

    def __init__(self, path, kind: str, doing: str):
        super().__init__(errno.EINVAL, f"is {kind}, not a regular file; {doing}", os.fsdecode(path))


def check_writable_target(path) -> None:
    """NotRegularFile if ``path`` (symbolic links followed) exists and is no regular file."""
    try:
        mode = os.stat(path).st_mode
    except (FileNotFoundError, NotADirectoryError):
        return
    kind = kind_name(mode)
    if kind:
        raise NotRegularFile(path, kind, "saving would replace it, so it is refused")


def open_regular(path) -> int:
    """A read-only descriptor of the regular file ``path``; NotRegularFile for anything else.
    Opened without blocking (a FIFO with no writer would block ``open`` itself) and checked on
    the descriptor, so a file swapped after a check cannot slip through."""
    mode = os.stat(path).st_mode  # before opening: opening a device can have effects
    kind = kind_name(mode)
    if kind:
        raise NotRegularFile(path, kind, "scene files are read from regular files only")
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    kind = kind_name(os.fstat(fd).st_mode)
    if kind:
        os.close(fd)
        raise NotRegularFile(path, kind, "scene files are read from regular files only")
    return fd
