"""The fuzzer's own energy measure and the bound it holds accepted steps to.

The energy is computed here from the bodies' and springs' public state, not by the engine, so a
guard that misses its own bound is found: kinetic energy plus gravity measured from the positions
at the start of the run (where the origin lies does not matter) plus springs.  The bound is the
energy guard's stated one (physics/step/energy_guard.py).
"""
from __future__ import annotations

import math

import numpy as np

from physics.step.energy_guard import noise_floor, push_allowance


class Energy:
    """(E, S) of a world: E = kinetic + gravity from each body's start + springs; the scale S =
    kinetic + springs + the height the bodies can still fall, sum_i m_i |g| (h_i - h_min) with h_min
    the lowest body at the first measure (at least 0), as the
    guard's.  Joints' soft springs are not counted (their energy is the engine's to report)."""

    def __init__(self, w):
        self.start = {}  # body id -> centre of mass when first measured (gravity counts from there)
        self.low0 = None  # the lowest dynamic body's height at the first measure
        self(w)

    def __call__(self, w) -> tuple[float, float]:
        gx, gy = w.gravity
        g = math.hypot(gx, gy)
        ke = pe = springs = fall = 0.0
        heights = []
        with np.errstate(all="ignore"):
            for b in w.bodies:
                if b.kind != "dynamic":
                    continue
                m, (x, y), (vx, vy) = b.mass, b.center_of_mass, b.velocity
                x0, y0 = self.start.setdefault(b.id, (x, y))
                ke += 0.5 * (m * (vx * vx + vy * vy) + b.inertia * b.angular_velocity ** 2)
                pe -= m * (gx * (x - x0) + gy * (y - y0))
                heights.append((m, -(gx * x + gy * y) / g if g > 0.0 else 0.0))  # height along -g
            for s in w.springs:
                (ax, ay), (bx, by) = s.endpoints()
                springs += 0.5 * s.stiffness * (math.hypot(bx - ax, by - ay) - s.rest_length) ** 2
            if heights:
                if self.low0 is None:  # heights from the first measure's lowest body, as the guard's
                    self.low0 = min(h for _, h in heights)
                fall = max(sum(m * g * (h - self.low0) for m, h in heights), 0.0)
        return ke + pe + springs, ke + springs + fall


class EnergyBound:
    """E <= E0 + r (S0 + S / 2) + the largest push-out allowance of any step so far + the noise
    floor (world.energy_guard = r), with E and S from ``Energy``.  ``gain``: the largest
    (E - E0) / (S0 + F0) of the accepted steps so far, the gain as a share of the starting energy
    scale (F0, the noise floor at the start, gives a world starting at rest a scale), and
    ``gain_mode`` the mode that stepped to it."""

    def __init__(self, w):
        self.energy = Energy(w)
        self.e0, self.s0 = self.energy(w)
        self.scale0 = self.s0 + noise_floor(w, w.dt)
        self.push = 0.0
        self.r = w.energy_guard
        self.gain = 0.0
        self.gain_mode = ""

    def limit(self, w, e: float, scale: float) -> float:
        """The bound after an accepted step of energy ``e`` and scale ``scale``; records the gain."""
        self.push = max(self.push, push_allowance(w))
        ratio = (e - self.e0) / self.scale0 if self.scale0 > 0.0 else 0.0
        if ratio > self.gain:
            self.gain, self.gain_mode = ratio, w.solver
        return self.e0 + self.r * (self.s0 + 0.5 * scale) + self.push + noise_floor(w, w.dt)
