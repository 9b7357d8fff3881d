"""Jointed rigs shared by the joint tests (not a test module): pendulums, chains, a cantilever,
and reads through the public API (periods, joint separations, energies).

Each builder is the scene whose Box2D v3 figure is in bench/results/box2d_v3_figures.json
(measured by bench/box2d/figures_samples.py), so a test can cite the figure it is compared with.
"""
from __future__ import annotations

import math

import numpy as np

import physics
from builders import world

G = 10.0
MODES = ("soft_step", "sequential_impulse", "impulse", "penalty", "hybrid")
SEED_MODES = ("impulse", "penalty", "hybrid")


def rod_pendulum(solver, theta0=0.05, length=1.0, width=0.05, **kw):
    """A ``length`` x ``width`` rod on a world hinge at its top end, ``theta0`` from vertical.
    Returns (world, rod, joint, exact period with the finite-amplitude correction)."""
    w = world(solver, **kw)
    c = (0.5 * length * math.sin(theta0), -0.5 * length * math.cos(theta0))
    rod = w.add_body(physics.Polygon.box(width, length), position=c, angle=theta0, name="rod")
    j = w.add_joint("revolute", rod, None, anchor=(0.0, 0.0), name="hinge")
    d = 0.5 * length
    inertia = (length ** 2 + width ** 2) / 12.0 + d * d  # per unit mass, about the pivot
    return w, rod, j, 2 * math.pi * math.sqrt(inertia / (G * d)) * (1 + theta0 ** 2 / 16)


def disc_pendulum(solver, theta0=0.05, length=1.0, radius=0.1, **kw):
    """A disc on a rigid ``length`` distance joint from the world origin (point-pendulum period:
    the disc's own rotation is free, so it does not take part)."""
    w = world(solver, **kw)
    p = (length * math.sin(theta0), -length * math.cos(theta0))
    disc = w.add_body(physics.Circle(radius), position=p, name="disc")
    j = w.add_joint("distance", disc, None, anchor_a=p, anchor_b=(0.0, 0.0), name="rod")
    return w, disc, j, 2 * math.pi * math.sqrt(length / G) * (1 + theta0 ** 2 / 16)


def period(samples, dt):
    """Mean period from the upward crossings of the mean (linear interpolation)."""
    x = np.asarray(samples) - np.mean(samples)
    up = [i + x[i] / (x[i] - x[i + 1]) for i in range(len(x) - 1) if x[i] < 0.0 <= x[i + 1]]
    return (up[-1] - up[0]) / (len(up) - 1) * dt


def separation(j) -> float:
    """Distance between a point joint's two anchors now (m)."""
    a, b = np.array(j.anchor_a), np.array(j.anchor_b)
    return float(np.hypot(*(a - b)))


def hanging_chain(solver, links=50, size=(0.1, 0.5), end_mass_ratio=0.0, **kw):
    """``links`` links of ``size`` (w x h) hanging straight down from a world hinge at the origin,
    each hinged to the next at their shared end; with ``end_mass_ratio`` a 0.5 m box of that
    many link masses hung from the last.  Returns (world, bodies, joints)."""
    w = world(solver, **kw)
    lw, lh = size
    bodies, joints = [], []
    prev = None
    for i in range(links):
        b = w.add_body(physics.Polygon.box(lw, lh), position=(0.0, -(i + 0.5) * lh), name=f"link{i}")
        joints.append(w.add_joint("revolute", b, prev, anchor=(0.0, -i * lh)))
        bodies.append(b)
        prev = b
    if end_mass_ratio:
        side = 0.5
        link_mass = bodies[0].mass
        dens = end_mass_ratio * link_mass / (side * side)
        y = -links * lh
        b = w.add_body(physics.Polygon.box(side, side), position=(0.0, y - 0.5 * side), density=dens,
                       name="weight")
        joints.append(w.add_joint("revolute", b, prev, anchor=(0.0, y)))
        bodies.append(b)
    return w, bodies, joints


def horizontal_chain(solver, links=30, size=(0.5, 0.1), **kw):
    """``links`` links of ``size`` laid along +x from a world hinge at the origin."""
    w = world(solver, **kw)
    lw, lh = size
    bodies, joints = [], []
    prev = None
    for i in range(links):
        b = w.add_body(physics.Polygon.box(lw, lh), position=((i + 0.5) * lw, 0.0), name=f"link{i}")
        joints.append(w.add_joint("revolute", b, prev, anchor=(i * lw, 0.0)))
        bodies.append(b)
        prev = b
    return w, bodies, joints


def cantilever(solver, boxes=10, size=(1.0, 0.25), **kw):
    """``boxes`` boxes welded rigidly end to end along +x, the first to the world at the origin.
    Returns (world, bodies, joints); the tip is the far end of the last box on its axis."""
    w = world(solver, **kw)
    bw, bh = size
    bodies, joints = [], []
    prev = None
    for i in range(boxes):
        b = w.add_body(physics.Polygon.box(bw, bh), position=((i + 0.5) * bw, 0.0), name=f"beam{i}")
        joints.append(w.add_joint("weld", b, prev, anchor=(i * bw, 0.0)))
        bodies.append(b)
        prev = b
    return w, bodies, joints


def tip(body, half_length=0.5):
    """World point at the far end of a beam body on its axis."""
    return np.array(body.local_to_world((half_length, 0.0)))


def energy(w, bodies, g=G) -> float:
    """Kinetic plus gravitational potential energy of ``bodies`` (J)."""
    e = 0.0
    for b in bodies:
        v = np.array(b.velocity)
        e += 0.5 * b.mass * float(v @ v) + 0.5 * b.inertia * b.angular_velocity ** 2 + b.mass * g * b.position[1]
    return e
