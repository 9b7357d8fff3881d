"""The solver panel's Find settings: the tuner (issue 19) on a copy of the scene, in a background
process (``app.tune_worker``), and the choice applied as one undoable edit.

The scene sent is the document's (its bodies, springs and joints as loaded or last saved: what
Reset returns to) with the world settings and the solver choice the window has now, so the
tuner's baseline is what the user runs and the choice is relative to it.  The live world is never
read from another thread: the copy is made on the UI thread when the button is pressed.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

from .commands import Group, SetWorld
from .document import WORLD_FIELDS, restore

ROOT = Path(__file__).resolve().parent.parent
#: seconds a cancelled search may take to finish its current run before the process is killed
CANCEL_GRACE = 3.0
#: seconds after a kernel's compile the search still shows "compiling" (numba's next may follow)
COMPILE_GAP = 1.0


def scene_copy(editor) -> dict:
    """Scene data for the tuner: the document's loaded bodies with the live world's settings."""
    from physics.scene import scene_to_dict
    from .files import keep_solver_choice
    live = editor.world
    w = restore(editor.doc.loaded)
    for f in WORLD_FIELDS:
        setattr(w, f, getattr(live, f))
    keep_solver_choice(live, w)
    return scene_to_dict(w)


class Finder:
    """One search at a time.  ``state``: idle, running, cancelling, done, cancelled or error;
    ``progress`` (stage, done, total); ``result`` (``tune_worker.summary``) when done; ``error``;
    ``compiling`` (kernels numba is compiling in the search's process now: nested, so a depth),
    ``compiled`` (kernels it has finished) and ``kernel`` (the last one begun).  Fields are
    written by the reader thread and read by the UI each frame (plain assignments)."""

    def __init__(self):
        self.state = "idle"
        self.progress = ("", 0, 0)
        self.result: dict | None = None
        self.error = ""
        self.compiling, self.compiled, self.kernel = 0, 0, ""
        self._compile_t = -1e9
        self.options: dict = {}
        self.started = 0.0
        self.seconds = 0.0
        self._proc = None
        self._deadline = None

    @property
    def pid(self) -> int | None:
        """The search process's id (None before the first search)."""
        return self._proc.pid if self._proc is not None else None

    @property
    def busy(self) -> bool:
        return self.state in ("running", "cancelling")

    def start(self, scene: dict, steps: int, metric: str, budget: float) -> None:
        """Start a search (a running one is cancelled first); OSError if the process cannot start."""
        self.close()
        env = dict(os.environ)       # NUMBA_CACHE_DIR (set by physics._jit): the window's kernel cache
        # stderr is the sandbox's own: a crash in the worker leaves its traceback in the log
        env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), env.get("PYTHONPATH")) if p)
        proc = subprocess.Popen([sys.executable, "-m", "app.tune_worker"], cwd=ROOT, env=env, text=True,
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=None,
                                bufsize=1)
        self.options = {"steps": steps, "metric": metric, "budget": budget}
        self.state, self.progress, self.result, self.error = "running", ("starting", 0, 0), None, ""
        self.compiling, self.compiled, self.kernel = 0, 0, ""
        self.started, self.seconds, self._deadline, self._proc = time.monotonic(), 0.0, None, proc
        proc.stdin.write(json.dumps({"scene": scene, **self.options}) + "\n")
        proc.stdin.flush()
        threading.Thread(target=self._read, args=(proc,), name="find-settings-reader", daemon=True).start()

    def _read(self, proc) -> None:
        try:
            for line in proc.stdout:
                if proc is not self._proc:     # a search replaced or closed: its last words are not ours
                    break
                self._record(line)
        except (OSError, ValueError):          # close() closed the pipe under us
            return
        proc.wait()
        if proc is self._proc and self.busy:   # it died without a word (killed, or crashed)
            self._finish("cancelled" if self.state == "cancelling" else "error",
                         error=f"the tuner process exited with code {proc.returncode}")

    def _record(self, line) -> None:
        try:
            rec = json.loads(line)
        except ValueError:
            return
        if "compile" in rec:
            self._compile(*rec["compile"])
        elif "progress" in rec:
            self.progress = tuple(rec["progress"])
        elif "result" in rec:
            self._finish("done", result=rec["result"])
        elif "error" in rec:
            self._finish("error", error=rec["error"])
        elif "cancelled" in rec:
            self._finish("cancelled")

    @property
    def is_compiling(self) -> bool:
        """Numba is compiling in the search's process (or finished a kernel under COMPILE_GAP s
        ago: between two kernels the state does not flicker)."""
        return self.busy and (self.compiling > 0 or time.monotonic() - self._compile_t < COMPILE_GAP)

    def _compile(self, what, kernel) -> None:
        self._compile_t = time.monotonic()
        if what == "start":
            self.compiling, self.kernel = self.compiling + 1, kernel
        else:
            self.compiling, self.compiled = max(0, self.compiling - 1), self.compiled + 1

    def _finish(self, state, result=None, error="") -> None:
        self.result, self.error, self.compiling = result, error, 0
        self.seconds = time.monotonic() - self.started
        self.state = state

    def cancel(self) -> None:
        """Ask the search to stop at its next run; it is killed if it has not within CANCEL_GRACE."""
        if not self.busy or self._proc is None:
            return
        self.state = "cancelling"
        self._deadline = time.monotonic() + CANCEL_GRACE
        try:
            self._proc.stdin.write("cancel\n")
            self._proc.stdin.flush()
        except (OSError, ValueError):
            pass

    def poll(self) -> None:
        """Called each frame: kill a cancelled search that overran its grace period."""
        if self.state == "cancelling" and self._deadline and time.monotonic() > self._deadline:
            self._kill()

    def discard(self) -> None:
        """Forget the result (another scene was opened); a running search is stopped."""
        self.close()
        self.state, self.result, self.error = "idle", None, ""

    def _kill(self) -> None:
        proc = self._proc
        if proc is not None and proc.poll() is None:
            proc.kill()

    def close(self) -> None:
        """Stop the process, if any (the sandbox quits or a new search starts)."""
        proc, self._proc = self._proc, None
        if proc is None:
            return
        if proc.poll() is None:
            proc.kill()
            proc.wait(5)
        for f in (proc.stdin, proc.stdout):
            try:
                f.close()
            except (OSError, ValueError):
                pass
        if self.busy:
            self.state = "cancelled"


def apply_command(world, choice: dict) -> Group:
    """One undoable edit setting the world's solver, that mode's settings, dt and integrator to
    ``choice`` (a ``tune_worker.summary`` choice); only what differs is changed."""
    mode = choice["solver"]
    cmds = []
    if world.solver != mode:
        def set_solver(m):
            world.solver = m
            world.wake_all()     # as a mode switch does: a sleeping pile would show nothing new
        cmds.append(SetWorld(lambda: world.solver, set_solver, mode, "solver"))
    now = world.settings_for(mode)
    for name, value in choice["settings"].items():
        if now[name] != value:
            cmds.append(SetWorld(lambda n=name: world.settings_for(mode)[n],
                                 lambda v, n=name: world.settings_for(mode).__setitem__(n, v), value,
                                 f"{mode}.{name}"))
    for attr in ("dt", "integrator"):
        if getattr(world, attr) != choice[attr]:
            cmds.append(SetWorld(lambda a=attr: getattr(world, a), lambda v, a=attr: setattr(world, a, v),
                                 choice[attr], attr))
    return Group(cmds, "apply found settings")
