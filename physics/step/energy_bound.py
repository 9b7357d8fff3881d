"""The energy guard's reference and bound as compiled functions over one state array.

The guard's memory between steps (energy_guard.py explains the bound) is the float array
``G``: the slots below.  The Python guard and the step driver (driver.py) call the same two
functions, so the bound is written once and a step that is one compiled call keeps it.
"""
from __future__ import annotations

import math

from .._jit import kernel
from .energy_sums import ELASTIC, EXTERNAL, KE, LOWEST, MASS, PE, PUSH

#: G's slots: the energy at the end of the last accepted step (nan: none), the reference's
#: energy and scale, the largest push-out allowance since it, the motors' work bound since it,
#: the motors' power bound at this step's start, whether the guard is on for this step (1.0),
#: the energy this step started with, the refused step's energy and bound (outputs), and the
#: reference's lowest dynamic body (gravitational potential per kg)
LAST, E0, S0, PUSH_MAX, WORK, P_START, ACTIVE, E_START, E_OUT, LIMIT_OUT, LOW0 = range(11)
SLOTS = 11

#: m/s: speeds below this are solver noise, not a gain (energy_guard.py: the noise floor)
NOISE_SPEED = 1e-3


@kernel
def energy_and_scale_from(sums, lowest):
    """(E, S) from a sums array (energy_sums.py), S's gravitational part measured from the
    potential per kg ``lowest``: sum_i m_i (phi_i - lowest), at least 0."""
    ke, pe, elastic = sums[KE], sums[PE], sums[ELASTIC]
    return ke + pe + elastic, ke + elastic + max(pe - sums[MASS] * lowest, 0.0)


@kernel(entry=True)
def energy_and_scale(sums):
    """(E, S) from a sums array (energy_sums.py); S's gravitational part is measured from the
    lowest dynamic body, sum_i m_i |g| (h_i - h_min), so where the origin lies does not matter."""
    return energy_and_scale_from(sums, sums[LOWEST])


@kernel(entry=True)
def guard_begin(G, start, growth, p_start, dragged):
    """Before a step: a new reference after an edit (the energy differs from the last step's end)
    or external input; the guard is off for a step with input, a drag, or ``growth`` <= 0."""
    G[P_START] = p_start
    if growth <= 0.0 or start[EXTERNAL] != 0.0 or dragged:
        G[ACTIVE] = 0.0
        G[LAST] = math.nan
        return
    e, s = energy_and_scale(start)
    if not (e == G[LAST] and G[ACTIVE] != 0.0):
        G[E0] = e
        G[S0] = s
        G[LOW0] = start[LOWEST]
        G[PUSH_MAX] = 0.0
        G[WORK] = 0.0
    G[ACTIVE] = 1.0
    G[E_START] = e


@kernel(entry=True)
def guard_excess(G, end, growth, dt, g, slop, p_end):
    """After a step: True (the energy and the bound in ``G[E_OUT]``, ``G[LIMIT_OUT]``) when the
    energy is beyond E0 + r (S0 + S/2) + push-out + motors' work + noise floor."""
    if G[ACTIVE] == 0.0:
        return False
    # S's height is counted from the reference's lowest body, not the step's: a body thrown far
    # down (a light one, by a solver fault) would otherwise lift every other body's m g h into
    # the slack, and with it accept the very gain that threw it
    e, s = energy_and_scale_from(end, G[LOW0])
    push = max(G[PUSH_MAX], end[PUSH])
    floor = end[MASS] * (g * slop + 0.5 * (g * dt) ** 2 + 0.5 * NOISE_SPEED ** 2)
    # the motors' work: at most their power bound at the step's start and at its end, each over
    # the whole step (the speeds in between lie between them, give or take the solver)
    work = G[WORK] + dt * (G[P_START] + p_end)
    limit = G[E0] + growth * (G[S0] + 0.5 * s) + push + work + floor
    G[PUSH_MAX] = push
    # rounding: E sums terms of size up to S
    if e - limit > 1e-12 * (s + G[S0] + abs(G[E0])) + 1e-300:
        G[LAST] = G[E_START]  # the step is reverted to the state it started from
        G[E_OUT] = e
        G[LIMIT_OUT] = limit
        return True
    G[LAST] = e
    G[WORK] = work
    return False
