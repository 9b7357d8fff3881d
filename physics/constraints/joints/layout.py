"""Where a joint's prepared constants and its rows' per-pass geometry live.

``F`` (one row of NF floats per joint, written by ``prepare`` once per step):
the arms from each centre of mass to its anchor and the axis, rotated into the
world at the step start; the centre separation x_a - x_b at the step start;
the angular effective mass; per equality row the softness triples (bias rate,
mass scale, impulse scale; constraints/softness.py) of the biased pass and of
the relax pass; the spring's and the limits' triples; the motor's clamp.

``G`` (per joint ``ROWS`` rows of NG floats, written by the kind's ``rows_*``
each pass): the row's Jacobian in the form
    C' = n . (v_a - v_b) + ka w_a - kb w_b,
its position error C (a limit row's C >= 0 when satisfied) and its effective
mass 1 / (J M^-1 J^T) (0 when nothing can move it).
"""
from __future__ import annotations

# F: prepared constants
RA0 = 0            # arm of a (x, y), world, step start
RB0 = 2            # arm of b (for the world: the world point)
D0 = 4             # x_a - x_b at the step start
U0 = 6             # axis, world, step start
MASS_ANG = 8       # 1 / (I_a^-1 + I_b^-1)
SOFT_EQ = 9        # per equality row r: 6 floats at SOFT_EQ + 6 r: (rate, ms, is) biased, then relax
SOFT_SPRING = 27   # (rate, ms, is) of the spring row
SOFT_LIMIT = 30    # (rate, ms, is) of the limit rows in the biased pass
MAX_MOTOR = 33     # motor row clamp: impulse per pass span (N s / N m s); motor and mouse: force clamp
MAX_TORQUE = 34    # motor joint: torque clamp
NF = 35

# G: per row
NX, NY, KA, KB, CC, MASS = range(6)
NG = 6
