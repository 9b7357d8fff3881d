"""Newton's cradle in every solver mode and in pymunk: ``python -m bench.cradle``.

Five discs (r 0.25 m, restitution 1, no friction) touch in a row, each on a 2 m distance joint
to the world; the first is released from 60 degrees; dt 1/60, gravity -10, sleeping off.  The
figures: the swing energy (kinetic plus m g (y - y_rest)) as a share of the start, at 2.5 s and
at 10 s, its highest share on the way, and how far the three middle discs wandered from rest.
pymunk builds the same discs on PinJoints with 10 iterations.  The table goes to
docs/reliability.md by hand.
"""
from __future__ import annotations

import argparse
import math
from dataclasses import dataclass

G = 10.0
DT = 1 / 60
MARKS = (150, 600)  # 2.5 s and 10 s


@dataclass
class CradleRun:
    kept: dict  # step -> swing energy share
    peak: float  # highest share on the way
    wander: float  # the middle discs' largest distance from rest (m)


def _start(i, r, length, degrees):
    x = 2 * r * i
    a = math.radians(degrees) if i == 0 else 0.0
    return x, (x - length * math.sin(a), length - length * math.cos(a))


def _run(step, energy, xs, rest, steps):
    e0 = energy()
    kept, peak, wander = {}, 1.0, 0.0
    for k in range(1, steps + 1):
        step()
        share = energy() / e0
        peak = max(peak, share)
        wander = max(wander, max(abs(x - x0) for x, x0 in zip(xs()[1:-1], rest[1:-1])))
        if k in MARKS:
            kept[k] = share
    return CradleRun(kept, peak, wander)


def stelkropp(mode="soft_step", steps=600, n=5, r=0.25, length=2.0, degrees=60.0) -> CradleRun:
    import physics
    w = physics.World(gravity=(0.0, -G), solver=mode, sleeping=False, dt=DT)
    balls = []
    for i in range(n):
        x, pos = _start(i, r, length, degrees)
        b = w.add_body(physics.Circle(r), position=pos, restitution=1.0, friction=0.0)
        w.add_joint("distance", b, None, local_anchor_a=(0, 0), local_anchor_b=(x, length), length=length)
        balls.append(b)

    def energy():  # y_rest = 0: the discs hang 2 m below their pins at y = 2
        return sum(0.5 * b.mass * (b.velocity[0] ** 2 + b.velocity[1] ** 2) + 0.5 * b.inertia * b.angular_velocity ** 2
                   + b.mass * G * b.position[1] for b in balls)
    return _run(w.step, energy, lambda: [b.position[0] for b in balls], [b.position[0] for b in balls], steps)


def pymunk(steps=600, n=5, r=0.25, length=2.0, degrees=60.0) -> CradleRun:
    import pymunk as pm
    space = pm.Space()
    space.gravity = (0.0, -G)
    space.iterations = 10
    balls = []
    for i in range(n):
        x, pos = _start(i, r, length, degrees)
        m = math.pi * r * r
        b = pm.Body(m, pm.moment_for_circle(m, 0, r))
        b.position = pos
        shape = pm.Circle(b, r)
        shape.elasticity, shape.friction = 1.0, 0.0
        space.add(b, shape, pm.PinJoint(b, space.static_body, (0, 0), (x, length)))
        balls.append(b)

    def energy():
        return sum(0.5 * b.mass * b.velocity.length ** 2 + 0.5 * b.moment * b.angular_velocity ** 2
                   + b.mass * G * b.position.y for b in balls)
    return _run(lambda: space.step(DT), energy, lambda: [b.position.x for b in balls],
                [b.position.x for b in balls], steps)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--modes", default="soft_step,sequential_impulse,impulse,penalty,hybrid")
    args = ap.parse_args(argv)
    rows = [(m, stelkropp(m)) for m in args.modes.split(",")]
    try:
        rows.append(("pymunk", pymunk()))
    except ImportError:
        pass
    print("| engine / mode | kept at 2.5 s | kept at 10 s | highest | middle discs' wander (m) |")
    print("|---|---|---|---|---|")
    for name, run in rows:
        print(f"| {name} | {run.kept[150]:.3f} | {run.kept[600]:.3f} | {run.peak:.3f} | {run.wander:.3f} |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
