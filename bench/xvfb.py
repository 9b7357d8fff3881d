"""A private Xvfb server for the window tests and the launch benchmark."""
from __future__ import annotations

import os
import subprocess
import time
from pathlib import Path


def start_xvfb(size: str = "1280x800x24", timeout: float = 20.0):
    """(process, ``":N"``) of a new Xvfb server, once its socket accepts clients.

    Xvfb picks the free display number itself and writes it to a pipe (``-displayfd``): picking
    one by looking for free lock files first raced between concurrent callers (pytest-xdist
    workers), which then both drew on the first one's screen and took each other's input.
    RuntimeError, with Xvfb's own message, when it does not start."""
    rfd, wfd = os.pipe()
    proc = subprocess.Popen(["Xvfb", "-displayfd", str(wfd), "-screen", "0", size, "-nolisten", "tcp"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, pass_fds=(wfd,))
    os.close(wfd)
    with os.fdopen(rfd) as r:
        got = r.readline().strip()  # empty when Xvfb exits before it has a display
    sock = Path(f"/tmp/.X11-unix/X{got}")
    t0 = time.monotonic()
    while not (got.isdigit() and sock.exists()):
        if not got.isdigit() or proc.poll() is not None or time.monotonic() - t0 > timeout:
            proc.kill()
            err = proc.communicate()[1].decode(errors="replace")
            raise RuntimeError(f"Xvfb did not start: {err.strip() or f'no display within {timeout:g} s'}")
        time.sleep(0.05)
    return proc, f":{got}"
