"""``python -m app.compile_worker``: the second core's compiler (started by ``app.warmup``).

Reads compile-unit names (``app.compile_units``), one a line, from stdin and compiles each into
numba's disk cache (the same cache directory as the sandbox: it inherits NUMBA_CACHE_DIR).  Says
what it does on stdout, one line each, so the sandbox's progress bar counts both processes:

    start <kernel>       numba began compiling a kernel
    end <kernel>         ... and finished it
    ok <unit>            every kernel of the unit is in the cache
    error <unit> <why>   the unit failed (the sandbox compiles it itself when it needs it)

Exits at the end of its input (the sandbox closed the pipe or exited).
"""
from __future__ import annotations

import os
import sys
import threading
import time
import traceback


def kernel_name(dispatcher) -> str:
    """``module.function`` of a numba dispatcher (for progress labels)."""
    f = dispatcher.py_func
    return f"{f.__module__}.{f.__qualname__}"


def listen(on_start, on_end) -> None:
    """Call ``on_start(name)`` / ``on_end(name)`` around each kernel numba really compiles in this
    process (a kernel loaded from the disk cache raises no event)."""
    from numba.core import event

    class _Listener(event.Listener):
        def on_start(self, ev):
            on_start(kernel_name(ev.data["dispatcher"]))

        def on_end(self, ev):
            on_end(kernel_name(ev.data["dispatcher"]))

    event.register("numba:compile", _Listener())


def _say(*words) -> None:
    try:
        print(*words, flush=True)
    except (BrokenPipeError, ValueError):   # the sandbox is gone: so is the point of compiling
        os._exit(0)


def _die_with_parent() -> None:
    """Exit as soon as the sandbox is gone (killed: it could not close our input)."""
    parent = os.getppid()

    def watch():
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(0)
    threading.Thread(target=watch, name="parent-watch", daemon=True).start()


def hold(unit: str) -> None:
    """Wait before ``unit`` while a hold asks for it: ``STELKROPP_HOLD="<prefix>,<prefix>...:<file>"``
    holds every unit whose name starts with one of the prefixes for as long as ``file`` exists.  A
    compile that loads from a warm cache takes seconds, one from a cold cache minutes: the window
    tests hold units to see, for certain and without the minutes, what the sandbox shows while it
    waits for them."""
    prefixes, _, path = os.environ.get("STELKROPP_HOLD", "").rpartition(":")
    if path and any(p and unit.startswith(p) for p in prefixes.split(",")):
        while os.path.exists(path):
            time.sleep(0.1)


def main() -> int:
    _die_with_parent()
    from . import compile_units
    listen(lambda k: _say("start", k), lambda k: _say("end", k))
    for line in sys.stdin:
        unit = line.strip()
        if not unit:
            continue
        hold(unit)
        try:
            with compile_units.unit_lock(unit):
                compile_units.run(unit)
        except Exception as exc:  # noqa: BLE001  (one broken mode must not stop the others)
            traceback.print_exc(file=sys.stderr)
            _say("error", unit, f"{type(exc).__name__}: {exc}".replace("\n", " "))
        else:
            compile_units.mark(unit)
            _say("ok", unit)
    return 0


if __name__ == "__main__":
    sys.exit(main())
