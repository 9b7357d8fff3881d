"""Constraint rows: what every solver mode is built from.

Contacts (and, next, joints) are constraint rows that speak the same verbs
(Box2D v3's contact_solver.c and *_joint.c): prepare (once per step), warm
start, solve (with bias), relax (solve without bias), restitution, store.  A
solver mode (physics/solvers/) is an ordering of those verbs.

- ``softness``: soft-constraint coefficients from a frequency and damping ratio.
- ``block``: the 2x2 block LCP of a two-point manifold (every solver's).
- ``body_rows``: the bodies as the rows see them (one compact row per body).
- ``contact_soft``: soft contact rows in projected form (soft_step).
- ``point``: the arms-and-vectors form of a contact point (sequential impulses,
  the seed modes): relative velocity, impulse application, per-step point rows.
- ``contact_rigid``: rigid PGS contact rows (sequential_impulse).
- ``split_impulse``: position correction on pseudo-velocities.
- ``springs``: springs as force generators and as implicit soft constraints.
"""
