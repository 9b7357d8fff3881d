"""The compiler process on the second core: a queue of compile units fed to ``app.compile_worker``.

One unit at a time goes down the pipe, so the queue stays here and a unit the user needs now
(``push(unit, first=True)``) is the next one compiled.  A reader thread follows the worker's
lines: the kernel being compiled (the progress label), how many it finished, which units are in
the cache (``done``) or failed (``failed``: the sandbox then compiles those itself).
"""
from __future__ import annotations

import os
import subprocess
import sys
import threading
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


class CompileHelper:
    """``CompileHelper(on_change)``: ``on_change()`` is called (from the reader thread) whenever a
    unit finishes; ``start()`` launches the process."""

    def __init__(self, on_change=lambda: None):
        self.on_change = on_change
        self.queue: list[str] = []
        self.current: str | None = None
        self.done: set[str] = set()
        self.failed: dict[str, str] = {}
        self.kernels = 0             # kernels the worker finished compiling
        self.unit_kernels: dict[str, int] = {}   # ... per unit (the one compiling now included)
        self.label = ""              # the kernel it is compiling now
        self.alive = False
        self._lock = threading.Lock()
        self._proc = None

    def start(self) -> "CompileHelper":
        env = dict(os.environ)        # NUMBA_CACHE_DIR: set by physics._jit, the same cache
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), env.get("PYTHONPATH")) if p)
        try:
            self._proc = subprocess.Popen([sys.executable, "-m", "app.compile_worker"], cwd=ROOT, env=env,
                                          stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
        except OSError as exc:
            self.failed["*"] = f"could not start the compiler process: {exc}"
            return self
        self.alive = True
        threading.Thread(target=self._read, name="compile-helper-reader", daemon=True).start()
        with self._lock:
            self._feed()
        return self

    def push(self, unit: str, first: bool = False) -> None:
        """Compile ``unit`` after the queued ones (``first``: before them)."""
        with self._lock:
            if unit in self.done or unit in self.failed or unit == self.current:
                return
            if unit in self.queue:
                if not first:
                    return
                self.queue.remove(unit)
            self.queue.insert(0, unit) if first else self.queue.append(unit)
            self._feed()

    def claim(self, unit: str) -> bool:
        """Take ``unit`` back for the caller to compile: True unless the helper is compiling it
        or has it in the cache (then wait for it with ``settled``)."""
        with self._lock:
            if unit in self.queue:
                self.queue.remove(unit)
                return True
            return unit != self.current and unit not in self.done

    def settled(self, unit: str) -> bool:
        """Is ``unit`` finished one way or the other (or will the helper never do it)?"""
        return unit in self.done or unit in self.failed or not self.alive

    def kernels_for(self, units) -> int:
        """Kernels compiled for ``units`` so far (finished or in progress)."""
        return sum(self.unit_kernels.get(u, 0) for u in units)

    def busy(self) -> bool:
        return self.alive and (self.current is not None or bool(self.queue))

    def _feed(self) -> None:
        if self.current is not None or not self.queue or not self.alive:
            return
        self.current = self.queue.pop(0)
        try:
            self._proc.stdin.write(self.current + "\n")
            self._proc.stdin.flush()
        except OSError:
            self._died()

    def _read(self) -> None:
        for line in self._proc.stdout:
            word, _, rest = line.rstrip("\n").partition(" ")
            if word == "start":
                self.label = rest
            elif word == "end":
                self.kernels += 1
                unit = self.current
                self.unit_kernels[unit] = self.unit_kernels.get(unit, 0) + 1
            elif word in ("ok", "error"):
                unit, _, why = rest.partition(" ")
                with self._lock:
                    if word == "ok":
                        self.done.add(unit)
                    else:
                        self.failed[unit] = why
                    self.current = None
                    self.label = ""
                    self._feed()
                self.on_change()
        self._died()

    def _died(self) -> None:
        with self._lock:
            self.alive = False
            if self.current is not None:
                self.failed.setdefault(self.current, "the compiler process ended")
                self.current = None
        self.on_change()

    def close(self) -> None:
        """End the worker (its input closes; it exits after the unit it is compiling)."""
        proc, self._proc = self._proc, None
        if proc is None:
            return
        self.alive = False
        try:
            proc.stdin.close()
        except OSError:
            pass
        try:
            proc.wait(timeout=0.5)
        except subprocess.TimeoutExpired:
            proc.kill()
