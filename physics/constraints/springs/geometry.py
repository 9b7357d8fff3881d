"""Where a spring's anchors are: the one piece every spring formulation shares."""
from __future__ import annotations

import math

from ..._jit import kernel


@kernel
def anchor(X, Q, i, lx, ly):
    """World position of body-frame point (lx, ly) of body i, and its arm r = R(q) l.

    ``X``, ``Q`` are positions and angles: the body table's, or an integrator's
    intermediate state (Runge-Kutta evaluates forces there)."""
    c = math.cos(Q[i])
    s = math.sin(Q[i])
    rx = c * lx - s * ly
    ry = s * lx + c * ly
    return X[i, 0] + rx, X[i, 1] + ry, rx, ry


@kernel
def movable(B, i):
    """Body slot i exists (i >= 0) and responds to impulses."""
    return i >= 0 and (B.inv_m[i] > 0.0 or B.inv_i[i] > 0.0)
