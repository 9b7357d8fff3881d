"""What the open scene still waits for before it can step, for the progress note above the scene.

A launch compiles the gate of the scene it opened with (``app.warmup``).  A scene opened while
that compiles, in another solver mode (or with the other narrow phase, or joints where the first
scene had none), waits for the gate and then for units of its own.  The note counted and named
only the gate's ("waiting for the soft_step solver" over a penalty scene), went away with it,
and left a bare "compiling penalty ..." line while that mode still compiled, Play showing Pause
over a scene that did not move.  Here the open scene's own units join the count and the names,
and the note stays until the scene can step."""
from __future__ import annotations

from . import compile_units


def _needs(world):
    """(solver, integrator, broad phase), the narrow-phase unit and whether it has joints."""
    key = (world.solver, world.integrator, compile_units.broadphase_of(world))
    return key, compile_units.narrow_unit(world), bool(world.joints)


class SceneWait:
    def __init__(self, warmup):
        self.warmup = warmup
        # the units each set of needs was missing when first seen: kept, so that a unit finished
        # counts as done instead of leaving the count
        self._units: dict[tuple, list[str]] = {}

    def units(self, world) -> list[str]:
        """The units ``world`` needs beyond the launch's gate that were not in the cache."""
        need = _needs(world)
        if need not in self._units:
            w = self.warmup
            (solver, integrator, bp), narrow, joints = need
            units = [] if (solver, integrator, bp) == w.key else w.mode_units(solver, integrator, bp)
            units += [narrow] if narrow != w.narrow else []
            units += [compile_units.joints_unit(solver, integrator)] if joints else []
            self._units[need] = [u for u in units if u not in w.todo and not w.cached(u)]
        return self._units[need]

    def waiting(self, world) -> bool:
        """Does a step of ``world`` still wait for kernels (the note and "waiting" are shown)?"""
        w = self.warmup
        if not w.ready:
            return True
        (solver, integrator, bp), narrow, joints = _needs(world)
        return not (w.can_step(solver, integrator, bp) and w.narrow_ready(narrow)
                    and (not joints or w.joints_ready(solver, integrator)))

    def progress(self, world):
        """(fraction, the work left and what it waits for, in words): the gate's units while the
        launch compiles them, and the open scene's own."""
        return self.warmup.progress(self.units(world))
