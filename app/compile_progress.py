"""What the first launch still waits for: the kernels left to compile for the open scene, named.

Counted per compile unit (``app.compile_units``).  A unit already in the cache at launch counts
for nothing, neither done nor left, so a launch whose cache holds half the units counts only the
other half.  A unit finished (by a helper, or here) leaves nothing; one compiling leaves what the
last cold launch compiled for it (``kernel_counts.json`` beside numba's cache, per unit;
``DEFAULT_COUNTS`` by kind before that) less what it has compiled so far, at least one kernel
while it is not finished; a queued one all of it.  A single total (the old count) overstated the
work left whenever part of the cache was warm, and the bar then sat low to jump at the end.
"""
from __future__ import annotations

import json

# kernels a cold launch compiles per unit kind, until a cold launch has saved its own: the
# default scene's, counted (soft_step, sweep: 254 in all, the whole step none of its own); the
# joint stage's and the overlay's are guesses (neither is in that scene's gate)
DEFAULT_COUNTS = {"solve": 122, "frame": 64, "broad": 25, "narrow": 37, "guard": 6, "step": 1, "joints": 30,
                  "extras": 5}
MIN_COUNTED = 20          # fewer kernels than this in a whole launch: a warm numba cache, not a count

_KIND_NAMES = {"frame": "the frame's kernels (geometry, islands, drawing)", "guard": "the step's guard",
               "extras": "the quadtree overlay"}


def unit_name(unit: str) -> str:
    """A compile unit in words, for the progress line ("the soft_step solver (euler)")."""
    kind, *rest = unit.split(":")
    if kind == "solve":
        return f"the {rest[0]} solver ({rest[1]})"
    if kind == "broad":
        return f"the {rest[0]} broad phase"
    if kind == "narrow":
        return "the narrow phase" + (" (all shapes)" if rest else "")
    if kind == "step":
        return "the whole step"
    if kind == "joints":
        return f"the joints of {rest[0]}"
    return _KIND_NAMES.get(kind, unit)


class KernelCounts:
    """The per-unit kernel counts of the last cold launch, in ``path`` (None: defaults only)."""

    def __init__(self, path):
        self.path = path
        try:
            self.units = {str(k): int(v) for k, v in json.loads(path.read_text())["units"].items()}
        except (OSError, ValueError, KeyError, TypeError, AttributeError):
            self.units = {}

    def expected(self, unit: str) -> int:
        n = self.units.get(unit, 0)
        return n if n > 0 else DEFAULT_COUNTS.get(unit.split(":")[0], 10)

    def save(self, compiled: dict[str, int]) -> None:
        """Keep what this launch compiled per unit, if it compiled (a warm cache loads: nothing
        to learn); units it did not compile keep their earlier count."""
        if self.path is None or sum(compiled.values()) < MIN_COUNTED:
            return
        self.units.update({u: n for u, n in compiled.items() if n > 0})
        try:
            self.path.write_text(json.dumps({"units": self.units}, indent=1))
        except OSError:
            pass


def progress(units, compiled, finished, compiling, counts: KernelCounts):
    """(fraction done, kernels done, kernels left, names of the units waited for, compiling ones
    first).  ``units``: the units still to compile at launch; ``compiled(u)``: kernels compiled
    for ``u`` so far; ``finished(u)``: is it in the cache (or failed: nothing more will come);
    ``compiling``: {unit: the kernel compiling now} in the helpers and here."""
    done = left = 0
    waiting = []
    for u in units:
        n = compiled(u)
        done += n
        if finished(u):
            continue
        left += max(counts.expected(u) - n, 1)
        kernel = compiling.get(u)
        waiting.append((kernel is None, f"{unit_name(u)} ({kernel})" if kernel else unit_name(u)))
    frac = done / (done + left) if done + left else 1.0
    return frac, done, left, [name for _, name in sorted(waiting, key=lambda w: w[0])]


def describe(done: int, left: int, waiting: list[str], loading: bool) -> str:
    """The progress line: the work left first, then what it waits for."""
    if not waiting:
        return "loading the compiled kernels" if loading else "starting the compiler"
    return f"~{left} kernels left ({done} compiled); waiting for " + ", ".join(waiting)
