"""Each contact's stiffness from the load it carries and the size of its bodies (issue 18).

A soft contact (constraints/softness.py) is a spring: at rest it carries its load with a
deflection  C = a / omega^2,  a = J (1/m_a + 1/m_b) / h  the acceleration its impulse J per
sub-step gives the pair (Catto, "Solver2D", 2024: the soft step's steady state).  With one
frequency for every contact, C is fixed in metres: five 1 cm boxes at 60 Hz sink 1.7 mm, 17 % of
a box, while the same stack of 1 m boxes sinks 0.17 %.  Here a contact whose deflection at the
mode's frequency would exceed ``DEFLECTION`` of its smaller moving body's bounding radius is
made stiffer, just enough to meet it, up to ``STIFFEN`` times the mode's frequency (four
sub-steps: 60 Hz -> 240 Hz; the stacks measured stay steady there).  The load is last step's
impulse (the warm start), so a contact that carries nothing keeps the mode's stiffness and
ordinary 1 m scenes are unchanged.

Heavy loads keep the mode's stiffness: a contact whose load accelerates the pair by more than
``MAX_LOAD`` times gravity (a light body under a heavy one), or between moving bodies whose
masses differ more than ``MAX_RATIO``.  Stiffened, such contacts launched the heavy boxes of
Box2D's HighMassRatio samples and of the 1000:1 stack (measured: one Gauss-Seidel pass cannot
share a heavy load between a light body's contacts at that stiffness).
"""
from __future__ import annotations

import math

from .._jit import kernel

DEFLECTION = 0.005  # largest static deflection, relative to the smaller moving body's bounding radius
STIFFEN = 4.0       # at most this many times the mode's contact frequency
MAX_RATIO = 10.0    # moving pairs with a larger mass ratio keep the mode's frequency
MAX_LOAD = 50.0     # loads accelerating the pair by more than this many g keep it too


@kernel(forceinline=True, error_model="numpy")
def moving_size(ima, imb, ra, rb):
    """The smaller bounding radius of the pair's moving bodies (inverse mass > 0)."""
    if ima > 0.0 and imb > 0.0:
        return min(ra, rb)
    return ra if ima > 0.0 else rb


@kernel(forceinline=True, error_model="numpy")
def contact_hertz(hertz, load, ima, imb, ra, rb, h, g):
    """Frequency (Hz) of a contact: the mode's ``hertz``, raised for the ``load`` (N s per
    sub-step, all points) so that its deflection stays below DEFLECTION of the smaller moving
    body's bounding radius (``ra``/``rb``, ignored for a body that does not move: inverse mass 0);
    ``g`` the magnitude of gravity (m/s^2)."""
    if load <= 0.0 or hertz <= 0.0:
        return hertz
    accel = load * (ima + imb) / h
    if accel > MAX_LOAD * g:
        return hertz
    if ima > 0.0 and imb > 0.0 and (ima > MAX_RATIO * imb or imb > MAX_RATIO * ima):
        return hertz
    size = moving_size(ima, imb, ra, rb)
    need = math.sqrt(accel / (DEFLECTION * size)) / (2.0 * math.pi)
    return min(max(hertz, need), STIFFEN * hertz)
