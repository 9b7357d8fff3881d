"""A solver mode, integrator or broad phase picked before its kernels are loaded: the scene goes
on with what it runs, the new (mode, integrator, broad phase) compiles first, and the switch
happens by itself once it is ready.  What is said below of a mode holds for the integrator and
the broad phase (``Editor.set_integrator``, ``set_broadphase``); parts picked one after another
wait together and apply together.

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

PARTS = ("solver", "integrator", "broadphase")
WORDS = {"solver": "", "integrator": "integrator ", "broadphase": "broad phase "}


class PendingSwitch:
    """The choice of solver mode, integrator and broad phase of ``editor`` that waits for
    ``warmup``: ``choice`` holds the parts picked and not applied yet ({} : nothing pending);
    ``mode`` is its solver mode (None: the mode is not part of it)."""

    def __init__(self, editor, warmup):
        self.editor = editor
        self.warmup = warmup
        self.choice: dict[str, str] = {}  # part ("solver", "integrator", "broadphase") -> value
        self.since = 0.0                 # monotonic time the user picked it
        self._doc = None                 # the document it was picked in
        self._key = None                 # (mode, integrator, broad phase) it waits for
        self._units: list[str] = []      # its compile units that were not in the cache then
        editor.mode_gate = self.request
        editor.on_document.append(self._document)
        editor.on_mode.append(self._mode_set)

    @property
    def mode(self) -> str | None:
        return self.choice.get("solver")

    @property
    def integrator(self) -> str | None:
        return self.choice.get("integrator")

    @property
    def broadphase(self) -> str | None:
        return self.choice.get("broadphase")

    @property
    def active(self) -> bool:
        return bool(self.choice)

    # -- what the editor and the panels ask -------------------------------------------
    def request(self, solver: str | None = None, integrator: str | None = None,
                broadphase: str | None = None) -> bool:
        """``Editor.switch_solver(mode)``, ``set_integrator`` and ``set_broadphase`` ask first
        (one part each): True if the change is handled here (it is the running value, or the
        choice compiles first and applies later); False to apply it now."""
        ed = self.editor
        w = ed.world
        asked = {k: v for k, v in zip(PARTS, (solver, integrator, broadphase)) if v is not None}
        part, value = next(iter(asked.items()))
        if value == self._running(part):
            if part in self.choice:
                was = self.label()
                del self.choice[part]
                ed.notify(f"{WORDS[part] or 'solver '}stays {value}: the switch to {was} is cancelled")
                if not self.choice:
                    self.clear()
            return True
        if waits_for(self.warmup, w):
            self.clear()        # the running choice is not ready either: the scene waits anyway
            return False
        choice = {**self.choice, part: value}
        key = self._key_of(choice)
        self.warmup.prioritize(*key, first=True)
        if not self._waits(choice):
            # ready: apply now, with the parts picked before (they are ready with it)
            self.clear()
            self._apply(choice)
            return True
        if not self.choice:
            self.since, self._doc = time.monotonic(), ed.doc
        self.choice = choice
        self._rekey(key)
        now = self._running_label()
        ed.notify(f"{self.label()} compiles first: {now} runs until then (pick {WORDS[part]}"
                  f"{self._running(part)} again to stay)")
        return True

    def update(self) -> None:
        """Every frame: apply the pending choice once it is ready."""
        if not self.choice:
            return
        ed = self.editor
        if ed.doc is not self._doc:
            self.cancel(f"the switch to {self.label()} is cancelled: another scene is open")
            return
        for part in [k for k, v in self.choice.items() if self._running(k) == v]:
            del self.choice[part]      # there another way (redo, Find settings' apply)
        if not self.choice:
            self.clear()
            return
        key = self._key_of(self.choice)
        if key != self._key:           # something else changed meanwhile (an undo, the shapes)
            self.warmup.prioritize(*key, first=True)
            self._rekey(key)
        if ed.tool_joints or self._waits(self.choice):
            return                     # (a mouse drag holds a body: after its release)
        choice = self.choice
        self.clear()
        self._apply(choice)

    def cancel(self, why: str) -> None:
        if self.choice:
            self.editor.notify(why)
        self.clear()

    def clear(self) -> None:
        self.choice = {}
        self._doc = self._key = None
        self._units = []

    def label(self) -> str:
        """The pending choice in words: "penalty", "integrator rk4, broad phase sap" ..."""
        return ", ".join(f"{WORDS[k]}{v}" for k, v in sorted(self.choice.items(),
                                                              key=lambda kv: PARTS.index(kv[0])))

    def running_label(self) -> str:
        """What runs until then, in the pending choice's words ("soft_step", "integrator euler")."""
        return self._running_label()

    def progress(self):
        """(fraction 0..1, the work left in words) of the pending choice's kernels."""
        if not self.choice:
            return 1.0, ""
        if not self._units:
            return 0.99, "loading its kernels from the cache"
        return self.warmup.mode_progress(self._units)

    def describe(self):
        """For the status file: the pending switch, or None."""
        if not self.choice:
            return None
        frac, text = self.progress()
        w = self.editor.world
        return {"mode": self.mode, "integrator": self.integrator, "broadphase": self.broadphase,
                "what": self.label(), "from": w.solver, "from_integrator": w.integrator,
                "from_broadphase": w.broadphase, "progress": frac, "text": text,
                "seconds": time.monotonic() - self.since}

    # -- inside -------------------------------------------------------------------------
    def _running(self, part):
        return getattr(self.editor.world, part)

    def _running_label(self) -> str:
        return ", ".join(f"{WORDS[k]}{self._running(k)}" for k in PARTS if k in self.choice)

    def _key_of(self, choice):
        """(mode, integrator, resolved broad phase) a step with ``choice`` applied would run."""
        w = self.editor.world
        bp = choice.get("broadphase")
        if bp is None:
            bp = compile_units.broadphase_of(w)
        else:
            from physics.collision.broadphase import resolve
            bp = resolve(bp, w._store.fixtures.n)
        solver = choice.get("solver", w.solver)
        return solver, compile_units.step_integrator(solver, choice.get("integrator", w.integrator)), bp

    def _apply(self, choice) -> None:
        """Through the same undoable edits as a pick of a ready value; the mode last (its
        ``on_mode`` listeners see the integrator it runs with)."""
        ed = self.editor
        if "integrator" in choice:
            ed.set_integrator(choice["integrator"], now=True)
        if "broadphase" in choice:
            ed.set_broadphase(choice["broadphase"], now=True)
        if "solver" in choice:
            ed.switch_solver(choice["solver"], now=True)

    def _rekey(self, key) -> None:
        self._key = key
        units = self.warmup.mode_units(*key, joints=bool(self.editor.world.joints))
        self._units = [u for u in units if not self.warmup.cached(u)]

    def _waits(self, choice) -> bool:
        """Would a step with ``choice`` wait for a kernel?  As ``simulation.waits_for``, except
        that a joint stage is compiled by the helper process and only loaded here (a compile in
        the window's process would slow its frames while the scene runs)."""
        w = self.editor.world
        warm = self.warmup
        solver, integrator, bp = self._key_of(choice)
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
        """A mode or integrator set another way meanwhile (Find settings' apply) is the newer
        choice: the pending parts it differs from are dropped."""
        dropped = [k for k, v in (("solver", solver), ("integrator", integrator))
                   if k in self.choice and self.choice[k] != v]
        if not dropped:
            return
        was = self.label()
        for k in dropped:
            del self.choice[k]
        self.editor.notify(f"the switch to {was} is cancelled: {solver} ({integrator}) was chosen")
        if not self.choice:
            self.clear()

    def _document(self, world, path, keep_camera) -> None:
        if not self.choice:
            return
        if keep_camera:                # a reset: the same scene, and it keeps the solver choice
            self._doc = self.editor.doc
        else:
            self.cancel(f"the switch to {self.label()} is cancelled: another scene is open")
