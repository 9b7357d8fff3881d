"""Springs between bodies, one module per formulation.

- ``geometry``: anchors in the world (shared by every formulation);
- ``force``: Hooke + damper as a force at a state (the seed's integrators);
- ``substep``: impulses per (sub-)step, explicit while soft, implicit when stiff;
- ``implicit``: all implicit springs of a (sub-)step as one linear system (PCG).
"""
