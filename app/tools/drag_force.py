"""How hard the mouse drag may pull: Box2D's mouse joint caps its force at k * mass * g, so a
pinned or wedged body is not torn loose and a drag feeds a pile no more than k body weights.

k depends on the solver mode: the stiff modes (penalty springs, the hybrid's penalty contacts)
turn a strong pull through a pile into deep overlaps that their springs then release as an
explosion (on the default scene, a 100 g drag through the pyramid in penalty mode reached 0.54 m
of overlap and threw bodies past the world bound; at 10 g it stays at 0.11 m, the overlap of
pulling one box out of the pile).  The hybrid's penalty contacts are stiffer still: at 10 g the
same drag through the pyramid could throw its top boxes several metres, at 5 g it does not
(tests/app/test_drag_force.py drags it so in every mode).  The soft and sequential impulse
modes take Box2D's 100 g."""
from __future__ import annotations

import math

#: the drag's force limit per mode, in weights of the dragged body (k in k * mass * g)
WEIGHTS = {"soft_step": 100.0, "sequential_impulse": 100.0, "impulse": 30.0, "penalty": 10.0, "hybrid": 5.0}
DEFAULT_WEIGHTS = 10.0      # a mode not listed: the cautious limit
STANDARD_G = 9.81           # m/s^2: below this gravity (or none) the limit uses it, so a drag still lifts


def drag_force_limit(world, body) -> float:
    """The mouse joint's max force (N) for dragging ``body`` in ``world``'s current mode."""
    g = max(math.hypot(*world.gravity), STANDARD_G)
    return WEIGHTS.get(world.solver, DEFAULT_WEIGHTS) * max(body.mass, 1e-6) * g
