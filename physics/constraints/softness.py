"""Soft constraints (Catto, "Solver2D" 2024 / Box2D v3; "Soft Constraints", GDC 2011).

A soft constraint is a stiff damped spring expressed as a velocity constraint:
with stiffness omega = 2 pi f and damping ratio zeta over (sub-)step h,
  bias_rate = omega / (2 zeta + h omega),
  mass_scale = h omega (2 zeta + h omega) / (1 + h omega (2 zeta + h omega)),
  impulse_scale = 1 / (1 + h omega (2 zeta + h omega)),
and a row's impulse is  j = -m_eff mass_scale (v + bias_rate C) - impulse_scale j_acc,
so an error C is removed smoothly (at a rate capped by the caller) and the
relax pass (no bias) then removes the velocity the bias added.  Contacts use it
(constraints/contact_soft.py) and so will joints.
"""
from __future__ import annotations

import math

from .._jit import kernel


@kernel(entry=True, forceinline=True, error_model="numpy")
def softness(hertz, zeta, h):
    """(bias_rate, mass_scale, impulse_scale) of a soft constraint; hertz 0 = rigid."""
    if hertz <= 0.0:
        return 0.0, 1.0, 0.0
    omega = 2.0 * math.pi * hertz
    a1 = 2.0 * zeta + h * omega
    a2 = h * omega * a1
    a3 = 1.0 / (1.0 + a2)
    return omega / a1, a2 * a3, a3
