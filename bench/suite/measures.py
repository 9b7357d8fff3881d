"""Engine-independent measurements on a recorded run (a ``Trace``) of a scene description.

A ``Trace`` holds, for every step 0..N (0 = the initial state), each body's origin, angle,
centre of mass and velocities, and (when the engine reports them) each joint's linear
separation and reaction force. Every figure of ``bench.box2d.samples`` is one of the functions
below applied to a trace, so Stelkropp's tests can measure themselves the same way.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass
class Trace:
    """Per-step body (and joint) arrays of one run; ``names`` maps body names to indices."""
    dt: float
    names: dict
    origin: list = field(default_factory=list)
    angle: list = field(default_factory=list)
    com: list = field(default_factory=list)
    v: list = field(default_factory=list)
    w: list = field(default_factory=list)
    joint_sep: list = field(default_factory=list)
    joint_force: list = field(default_factory=list)

    def k(self, seconds):
        """Step index at ``seconds`` (clamped to the run)."""
        return min(int(round(seconds / self.dt)), len(self.origin) - 1)

    def i(self, name):
        """Body index of a named body."""
        return self.names[name]

    def arrays(self):
        """Stack the lists into arrays (T, n, ...) once recording is done."""
        for key in ("origin", "angle", "com", "v", "w", "joint_sep", "joint_force"):
            setattr(self, key, np.asarray(getattr(self, key)))
        return self


def _take(trace, sim):
    if hasattr(sim, "snapshot"):
        b = sim.snapshot()
        trace.origin.append(b[:, 0:2])
        trace.angle.append(b[:, 2])
        trace.v.append(b[:, 3:5])
        trace.w.append(b[:, 5])
        trace.com.append(b[:, 6:8])
    else:
        com, ang, v, w = sim.state()
        trace.origin.append(sim.origins())
        trace.com.append(com), trace.angle.append(ang), trace.v.append(v), trace.w.append(w)
    if hasattr(sim, "joint_readouts"):
        r = sim.joint_readouts()
        trace.joint_sep.append(r["linear_separation"].copy())
        trace.joint_force.append(r["force"].copy())


def record(sim, seconds, names):
    """Run ``sim`` for ``seconds`` recording every step; ``names``: body name -> index."""
    trace = Trace(dt=sim.dt, names=dict(names))
    _take(trace, sim)
    for _ in range(int(round(seconds / sim.dt))):
        sim.step()
        _take(trace, sim)
    return trace.arrays()


# -- figures ----------------------------------------------------------------------------------
def displacement(tr, name, t1, t0=0.0):
    """|origin(t1) - origin(t0)| of a named body (m)."""
    i = tr.i(name)
    return float(np.hypot(*(tr.origin[tr.k(t1), i] - tr.origin[tr.k(t0), i])))


def max_displacement(tr, t1, t0=0.0, dynamic=None):
    """The largest |origin(t1) - origin(t0)| over bodies (``dynamic``: mask of bodies to include)."""
    d = np.hypot(*(tr.origin[tr.k(t1)] - tr.origin[tr.k(t0)]).T)
    if dynamic is not None:
        d = d[dynamic]
    return float(np.nanmax(d))


def max_speed(tr, t0=0.0, t1=None, dynamic=None):
    """The largest centre-of-mass speed of any body between t0 and t1 (m/s)."""
    k1 = len(tr.v) if t1 is None else tr.k(t1) + 1
    s = np.hypot(tr.v[tr.k(t0):k1, :, 0], tr.v[tr.k(t0):k1, :, 1])
    if dynamic is not None:
        s = s[:, dynamic]
    return float(np.nanmax(s))


def upward_crossings(t, x):
    """Times where x crosses its mean upwards (linear interpolation)."""
    x = x - x.mean()
    idx = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    return t[idx] - x[idx] * (t[idx + 1] - t[idx]) / (x[idx + 1] - x[idx])


def period(tr, signal, skip=1):
    """Mean period (s) of an oscillating signal (array over steps) from its upward mean crossings,
    ignoring the first ``skip`` crossings."""
    t = np.arange(len(signal)) * tr.dt
    c = upward_crossings(t, np.asarray(signal, float))[skip:]
    if len(c) < 2:
        return float("nan")
    return float((c[-1] - c[0]) / (len(c) - 1))


def pendulum_period(theta0, inertia_pivot, m_g_d):
    """Exact period of a pendulum of amplitude theta0 (series of the complete elliptic integral):
    T0 (1 + theta0^2/16 + 11 theta0^4/3072), T0 = 2 pi sqrt(I / (m g d))."""
    t0 = 2 * math.pi * math.sqrt(inertia_pivot / m_g_d)
    return t0 * (1 + theta0 ** 2 / 16 + 11 * theta0 ** 4 / 3072)


def box_corners(origin, angle, hw, hh):
    """World corners (4, 2) of a box of half extents (hw, hh) centred on its origin."""
    c, s = math.cos(angle), math.sin(angle)
    local = np.array([(-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh)])
    return local @ np.array([[c, s], [-s, c]]) + origin


def stack_sink(tr, k, light, heavy, half=0.5):
    """Combined sink of a two-box stack at step k (bench/reliability.py ``mass_ratio_stack``):
    light box below the ground + overlap of heavy into light (m)."""
    lo = box_corners(tr.origin[k, light], tr.angle[k, light], half, half)
    hi = box_corners(tr.origin[k, heavy], tr.angle[k, heavy], half, half)
    return max(0.0, -lo[:, 1].min()) + max(0.0, lo[:, 1].max() - hi[:, 1].min())


def bounce_apex(tr, i, contact_height):
    """Highest centre-of-mass rise above ``contact_height`` after the first bounce (the first step
    where the vertical velocity turns from falling to rising), up to the next fall."""
    vy = tr.v[:, i, 1]
    y = tr.com[:, i, 1]
    up = np.nonzero((vy[:-1] < 0) & (vy[1:] >= 0))[0]
    if not len(up):
        return 0.0
    k0 = up[0] + 1
    down = np.nonzero(vy[k0:] < 0)[0]
    k1 = k0 + (down[0] if len(down) else len(vy) - k0)
    return float(y[k0:k1 + 1].max() - contact_height)


def circle_overlaps(centres, radius):
    """(max, mean over overlapping pairs) overlap depth of equal discs (m)."""
    d = np.hypot(*(centres[:, None, :] - centres[None, :, :]).transpose(2, 0, 1))
    iu = np.triu_indices(len(centres), 1)
    depth = 2 * radius - d[iu]
    depth = depth[depth > 0]
    return (float(depth.max()), float(depth.mean())) if len(depth) else (0.0, 0.0)
