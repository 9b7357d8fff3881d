"""The energy guard: a step whose world gains energy it cannot have been given is refused.

Without external input (a user force, a moving kinematic body, a mouse joint's drag) a
world's total energy E = kinetic + gravitational + elastic (springs) cannot grow: contacts,
friction, springs' dampers and joints only conserve or dissipate it.  The solvers are not
exact, so the guard allows a stated bound instead of zero.  From the reference state (the
first step, or the first one after an edit or an external input) with energy E0 and energy
scale S0 = KE + elastic + gravitational above the lowest dynamic body (all >= 0) and S the
scale now,

    E <= E0 + r (S0 + S / 2) + sum_k m_k ((P_k v_p)^2 / 2 + |g| d_k) + W + F,

- ``r`` (``world.energy_guard``, default 1): the energy present may grow by its own size.
  Symplectic Euler's energy error on an oscillator is O(omega h) of its energy and the seed
  modes keep omega h <= 1 per sub-step (integrators.LIMITS).  The S / 2 term is for a body
  falling from rest (S0 = 0): symplectic Euler gains m g^2 h^2 / 2 per step while S grows
  as m g^2 h^2 n^2, at least 3/2 m g^2 h^2 after one step.  An explosion has E ~ S, so it is
  caught once S > 2 (E0 + r S0 + allowance); those issue 20 found were 1e3..1e24 times the
  energy present.
- the push-out allowance (push_out.py): push-out may add only the energy of separating the
  overlap it found.  A manifold k of depth d_k > 0 between bodies a and b may leave at up to the
  mode's push-out speed v_p (SolverMode.push_speed: soft_step's push_out_speed, 3 m/s;
  penalty's and hybrid's, 2 m/s; sequential_impulse's Baumgarte cap, 10 m/s; 0 where push-out
  only moves positions: split impulses, impulse's projection), times P_k, the number of
  contacts a push can travel through in its cluster of overlapping bodies (1 for a lone pair),
  and be lifted apart by d_k against gravity: m_k ((P_k v_p)^2 / 2 + |g| d_k), with
  m_k = 1 / (1/m_a + 1/m_b), at least the contact's effective mass along its normal.  A light
  body overlapping a heavy one is allowed its own energy, not the heavy body's.  The largest
  allowance seen since the reference counts, so a pair pushed out earlier keeps its speed.

- the scale measures gravitational energy from the lowest dynamic body, sum_i m_i |g| (h_i -
  h_min), not from y = 0: where the origin lies is the user's choice, and a world 100 km up
  would otherwise get m g 1e5 J of slack, enough to accept what the same world at the origin
  refuses.  The height the bodies can still fall is the world's own scale (a hanging joint
  grid's links swing through it).  E itself may keep any zero: only its change is bounded.
  After a step, S counts heights from the reference's lowest body, sum_i m_i |g| (h_i - h_min,0)
  (at least 0), not from the step's: a light body thrown far down by a solver fault would
  otherwise raise every other body's m g h and accept the gain that threw it (a 6.5 ug disc
  spun to 7e7 rad/s while a 0.2 ug box fell 9,000 km gave a 141 kg body 1.3e10 J of slack).

- the motors' work W: a joint motor adds at most its force or torque times the relative speed
  it acts on (energy_sums.motor_power), so each step adds dt (P_start + P_end) to W, P the
  bound at the step's start and end.  A motor does not switch the guard off: joint friction
  (a motor of speed 0 and a small torque, as in the ragdoll) only takes energy out, and a
  driven wheel may gain what its motor can give and no more.

- the noise floor F = sum_i m_i (|g| slop + (|g| dt)^2 / 2 + v_n^2 / 2), v_n = 1 mm/s: a body
  lifted by the linear slop, the speed of one step's fall, and 1 mm/s are solver noise, not
  a gain.  Without it a welded cantilever at rest near y = 0 (E0 = S0 = 0, energies ~1e-32 J)
  was refused for rounding, and soft joints and contacts store energy the sum leaves out.

An edit between steps is seen as the energy at a step's start differing from the one the last
step ended with; it (and any step with external input) starts a new reference.  A step beyond
the bound is reverted and raised as SimulationError at the 'solve' stage, like a non-finite
step (pipeline.Pipeline).  ``world.energy_guard = 0`` turns the guard off.
"""
from __future__ import annotations

import math

import numpy as np

from ..store import DYNAMIC
from .energy_bound import (ACTIVE, E0, E_OUT, E_START, LAST, LIMIT_OUT, NOISE_SPEED, P_START, PUSH_MAX, S0,
                           SLOTS, WORK, guard_begin, guard_excess)
from .energy_sums import SUMS, motor_power
from .push_out import push_allowance  # noqa: F401  (the numpy reference, with the others here)

def energies(world) -> tuple[float, float]:
    """(total energy E, its scale S) of the world in J: the numpy reference of what the step's
    kernels compute (energy_sums.guard_sums, energy_bound.energy_and_scale; tests and tools use
    it).  S = KE + elastic + sum_i m_i |g| (h_i - h_min): gravity counts from the lowest dynamic
    body, not from the origin."""
    store = world._store
    n = store.bodies.n
    B = store.bodies.view
    # the dynamic slots gathered by index once: the same arrays (and sums) as masking each column
    dyn = np.flatnonzero(B.kind[:n] == DYNAMIC)
    with np.errstate(all="ignore"):
        m = B.m[dyn]
        ke = 0.5 * float((m * (B.v[dyn] ** 2).sum(1) + B.inertia[dyn] * B.w[dyn] ** 2).sum())
        per_kg = -(B.x[dyn] @ world._gravity)  # gravitational potential per kg (J/kg)
        pe = float((m * per_kg).sum())
        lowest = float(per_kg.min()) if len(dyn) else 0.0
        elastic = 0  # (the empty sum's value)
        if store.springs.n:
            elastic = sum(0.5 * s.stiffness * (s.length - s.rest_length) ** 2 for s in world.springs)
    return ke + pe + elastic, ke + elastic + max(pe - float(m.sum()) * lowest, 0.0)



def noise_floor(world, dt: float) -> float:
    """F = sum_i m_i (|g| slop + (|g| dt)^2 / 2 + NOISE_SPEED^2 / 2) over the dynamic bodies (J)."""
    store = world._store
    n = store.bodies.n
    B = store.bodies.view
    return floor_for(float(B.m[:n][B.kind[:n] == DYNAMIC].sum()), world, dt)


def floor_for(mass: float, world, dt: float) -> float:
    """The noise floor of ``mass`` kg of dynamic bodies in ``world`` after a step of ``dt`` (J)."""
    g = math.hypot(world._gravity[0], world._gravity[1])
    return mass * (g * world.linear_slop + 0.5 * (g * dt) ** 2 + 0.5 * NOISE_SPEED ** 2)


def _motor_power(world) -> tuple[float, bool]:
    """(the joints' motor power bound in W, whether a mouse joint pulls): energy_sums.motor_power."""
    store = world._store
    if not store.joints.n:
        return 0.0, False
    p, dragged = motor_power(*store.joints.arrays.flat, *store.bodies.arrays.flat, store.joints.n)
    return float(p), bool(dragged)


def _slot(i: int, kind=float):
    """A property over the guard's state array ``G`` (energy_bound.py's slots)."""
    def get(self):
        return kind(self.G[i])

    def put(self, value):
        self.G[i] = value
    return property(get, put)


class EnergyGuard:
    """The reference energy and the bound of the current run without external input.

    Its memory is the array ``G`` (energy_bound.py), which the step driver updates in place;
    ``start`` and ``end`` are the sums (energy_sums.py) that the step's opening and closing
    kernels fill.  The functions above compute the same quantities in numpy for tests and tools.
    """

    last = _slot(LAST)        # energy at the end of the last accepted step (nan: none)
    e0 = _slot(E0)
    s0 = _slot(S0)
    push = _slot(PUSH_MAX)
    work = _slot(WORK)        # bound of the work the motors did since the reference (J)
    p_start = _slot(P_START)  # the motors' power bound at this step's start (W)
    active = _slot(ACTIVE, bool)
    e_start = _slot(E_START)

    def __init__(self):
        self.G = np.zeros(SLOTS)
        self.G[LAST] = math.nan
        self._start = np.zeros(SUMS)
        self.end = np.zeros(SUMS)

    @property
    def start(self):
        return self._start

    @start.setter
    def start(self, values):  # in place: the step driver holds this array
        self._start[:] = values

    def begin(self, world) -> None:
        """Before a step (after begin_step filled ``self.start``): start a new reference after an
        edit or an external input."""
        p, dragged = _motor_power(world)
        guard_begin(self.G, self._start, float(world.energy_guard), p, dragged)

    def excess(self, world, dt: float) -> tuple[float, float] | None:
        """After a step (end_step filled ``self.end``): (energy, bound) when the energy is beyond
        the bound, else None."""
        if not self.G[ACTIVE]:
            return None
        g = math.hypot(world._gravity[0], world._gravity[1])
        if guard_excess(self.G, self.end, float(world.energy_guard), dt, g, world.linear_slop,
                        _motor_power(world)[0]):
            return float(self.G[E_OUT]), float(self.G[LIMIT_OUT])
        return None
