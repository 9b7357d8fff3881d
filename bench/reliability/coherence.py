"""Warm-start coherence: how many pushing contact points keep their impulse into the next step.

    python -m bench.reliability.coherence tiny_pyramid [--steps 60] [--scene-arg extent=0.5]

A sub-stepped solver with one biased pass per sub-step (soft_step, Box2D v3) converges over
steps, not within one: it relies on each point's accumulated impulse being carried to the next
step (Catto, "Iterative dynamics with temporal coherence", GDC 2005).  The narrow phase carries it
only where the point is made by the same features (collision/narrowphase/carry.py); a point
whose pair persists but whose features change (the reference face flips from one body to the
other, an incident edge changes) restarts from zero.  This tool counts, step by step, the points
that pushed (normal impulse > 0) and what became of them in the next step:

* ``carried``: same pair, same feature id: its impulse is warm-started;
* ``new_feature``: same pair, no point with that feature: the impulse is lost;
* ``pair_gone``: the pair has no row any more.

Measured on this machine (issue 18, 2026-12-03, first 60 steps, 4 sub-steps): Box2D v3's Tiny
Pyramid (465 boxes of 5 cm) loses 23.5 % of its pushing points' impulses per step, almost all to
a flip of the reference face between the two boxes; the same pyramid of 1 m boxes loses 6.7 %,
the Card House 6.7 %, the Vertical Stack 0 %.  At 8 sub-steps the tiny pyramid holds (top box
1.0 box sizes in 10 s) and still loses 19.2 %: the loss is not by itself what topples it.
"""
from __future__ import annotations

import argparse
import sys
from dataclasses import dataclass


@dataclass
class Coherence:
    """One step's fate of the previous step's pushing points."""
    step: int
    pushing: int
    carried: int
    new_feature: int
    pair_gone: int

    @property
    def lost_fraction(self) -> float:
        """Share of the pushing points whose impulse was not carried (0 when none pushed)."""
        return (self.new_feature + self.pair_gone) / self.pushing if self.pushing else 0.0


def pushing_points(world) -> tuple[dict, set]:
    """({(pair key, feature id): normal impulse} of the points with impulse > 0, {pair keys})
    of ``world``'s contact table after its last step."""
    buf = world._store.contacts
    c = buf.cur
    out = {}
    keys = set()
    for k in range(buf.n):
        key = int(c.key[k])
        keys.add(key)
        for p in range(int(c.count[k])):
            if c.jn[k, p] > 0.0:
                out[(key, int(c.feature[k, p]))] = float(c.jn[k, p])
    return out, keys


def compare(prev, cur, step: int) -> Coherence:
    """The fate, in ``cur`` (a ``pushing_points`` result), of ``prev``'s pushing points."""
    pts, _ = prev
    now, keys = cur
    carried = sum(1 for kf in pts if kf in now)
    gone = sum(1 for kf in pts if kf[0] not in keys)
    return Coherence(step, len(pts), carried, len(pts) - carried - gone, gone)


def measure(world, steps: int, step=None) -> list[Coherence]:
    """Step ``world`` ``steps`` times (``step``: a callable that steps it, default
    ``world.step``) and return each step's Coherence of the step before's pushing points."""
    step = step or world.step
    out = []
    prev = None
    for i in range(steps):
        step()
        cur = pushing_points(world)
        if prev is not None:
            out.append(compare(prev, cur, i))
        prev = cur
    return out


def _scene_arg(text: str):
    k, _, v = text.partition("=")
    if not k or not v:
        raise argparse.ArgumentTypeError(f"--scene-arg: expected NAME=VALUE, got {text!r}")
    return k, (int(v) if v.lstrip("-").isdigit() else float(v))


def main(argv=None) -> int:
    """Print the coherence of a bench sample (bench/suite/samples.py) in soft_step."""
    from ..engines.ours import OursSim, scene_world
    from ..suite.samples import SAMPLES
    ap = argparse.ArgumentParser(description="Warm-start coherence of a sample's contact points")
    ap.add_argument("sample", choices=sorted(SAMPLES))
    ap.add_argument("--steps", type=int, default=60)
    ap.add_argument("--substeps", type=int, default=4)
    ap.add_argument("--scene-arg", type=_scene_arg, action="append", default=[],
                    help="a keyword of the sample's builder, e.g. extent=0.5 (repeatable)")
    a = ap.parse_args(argv)
    desc = SAMPLES[a.sample](**dict(a.scene_arg))
    sim = OursSim(desc, world=scene_world(desc, source=a.sample), solver="soft_step",
                  settings={"substeps": a.substeps})
    rows = measure(sim.world, a.steps, sim.step)
    print(f"{'step':>5} {'pushing':>8} {'carried':>8} {'new_feature':>12} {'pair_gone':>10} {'lost':>6}")
    for r in rows:
        print(f"{r.step:5d} {r.pushing:8d} {r.carried:8d} {r.new_feature:12d} {r.pair_gone:10d} "
              f"{r.lost_fraction:6.1%}")
    total = sum(r.pushing for r in rows)
    lost = sum(r.new_feature + r.pair_gone for r in rows)
    print(f"lost over {len(rows)} steps: {lost / total if total else 0.0:.1%} of {total} pushing points")
    return 0


if __name__ == "__main__":
    sys.exit(main())
