"""A solver mode picked before its kernels are loaded: the scene goes on in the mode it runs, the
new mode compiles first, and the switch happens by itself once it is ready.

Switching at once would stop the scene until the new mode is compiled (a minute or more on a
cold cache: ``app.warmup``); the user would see a frozen scene and could not tell it apart from
a hang.  So ``Editor.switch_solver`` asks ``PendingSwitch.request`` first.  A mode whose kernels
are loaded switches at once, as before; so does any mode while the running one is not ready
either (the first launch: the scene waits in any case).  Otherwise the mode is pending: the
warmup compiles it before anything else it was asked for, the solver panel shows it with its
progress, and ``update`` (every frame) switches through the same undoable edit as a click would
once every kernel a step of the new mode runs is loaded.

Picking the running mode again, or another mode that is ready, cancels it; picking another mode
that is not ready replaces it; a mode set another way (Find settings' apply) cancels it.  Undo and redo leave it alone (it is not an edit yet), a reset
keeps it (a reset keeps the solver choice: ``app.files``), opening another scene cancels it (it
was asked for that scene, not this one).  While the mouse drag holds a body, the switch waits
for the release.
"""
from __future__ import annotations

import time

from . import compile_units
from .simulation import waits_for


class PendingSwitch:
    """The mode switch of ``editor`` that waits for ``warmup``; ``mode`` is the mode waited for
    (None: nothing pending)."""

    def __init__(self, editor, warmup):
        self.editor = editor
        self.warmup = warmup
        self.mode: str | None = None
        self.since = 0.0                 # monotonic time the user picked it
        self._doc = None                 # the document it was picked in
        self._key = None                 # (mode, integrator, broad phase) it waits for
        self._units: list[str] = []      # its compile units that were not in the cache then
        editor.mode_gate = self.request
        editor.on_document.append(self._document)
        editor.on_mode.append(self._mode_set)

    # -- what the editor and the panels ask -------------------------------------------
    def request(self, mode: str) -> bool:
        """``Editor.switch_solver(mode)`` asks first: True if the switch is handled here (the mode
        is the running one, or it compiles first and switches later); False to switch now."""
        ed = self.editor
        w = ed.world
        if mode == w.solver:
            if self.mode is not None:
                self.cancel(f"solver stays {w.solver}: the switch to {self.mode} is cancelled")
            return True
        if waits_for(self.warmup, w):
            self.clear()        # the running mode is not ready either: the scene waits anyway
            return False
        key = self._key_of(mode)
        self.warmup.prioritize(*key, first=True)
        if not self._waits(mode):
            self.clear()        # ready: switch now (a pending one is dropped)
            return False
        self.mode, self.since, self._doc = mode, time.monotonic(), ed.doc
        self._rekey(key)
        ed.notify(f"{mode} compiles first: {w.solver} runs until then (pick {w.solver} again to stay)")
        return True

    def update(self) -> None:
        """Every frame: switch once the pending mode is ready."""
        if self.mode is None:
            return
        ed = self.editor
        w = ed.world
        if ed.doc is not self._doc:
            self.cancel(f"the switch to {self.mode} is cancelled: another scene is open")
            return
        if w.solver == self.mode:      # there another way (redo, Find settings' apply)
            self.clear()
            return
        key = self._key_of(self.mode)
        if key != self._key:           # the integrator or broad phase changed meanwhile
            self.warmup.prioritize(*key, first=True)
            self._rekey(key)
        if ed.tool_joints or self._waits(self.mode):
            return                     # (a mouse drag holds a body: after its release)
        mode = self.mode
        self.clear()
        ed.switch_solver(mode, now=True)

    def cancel(self, why: str) -> None:
        if self.mode is not None:
            self.editor.notify(why)
        self.clear()

    def clear(self) -> None:
        self.mode = self._doc = self._key = None
        self._units = []

    def progress(self):
        """(fraction 0..1, the work left in words) of the pending mode's kernels."""
        if self.mode is None:
            return 1.0, ""
        if not self._units:
            return 0.99, "loading its kernels from the cache"
        return self.warmup.mode_progress(self._units)

    def describe(self):
        """For the status file: the pending switch, or None."""
        if self.mode is None:
            return None
        frac, text = self.progress()
        return {"mode": self.mode, "from": self.editor.world.solver, "progress": frac, "text": text,
                "seconds": time.monotonic() - self.since}

    # -- inside -------------------------------------------------------------------------
    def _key_of(self, mode):
        w = self.editor.world
        return mode, w.integrator, compile_units.broadphase_of(w)

    def _rekey(self, key) -> None:
        self._key = key
        units = self.warmup.mode_units(*key, joints=bool(self.editor.world.joints))
        self._units = [u for u in units if not self.warmup.cached(u)]

    def _waits(self, mode) -> bool:
        """Would a step in ``mode`` wait for a kernel?  As ``simulation.waits_for``, except that a
        joint stage is compiled by the helper process and only loaded here (a compile in the
        window's process would slow its frames while the scene runs)."""
        w = self.editor.world
        warm = self.warmup
        solver, integrator, bp = self._key_of(mode)
        if not warm.can_step(solver, integrator, bp):
            warm.prioritize(solver, integrator, bp)
            return True
        narrow = compile_units.narrow_unit(w)
        if not warm.narrow_ready(narrow):
            warm.want_unit(narrow)
            return True
        if w.joints and not warm.joints_ready(solver, integrator):
            warm.want_apart(compile_units.joints_unit(solver, integrator))
            return True
        return False

    def _mode_set(self, solver, integrator) -> None:
        """A mode set another way meanwhile (Find settings' apply) is the newer choice."""
        if self.mode is not None and solver != self.mode:
            self.cancel(f"the switch to {self.mode} is cancelled: {solver} was chosen")

    def _document(self, world, path, keep_camera) -> None:
        if self.mode is None:
            return
        if keep_camera:                # a reset: the same scene, and it keeps the solver choice
            self._doc = self.editor.doc
        else:
            self.cancel(f"the switch to {self.mode} is cancelled: another scene is open")
